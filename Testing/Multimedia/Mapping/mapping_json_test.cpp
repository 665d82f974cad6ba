#include "Mapping/mapping_json.h"

#include "example_mapping.h"

#include <gtest/gtest.h>

#include <regex>

namespace frep::mapping
{
namespace
{

using testing::example_mapping;

// The text with the first occurrence of `from` replaced by `to` (a bad variant of a file).
std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

bool has_error(const LoadResult& r, const std::string& place, const std::string& fragment)
{
  for (const PlanError& e : r.errors)
  {
    if (e.place == place && e.message.find(fragment) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

TEST(MappingJson, LoadsTheExample)
{
  const LoadResult r = load_mapping(example_mapping);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  const Spec& s = r.spec;
  EXPECT_EQ(s.object, "meta5d");
  ASSERT_EQ(s.coordinates.size(), 6u);
  EXPECT_EQ(s.coordinates[3].name, "x4");
  const Channel& sheet = s.coordinates[3].channels[0];
  EXPECT_EQ(sheet.type, Channel::Type::Spreadsheet);
  EXPECT_EQ(sheet.grid_axis, 0);
  EXPECT_EQ(sheet.values, (std::vector<double>{ 0, 0.25, 0.5, 0.75, 1 }));
  const Channel& pitch = s.coordinates[3].channels[2];
  EXPECT_EQ(pitch.type, Channel::Type::Audio);
  EXPECT_EQ(pitch.curve.kind, Curve::Kind::Power);
  EXPECT_EQ(pitch.curve.exponent, 2);
  ASSERT_TRUE(pitch.target);
  EXPECT_EQ(pitch.target->hi, 440);
  const Channel& rotate = s.coordinates[4].channels[4];
  EXPECT_EQ(rotate.transform, Channel::Transform::Rotate);
  EXPECT_EQ(rotate.target->hi, 90);
  EXPECT_EQ(s.coordinates[5].channels[0].value, 0.5);
  ASSERT_TRUE(s.animation.path);
  EXPECT_TRUE(s.animation.path->closed);
  EXPECT_EQ(s.animation.path->points.size(), 4u);
  EXPECT_EQ(s.audio.sample_rate, 44100);
}

TEST(MappingJson, StepReachesTheEndWithoutDrift)
{
  const LoadResult r =
    load_mapping(replaced(replaced(example_mapping, "\"step\": 0.25", "\"step\": 0.1"),
      "\"range\": [0, 1], \"step\"",
      "\"range\": [0, 0.7], \"step\""));
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  const auto& v = r.spec.coordinates[3].channels[0].values;
  ASSERT_EQ(v.size(), 8u);
  EXPECT_EQ(v.back(), 0.7);
  // A step that does not divide the range stops below hi.
  const LoadResult r2 = load_mapping(replaced(example_mapping, "\"step\": 0.25", "\"step\": 0.3"));
  ASSERT_TRUE(r2.ok());
  EXPECT_EQ(r2.spec.coordinates[3].channels[0].values.size(), 4u);
}

TEST(MappingJson, RoundTrip)
{
  const LoadResult r = load_mapping(example_mapping);
  ASSERT_TRUE(r.ok());
  const std::string saved = save_mapping(r.spec);
  const LoadResult again = load_mapping(saved);
  ASSERT_TRUE(again.ok()) << format_errors(again.errors) << saved;
  EXPECT_EQ(again.spec, r.spec);
  EXPECT_EQ(save_mapping(again.spec), saved);
}

TEST(MappingJson, RoundTripOfEveryKindOfField)
{
  Spec s;
  s.version = 1;
  s.object = "cat";
  s.parameters = { 1.5, -2 };
  s.world = { WorldSystem::Spherical, 64, 0.25 };
  CoordinateMapping x1{ "x1", {} };
  Channel r;
  r.type = Channel::Type::World;
  r.axis = 0;
  r.range = Interval{ 0, 2 };
  r.target = Interval{ 0, 3 };
  x1.channels.push_back(r);
  Channel colour;
  colour.type = Channel::Type::Colour;
  colour.colormap = "red";
  colour.applies_to = PhotometricTarget::Background;
  colour.curve.kind = Curve::Kind::Table;
  colour.curve.table = { { 0, 0 }, { 0.25, 0.75 }, { 1, 1 } };
  x1.channels.push_back(colour);
  CoordinateMapping x2{ "x2", {} };
  Channel theta;
  theta.type = Channel::Type::World;
  theta.axis = 2;
  theta.curve.kind = Curve::Kind::Expression;
  theta.curve.expression = "t*t";
  x2.channels.push_back(theta);
  CoordinateMapping x10{ "x10", {} };
  Channel sheet;
  sheet.type = Channel::Type::Spreadsheet;
  sheet.grid_axis = 2;
  sheet.values = { 0.1, 0.2, 0.7 };
  sheet.curve.kind = Curve::Kind::EaseInOut;
  x10.channels.push_back(sheet);
  Channel scale;
  scale.type = Channel::Type::Transformation;
  scale.transform = Channel::Transform::Translate;
  scale.vector = { 1, 2, 3 };
  x10.channels.push_back(scale);
  Channel timbre;
  timbre.type = Channel::Type::Audio;
  timbre.audio_parameter = Channel::AudioParameter::Timbre;
  timbre.voice = 3;
  x10.channels.push_back(timbre);
  Channel light;
  light.type = Channel::Type::Transparency;
  light.applies_to = PhotometricTarget::Light;
  light.range = Interval{ -1, 0.5 };
  x10.channels.push_back(light);
  Channel dynamic;
  dynamic.type = Channel::Type::Dynamic;
  dynamic.target = Interval{ 2, 1 };
  x10.channels.push_back(dynamic);
  s.coordinates = { x10, x1, x2 }; // not sorted: the file keeps this order
  s.animation.duration = 3.5;
  s.animation.fps = 30;
  Path path;
  path.coordinates = { "x10" };
  path.points = { { 0 }, { 0.5 }, { 1 } };
  path.interpolation = Path::Interpolation::Polyline;
  path.timing = Path::Timing::Keys;
  path.key_times = { 0, 1, 3.5 };
  s.animation.path = path;
  s.animation.ghost = GhostSettings{ 40, 0.002 };
  s.spreadsheet = { 128, 0.25, false };
  s.render.width = 640;
  s.render.height = 480;
  s.render.background = { 0, 0.1, 0.2 };
  s.render.colour = { 0.3, 0.4, 0.5 };
  s.render.azimuth = -10.5;
  s.render.elevation = 80;
  s.render.inset = false;
  s.render.colour_source = RenderSettings::ColourSource::Attributes;
  s.audio.sample_rate = 48000;
  const std::string saved = save_mapping(s);
  const LoadResult r2 = load_mapping(saved);
  ASSERT_TRUE(r2.ok()) << format_errors(r2.errors) << saved;
  EXPECT_EQ(r2.spec, s) << saved;
}

TEST(MappingJson, UnknownTypeNamesThePlaceAndTheChoices)
{
  const LoadResult r = load_mapping(replaced(example_mapping,
    "\"type\": \"world\", \"axis\": \"y\"",
    "\"type\": \"wrld\", \"axis\": \"y\""));
  EXPECT_TRUE(has_error(r,
    "coordinates.x2[0].type",
    "unknown type \"wrld\" (expected world, dynamic, spreadsheet, fixed, colour, transparency, "
    "transformation, audio, projected)"))
    << format_errors(r.errors);
}

TEST(MappingJson, RangeMustRise)
{
  const LoadResult r = load_mapping(
    replaced(example_mapping, "\"range\": [0, 1], \"step\"", "\"range\": [1, 1], \"step\""));
  EXPECT_TRUE(has_error(r, "coordinates.x4[0].range", "lo must be < hi"))
    << format_errors(r.errors);
}

TEST(MappingJson, FpsMustBePositive)
{
  const LoadResult r = load_mapping(replaced(example_mapping, "\"fps\": 24", "\"fps\": 0"));
  EXPECT_TRUE(has_error(r, "animation.fps", "must be > 0")) << format_errors(r.errors);
}

TEST(MappingJson, GhostSettingsAreChecked)
{
  const LoadResult unknown = load_mapping(replaced(
    example_mapping, "\"fps\": 24", "\"fps\": 24, \"ghost\": { \"size\": 2 }"));
  EXPECT_TRUE(has_error(unknown, "animation.ghost.size", "unknown key \"size\""))
    << format_errors(unknown.errors);
  const LoadResult r = load_mapping(replaced(example_mapping, "\"fps\": 24",
    "\"fps\": 24, \"ghost\": { \"resolution\": 1, \"tolerance\": 0 }"));
  EXPECT_TRUE(has_error(r, "animation.ghost.resolution", "must be from 2 to 8192"))
    << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "animation.ghost.tolerance", "must be > 0")) << format_errors(r.errors);
  const LoadResult defaults =
    load_mapping(replaced(example_mapping, "\"fps\": 24", "\"fps\": 24, \"ghost\": {}"));
  ASSERT_TRUE(defaults.ok()) << format_errors(defaults.errors);
  EXPECT_EQ(defaults.spec.animation.ghost, GhostSettings{});
}

// The map of the topology's settings: checked with their place, defaults, and written back.
TEST(MappingJson, TopologySettingsAreChecked)
{
  const auto with = [](const std::string& topology)
  {
    const std::string text(example_mapping);
    return load_mapping(text.substr(0, text.rfind('}')) + ", \"topology\": " + topology + " }");
  };
  const LoadResult r = with(R"({ "resolution": 1, "bisections": 30, "steps": 2 })");
  EXPECT_TRUE(has_error(r, "topology.resolution", "must be from 2 to 8192")) << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "topology.bisections", "must be from 0 to 20")) << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "topology.steps", "unknown key")) << format_errors(r.errors);
  const LoadResult good = with(R"({ "resolution": 40 })");
  ASSERT_TRUE(good.ok()) << format_errors(good.errors);
  ASSERT_TRUE(good.spec.topology.has_value());
  EXPECT_EQ(good.spec.topology->resolution, 40);
  EXPECT_EQ(good.spec.topology->bisections, 4);
  EXPECT_EQ(load_mapping(save_mapping(good.spec)).spec, good.spec);
}

