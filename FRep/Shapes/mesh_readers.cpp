#include "Shapes/mesh_readers.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <unordered_map>

namespace frep::shapes
{
namespace
{

std::string extension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// Merges equal points (STL writes each triangle's corners separately).
class PointMerger
{
public:
  explicit PointMerger(TriangleMesh& mesh)
    : mesh_(mesh)
  {
  }
  std::uint32_t add(double x, double y, double z)
  {
    const std::array<double, 3> key{ x == 0 ? 0.0 : x, y == 0 ? 0.0 : y, z == 0 ? 0.0 : z };
    auto [it, inserted] = ids_.try_emplace(key, static_cast<std::uint32_t>(mesh_.point_count()));
    if (inserted)
    {
      mesh_.points.insert(mesh_.points.end(), key.begin(), key.end());
    }
    return it->second;
  }

private:
  TriangleMesh& mesh_;
  std::map<std::array<double, 3>, std::uint32_t> ids_;
};

MeshReadResult failure(std::string message)
{
  MeshReadResult r;
  r.error = std::move(message);
  return r;
}

template<class T>
T load(const char* p, bool big_endian)
{
  T v;
  std::memcpy(&v, p, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big))
  {
    auto* b = reinterpret_cast<unsigned char*>(&v);
    std::reverse(b, b + sizeof(T));
  }
  return v;
}

MeshReadResult read_binary_stl(std::string_view bytes)
{
  MeshReadResult r;
  const std::uint32_t count = load<std::uint32_t>(bytes.data() + 80, false);
  PointMerger merge(r.mesh);
  for (std::uint32_t t = 0; t < count; ++t)
  {
    const char* p = bytes.data() + 84 + 50 * static_cast<std::size_t>(t) + 12;
    for (int k = 0; k < 3; ++k)
    {
      const float x = load<float>(p + 12 * k, false);
      const float y = load<float>(p + 12 * k + 4, false);
      const float z = load<float>(p + 12 * k + 8, false);
      r.mesh.triangles.push_back(merge.add(x, y, z));
    }
  }
  return r;
}

// Whitespace-separated words of a line-oriented text.
bool next_word(std::string_view text, std::size_t& pos, std::string_view& word)
{
  while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos])))
  {
    ++pos;
  }
  if (pos >= text.size())
  {
    return false;
  }
  const std::size_t start = pos;
  while (pos < text.size() && !std::isspace(static_cast<unsigned char>(text[pos])))
  {
    ++pos;
  }
  word = text.substr(start, pos - start);
  return true;
}

bool to_double(std::string_view w, double& v)
{
  const char* end = w.data() + w.size();
  const auto r = std::from_chars(w.data(), end, v);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(v);
}

MeshReadResult read_ascii_stl(std::string_view text)
{
  MeshReadResult r;
  PointMerger merge(r.mesh);
  std::size_t pos = 0;
  std::string_view w;
  std::size_t corners = 0;
  while (next_word(text, pos, w))
  {
    if (w != "vertex")
    {
      continue;
    }
    double c[3];
    for (double& v : c)
    {
      std::string_view number;
      if (!next_word(text, pos, number) || !to_double(number, v))
      {
        return failure("ASCII STL: a vertex without three finite numbers");
      }
    }
    r.mesh.triangles.push_back(merge.add(c[0], c[1], c[2]));
    ++corners;
  }
  if (corners % 3 != 0)
  {
    return failure("ASCII STL: a facet without three vertices");
  }
  return r;
}

} // namespace

bool is_mesh_file(const std::string& path)
{
  const std::string e = extension(path);
  return e == "stl" || e == "obj" || e == "ply";
}

MeshReadResult read_stl(std::string_view bytes)
{
  // Binary if the size is what the count says (an ASCII file may also start with "solid").
  if (bytes.size() >= 84)
  {
    const std::uint32_t count = load<std::uint32_t>(bytes.data() + 80, false);
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count))
    {
      return read_binary_stl(bytes);
    }
  }
  if (bytes.substr(0, 5) == "solid")
  {
    return read_ascii_stl(bytes);
  }
  return failure("not an STL file (neither a binary STL of consistent size nor ASCII)");
}

