#include "cli_writer.h"

#include <cstdio>
#include <ctime>
#include <string>

namespace frepkit
{
namespace
{

/// Coordinates as %.9g: exact to about a nanometre at model sizes, still plain decimal text.
void append_coordinate(std::string& text, double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  text += buffer;
}

} // namespace

void write_cli_header(std::ostream& out)
{
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::snprintf(date, sizeof date, "%02d%02d%02d", utc.tm_mday, utc.tm_mon + 1, utc.tm_year % 100);
  out << "$$HEADERSTART\n$$ASCII\n$$UNITS/1\n$$DATE/" << date << "\n$$HEADEREND\n\n"
      << "$$GEOMETRYSTART\n";
}

void write_cli_layer(std::ostream& out, double z, const std::vector<ContourLoop>& loops)
{
  std::string text = "$$LAYER/";
  append_coordinate(text, z);
  text += '\n';
  for (const ContourLoop& loop : loops)
  {
    text += "$$POLYLINE/1,";
    text += loop.signed_area > 0 ? "1," : "0,";
    text += std::to_string(loop.points.size());
    for (const auto& point : loop.points)
    {
      text += ',';
      append_coordinate(text, point[0]);
      text += ',';
      append_coordinate(text, point[1]);
    }
    text += '\n';
  }
  out << text;
}

void write_cli_end(std::ostream& out)
{
  out << "$$GEOMETRYEND\n";
}

} // namespace frepkit
