#include "hfp_arguments.h"

#include <algorithm>
#include <cstdlib>

namespace frepkit
{
namespace
{

const std::vector<std::string> kOptions = { "-o",
  "-x",
  "-a",
  "-t",
  "-g",
  "-gs",
  "-b",
  "-cl",
  "-cf",
  "-i",
  "-h",
  "-w",
  "-s",
  "-r",
  "-stl",
  "-stlb",
  "-wrl",
  "-pov",
  "-cli",
  "-d",
  "-sb",
  "-sa",
  "-ct",
  "-usedc" };

bool is_option(const std::string& token)
{
  return std::find(kOptions.begin(), kOptions.end(), token) != kOptions.end();
}

std::vector<std::string> split_commas(const std::string& text)
{
  // hfp's splitting: every comma separates, an empty text is one empty entry.
  std::vector<std::string> parts(1);
  for (char c : text)
  {
    if (c == ',')
    {
      parts.emplace_back();
    }
    else
    {
      parts.back() += c;
    }
  }
  return parts;
}

class Parser
{
public:
  Parser(const std::vector<std::string>& args, std::ostream& messages)
    : args_(args)
    , messages_(messages)
  {
  }

  void parse(HfpArguments& a)
  {
    a.model = args_[0];
    position_ = 1;
    while (position_ < args_.size())
    {
      const std::string token = args_[position_++];
      if (!is_option(token))
      {
        messages_ << "\"" << token << "\" is not a valid argument.\nIgnoring\n";
        a.ignored.push_back(token);
        continue;
      }
      option(token, a);
    }
  }

private:
  /// The value after an option, if there is one that is not itself an option.
  bool has_value(const std::string& key, bool report = true)
  {
    if (position_ >= args_.size() || is_option(args_[position_]))
    {
      if (report)
      {
        messages_ << key << " requires an argument.\nUsing default value.\n";
      }
      return false;
    }
    return true;
  }
  const std::string& take() { return args_[position_++]; }

  int to_int(const std::string& text)
  {
    const int value = std::atoi(text.c_str());
    if (value == 0 && text != "0")
    {
      messages_ << "\"" << text
                << "\" is not a proper integer value.\nUsing the value 0 instead.\n";
    }
    return value;
  }
  double to_double(const std::string& text)
  {
    const double value = std::atof(text.c_str());
    if (value == 0 && text != "0" && text != "0.0")
    {
      messages_ << "\"" << text
                << "\" is not a proper floating point value.\nUsing the value 0.0 instead.\n";
    }
    return value;
  }
  std::vector<int> to_ints(const std::string& text)
  {
    std::vector<int> values;
    for (const std::string& part : split_commas(text))
    {
      values.push_back(to_int(part));
    }
    return values;
  }
  std::vector<double> to_doubles(const std::string& text)
  {
    std::vector<double> values;
    for (const std::string& part : split_commas(text))
    {
      values.push_back(to_double(part));
    }
    return values;
  }
  template<typename T>
  T clamp(T value, T low, T high, const std::string& key)
  {
    if (value < low || value > high)
    {
      const T bound = value < low ? low : high;
      messages_ << "The value " << value << " in the <" << key
                << "> argument is not within the specified range.\nClamping to " << bound << ".\n";
      return bound;
    }
    return value;
  }
  void invalid(const std::string& value, const std::string& key, bool plural = true)
  {
    messages_ << "\"" << value << "\" is not a valid argument for <" << key << ">.\nUsing default "
              << (plural ? "values" : "value") << ".\n";
  }

