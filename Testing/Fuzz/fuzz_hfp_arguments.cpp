// Fuzz harness (d2): hfp's command-line grammar (Apps/frepkit/hfp_arguments.*) on arbitrary
// argument lists: the input's lines are the arguments. Properties: the parser never throws; a
// parse that succeeds has its model file, and every clamped value inside hfp's clamps. Doubles
// are compared with !(v < lo) && !(v > hi): hfp compares the same way, so atof("nan") passes
// its clamps and ours alike (that is hfp's grammar; the mesher must cope).
#include "fuzz_check.h"
#include "hfp_arguments.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace
{

bool within(double v, double lo, double hi)
{
  return !(v < lo) && !(v > hi);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < size; ++i)
  {
    const char c = static_cast<char>(data[i]);
    if (c == '\n')
    {
      args.emplace_back();
    }
    else
    {
      args.back() += c;
    }
  }
  if (size == 0)
  {
    args.clear();
  }
  std::ostringstream messages;
  try
  {
    const frepkit::HfpParseResult result = frepkit::parse_hfp_arguments(args, messages);
    if (result.status != frepkit::HfpParseStatus::Ok)
    {
      return 0;
    }
    const frepkit::HfpArguments& a = result.arguments;
    FUZZ_CHECK(!args.empty() && a.model == args.front(), "the model is the first argument");
    for (const int g : a.grid)
    {
      FUZZ_CHECK(g >= frepkit::kHfpGridMin && g <= frepkit::kHfpGridMax, "-g is clamped");
    }
    FUZZ_CHECK(a.window[0] >= 160 && a.window[0] <= 1600, "-w width is clamped");
    FUZZ_CHECK(a.window[1] >= 120 && a.window[1] <= 1200, "-w height is clamped");
    for (const double s : a.slicing_step)
    {
      FUZZ_CHECK(within(s, 0.001, 10.0), "-gs is clamped");
    }
    for (const double c : a.face_colour)
    {
      FUZZ_CHECK(within(c, 0.0, 1.0), "-cf is clamped");
    }
    for (const double c : a.line_colour)
    {
      FUZZ_CHECK(within(c, 0.0, 1.0), "-cl is clamped");
    }
    FUZZ_CHECK(within(a.search_fraction, 0.0001, 1.0), "-s is clamped");
    const auto& m = a.xyz_mapping;
    FUZZ_CHECK(m[0] != m[1] && m[0] != m[2] && m[1] != m[2], "-x maps X, Y, Z apart");
    for (const int axis : m)
    {
      FUZZ_CHECK(axis >= 0 && static_cast<std::size_t>(axis) < a.x_constants.size(),
        "-x maps X, Y, Z to positions of its list");
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "exception: %s\n", e.what());
    FUZZ_CHECK(false, "hfp's parser never throws");
  }
  return 0;
}
