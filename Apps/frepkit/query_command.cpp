#include "query_command.h"

#include "Durable/atomic_output.h"
#include "Project/space_time.h"
#include "box_option.h"
#include "model_loading.h"
#include "number_format.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

namespace frepkit
{

CLI::App* add_query_command(CLI::App& app, QueryOptions& o)
{
  CLI::App* cmd = app.add_subcommand("query",
    "Questions asked of space-time: 'contact A.hf B.hf' (when two moving solids first touch, "
    "and where), 'presence MODEL.hf --at P' (when a point is inside), 'volume MODEL.hf' (the "
    "section's volume or area over time), 'topology MODEL.hf' (where the section's pieces or "
    "genus change). One coordinate is time (--time)");
  cmd->add_option("question", o.question, "contact, presence, volume or topology")
    ->required()
    ->check(CLI::IsMember({ "contact", "presence", "volume", "topology" }));
  cmd->add_option("models", o.models, "the model (contact: two models)")->required();
  cmd->add_option("--object", o.object, "the object of every model (default: my_model, else the first)");
  cmd->add_option("-a,--parameters", o.parameters, "a[] values")->delimiter(',');
  cmd->add_option("--time", o.time, "the time coordinate and its range, e.g. x4=0:1")->required();
  cmd->add_option("--box",
       o.box,
       "contact, volume: the space searched, over the coordinates besides time "
       "(x1=-1:1,x2=-1:1,... or all minima then all maxima)")
    ->delimiter(',');
  cmd->add_option("--at", o.at, "presence: the point, its coordinates besides time")->delimiter(',');
  cmd->add_option("--time-tolerance", o.time_tolerance,
       "how exactly times are located (contact, presence; topology: its events)")
    ->capture_default_str()
    ->check(CLI::PositiveNumber);
  cmd->add_option("--steps", o.steps, "volume, topology: times sampled, ends included")
    ->capture_default_str()
    ->check(CLI::Range(1, 100000));
  cmd->add_option("--grid", o.grid, "volume, topology: samples per axis of the section's mesh")
    ->capture_default_str()
    ->check(CLI::Range(2, 2048));
  cmd->add_option("-o,--output", o.output, "where the answer goes ('-': standard output)")
    ->capture_default_str();
  add_user_input_options(cmd, o.user);
  return cmd;
}

namespace
{

struct Asked
{
  std::vector<frep::LoadedModel> models;
  frep::project::CoordinateRange time;
  std::vector<int> space; // 0-based coordinates besides time
};

Asked read_question(const QueryOptions& o)
{
  const std::size_t wanted = o.question == "contact" ? 2 : 1;
  if (o.models.size() != wanted)
    throw UserError("query " + o.question + " takes " + std::to_string(wanted) +
                    (wanted == 1 ? " model" : " models") + ", got " + std::to_string(o.models.size()));
  Asked asked;
  for (const std::string& path : o.models)
    asked.models.push_back(load_model(path, o.user, o.object, o.parameters.size()));
  std::string error;
  const auto times = frep::project::parse_eliminated(o.time, error);
  if (!error.empty() || times.size() != 1)
    throw UserError("--time " + (error.empty() ? "'" + o.time + "': one coordinate" : error));
  asked.time = times.front();
  const frep::Model& first = *asked.models.front().model;
  const int x_dim = first.x_dim();
  if (asked.time.coordinate < 1 || asked.time.coordinate > x_dim)
    throw UserError("--time: time x" + std::to_string(asked.time.coordinate) + ": " +
                    first.name() + " has x[" + std::to_string(x_dim) + "]");
  for (int i = 0; i < x_dim; ++i)
    if (i != asked.time.coordinate - 1)
      asked.space.push_back(i);
  return asked;
}

std::vector<frep::Interval> space_box(const QueryOptions& o, const Asked& asked)
{
  if (o.box.empty())
    throw UserError("query " + o.question + " needs --box over the coordinates besides time");
  const std::vector<double> bounds = parse_box(o.box, asked.space);
  const std::size_t n = asked.space.size();
  std::vector<frep::Interval> box;
  for (std::size_t i = 0; i < n; ++i)
    box.push_back({ bounds[i], bounds[n + i] });
  return box;
}

std::string coordinates(const std::vector<double>& x)
{
  std::string out;
  for (const double v : x)
    out += (out.empty() ? "" : ",") + format_short(v);
  return out;
}

std::string pieces(std::size_t components, long long genus)
{
  return std::to_string(components) + (components == 1 ? " piece" : " pieces") + " of genus " +
         std::to_string(genus);
}

void topology(const QueryOptions& o, const Asked& asked,
  const frep::project::SpaceTimeOptions& options, std::ostream& out)
{
  const frep::project::TopologyTrack track = frep::project::topology_events(*asked.models.front().model,
    asked.time, space_box(o, asked), o.steps, o.grid, o.time_tolerance, options);
  if (!track.ok())
    throw UserError("query topology: " + track.error);
  const std::string t = "x" + std::to_string(asked.time.coordinate);
  out << t << ",components,genus\n";
  for (const frep::project::TopologySample& s : track.samples)
    out << format_short(s.time) << "," << s.components << "," << s.genus << "\n";
  if (track.events.empty())
    out << "no change of topology between the samples\n";
  for (const frep::project::TopologyEvent& e : track.events)
    out << "changes for " << t << " in [" << format_short(e.before) << ", "
        << format_short(e.after) << "]: " << pieces(e.components_before, e.genus_before) << " -> "
        << pieces(e.components_after, e.genus_after) << "\n";
}

void answer(const QueryOptions& o, const Asked& asked, std::ostream& out)
{
  frep::project::SpaceTimeOptions options;
  options.time_tolerance = o.time_tolerance;
  options.parameters = o.parameters;
  const frep::Model& model = *asked.models.front().model;
  if (o.question == "contact")
  {
    const frep::project::Contact c = frep::project::first_contact(
      asked.models.front().model, asked.models.back().model, asked.time, space_box(o, asked),
      options);
    if (!c.ok())
      throw UserError("query contact: " + c.error);
    if (!c.found)
      out << "no contact for x" << asked.time.coordinate << " in [" << format_short(asked.time.lo)
          << ", " << format_short(asked.time.hi) << "] within the box\n";
    else
      out << "first contact at x" << asked.time.coordinate << " = " << format_short(c.time)
          << " (none before " << format_short(c.time_lo) << ")\nat " << coordinates(c.where)
          << "\n";
    return;
  }
  if (o.question == "presence")
  {
    if (o.at.size() != asked.space.size())
      throw UserError("--at: give the " + std::to_string(asked.space.size()) +
                      " coordinates besides time");
    std::vector<double> at(o.at);
    at.insert(at.begin() + (asked.time.coordinate - 1), 0.0);
    const frep::project::Presence p = frep::project::presence(model, asked.time, at, options);
    if (!p.ok())
      throw UserError("query presence: " + p.error);
    out << (p.inside.empty() ? "never inside\n" : "");
    for (const frep::Interval& i : p.inside)
      out << "inside for x" << asked.time.coordinate << " in [" << format_short(i.lo) << ", "
          << format_short(i.hi) << "]\n";
    return;
  }
  if (o.question == "topology")
    return topology(o, asked, options, out);
  const frep::project::SectionMeasures m = frep::project::section_measures(
    model, asked.time, space_box(o, asked), o.steps, o.grid, options);
  if (!m.ok())
    throw UserError("query volume: " + m.error);
  out << "x" << asked.time.coordinate << "," << (m.dimension == 3 ? "volume" : "area")
      << ",components\n";
  for (const frep::project::SectionMeasure& s : m.table)
    out << format_short(s.time) << "," << format_short(s.measure) << "," << s.components << "\n";
}

} // namespace

int run_query(const QueryOptions& options)
{
  const Asked asked = read_question(options);
  std::ostringstream text;
  answer(options, asked, text);
  frep::durable::AtomicOutput output(options.output);
  output.stream() << text.str();
  output.commit();
  return 0;
}

} // namespace frepkit