  void option(const std::string& key, HfpArguments& a)
  {
    if (key == "-o")
    {
      if (has_value(key))
      {
        a.object = take();
      }
    }
    else if (key == "-x")
    {
      if (has_value(key))
      {
        mapping(take(), a);
      }
    }
    else if (key == "-a")
    {
      if (has_value(key))
      {
        a.parameters = to_doubles(take());
      }
    }
    else if (key == "-t")
    {
      a.time_report = true;
    }
    else if (key == "-g")
    {
      grid_option(key, a);
    }
    else if (key == "-gs")
    {
      slicing_step_option(key, a);
    }
    else if (key == "-b")
    {
      if (has_value(key))
      {
        box(take(), a);
      }
    }
    else if (key == "-cl" || key == "-cf")
    {
      colour_option(key, a);
    }
    else if (key == "-i")
    {
      if (has_value(key))
      {
        a.iso = to_double(take());
      }
    }
    else if (key == "-h")
    {
      messages_ << hfp_help_text();
    }
    else if (key == "-w")
    {
      window_option(key, a);
    }
    else if (key == "-s")
    {
      search_option(key, a);
    }
    else if (key == "-r")
    {
      a.reduce = true;
    }
    else if (key == "-wrl")
    {
      a.wrl = true;
      if (has_value(key))
      {
        a.wrl_name = take();
      }
    }
    else if (key == "-stl" || key == "-stlb")
    {
      (key == "-stl" ? a.stl : a.stlb) = true;
      if (has_value(key))
      {
        a.stl_name = take();
      }
    }
    else if (key == "-pov")
    {
      a.pov = true;
      if (has_value(key))
      {
        a.pov_name = take();
      }
    }
    else if (key == "-cli")
    {
      a.cli = true;
      if (has_value(key))
      {
        a.cli_name = take();
      }
    }
    else if (key == "-d")
    {
      display_option(key, a);
    }
    else if (key == "-sb")
    {
      a.show_box = true;
    }
    else if (key == "-sa")
    {
      a.show_axes = true;
    }
    else if (key == "-usedc")
    {
      use_dc_option(key, a);
    }
    else if (key == "-ct")
    {
      a.attributes = true;
    }
  }

  /// -g N or NX,NY,NZ: samples per axis.
  void grid_option(const std::string& key, HfpArguments& a)
  {
    if (has_value(key))
    {
      const std::string& text = take();
      const std::vector<int> values = to_ints(text);
      if (values.size() == 1 || values.size() == 3)
      {
        for (std::size_t k = 0; k < 3; ++k)
        {
          a.grid[k] = clamp(values[values.size() == 1 ? 0 : k], kHfpGridMin, kHfpGridMax, key);
          if (values.size() == 1)
          {
            a.grid = { a.grid[0], a.grid[0], a.grid[0] };
            break;
          }
        }
      }
      else
      {
        a.grid = { 30, 30, 30 };
        invalid(text, key);
      }
    }
  }

  /// -gs S, SXY,SZ or SX,SY,SZ: the slicing step.
  void slicing_step_option(const std::string& key, HfpArguments& a)
  {
    if (has_value(key))
    {
      const std::string& text = take();
      const std::vector<double> v = to_doubles(text);
      auto c = [&](double value) { return clamp(value, 0.001, 10.0, key); };
      if (v.size() == 1)
      {
        const double step = c(v[0]);
        a.slicing_step = { step, step, step };
      }
      else if (v.size() == 2)
      {
        // hfp: the first value for x and y, the second for z.
        const double xy = c(v[0]);
        a.slicing_step = { xy, xy, c(v[1]) };
      }
      else if (v.size() == 3)
      {
        a.slicing_step = { c(v[0]), c(v[1]), c(v[2]) };
      }
      else
      {
        a.slicing_step = { 1.0, 1.0, 1.0 };
        invalid(text, key);
      }
    }
  }

  /// -cl / -cf: the line or face colour, one grey level or R,G,B in 0..255.
  void colour_option(const std::string& key, HfpArguments& a)
  {
    if (has_value(key))
    {
      const std::string& text = take();
      const std::vector<int> v = to_ints(text);
      std::array<double, 3>& colour = key == "-cl" ? a.line_colour : a.face_colour;
      if (v.size() == 1 || v.size() == 3)
      {
        for (std::size_t k = 0; k < 3; ++k)
        {
          colour[k] = clamp(v[v.size() == 1 ? 0 : k], 0, 255, key) / 255.0;
          if (v.size() == 1)
          {
            colour = { colour[0], colour[0], colour[0] };
            break;
          }
        }
      }
      else
      {
        colour = key == "-cl" ? std::array<double, 3>{ 0, 0, 0 }
                              : std::array<double, 3>{ 0.196078, 0.784314, 0.313725 };
        invalid(text, key);
      }
    }
  }

