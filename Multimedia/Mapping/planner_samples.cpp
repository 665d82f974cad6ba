// The Planner's samples: the spreadsheet's cells, the animation's frames and the still shape,
// each with its channels applied.
#include "Mapping/detail/planner.h"

#include "Mapping/colour_maps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frep::mapping::planning
{
namespace
{

using Matrix = std::array<double, 16>;

constexpr Matrix identity{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

Matrix multiply(const Matrix& a, const Matrix& b)
{
  Matrix m{};
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      double s = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        s += a[i * 4 + k] * b[k * 4 + j];
      }
      m[i * 4 + j] = s;
    }
  }
  return m;
}

Matrix translation(double x, double y, double z)
{
  Matrix m = identity;
  m[3] = x;
  m[7] = y;
  m[11] = z;
  return m;
}

std::array<double, 3> normalised(const std::array<double, 3>& v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / n, v[1] / n, v[2] / n };
}

// Rodrigues: rotation by `degrees` about the unit axis a (right-handed).
Matrix rotation(const std::array<double, 3>& axis, double degrees)
{
  const auto a = normalised(axis);
  const double t = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(t);
  const double s = std::sin(t);
  const double d = 1.0 - c;
  return { c + a[0] * a[0] * d,
    a[0] * a[1] * d - a[2] * s,
    a[0] * a[2] * d + a[1] * s,
    0,
    a[1] * a[0] * d + a[2] * s,
    c + a[1] * a[1] * d,
    a[1] * a[2] * d - a[0] * s,
    0,
    a[2] * a[0] * d - a[1] * s,
    a[2] * a[1] * d + a[0] * s,
    c + a[2] * a[2] * d,
    0,
    0,
    0,
    0,
    1 };
}

} // namespace