TEST(MappingJson, UnknownKeysAreErrors)
{
  LoadResult r = load_mapping(replaced(example_mapping, "\"fps\": 24", "\"fsp\": 24"));
  EXPECT_TRUE(has_error(r, "animation.fsp", "unknown key \"fsp\"")) << format_errors(r.errors);
  r = load_mapping(
    replaced(example_mapping, "\"colormap\": \"viridis\"", "\"colourmap\": \"viridis\""));
  EXPECT_TRUE(has_error(r, "coordinates.x3[1].colourmap", "unknown key"))
    << format_errors(r.errors);
  // A key of another channel type does not apply either.
  r = load_mapping(replaced(
    example_mapping, "{ \"type\": \"dynamic\" }", "{ \"type\": \"dynamic\", \"value\": 1 }"));
  EXPECT_TRUE(has_error(r, "coordinates.x4[1].value", "unknown key")) << format_errors(r.errors);
  r = load_mapping(replaced(example_mapping, "\"version\": 1,", "\"version\": 1, \"extra\": 2,"));
  EXPECT_TRUE(has_error(r, "extra", "unknown key")) << format_errors(r.errors);
}

TEST(MappingJson, SyntaxErrorGivesLineAndColumn)
{
  // Line 5 of the example, a missing comma after "resolution": 128; nlohmann stops at the end
  // of the unexpected token ("iso", columns 55-59).
  const std::string bad = replaced(example_mapping, "\"resolution\": 128,", "\"resolution\": 128");
  const LoadResult r = load_mapping(bad);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].place, "5:59") << r.errors[0].message;
  EXPECT_NE(r.errors[0].message.find("syntax error"), std::string::npos) << r.errors[0].message;
  const LoadResult r2 = load_mapping("{\n  \"version\": 1,\n  oops\n}");
  ASSERT_EQ(r2.errors.size(), 1u);
  EXPECT_EQ(r2.errors[0].place, "3:3");
}