  /// -w W[,H]: the window size.
  void window_option(const std::string& key, HfpArguments& a)
  {
    if (has_value(key))
    {
      const std::string& text = take();
      const std::vector<int> v = to_ints(text);
      if (v.size() == 1 || v.size() == 2)
      {
        a.window = { clamp(v[0], 160, 1600, key), clamp(v[v.size() - 1], 120, 1200, key) };
      }
      else
      {
        a.window = { 480, 320 };
        invalid(text, key);
      }
    }
  }

  /// -s [F]: the surface search, to within F of a cell.
  void search_option(const std::string& key, HfpArguments& a)
  {
    a.search = true;
    if (has_value(key, false))
    {
      a.search_fraction = clamp(to_double(take()), 0.0001, 1.0, key);
      if (a.search_fraction == 1.0)
      {
        a.search = false; // hfp: a search to within one cell is no search
      }
    }
  }

  /// -d M: the display mode 1..7.
  void display_option(const std::string& key, HfpArguments& a)
  {
    if (has_value(key))
    {
      const std::string& text = take();
      const std::vector<int> v = to_ints(text);
      if (v.size() == 1 && v[0] >= 1 && v[0] <= 7)
      {
        a.display_mode = v[0];
        a.normals = v[0] > 2; // modes 1 and 2 compute no normals
      }
      else
      {
        if (v.size() != 1)
        {
          a.display_mode = 5;
        }
        invalid(text, key);
      }
    }
  }

  /// -usedc 0|1: hfp reads the next token whatever it is (even another option).
  void use_dc_option(const std::string& key, HfpArguments& a)
  {
    if (position_ >= args_.size())
    {
      messages_ << key << " requires an argument.\nUsing default value.\n";
      return;
    }
    const std::string& text = take();
    const std::vector<int> v = to_ints(text);
    if (v.size() != 1)
    {
      invalid(text, key);
    }
    a.use_dc = v[0] != 0;
  }

  void mapping(const std::string& text, HfpArguments& a)
  {
    // hfp: the positions of X, Y, Z are recorded over the current mapping (a letter that is
    // missing keeps its previous position), other entries become constants; then the mapping
    // must name three distinct positions inside the list.
    const std::vector<std::string> entries = split_commas(text);
    a.x_constants.resize(entries.size(), 0.0);
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
      if (entries[i] == "X")
      {
        a.xyz_mapping[0] = static_cast<int>(i);
      }
      else if (entries[i] == "Y")
      {
        a.xyz_mapping[1] = static_cast<int>(i);
      }
      else if (entries[i] == "Z")
      {
        a.xyz_mapping[2] = static_cast<int>(i);
      }
      else
      {
        a.x_constants[i] = to_double(entries[i]);
      }
    }
    const int size = static_cast<int>(a.x_constants.size());
    const auto& m = a.xyz_mapping;
    bool valid = m[0] != m[1] && m[0] != m[2] && m[1] != m[2];
    for (int axis : m)
    {
      valid = valid && axis >= 0 && axis < size;
    }
    if (!valid)
    {
      a.xyz_mapping = { 0, 1, 2 };
      a.x_constants.assign(3, 0.0);
      invalid(text, "-x", false);
    }
  }

  void box(const std::string& text, HfpArguments& a)
  {
    std::vector<double> v = to_doubles(text);
    std::array<double, 6>& b = a.box;
    const std::array<double, 6> fallback{ -10, -10, -10, 10, 10, 10 };
    switch (v.size())
    {
      case 1:
      {
        const double half = v[0] > 0 ? v[0] : -v[0];
        b = { -half, -half, -half, half, half, half };
        break;
      }
      case 2:
      {
        const double lo = std::min(v[0], v[1]);
        const double hi = std::max(v[0], v[1]);
        b = { lo, lo, lo, hi, hi, hi };
        break;
      }
      case 3:
        for (std::size_t k = 0; k < 3; ++k)
        {
          const double half = v[k] > 0 ? v[k] : -v[k];
          b[k] = -half;
          b[k + 3] = half;
        }
        break;
      case 6:
        std::copy(v.begin(), v.end(), b.begin());
        break;
      default:
        b = fallback;
        invalid(text, "-b");
        return;
    }
    if (!(b[0] < b[3] && b[1] < b[4] && b[2] < b[5]))
    {
      b = fallback;
      invalid(text, "-b");
    }
  }

