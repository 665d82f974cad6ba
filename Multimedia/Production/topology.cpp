// produce, phase 6c: the map of the topology (issue 29, item 5). Every spreadsheet cell's and
// animation frame's section is meshed at the mapping's topology.resolution and its pieces and
// genus counted (mesh::shape_topology); where two neighbouring cells, or two consecutive frames,
// differ, the change is located by bisection of the step between them
// (project::locate_topology_changes), the sections in between taken at values between theirs:
// on the straight line between two cells' values, on the chord between two frames' (the path
// itself between frames would need the path's time parametrisation, which the plan does not
// keep; the chord's distance from the path shrinks with the square of the frames' spacing). The answers go into the manifest, over the spreadsheet
// (spreadsheet-topology.png) and along the animation (topology.png).
#include "Production/detail/phases.h"

#include "Mesh/mesh_topology.h"
#include "Project/space_time.h"
#include "Scene/topology_pictures.h"

#include <cmath>
#include <utility>

namespace frep::mapping::production
{
namespace
{

using Shape = mesh::ShapeTopology;


// The sample a fraction u of the way from a to b: its values, time and path parameter between
// theirs; everything else (transform, colour) a's, which the topology does not see.
Sample between(const Sample& a, const Sample& b, double u)
{
  Sample s = a;
  for (std::size_t i = 0; i < s.values.size() && i < b.values.size(); ++i)
  {
    if (!std::isnan(a.values[i]))
      s.values[i] = a.values[i] + u * (b.values[i] - a.values[i]);
  }
  s.time = a.time + u * (b.time - a.time);
  s.path_parameter = a.path_parameter + u * (b.path_parameter - a.path_parameter);
  return s;
}

// The pieces and genus of a sample's section, meshed at `resolution` on the calling thread.
Shape section_topology(const Job& job, const Sample& sample, int resolution)
{
  SectionOptions options;
  options.threads = 1;
  options.normals = false;
  options.cancel = [&job] { return job.stopped(); };
  options.samples.fill(resolution);
  const Section section =
    make_section(job.section_source(), job.inputs.parameters, job.plan, sample, options);
  job.throw_if_stopped();
  if (section.cancelled)
    throw Stopped();
  if (!section.ok())
    throw ProductionError("the topology map: " + sample.label + ": " + section.error);
  return mesh::shape_topology(section.surface);
}

// Each sample's topology, then each change between the pairs whose ends differ, on the workers.
TopologyMap track(const Job& job, Workers& workers, const std::vector<Sample>& samples,
  const std::vector<std::pair<std::size_t, std::size_t>>& pairs, const TopologySettings& settings)
{
  TopologyMap t;
  t.shapes.resize(samples.size());
  workers.parallel(samples.size(), [&](std::size_t i, int)
    {
      t.shapes[i] = section_topology(job, samples[i], settings.resolution);
      workers.advance();
    });
  std::vector<std::pair<std::size_t, std::size_t>> differ;
  for (const auto& p : pairs)
  {
    if (!(t.shapes[p.first] == t.shapes[p.second]))
      differ.push_back(p);
  }
  std::vector<std::vector<TopologyChange>> found(differ.size());
  const double resolution = std::ldexp(1.0, -settings.bisections);
  workers.parallel(differ.size(), [&](std::size_t i, int)
    {
      // Named, not a structured binding: clang 14 (the sanitizer build) cannot capture those.
      const std::size_t a = differ[i].first, b = differ[i].second;
      const auto at = [&](double u)
      { return section_topology(job, between(samples[a], samples[b], u), settings.resolution); };
      for (const project::TopologyEvent& e : project::locate_topology_changes(
             0.0, t.shapes[a], 1.0, t.shapes[b], resolution, at))
        found[i].push_back({ a, b, e });
    });
  for (auto& f : found)
    t.changes.insert(t.changes.end(), f.begin(), f.end());
  return t;
}

// Neighbouring cells: along the columns, the rows and the layers of the grid.
std::vector<std::pair<std::size_t, std::size_t>> cell_pairs(const Plan& plan)
{
  const std::array<int, 3> n{ std::max(1, plan.grid_shape[0]), std::max(1, plan.grid_shape[1]),
    std::max(1, plan.grid_shape[2]) };
  const auto index = [&](int c, int r, int l)
  { return static_cast<std::size_t>(c + n[0] * (r + n[1] * l)); };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (int l = 0; l < n[2]; ++l)
    for (int r = 0; r < n[1]; ++r)
      for (int c = 0; c < n[0]; ++c)
      {
        if (c + 1 < n[0])
          pairs.push_back({ index(c, r, l), index(c + 1, r, l) });
        if (r + 1 < n[1])
          pairs.push_back({ index(c, r, l), index(c, r + 1, l) });
        if (l + 1 < n[2])
          pairs.push_back({ index(c, r, l), index(c, r, l + 1) });
      }
  return pairs;
}

nlohmann::json shape_json(const Shape& s)
{
  return { { "pieces", s.components }, { "genus", s.genus }, { "slivers", s.slivers } };
}

// A change: where along the step (and so the values of the coordinates that move), before and
// after.
nlohmann::json change_json(const Job& job,
  const std::vector<Sample>& samples,
  const TopologyChange& c,
  bool frames)
{
  const project::TopologyEvent& e = c.event;
  const Sample& a = samples[c.from];
  const Sample& b = samples[c.to];
  nlohmann::json values = nlohmann::json::object();
  const Sample lo = between(a, b, e.before), hi = between(a, b, e.after);
  for (std::size_t i = 0; i < a.values.size() && i < job.coordinates.names.size(); ++i)
  {
    if (!std::isnan(a.values[i]) && a.values[i] != b.values[i])
      values[job.coordinates.names[i]] = { lo.values[i], hi.values[i] };
  }
  nlohmann::json j{ { "values", values },
    { "before", { { "pieces", e.components_before }, { "genus", e.genus_before } } },
    { "after", { { "pieces", e.components_after }, { "genus", e.genus_after } } } };
  if (frames)
  {
    j["frames"] = { static_cast<double>(c.from) + e.before, static_cast<double>(c.from) + e.after };
    j["time"] = { lo.time, hi.time };
  }
  else
  {
    j["cells"] = { { a.cell[0], a.cell[1], a.cell[2] }, { b.cell[0], b.cell[1], b.cell[2] } };
    j["between"] = { e.before, e.after };
  }
  return j;
}

nlohmann::json track_json(const Job& job, const std::vector<Sample>& samples, const TopologyMap& t,
  bool frames)
{
  nlohmann::json j = nlohmann::json::object();
  nlohmann::json changes = nlohmann::json::array();
  for (const TopologyChange& c : t.changes)
    changes.push_back(change_json(job, samples, c, frames));
  if (frames)
  {
    nlohmann::json pieces = nlohmann::json::array(), genus = nlohmann::json::array(),
                   slivers = nlohmann::json::array();
    for (const Shape& s : t.shapes)
    {
      pieces.push_back(s.components);
      genus.push_back(s.genus);
      slivers.push_back(s.slivers);
    }
    j["pieces"] = pieces;
    j["genus"] = genus;
    j["slivers"] = slivers;
  }
  else
  {
    nlohmann::json cells = nlohmann::json::array();
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      nlohmann::json cell = shape_json(t.shapes[i]);
      cell["cell"] = { samples[i].cell[0], samples[i].cell[1], samples[i].cell[2] };
      cells.push_back(cell);
    }
    j["cells"] = cells;
  }
  j["changes"] = changes;
  return j;
}

std::string changes_text(const TopologyMap& t)
{
  return std::to_string(t.changes.size()) + (t.changes.size() == 1 ? " change" : " changes");
}

} // namespace

