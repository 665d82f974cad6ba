#include "benchmark_models.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

namespace frep::bench
{
namespace
{

std::string read_file(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot read " + path.string());
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The box of a model = the bounding box of the grid its reference values were computed on.
void box_from_expected(const std::filesystem::path& expected, BenchModel& model)
{
  std::ifstream in(expected);
  std::string line;
  model.lo.fill(std::numeric_limits<double>::infinity());
  model.hi.fill(-std::numeric_limits<double>::infinity());
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::array<double, 3> p{};
    if (!(fields >> p[0] >> p[1] >> p[2]))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      model.lo[k] = std::min(model.lo[k], p[k]);
      model.hi[k] = std::max(model.hi[k], p[k]);
    }
  }
}

} // namespace

std::string sphere_union_model(int count, bool balanced, bool by_max)
{
  std::mt19937_64 random(20261123);
  std::uniform_real_distribution<double> coordinate(-8.0, 8.0);
  std::ostringstream text;
  text.precision(17);
  text << "my_model(x[3], a[1])\n{\n";
  for (int i = 1; i <= count; ++i)
  {
    text << "  array c" << i << "[3];\n";
  }
  for (int i = 1; i <= count; ++i)
  {
    const double cx = coordinate(random), cy = coordinate(random), cz = coordinate(random);
    text << "  c" << i << " = [" << cx << ", " << cy << ", " << cz << "];\n";
  }
  if (!balanced)
  {
    text << "  u = hfSphere(x, c1, 0.6);\n";
    for (int i = 2; i <= count; ++i)
    {
      if (by_max)
      {
        text << "  u = max(u, hfSphere(x, c" << i << ", 0.6));\n";
      }
      else
      {
        text << "  u = u | hfSphere(x, c" << i << ", 0.6);\n";
      }
    }
    text << "  my_model = u;\n}\n";
    return text.str();
  }
  // Balanced pairwise tree: pair 1-2, 3-4, ..., an odd last element carried up, level by level.
  std::vector<std::string> level;
  for (int i = 1; i <= count; ++i)
  {
    text << "  t" << i << " = hfSphere(x, c" << i << ", 0.6);\n";
    level.push_back("t" + std::to_string(i));
  }
  int next = 0;
  while (level.size() > 1)
  {
    std::vector<std::string> up;
    for (std::size_t i = 0; i + 1 < level.size(); i += 2)
    {
      const std::string name = "v" + std::to_string(++next);
      text << "  " << name << " = " << level[i] << " | " << level[i + 1] << ";\n";
      up.push_back(name);
    }
    if (level.size() % 2 == 1)
    {
      up.push_back(level.back());
    }
    level = std::move(up);
  }
  text << "  my_model = " << level.front() << ";\n}\n";
  return text.str();
}

std::vector<BenchModel> benchmark_models(const std::string& shared_dir)
{
  namespace fs = std::filesystem;
  const fs::path models = fs::path(shared_dir) / "hyperfun" / "models";
  if (!fs::is_directory(models))
  {
    throw std::runtime_error("no models folder at " + models.string());
  }
  std::vector<BenchModel> result;
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(models))
  {
    if (entry.path().extension() == ".hf")
    {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files)
  {
    fs::path expected = file;
    expected.replace_extension(".expected.txt");
    if (!fs::exists(expected))
    {
      continue;
    }
    BenchModel model;
    model.name = file.stem().string();
    model.text = read_file(file);
    // HF_prog's reference values are for its object CSGobj (SOURCES.txt); others: my_model.
    model.object = model.name == "HF_prog" ? "csgobj" : "my_model";
    box_from_expected(expected, model);
    result.push_back(std::move(model));
  }
  for (const bool balanced : { false, true })
  {
    BenchModel model;
    model.name = balanced ? "union200_balanced" : "union200_chain";
    model.text = sphere_union_model(200, balanced);
    model.object = "my_model";
    model.lo = { -8, -8, -8 };
    model.hi = { 8, 8, 8 };
    result.push_back(std::move(model));
  }
  BenchModel by_max;
  by_max.name = "max200_chain";
  by_max.text = sphere_union_model(200, false, true);
  by_max.object = "my_model";
  by_max.lo = { -8, -8, -8 };
  by_max.hi = { 8, 8, 8 };
  result.push_back(std::move(by_max));
  return result;
}

} // namespace frep::bench