Sample Planner::base_sample() const
{
  Sample s;
  s.values.assign(n(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < n(); ++i)
  {
    if (const Resolved* r = find(i, Channel::Type::Fixed))
    {
      s.values[i] = r->channel->value;
    }
  }
  // A projected coordinate's value is read by nothing (the sections are cut from the
  // projection, which keeps the coordinates' numbers): its range's middle, not NaN (that is a
  // world coordinate's).
  for (const ProjectedCoordinate& p : result_.plan.projected)
  {
    s.values[static_cast<std::size_t>(p.coordinate)] = 0.5 * (p.range.lo + p.range.hi);
  }
  s.colour = spec_.render.colour;
  s.background = spec_.render.background;
  return s;
}

/// The photometric, transformation and audio channels at this sample's values, in file
/// order (transformations compose in that order: a later one applies after an earlier one).
void Planner::apply_channels(Sample& s) const
{
  const Plan& p = result_.plan;
  s.voices.assign(static_cast<std::size_t>(p.voice_count), Voice{});
  Matrix m = identity;
  const double cx = 0.5 * (p.world_box[0].lo + p.world_box[0].hi);
  const double cy = 0.5 * (p.world_box[1].lo + p.world_box[1].hi);
  const double cz = 0.5 * (p.world_box[2].lo + p.world_box[2].hi);
  for (const Resolved* r : values_)
  {
    const Channel& c = *r->channel;
    const double x = s.values[static_cast<std::size_t>(r->coordinate)];
    if (std::isnan(x))
    {
      continue;
    }
    const double y = r->map.forward(x);
    switch (c.type)
    {
      case Channel::Type::Colour:
      {
        if (c.applies_to == PhotometricTarget::Light)
        {
          // The light is white: a colour channel on it sets its intensity.
          s.light_intensity = std::max(0.0, y);
          break;
        }
        std::array<double, 3>& colour =
          c.applies_to == PhotometricTarget::Shape ? s.colour : s.background;
        if (const auto component = colour_component(c.colormap))
        {
          colour[static_cast<std::size_t>(*component)] = std::clamp(y, 0.0, 1.0);
        }
        else if (const auto rgb = colour_map(c.colormap, y))
        {
          colour = *rgb;
        }
        break;
      }
      case Channel::Type::Transparency:
        if (c.applies_to == PhotometricTarget::Light)
        {
          s.light_intensity = std::max(0.0, y);
        }
        else
        {
          s.opacity = std::clamp(y, 0.0, 1.0);
        }
        break;
      case Channel::Type::Transformation:
      {
        Matrix t = identity;
        switch (c.transform)
        {
          case Channel::Transform::Rotate:
            t = multiply(translation(cx, cy, cz),
              multiply(rotation(c.vector, y), translation(-cx, -cy, -cz)));
            break;
          case Channel::Transform::Scale:
          {
            Matrix scale = identity;
            scale[0] = scale[5] = scale[10] = y;
            t = multiply(translation(cx, cy, cz), multiply(scale, translation(-cx, -cy, -cz)));
            break;
          }
          case Channel::Transform::Translate:
          {
            const auto v = normalised(c.vector);
            t = translation(v[0] * y, v[1] * y, v[2] * y);
            break;
          }
        }
        m = multiply(t, m);
        break;
      }
      case Channel::Type::Audio:
      {
        Voice& v = s.voices[static_cast<std::size_t>(c.voice)];
        switch (c.audio_parameter)
        {
          case Channel::AudioParameter::Pitch:
            v.pitch = y;
            break;
          case Channel::AudioParameter::Loudness:
            v.loudness = y;
            break;
          case Channel::AudioParameter::Timbre:
            v.timbre = y;
            break;
        }
        break;
      }
      default:
        break;
    }
  }
  s.transform = m;
}

/// "x4 = 0.25, x5 = 0.5" over the coordinates for which `shown` holds, in model order.
std::string Planner::label(const Sample& s, const std::vector<bool>& shown) const
{
  std::string text;
  for (std::size_t i = 0; i < n(); ++i)
  {
    if (shown[i])
    {
      text += (text.empty() ? "" : ", ") + model_.names[i] + " = " + format_value(s.values[i]);
    }
  }
  return text;
}

/// The dynamic coordinates' values at frame k (time k / fps), and the path parameter.
void Planner::place_frame(Sample& s, std::size_t k) const
{
  const AnimationSettings& a = spec_.animation;
  s.time = static_cast<double>(k) / a.fps;
  if (path_)
  {
    double fraction;
    if (path_->spec().timing == Path::Timing::Keys)
    {
      fraction = path_->fraction_at_time(s.time);
    }
    else if (path_->spec().closed)
    {
      // [0, duration): the last frame stops one step short of the start it loops back to.
      fraction = static_cast<double>(k) / static_cast<double>(frame_count_);
    }
    else
    {
      // Both ends of an open path are shown: the first frame at its start, the last at its end.
      fraction =
        frame_count_ > 1 ? static_cast<double>(k) / static_cast<double>(frame_count_ - 1) : 0.0;
    }
    s.path_parameter = fraction;
    s.path_point = path_->point_at(fraction);
    for (std::size_t d = 0; d < dynamic_.size(); ++d)
    {
      s.values[static_cast<std::size_t>(dynamic_[d])] = s.path_point[d];
    }
  }
  else if (dynamic_.size() == 1)
  {
    // One dynamic coordinate: its channel maps it onto time, so the value is the inverse.
    const Resolved* r = find(static_cast<std::size_t>(dynamic_.front()), Channel::Type::Dynamic);
    const double x = r->map.inverse(s.time);
    s.values[static_cast<std::size_t>(dynamic_.front())] = x;
    s.path_point = { x };
    s.path_parameter = std::clamp(s.time / a.duration, 0.0, 1.0);
  }
}

void Planner::fill_cells()
{
  Plan& p = plan();
  if (std::none_of(grid_.begin(), grid_.end(), [](int g) { return g >= 0; }))
  {
    return;
  }
  std::vector<bool> shown(n(), false);
  std::array<std::size_t, 3> count{ 1, 1, 1 };
  std::array<const std::vector<double>*, 3> nodes{};
  for (std::size_t k = 0; k < 3; ++k)
  {
    if (grid_[k] >= 0)
    {
      shown[static_cast<std::size_t>(grid_[k])] = true;
      nodes[k] =
        &find(static_cast<std::size_t>(grid_[k]), Channel::Type::Spreadsheet)->channel->values;
      count[k] = nodes[k]->size();
    }
  }
  // Coordinates that are only dynamic take their value of the first frame.
  Sample base = base_sample();
  if (!dynamic_.empty())
  {
    place_frame(base, 0);
    base.time = 0.0;
    base.path_parameter = 0.0;
    base.path_point.clear();
  }
  p.cells.reserve(count[0] * count[1] * count[2]);
  for (std::size_t layer = 0; layer < count[2]; ++layer)
    for (std::size_t row = 0; row < count[1]; ++row)
      for (std::size_t column = 0; column < count[0]; ++column)
      {
        Sample s = base;
        const std::size_t index[3] = { column, row, layer };
        for (std::size_t k = 0; k < 3; ++k)
        {
          if (grid_[k] >= 0)
          {
            s.cell[k] = static_cast<int>(index[k]);
            s.values[static_cast<std::size_t>(grid_[k])] = (*nodes[k])[index[k]];
          }
        }
        apply_channels(s);
        s.label = label(s, shown);
        p.cells.push_back(std::move(s));
      }
}

void Planner::fill_frames()
{
  Plan& p = plan();
  if (dynamic_.empty())
  {
    return;
  }
  std::vector<bool> shown(n(), false);
  for (int d : dynamic_)
  {
    shown[static_cast<std::size_t>(d)] = true;
  }
  // Coordinates that are only spreadsheet coordinates keep their first node value.
  Sample base = base_sample();
  for (std::size_t k = 0; k < 3; ++k)
  {
    if (grid_[k] >= 0 && !shown[static_cast<std::size_t>(grid_[k])])
    {
      base.values[static_cast<std::size_t>(grid_[k])] =
        find(static_cast<std::size_t>(grid_[k]), Channel::Type::Spreadsheet)
          ->channel->values.front();
    }
  }
  p.frames.reserve(frame_count_);
  for (std::size_t k = 0; k < frame_count_; ++k)
  {
    Sample s = base;
    place_frame(s, k);
    apply_channels(s);
    s.label = label(s, shown);
    p.frames.push_back(std::move(s));
  }
}

/// The shape with nothing varying: the first cell, else the first frame, else the fixed
/// values with the channels applied (a mapping of world and fixed coordinates only).
void Planner::fill_still()
{
  Plan& p = plan();
  if (!p.cells.empty())
  {
    p.still = p.cells.front();
  }
  else if (!p.frames.empty())
  {
    p.still = p.frames.front();
  }
  else
  {
    p.still = base_sample();
    apply_channels(p.still);
  }
}

} // namespace frep::mapping::planning
