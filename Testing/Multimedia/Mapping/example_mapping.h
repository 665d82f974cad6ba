// The mapping of the brief's Meta5D example (6 coordinates named; the tests' model has x1..x6).
#pragma once

namespace frep::mapping::testing
{

inline constexpr const char* example_mapping = R"({
  "version": 1,
  "object": "meta5d",
  "parameters": [],
  "world": { "system": "cartesian", "resolution": 128, "iso": 0 },
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-1, 1] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-1, 1] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-1, 1], "target": [-1, 1] },
           { "type": "colour", "colormap": "viridis" }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.25 },
           { "type": "dynamic" },
           { "type": "audio", "parameter": "pitch", "voice": 0, "target": [220, 440], "curve": { "kind": "power", "exponent": 2 } }],
    "x5": [{ "type": "spreadsheet", "axis": "rows", "values": [0, 0.25, 0.5, 0.75, 1] },
           { "type": "dynamic" },
           { "type": "audio", "parameter": "loudness", "target": [0.2, 0.8] },
           { "type": "transparency", "applies_to": "shape", "target": [1, 0.3] },
           { "type": "transformation", "transform": "rotate", "vector": [0, 0, 1], "target": [0, 90] }],
    "x6": [{ "type": "fixed", "value": 0.5 }]
  },
  "animation": { "duration": 10, "fps": 24,
                 "path": { "coordinates": ["x4", "x5"], "points": [[0, 0], [1, 0], [1, 1], [0, 1]],
                           "interpolation": "catmull-rom", "closed": true, "timing": "arc-length", "key_times": [] } },
  "spreadsheet": { "cell_size": 256, "spacing": 0.1, "labels": true },
  "render": { "width": 1280, "height": 720, "background": [1, 1, 1], "colour": [0.85, 0.62, 0.38], "azimuth": 35, "elevation": 25, "inset": true },
  "audio": { "sample_rate": 44100 }
})";

} // namespace frep::mapping::testing
