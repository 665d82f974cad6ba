#include "points.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

namespace peers
{
namespace
{

constexpr char kPointsMagic[8] = { 'F', 'R', 'P', 'K', 'P', 'T', 'S', '1' };
constexpr char kValuesMagic[8] = { 'F', 'R', 'P', 'K', 'V', 'A', 'L', '1' };

void write_doubles(const std::string& path, const char (&magic)[8], const std::vector<double>& v,
  std::uint64_t count)
{
  std::ofstream out(path, std::ios::binary);
  out.write(magic, 8);
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
  if (!out)
  {
    throw std::runtime_error("cannot write " + path);
  }
}

std::vector<double> read_doubles(const std::string& path, const char (&magic)[8], int per_item)
{
  std::ifstream in(path, std::ios::binary);
  char head[8];
  std::uint64_t count = 0;
  if (!in.read(head, 8) || std::memcmp(head, magic, 8) != 0 ||
      !in.read(reinterpret_cast<char*>(&count), sizeof count))
  {
    throw std::runtime_error(path + ": not a " + std::string(magic, 8) + " file");
  }
  std::vector<double> v(count * per_item);
  if (!in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double))))
  {
    throw std::runtime_error(path + ": truncated");
  }
  return v;
}

} // namespace

Points random_points(std::size_t count, const double lo[3], const double hi[3], unsigned long seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> axis[3] = { std::uniform_real_distribution<double>(lo[0], hi[0]),
    std::uniform_real_distribution<double>(lo[1], hi[1]),
    std::uniform_real_distribution<double>(lo[2], hi[2]) };
  Points p;
  p.xyz.resize(3 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      p.xyz[3 * i + k] = axis[k](random);
    }
  }
  return p;
}

void write_points(const std::string& path, const Points& points)
{
  write_doubles(path, kPointsMagic, points.xyz, points.count());
}

Points read_points(const std::string& path)
{
  Points p;
  p.xyz = read_doubles(path, kPointsMagic, 3);
  return p;
}

void write_values(const std::string& path, const std::vector<double>& values)
{
  write_doubles(path, kValuesMagic, values, values.size());
}

std::vector<double> read_values(const std::string& path)
{
  return read_doubles(path, kValuesMagic, 1);
}

void parse_box(const std::string& text, double lo[3], double hi[3])
{
  std::stringstream in(text);
  double v[6];
  char comma = 0;
  for (int i = 0; i < 6; ++i)
  {
    if (!(in >> v[i]) || (i < 5 && !(in >> comma && comma == ',')))
    {
      throw std::runtime_error("bad box '" + text + "' (want x0,y0,z0,x1,y1,z1)");
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = v[k];
    hi[k] = v[k + 3];
  }
}

} // namespace peers