// A number beyond a double makes nlohmann throw out_of_range (406), not parse_error: it was an
// exception out of load_mapping, which promises never to throw (found by fuzz_mapping_plan).
TEST(MappingJson, NumberOverflowIsAnErrorWithItsPlace)
{
  LoadResult r;
  ASSERT_NO_THROW(r = load_mapping("{\n  \"version\": 1,\n  \"animation\": { \"fps\": 2e999 }\n}"));
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].place, "3:25") << r.errors[0].message;
  EXPECT_NE(r.errors[0].message.find("number overflow"), std::string::npos) << r.errors[0].message;
}

TEST(MappingJson, AllErrorsAreCollected)
{
  std::string bad = replaced(example_mapping, "\"fps\": 24", "\"fps\": -1");
  bad = replaced(bad, "\"axis\": \"x\"", "\"axis\": \"q\"");
  bad = replaced(bad, "\"exponent\": 2", "\"exponent\": 0");
  bad = replaced(bad, "\"colormap\": \"viridis\"", "\"colormap\": \"virdis\"");
  bad = replaced(bad, "\"points\": [[0, 0], [1, 0], [1, 1], [0, 1]]", "\"points\": [[0, 0]]");
  bad = replaced(bad, "\"width\": 1280", "\"width\": 12.5");
  const LoadResult r = load_mapping(bad);
  EXPECT_TRUE(has_error(r, "animation.fps", "must be > 0"));
  EXPECT_TRUE(
    has_error(r, "coordinates.x1[0].axis", "unknown cartesian axis \"q\" (expected x, y, z)"));
  EXPECT_TRUE(has_error(r, "coordinates.x4[2].curve.exponent", "exponent must be > 0"));
  EXPECT_TRUE(has_error(r, "coordinates.x3[1].colormap", "unknown colour map \"virdis\""));
  EXPECT_TRUE(has_error(r, "animation.path.points", "at least 2 points"));
  EXPECT_TRUE(has_error(r, "render.width", "whole number"));
  EXPECT_EQ(r.errors.size(), 6u) << format_errors(r.errors);
}