void map_topology(const Job& job, Workers& workers, Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const TopologySettings& settings = *job.spec().topology;
  nlohmann::json topology{ { "resolution", settings.resolution },
    { "bisections", settings.bisections } };
  std::string summary;
  if (!plan.cells.empty())
  {
    const TopologyMap cells = track(job, workers, plan.cells, cell_pairs(plan), settings);
    topology["spreadsheet"] = track_json(job, plan.cells, cells, false);
    summary = std::to_string(plan.cells.size()) + " cells (" + changes_text(cells) + ")";
    if (!record.sheet.empty())
    {
      write_png_file(job.options.directory / "spreadsheet-topology.png",
        topology_sheet(record.sheet, record.sheet_rects, cells, workers.kit(0)));
      record.files.push_back(
        { { "file", "spreadsheet-topology.png" }, { "kind", "spreadsheet-topology" } });
    }
  }
  if (!plan.frames.empty())
  {
    std::vector<std::pair<std::size_t, std::size_t>> steps;
    for (std::size_t k = 0; k + 1 < plan.frames.size(); ++k)
      steps.push_back({ k, k + 1 });
    const TopologyMap frames = track(job, workers, plan.frames, steps, settings);
    topology["frames"] = track_json(job, plan.frames, frames, true);
    const imaging::Image chart = topology_chart(plan, frames, workers.kit(0));
    write_png_file(job.options.directory / "topology.png", chart);
    record.files.push_back({ { "file", "topology.png" }, { "kind", "topology" },
      { "width", chart.width }, { "height", chart.height } });
    summary += (summary.empty() ? "" : ", ") + std::to_string(plan.frames.size()) +
               " frames (" + changes_text(frames) + ")";
  }
  record.topology = topology;
  const bool solid = plan.world_coordinates[2] >= 0; // else 2-D sections: contours
  record.stages.push_back({ "topology", seconds_since(t0),
    summary + " at " + std::to_string(settings.resolution) + (solid ? "^3" : "^2") });
}

} // namespace frep::mapping::production