MeshReadResult read_obj(std::string_view text)
{
  MeshReadResult r;
  std::size_t line_start = 0;
  int line_number = 0;
  while (line_start < text.size())
  {
    std::size_t line_end = text.find('\n', line_start);
    if (line_end == std::string_view::npos)
    {
      line_end = text.size();
    }
    const std::string_view line = text.substr(line_start, line_end - line_start);
    line_start = line_end + 1;
    ++line_number;
    std::size_t pos = 0;
    std::string_view w;
    if (!next_word(line, pos, w))
    {
      continue;
    }
    if (w == "v")
    {
      for (int k = 0; k < 3; ++k)
      {
        std::string_view number;
        double v = 0;
        if (!next_word(line, pos, number) || !to_double(number, v))
        {
          return failure("OBJ line " + std::to_string(line_number) + ": a vertex needs 3 numbers");
        }
        r.mesh.points.push_back(v);
      }
    }
    else if (w == "f")
    {
      std::vector<std::uint32_t> face;
      std::string_view ref;
      while (next_word(line, pos, ref))
      {
        // "i", "i/t", "i/t/n", "i//n"; negative = relative to the end.
        const std::string_view index = ref.substr(0, ref.find('/'));
        long long i = 0;
        const auto res = std::from_chars(index.data(), index.data() + index.size(), i);
        const long long n = static_cast<long long>(r.mesh.point_count());
        if (res.ec != std::errc() || i == 0)
        {
          return failure("OBJ line " + std::to_string(line_number) + ": a bad face index");
        }
        const long long id = i > 0 ? i - 1 : n + i;
        if (id < 0 || id >= n)
        {
          return failure("OBJ line " + std::to_string(line_number) +
            ": a face refers to a vertex not defined before it");
        }
        face.push_back(static_cast<std::uint32_t>(id));
      }
      if (face.size() < 3)
      {
        return failure("OBJ line " + std::to_string(line_number) + ": a face with fewer than 3 vertices");
      }
      for (std::size_t k = 1; k + 1 < face.size(); ++k) // a fan: polygons must be convex
      {
        r.mesh.triangles.insert(r.mesh.triangles.end(), { face[0], face[k], face[k + 1] });
      }
    }
  }
  return r;
}

