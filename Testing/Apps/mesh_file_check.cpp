// frepkit_mesh_check FILE [--closed]: reads a mesh file written by frepkit (binary or ASCII STL,
// binary little-endian PLY, OBJ) and prints what the tests check: counts, normals/colours present,
// and the topology (every edge in exactly two triangles, run in opposite directions; the signed
// volume). With --closed the exit code is 1 unless the mesh is watertight, consistently oriented
// and encloses a positive volume. Exit code 2: the file could not be read or is malformed.
#include "Mesh/mesh_topology.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

struct Loaded
{
  frep::mesh::Surface surface;
  bool normals = false;
  bool colours = false;
};

std::string read_all(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot open " + path);
  }
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

template<typename T>
T little(const std::string& bytes, std::size_t offset)
{
  if (offset + sizeof(T) > bytes.size())
  {
    throw std::runtime_error("truncated file");
  }
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T)); // x86-64 is little-endian
  return value;
}

/// STL has no shared points: equal coordinates are one point.
class PointMerger
{
public:
  explicit PointMerger(frep::mesh::Surface& surface)
    : surface_(surface)
  {
  }
  std::uint32_t add(float x, float y, float z)
  {
    const auto [it, inserted] =
      ids_.try_emplace({ x, y, z }, static_cast<std::uint32_t>(surface_.points.size() / 3));
    if (inserted)
    {
      surface_.points.insert(surface_.points.end(), { x, y, z });
    }
    return it->second;
  }

private:
  frep::mesh::Surface& surface_;
  std::map<std::array<float, 3>, std::uint32_t> ids_;
};

Loaded read_stl(const std::string& bytes)
{
  Loaded loaded;
  PointMerger merger(loaded.surface);
  const bool binary =
    bytes.size() >= 84 &&
    bytes.size() == 84 + 50 * static_cast<std::size_t>(little<std::uint32_t>(bytes, 80));
  if (binary)
  {
    const std::uint32_t count = little<std::uint32_t>(bytes, 80);
    for (std::uint32_t t = 0; t < count; ++t)
    {
      const std::size_t base = 84 + 50 * static_cast<std::size_t>(t) + 12;
      for (int corner = 0; corner < 3; ++corner)
      {
        const std::size_t at = base + 12 * static_cast<std::size_t>(corner);
        loaded.surface.cells.push_back(merger.add(
          little<float>(bytes, at), little<float>(bytes, at + 4), little<float>(bytes, at + 8)));
      }
    }
    return loaded;
  }
  if (bytes.rfind("solid", 0) != 0 || bytes.find("endsolid") == std::string::npos)
  {
    throw std::runtime_error("neither binary STL (size 84 + 50 n) nor ASCII STL");
  }
  std::istringstream in(bytes);
  std::string word;
  int corners = 0;
  while (in >> word)
  {
    if (word == "vertex")
    {
      float x, y, z;
      if (!(in >> x >> y >> z))
      {
        throw std::runtime_error("bad vertex line");
      }
      loaded.surface.cells.push_back(merger.add(x, y, z));
      ++corners;
    }
    else if (word == "endloop" && corners % 3 != 0)
    {
      throw std::runtime_error("a facet without 3 vertices");
    }
  }
  return loaded;
}

