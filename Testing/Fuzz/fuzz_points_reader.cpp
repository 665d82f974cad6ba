// Fuzz harness (d1): frepkit eval's points reader on arbitrary text. The first byte chooses the
// dimension (1..8) and the read size (1..16 points per call). Properties: a malformed line is a
// UserError naming the source and line, never a crash or another exception; every call fills
// exactly `dimension` columns of the returned count.
#include "fuzz_check.h"
#include "points_reader.h"
#include "user_error.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  const int dimension = 1 + data[0] % 8;
  const std::size_t chunk = 1 + (data[0] >> 3) % 16;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  frepkit::PointsReader reader(in, "points.txt", dimension);
  std::vector<std::vector<double>> columns;
  try
  {
    for (;;)
    {
      const std::size_t n = reader.read(chunk, columns);
      FUZZ_CHECK(n <= chunk, "at most max_points points per call");
      FUZZ_CHECK(columns.size() == static_cast<std::size_t>(dimension), "one column per coordinate");
      for (const auto& column : columns)
      {
        FUZZ_CHECK(column.size() == n, "every column holds the points read");
      }
      if (n == 0)
      {
        break;
      }
    }
  }
  catch (const frepkit::UserError& e)
  {
    FUZZ_CHECK(std::string(e.what()).rfind("points.txt:", 0) == 0,
      "a points error names source:line");
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "exception: %s\n", e.what());
    FUZZ_CHECK(false, "the points reader throws only UserError");
  }
  return 0;
}
