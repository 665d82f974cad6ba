// Reads evaluation points: one point per line, whitespace-separated coordinates. Blank lines and
// lines starting with '#' are skipped. A malformed line is a UserError naming source:line.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace frepkit
{

class PointsReader
{
public:
  PointsReader(std::istream& in, std::string source_name, int dimension);

  /// Reads up to `max_points` points; columns[k][i] = coordinate k of point i (columns are
  /// resized to `dimension` vectors and cleared first). Returns the number read, 0 at the end.
  std::size_t read(std::size_t max_points, std::vector<std::vector<double>>& columns);

private:
  std::istream& in_;
  std::string source_name_;
  int dimension_;
  std::size_t line_number_ = 0;
  std::string line_;
};

} // namespace frepkit
