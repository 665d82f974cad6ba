// extract_contour: the 2-D case — interval-culled boxes, batch sampling, marching squares with
// the same face decision as the 3-D cells, segments with the inside on their left.
#include "Mesh/detail/cube_topology.h"
#include "Mesh/detail/extraction_common.h"
#include "Mesh/surface.h"

#include <algorithm>
#include <cmath>

namespace frep::mesh
{
namespace
{

using detail::CellBox;
using detail::GridFrame;

// Same margin as the surface: crossings never sit exactly on a grid vertex.
constexpr double crossing_margin = 1e-3;

class ContourWalker final : public detail::BoxWalker
{
public:
  using BoxWalker::BoxWalker;

private:
  // Square edge e: start corner and axis (corners 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1)).
  static constexpr std::array<int, 4> edge_start{ 0, 1, 2, 0 };
  static constexpr std::array<int, 4> edge_end{ 1, 3, 3, 2 };
  static constexpr std::array<int, 4> edge_axis{ 0, 1, 0, 1 };

  void leaf(const CellBox& box) override
  {
    const std::vector<double>& samples = values();
    const std::int64_t n0 = box.c1[0] - box.c0[0] + 1;
    const std::array<std::int64_t, 4> corner_offset_index{ 0, 1, n0, n0 + 1 };
    std::array<double, 4> g{};
    for (std::int64_t j = box.c0[1]; j < box.c1[1]; ++j)
    {
      for (std::int64_t i = box.c0[0]; i < box.c1[0]; ++i)
      {
        const std::int64_t base = (i - box.c0[0]) + n0 * (j - box.c0[1]);
        std::uint8_t in = 0;
        for (int c = 0; c < 4; ++c)
        {
          g[c] = samples[static_cast<std::size_t>(base + corner_offset_index[c])];
          in |= static_cast<std::uint8_t>((g[c] >= 0.0 ? 1u : 0u) << c);
        }
        if (in == 0 || in == 15)
        {
          continue;
        }
        // Ambiguous squares (0 and 3 inside, or 1 and 2): the decider of the 3-D faces.
        bool connected = false;
        if (in == 0b1001)
        {
          connected = g[0] * g[3] > g[1] * g[2];
        }
        else if (in == 0b0110)
        {
          connected = g[1] * g[2] > g[0] * g[3];
        }
        const SquareSegments& segments = square_segments(in, connected);
        auto& cells = builder_.piece().cells;
        for (int s = 0; s < segments.count; ++s)
        {
          for (int end = 0; end < 2; ++end)
          {
            cells.push_back(crossing(i, j, segments.segments[static_cast<std::size_t>(s)]
                                                            [static_cast<std::size_t>(end)], g));
          }
        }
      }
    }
  }

  std::uint32_t crossing(std::int64_t i, std::int64_t j, int edge, const std::array<double, 4>& g)
  {
    const auto e = static_cast<std::size_t>(edge);
    const int start = edge_start[e];
    const int axis = edge_axis[e];
    const std::int64_t vi = i + (start & 1);
    const std::int64_t vj = j + (start >> 1);
    return builder_.point(frame_.key(vi, vj, 0, axis),
      [&]
      {
        double t = g[start] / (g[start] - g[edge_end[e]]);
        t = std::isfinite(t) ? std::clamp(t, crossing_margin, 1.0 - crossing_margin) : 0.5;
        std::array<double, 3> p{ frame_.coord(0, vi), frame_.coord(1, vj), 0.0 };
        const std::int64_t v = axis == 0 ? vi : vj;
        const double a = frame_.coord(axis, v);
        const double b = frame_.coord(axis, v + 1);
        p[static_cast<std::size_t>(axis)] = a + t * (b - a);
        return p;
      });
  }
};

} // namespace

ExtractResult extract_contour(std::shared_ptr<const Tape> tape,
  const GridSpec& grid,
  const ExtractOptions& options)
{
  return detail::run_extraction(tape, grid, 2, options,
    [&](const GridFrame& frame) { return std::make_unique<ContourWalker>(tape, frame, options); });
}

} // namespace frep::mesh
