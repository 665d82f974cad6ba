#include "sweep_command.h"

#include "Durable/atomic_output.h"
#include "Project/sweep_text.h"
#include "model_loading.h"
#include "section_axes.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

namespace frepkit
{

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& o)
{
  CLI::App* cmd = app.add_subcommand("sweep",
    "A 3-D profile moved along a path, written as one model of x[4] (x4: 0 -> 1 along the "
    "path); mesh it with --project x4=0:1 (and --library PROFILE) for the volume it sweeps");
  cmd->add_option("profile", o.profile, "The profile's model file (.hf)")->required();
  cmd->add_option("--object", o.object, "The profile's object (default: my_model, else the first)");
  cmd->add_option("--path", o.path, "The path's points: X,Y,Z;X,Y,Z;... (at least 2)")->required();
  cmd->add_option("--curve", o.curve, "How the points are joined")
    ->check(CLI::IsMember({ "polyline", "catmull-rom" }))
    ->capture_default_str();
  cmd->add_flag("--closed", o.closed, "The path returns to its first point");
  cmd->add_option("--orient", o.orient,
       "fixed: the profile moves as it stands; tangent: its z axis follows the path")
    ->check(CLI::IsMember({ "fixed", "tangent" }))
    ->capture_default_str();
  cmd->add_option("--name", o.name, "The object written")->capture_default_str();
  cmd->add_option("-o,--output", o.output, "The model file written ('-': standard output)")
    ->capture_default_str();
  add_user_input_options(cmd, o.user);
  return cmd;
}

namespace
{

std::vector<std::array<double, 3>> parse_path(const std::string& text)
{
  std::vector<std::array<double, 3>> points;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ';'))
  {
    std::istringstream numbers(item);
    std::string number;
    std::array<double, 3> p{};
    int count = 0;
    while (std::getline(numbers, number, ','))
    {
      const std::optional<double> v = parse_number(number);
      if (!v || count == 3)
        throw UserError("--path '" + item + "': give X,Y,Z per point, points joined by ';'");
      p[static_cast<std::size_t>(count++)] = *v;
    }
    if (count != 3)
      throw UserError("--path '" + item + "': give X,Y,Z per point, points joined by ';'");
    points.push_back(p);
  }
  return points;
}

} // namespace

int run_sweep(const SweepOptions& options)
{
  frep::project::SweepPath path;
  path.points = parse_path(options.path);
  path.closed = options.closed;
  frep::project::sweep_curve_from_name(options.curve, path.curve);
  frep::project::sweep_orientation_from_name(options.orient, path.orientation);
  const frep::LoadedModel profile = load_model(options.profile, options.user, options.object);
  const frep::ast::Object& object =
    profile.program->objects[static_cast<std::size_t>(profile.object)];
  if (object.x_dim != 3)
    throw UserError(options.profile + ": the profile " + object.name + " has x[" +
                    std::to_string(object.x_dim) + "]; a profile is 3-D");
  const frep::project::SweepText sweep =
    frep::project::write_sweep(options.name, object.name, std::max(1, object.a_dim), path);
  if (!sweep.ok())
    throw UserError("sweep: " + sweep.diagnostics.front().message + "; nothing written");
  frep::durable::AtomicOutput out(options.output);
  out.stream() << sweep.text;
  out.commit();
  if (options.output != "-")
    std::cerr << "frepkit: wrote " << options.output << ": " << options.name
              << " of x[4]; load it with --library " << options.profile << '\n';
  return 0;
}

} // namespace frepkit