namespace
{

/// A PLY element's property: a number, or a list of numbers (count_type non-empty).
struct PlyProperty
{
  std::string name;
  std::string type;
  std::string count_type; ///< non-empty for a list
};
/// A PLY element: its name, count and properties, from the header.
struct PlyElement
{
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

/// Bytes of a PLY number type; 0 for an unknown one.
int ply_size_of(const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

/// The elements and the format named by a PLY header (the text before end_header); the error,
/// or "".
std::string read_ply_header(std::string_view header_text, std::vector<PlyElement>& elements,
  std::string& format)
{
  std::istringstream header{ std::string(header_text) };
  std::string line;
  while (std::getline(header, line))
  {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "format")
    {
      words >> format;
    }
    else if (key == "element")
    {
      PlyElement e;
      long long count = -1;
      words >> e.name >> count;
      if (count < 0 || count > 1'000'000'000)
      {
        return "PLY: a bad element count";
      }
      e.count = static_cast<std::size_t>(count);
      elements.push_back(e);
    }
    else if (key == "property")
    {
      if (elements.empty())
      {
        return "PLY: a property before any element";
      }
      PlyProperty p;
      words >> p.type;
      if (p.type == "list")
      {
        words >> p.count_type >> p.type;
      }
      words >> p.name;
      elements.back().properties.push_back(p);
    }
  }
  return {};
}

/// Reads the numbers of a PLY body one at a time, ASCII or binary, from `pos` on.
struct PlyNumbers
{
  std::string_view bytes;
  std::size_t pos;
  bool ascii;
  bool big;

  /// One number of type t; false at the end of the data or on a bad (or non-finite) number.
  bool read(const std::string& t, double& v)
  {
    if (ascii)
    {
      std::string_view w;
      return next_word(bytes, pos, w) && to_double(w, v);
    }
    const int n = ply_size_of(t);
    if (n == 0 || pos + static_cast<std::size_t>(n) > bytes.size())
    {
      return false;
    }
    const char* p = bytes.data() + pos;
    pos += static_cast<std::size_t>(n);
    if (t == "char" || t == "int8") v = load<std::int8_t>(p, big);
    else if (t == "uchar" || t == "uint8") v = load<std::uint8_t>(p, big);
    else if (t == "short" || t == "int16") v = load<std::int16_t>(p, big);
    else if (t == "ushort" || t == "uint16") v = load<std::uint16_t>(p, big);
    else if (t == "int" || t == "int32") v = load<std::int32_t>(p, big);
    else if (t == "uint" || t == "uint32") v = load<std::uint32_t>(p, big);
    else if (t == "float" || t == "float32") v = load<float>(p, big);
    else v = load<double>(p, big);
    return std::isfinite(v);
  }
};

} // namespace

MeshReadResult read_ply(std::string_view bytes)
{
  if (bytes.substr(0, 4) != "ply\n" && bytes.substr(0, 5) != "ply\r\n")
  {
    return failure("not a PLY file (no 'ply' line)");
  }
  const std::size_t header_end = bytes.find("end_header");
  if (header_end == std::string_view::npos)
  {
    return failure("PLY: no end_header");
  }
  std::size_t body = bytes.find('\n', header_end);
  if (body == std::string_view::npos)
  {
    return failure("PLY: nothing after end_header");
  }
  ++body;
  std::vector<PlyElement> elements;
  std::string format;
  if (std::string error = read_ply_header(bytes.substr(0, header_end), elements, format);
      !error.empty())
  {
    return failure(error);
  }
  const bool ascii = format == "ascii";
  const bool big = format == "binary_big_endian";
  if (!ascii && !big && format != "binary_little_endian")
  {
    return failure("PLY: unknown format '" + format + "'");
  }
  PlyNumbers numbers{ bytes, body, ascii, big };
  MeshReadResult r;
  for (const PlyElement& e : elements)
  {
    for (const PlyProperty& p : e.properties)
    {
      if (ply_size_of(p.type) == 0 || (!p.count_type.empty() && ply_size_of(p.count_type) == 0))
      {
        return failure("PLY: unknown property type in element " + e.name);
      }
    }
    for (std::size_t i = 0; i < e.count; ++i)
    {
      std::array<double, 3> xyz{};
      for (const PlyProperty& p : e.properties)
      {
        if (p.count_type.empty())
        {
          double v = 0;
          if (!numbers.read(p.type, v))
          {
            return failure("PLY: the data ends early or has a bad number (element " + e.name + ")");
          }
          if (e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z"))
          {
            xyz[static_cast<std::size_t>(p.name[0] - 'x')] = v;
          }
          continue;
        }
        double count = 0;
        if (!numbers.read(p.count_type, count) || count < 0 || count > 1000)
        {
          return failure("PLY: a bad list size in element " + e.name);
        }
        std::vector<std::uint32_t> ids;
        for (int k = 0; k < static_cast<int>(count); ++k)
        {
          double v = 0;
          if (!numbers.read(p.type, v) || v < 0 || v > 4294967295.0)
          {
            return failure("PLY: a bad index in element " + e.name);
          }
          ids.push_back(static_cast<std::uint32_t>(v));
        }
        if (e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index"))
        {
          if (ids.size() < 3)
          {
            return failure("PLY: a face with fewer than 3 vertices");
          }
          for (std::size_t k = 1; k + 1 < ids.size(); ++k)
          {
            r.mesh.triangles.insert(r.mesh.triangles.end(), { ids[0], ids[k], ids[k + 1] });
          }
        }
      }
      if (e.name == "vertex")
      {
        r.mesh.points.insert(r.mesh.points.end(), xyz.begin(), xyz.end());
      }
    }
  }
  return r;
}

MeshReadResult read_mesh_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return failure(path + ": cannot open the file");
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string e = extension(path);
  MeshReadResult r;
  if (e == "stl")
  {
    r = read_stl(bytes);
  }
  else if (e == "obj")
  {
    r = read_obj(bytes);
  }
  else if (e == "ply")
  {
    r = read_ply(bytes);
  }
  else
  {
    return failure(path + ": not a mesh file this reader knows (.stl, .obj, .ply)");
  }
  if (!r.ok())
  {
    r.error = path + ": " + r.error;
  }
  else if (std::string v = validate(r.mesh); !v.empty())
  {
    r.error = path + ": " + v;
  }
  return r;
}

} // namespace frep::shapes
