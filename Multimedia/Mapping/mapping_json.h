// The mapping file: a Spec as JSON (Documentation/mapping-file.md is the full reference).
//
//   {
//     "version": 1, "object": "meta5d", "parameters": [],
//     "world": { "system": "cartesian", "resolution": 128, "iso": 0 },
//     "coordinates": {
//       "x1": [{ "type": "world", "axis": "x", "range": [-1, 1] }],
//       "x3": [{ "type": "world", "axis": "z", "range": [-1, 1], "target": [-1, 1] },
//              { "type": "colour", "colormap": "viridis" }],
//       "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.25 },
//              { "type": "dynamic" },
//              { "type": "audio", "parameter": "pitch", "voice": 0, "target": [220, 440],
//                "curve": { "kind": "power", "exponent": 2 } }],
//       "x6": [{ "type": "fixed", "value": 0.5 }]
//     },
//     "animation": { "duration": 10, "fps": 24,
//                    "path": { "coordinates": ["x4", "x5"], "points": [[0, 0], [1, 0]],
//                              "interpolation": "catmull-rom", "closed": false,
//                              "timing": "arc-length", "key_times": [] } },
//     "spreadsheet": { "cell_size": 256, "spacing": 0.1, "labels": true },
//     "render": { "width": 1280, "height": 720, "background": [1, 1, 1],
//                 "colour": [0.85, 0.62, 0.38], "azimuth": 35, "elevation": 25, "inset": true,
//                 "colour_source": "uniform" },
//     "audio": { "sample_rate": 44100 }
//   }
//
// Every key is optional except "coordinates" and, per channel, "type" (and what a type needs:
// a world or spreadsheet "axis", a fixed "value", spreadsheet "values" or "step"). Channel
// types: world, dynamic, spreadsheet, fixed, colour, transparency, transformation, audio.
// Curves: "linear", "ease-in-out", { "kind": "power", "exponent": e },
// { "kind": "table", "points": [[u, v], ...] }, { "kind": "expression", "expression": "t*t" }.
//
// Loading checks what can be checked without the model (types, names, ranges lo < hi, fps > 0,
// curves compile, the path's shape); make_plan checks the rest against the model. Unknown keys
// are errors: a typo must not be silently ignored.
#pragma once

#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"

#include <string>
#include <vector>

namespace frep::mapping
{

struct LoadResult
{
  Spec spec; ///< what could be read (defaults elsewhere); meaningful only when ok()
  /// Every problem found. place is a JSON path such as "coordinates.x4[1].range" or
  /// "animation.fps"; for a syntax error it is "line:column" of the offending character.
  std::vector<PlanError> errors;
  bool ok() const { return errors.empty(); }
};

/// Reads a mapping file's text. Never throws; every error is collected, not only the first.
LoadResult load_mapping(const std::string& json_text);

/// Writes `spec` as a mapping file (2-space indented JSON, keys in the documented order, arrays
/// of numbers on one line). Only
/// the fields that apply to a channel's type and curve kind are written, so
/// load_mapping(save_mapping(s)).spec == s for every spec whose other fields keep their
/// defaults (every spec load_mapping returns). Spreadsheet node values are written as "values"
/// (a "step" is expanded when loading).
std::string save_mapping(const Spec& spec);

} // namespace frep::mapping
