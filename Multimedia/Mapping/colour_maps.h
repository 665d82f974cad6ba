// Named colour maps, v in [0, 1] -> RGB in [0, 1], for colour channels and per-vertex colours.
// Each map is a handful of control points of its published definition joined linearly: close
// enough to the original to read the same, small enough to write down.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frep::mapping
{

using Rgb = std::array<double, 3>;

/// "viridis", "plasma", "coolwarm", "grey" or "rainbow" (exact, lower case).
bool is_colour_map(std::string_view name);

/// The colour of map `name` at v (clamped to [0, 1]; NaN counts as 0); nullopt for a name that
/// is not a colour map.
std::optional<Rgb> colour_map(std::string_view name, double v);

/// "red", "green", "blue": a channel that sets one component of a colour (0, 1, 2) instead of
/// the whole colour; nullopt for any other name.
std::optional<int> colour_component(std::string_view name);

/// A name a colour channel accepts: a colour map or a single component.
bool is_colour_channel_name(std::string_view name);

/// Every accepted name, maps first, for error messages ("viridis, plasma, ..., blue").
std::string colour_channel_names();

} // namespace frep::mapping
