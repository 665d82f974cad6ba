#include "Project/detail/section_shape.h"
#include "Project/detail/space_time_checks.h"
#include "Project/space_time.h"

#include <cmath>
#include <functional>

namespace frep::project
{
namespace
{

using Shape = mesh::ShapeTopology;

// Bisection of [a, b], whose ends have different shapes, down to `resolution`: the change
// nearest to a (a shape in between that is neither end's is the new b).
TopologyEvent locate(double a, Shape at_a, double b, Shape at_b, double resolution,
  const TopologyAt& shape_at)
{
  while (b - a > resolution)
  {
    const double m = a + 0.5 * (b - a);
    const Shape s = shape_at(m);
    if (s == at_a)
      a = m;
    else
    {
      b = m;
      at_b = s;
    }
  }
  return { a, b, at_a.components, at_b.components, at_a.genus, at_b.genus };
}

} // namespace

std::vector<TopologyEvent> locate_topology_changes(double a, const mesh::ShapeTopology& at_a,
  double b, const mesh::ShapeTopology& at_b, double resolution, const TopologyAt& shape_at)
{
  std::vector<TopologyEvent> events;
  double from = a;
  Shape from_shape = at_a;
  // Each event ends where the next search begins, at a shape known there; the last ends at b.
  while (!(from_shape == at_b) && from < b)
  {
    const TopologyEvent e = locate(from, from_shape, b, at_b, resolution, shape_at);
    events.push_back(e);
    from = e.after;
    from_shape = Shape{ e.components_after, e.genus_after };
  }
  return events;
}

TopologyTrack topology_events(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples, double resolution,
  const SpaceTimeOptions& options)
{
  TopologyTrack track;
  track.error = detail::check_sections(model, time, space, steps, samples);
  if (track.error.empty() && steps < 2)
    track.error = "the topology along time needs at least two times";
  if (track.error.empty() && (!(resolution > 0.0) || !std::isfinite(resolution)))
    track.error = "the resolution must be > 0";
  if (!track.error.empty())
    return track;
  const GridSpec grid = detail::section_grid(space, samples);
  std::string error;
  const auto shape_at = [&](double t)
  {
    const detail::SectionShape s =
      detail::section_shape(model, time.coordinate, t, grid, options.parameters);
    if (!s.error.empty() && error.empty())
      error = s.error;
    return s.topology;
  };
  double previous_t = time.lo;
  Shape previous = shape_at(previous_t);
  track.samples.push_back({ previous_t, previous.components, previous.genus });
  const auto stop = [&](int done)
  {
    return options.cancel_requested() ||
      (options.progress && !options.progress(done / double(steps - 1)));
  };
  for (int i = 1; i < steps && error.empty(); ++i)
  {
    if (stop(i - 1))
    {
      track = {};
      track.cancelled = true;
      return track;
    }
    const double t = time.lo + (time.hi - time.lo) * (i / double(steps - 1));
    const Shape now = shape_at(t);
    track.samples.push_back({ t, now.components, now.genus });
    for (const TopologyEvent& e :
      locate_topology_changes(previous_t, previous, t, now, resolution, shape_at))
      track.events.push_back(e);
    previous_t = t;
    previous = now;
  }
  track.error = error;
  if (error.empty() && options.progress)
    options.progress(1.0);
  return track;
}

} // namespace frep::project