  const std::vector<std::string>& args_;
  std::ostream& messages_;
  std::size_t position_ = 0;
};

} // namespace

HfpParseResult parse_hfp_arguments(const std::vector<std::string>& args, std::ostream& messages)
{
  HfpParseResult result;
  if (args.empty())
  {
    result.status = HfpParseStatus::NoArguments;
    return result;
  }
  if (args[0] == "-h" || args[0] == "--help")
  {
    result.status = HfpParseStatus::Help;
    return result;
  }
  if (is_option(args[0]))
  {
    result.status = HfpParseStatus::NoModel;
    return result;
  }
  Parser(args, messages).parse(result.arguments);
  return result;
}

std::string hfp_help_text()
{
  return R"(Usage: frepkit hfp FileName [-a Parameters] [-b BoundingBox] [-cf FaceColor]
 [-cl LineColor] [-d DisplayMode] [-g GridDensity] [-gs SlicingGridStep] [-h] [-i IsoValue]
 [-o ObjectName] [-s Search] [-t] [-w WindowSize] [-wrl VRMLOut] [-stl STLOut]
 [-stlb STLOutBinary] [-pov POVOut] [-cli CLIOut] [-ct] [-x Mapping] [-r] [-sb] [-sa]
 [-usedc 0|1]

The HyperFun polygonizer's command line (hfp), run by FRepKit's mesher: the mesh is always
watertight and oriented outward. D = number, I = integer, S = text, lists are comma-separated
without spaces. The model file comes first; options are exact tokens in any order.

 FileName       the HyperFun model (required, first).
 -a D,D,...     a[1], a[2], ... of the object (default 0; missing ones are 0).
 -b B           bounding box: D (-|D|..|D| on every axis), D,D (min,max on every axis),
                D,D,D (-|Dx|..|Dx| x -|Dy|..|Dy| x -|Dz|..|Dz|) or xmin,ymin,zmin,xmax,ymax,zmax.
                Default 10. An invalid box falls back to the default.
 -g I | I,I,I   grid density in cells per axis (default 30, i.e. 31 samples per axis), clamped
                to [2, 4095] (hfp: [2, 250]).
 -i D           iso value: the surface F = D, inside F >= D (default 0).
 -o S           object to polygonize, as stored (lower case); not found: the first object.
 -x L           mapping: one entry per x[i]; X, Y and Z (upper case) say which x[i] the axes
                drive, numbers fix the others (e.g. X,Y,Z,0.5 slices a 4-D model at x[4] = 0.5).
                Coordinates beyond the list are 0.
 -wrl [S]       write VRML 2.0 (default out.wrl).
 -stl [S]       write ASCII STL (default out.stl).
 -stlb [S]      write binary STL (default out.stl; -stl wins if both are given).
 -pov [S]       write a POV-Ray scene with a mesh2 (default out.pov).
 -cli [S]       write CLI layers (default out.cli) instead of a mesh: contours of z-sections
                every -gs step from zmin while z < zmax, closed along the box.
 -gs D | D,D | D,D,D   CLI step (x,y sampling and z layers; two values: xy, z), clamped to
                [0.001, 10], default 1.
 -ct            colours from the model's s[1], s[2], s[3] (red, green, blue in [0, 1]).
 -cf I | I,I,I  face colour 0-255 (VRML diffuseColor, POV texture; default 50,200,80).
 -s [D]         vertex precision: refine each vertex to D cells (default 0.1, [0.0001, 1]).
 -d I           display mode 1-7 (default 5); 1 and 2 write no normals.
 -t             report the time of each stage.
 -r, -cl, -w, -sb, -sa, -usedc 0|1   accepted for compatibility: viewer options and hfp's
                engine choice (FRepKit has one mesher; -x is always honoured); -r (reduce) is
                not done.
 -h             this help.
)";
}

} // namespace frepkit