TEST(MappingJson, CurveErrorsNameTheirPlace)
{
  LoadResult r = load_mapping(replaced(example_mapping,
    "{ \"kind\": \"power\", \"exponent\": 2 }",
    "{ \"kind\": \"expression\", \"expression\": \"t * (t +\" }"));
  EXPECT_TRUE(has_error(r, "coordinates.x4[2].curve.expression", "t * (t +"))
    << format_errors(r.errors);
  r = load_mapping(replaced(example_mapping,
    "{ \"kind\": \"power\", \"exponent\": 2 }",
    "{ \"kind\": \"table\", \"points\": [[0, 0], [0.5, 0.8], [0.9, 1]] }"));
  EXPECT_TRUE(has_error(r, "coordinates.x4[2].curve.points", "from 0")) << format_errors(r.errors);
  r =
    load_mapping(replaced(example_mapping, "{ \"kind\": \"power\", \"exponent\": 2 }", "\"easy\""));
  EXPECT_TRUE(has_error(r, "coordinates.x4[2].curve", "unknown curve \"easy\""))
    << format_errors(r.errors);
  r = load_mapping(
    replaced(example_mapping, "{ \"kind\": \"power\", \"exponent\": 2 }", "\"ease-in-out\""));
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.spec.coordinates[3].channels[2].curve.kind, Curve::Kind::EaseInOut);
}

TEST(MappingJson, MissingAndConflictingPieces)
{
  LoadResult r = load_mapping(R"({ "version": 1 })");
  EXPECT_TRUE(has_error(r, "coordinates", "missing"));
  r = load_mapping(R"({ "coordinates": { "x1": [{ "axis": "x" }] } })");
  EXPECT_TRUE(has_error(r, "coordinates.x1[0].type", "missing"));
  r = load_mapping(R"({ "coordinates": { "x1": [{ "type": "spreadsheet", "axis": "rows" }] } })");
  EXPECT_TRUE(has_error(r, "coordinates.x1[0]", "node values are missing"));
  r = load_mapping(
    R"({ "coordinates": { "x1": [{ "type": "spreadsheet", "axis": "rows", "step": 0.5 }] } })");
  EXPECT_TRUE(has_error(r, "coordinates.x1[0].step", "needs a \"range\""));
  r = load_mapping(R"({ "coordinates": { "x1": [{ "type": "fixed" }] } })");
  EXPECT_TRUE(has_error(r, "coordinates.x1[0].value", "missing"));
  r = load_mapping(R"({ "version": 2, "coordinates": {} })");
  EXPECT_TRUE(has_error(r, "version", "unsupported version 2"));
  r = load_mapping(R"({ "coordinates": { "x1": [] , "x1": [{ "type": "fixed", "value": 1 }] } })");
  EXPECT_TRUE(has_error(r, "", "duplicate key \"x1\"")) << format_errors(r.errors);
  r = load_mapping("[1, 2]");
  EXPECT_TRUE(has_error(r, "", "expected an object"));
}

TEST(MappingJson, WorldAxisNamesFollowTheSystem)
{
  const LoadResult r = load_mapping(R"({ "world": { "system": "cylindrical" },
    "coordinates": { "x1": [{ "type": "world", "axis": "r" }], "x2": [{ "type": "world", "axis": "phi" }],
                     "x3": [{ "type": "world", "axis": "x" }] } })");
  EXPECT_TRUE(
    has_error(r, "coordinates.x3[0].axis", "unknown cylindrical axis \"x\" (expected r, phi, z)"))
    << format_errors(r.errors);
  EXPECT_EQ(r.errors.size(), 1u);
}

} // namespace
} // namespace frep::mapping
