// A sampled scalar volume (CT, simulation output) as an FRep: F = trilinear(v) - iso inside
// the grid, minus the distance to the grid outside it (so the object is bounded whatever the
// border values), with enclosures over boxes from the min/max of the covered cells' samples (a
// box of at most 256 such samples) or of 8^3-cell bricks (larger boxes).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace frep::shapes
{

struct VolumeGrid
{
  std::array<int, 3> dims{};        ///< samples per axis, x fastest
  std::array<double, 3> origin{};
  std::array<double, 3> spacing{ 1, 1, 1 };
  std::vector<double> values;       ///< dims[0] * dims[1] * dims[2]
};

class VolumeField
{
public:
  struct BuildResult
  {
    std::shared_ptr<const VolumeField> field; ///< null on error
    std::string error;
  };

  /// Refuses fewer than 2 samples on an axis, a size that does not match, spacing <= 0 or
  /// non-finite, and non-finite values (naming how many).
  static BuildResult build(VolumeGrid grid, double iso);

  double value(const std::array<double, 3>& p) const;
  /// F and its gradient (of the trilinear interpolant; outside the grid with the distance's).
  double value_and_gradient(const std::array<double, 3>& p, std::array<double, 3>& g) const;
  bool enclose(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double& f_lo,
    double& f_hi) const;
  std::array<double, 6> bounds() const;

private:
  static constexpr int kBrick = 8;
  double sample(int i, int j, int k) const;
  VolumeGrid grid_;
  double iso_ = 0;
  std::array<int, 3> bricks_{};
  std::vector<double> brick_min_;
  std::vector<double> brick_max_;
};

} // namespace frep::shapes
