// The command line of the original HyperFun polygonizer hfp, parsed exactly as hfp parsed it
// (../shared/hyperfun/POLYGONIZER_CLI.md): the model file first, then options as exact tokens in
// any order, comma-separated values, atoi/atof numbers with hfp's warnings, hfp's defaults,
// clamps and fallbacks, and hfp's messages. CLI11 cannot express this grammar (an option's value
// is missing when the next token is another option; "-usedc" eats the next token whatever it
// is; unknown tokens are ignored with a message), hence a parser of its own.
#pragma once

#include "Language/ast.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace frepkit
{

/// hfp's -g clamp is [2, 250] cells; frepkit's mesher is fast enough for more, so the upper
/// clamp is raised to 4095 cells (4096 samples per axis, the mesher's limit per axis at 4096^3).
constexpr int kHfpGridMin = 2;
constexpr int kHfpGridMax = 4095;

struct HfpArguments
{
  std::string model;
  std::string object{ frep::ast::default_object_name }; ///< hfp -o (matched exactly)
  /// Which x index (0-based) the polygonizer's X, Y, Z axes drive.
  std::array<int, 3> xyz_mapping{ 0, 1, 2 };
  /// -x's list: values of the fixed coordinates (entries at the X/Y/Z positions are unused).
  std::vector<double> x_constants{ 0.0, 0.0, 0.0 };
  std::vector<double> parameters{ 0.0 };
  bool time_report = false;
  std::array<int, 3> grid{ 30, 30, 30 };                  ///< cells per axis
  std::array<double, 3> slicing_step{ 1.0, 1.0, 1.0 };    ///< -gs (x, y, z)
  std::array<double, 6> box{ -10, -10, -10, 10, 10, 10 }; ///< xmin,ymin,zmin,xmax,ymax,zmax
  std::array<double, 3> face_colour{ 0.196078, 0.784314, 0.313725 }; ///< -cf / 255
  std::array<double, 3> line_colour{ 0, 0, 0 };
  double iso = 0.0;
  std::array<int, 2> window{ 480, 320 };
  bool search = false;
  double search_fraction = 0.1; ///< -s D: vertex precision in cell sizes
  bool reduce = false;
  bool wrl = false;
  std::string wrl_name = "out.wrl";
  bool stl = false;  ///< ASCII
  bool stlb = false; ///< binary (both share stl_name; -stl wins when both are given, as in hfp)
  std::string stl_name = "out.stl";
  bool pov = false;
  std::string pov_name = "out.pov";
  bool cli = false;
  std::string cli_name = "out.cli";
  int display_mode = 5;
  bool normals = true; ///< display modes 1 and 2 switch normals off (also in VRML)
  bool show_box = false;
  bool show_axes = false;
  bool use_dc = true;
  bool attributes = false;          ///< -ct
  std::vector<std::string> ignored; ///< unknown tokens
};

enum class HfpParseStatus
{
  Ok,
  Help,        ///< "-h" as the first argument
  NoArguments, ///< nothing at all
  NoModel      ///< the first argument is an option
};

struct HfpParseResult
{
  HfpArguments arguments;
  HfpParseStatus status = HfpParseStatus::Ok;
};

/// Parses `args` (without the program name). hfp's messages (ignored tokens, missing values,
/// clamps, bad numbers) go to `messages` as hfp printed them.
HfpParseResult parse_hfp_arguments(const std::vector<std::string>& args, std::ostream& messages);

/// The usage text of `frepkit hfp -h`.
std::string hfp_help_text();

} // namespace frepkit
