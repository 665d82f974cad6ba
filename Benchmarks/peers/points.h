// The files every driver shares, so all peers see exactly the same inputs and their outputs can
// be compared value by value:
//   points: "FRPKPTS1", uint64 count, then count x, y, z doubles (interleaved), little-endian;
//   values: "FRPKVAL1", uint64 count, then count doubles.
// And a wall-clock timer.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace peers
{

struct Points
{
  std::vector<double> xyz; ///< x0 y0 z0 x1 y1 z1 ...
  std::size_t count() const { return xyz.size() / 3; }
};

/// `count` points uniform in the box [lo, hi] from a fixed seed (std::mt19937_64, one
/// std::uniform_real_distribution per axis, x, y, z per point).
Points random_points(std::size_t count, const double lo[3], const double hi[3], unsigned long seed);

void write_points(const std::string& path, const Points& points);
/// Throws std::runtime_error on a missing or malformed file.
Points read_points(const std::string& path);

void write_values(const std::string& path, const std::vector<double>& values);
std::vector<double> read_values(const std::string& path);

/// Parses "a,b,c,d,e,f" into six numbers (x0,y0,z0,x1,y1,z1); throws on anything else.
void parse_box(const std::string& text, double lo[3], double hi[3]);

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace peers