Loaded read_ply(const std::string& bytes)
{
  Loaded loaded;
  const std::size_t end = bytes.find("end_header\n");
  if (bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0) != 0 || end == std::string::npos)
  {
    throw std::runtime_error("not a binary little-endian PLY");
  }
  std::istringstream header(bytes.substr(0, end));
  std::string line;
  std::size_t vertices = 0, faces = 0, vertex_floats = 0, vertex_bytes = 0;
  std::string element;
  while (std::getline(header, line))
  {
    std::istringstream words(line);
    std::string first, type, name;
    words >> first;
    if (first == "element")
    {
      words >> element >> (element == "vertex" ? vertices : faces);
    }
    else if (first == "property" && element == "vertex")
    {
      words >> type >> name;
      if (type == "float")
      {
        ++vertex_floats;
        vertex_bytes += 4;
        loaded.normals |= name == "nx";
      }
      else if (type == "uchar")
      {
        vertex_bytes += 1;
        loaded.colours |= name == "red";
      }
      else
      {
        throw std::runtime_error("unexpected vertex property type " + type);
      }
    }
    else if (first == "property" && element == "face" &&
             line != "property list uchar int vertex_indices")
    {
      throw std::runtime_error("unexpected face property: " + line);
    }
  }
  std::size_t at = end + std::strlen("end_header\n");
  for (std::size_t v = 0; v < vertices; ++v, at += vertex_bytes)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      loaded.surface.points.push_back(little<float>(bytes, at + 4 * k));
    }
  }
  (void)vertex_floats;
  for (std::size_t f = 0; f < faces; ++f)
  {
    if (little<std::uint8_t>(bytes, at) != 3)
    {
      throw std::runtime_error("a face that is not a triangle");
    }
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::int32_t id = little<std::int32_t>(bytes, at + 1 + 4 * k);
      if (id < 0 || static_cast<std::size_t>(id) >= vertices)
      {
        throw std::runtime_error("a face refers to a missing vertex");
      }
      loaded.surface.cells.push_back(static_cast<std::uint32_t>(id));
    }
    at += 13;
  }
  if (at != bytes.size())
  {
    throw std::runtime_error("PLY size does not match its header");
  }
  return loaded;
}

Loaded read_obj(const std::string& bytes)
{
  Loaded loaded;
  std::istringstream in(bytes);
  std::string line;
  std::size_t normals = 0;
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v")
    {
      double x, y, z, r;
      if (!(words >> x >> y >> z))
      {
        throw std::runtime_error("bad v line: " + line);
      }
      loaded.surface.points.insert(loaded.surface.points.end(), { x, y, z });
      loaded.colours |= static_cast<bool>(words >> r);
    }
    else if (kind == "vn")
    {
      ++normals;
    }
    else if (kind == "f")
    {
      std::string corner;
      int corners = 0;
      while (words >> corner)
      {
        const long id = std::stol(corner.substr(0, corner.find('/')));
        if (id < 1 || static_cast<std::size_t>(id) > loaded.surface.point_count())
        {
          throw std::runtime_error("a face refers to a missing vertex: " + line);
        }
        loaded.surface.cells.push_back(static_cast<std::uint32_t>(id - 1));
        ++corners;
      }
      if (corners != 3)
      {
        throw std::runtime_error("a face that is not a triangle: " + line);
      }
    }
  }
  loaded.normals = normals > 0;
  if (loaded.normals && normals != loaded.surface.point_count())
  {
    throw std::runtime_error("vn count differs from v count");
  }
  return loaded;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: frepkit_mesh_check FILE.{stl,ply,obj} [--closed]\n";
    return 2;
  }
  const std::string path = argv[1];
  const bool closed = argc > 2 && std::string(argv[2]) == "--closed";
  Loaded loaded;
  try
  {
    const std::string bytes = read_all(path);
    const std::string extension = path.substr(path.find_last_of('.') + 1);
    if (extension == "stl")
    {
      loaded = read_stl(bytes);
    }
    else if (extension == "ply")
    {
      loaded = read_ply(bytes);
    }
    else if (extension == "obj")
    {
      loaded = read_obj(bytes);
    }
    else
    {
      throw std::runtime_error("unknown extension");
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << path << ": " << e.what() << '\n';
    return 2;
  }
  const frep::mesh::MeshTopology topology = frep::mesh::analyse_topology(loaded.surface);
  std::cout << "triangles " << topology.triangles << " points " << loaded.surface.point_count()
            << " boundary " << topology.boundary_edges << " nonmanifold "
            << topology.nonmanifold_edges << " misoriented " << topology.misoriented_edges
            << " degenerate " << topology.degenerate_triangles << " components "
            << topology.components << " euler " << topology.euler_characteristic << " volume "
            << topology.signed_volume << " normals "
            << (loaded.normals ? "yes" : "no") << " colours " << (loaded.colours ? "yes" : "no")
            << '\n';
  if (closed && !(topology.watertight_and_oriented() && topology.signed_volume > 0))
  {
    std::cerr << path << ": not a closed, outward-oriented mesh\n";
    return 1;
  }
  return 0;
}
