// produce: a mapping made into files end to end. A ball that grows with x4 and x5, both mapped
// to time (and x4 to a spreadsheet): the files, the manifest's entries, the progress (rising to 1, one
// call at a time), a mapping that does not fit (nothing written), resuming (frames kept only for
// the same inputs), and cancelling (what finished kept, no temporary, no movie).
#include "Production/production.h"

#include "Mapping/mapping_json.h"

#include "Compiler/load_model.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <vector>

namespace
{

namespace fs = std::filesystem;
using frep::mapping::ProductionInputs;
using frep::mapping::ProductionOptions;
using frep::mapping::ProductionReport;

const char* const Growing = R"(
grow(x[5], a[1])
{
  grow = (0.5 + 0.5 * x[4] + 0.5 * x[5]) - sqrt(x[1]^2 + x[2]^2 + x[3]^2);
}
)";

// x4 and x5 run along the animation's path (path.png); with `spreadsheet`, x4 also lays out
// three cells (x5 is then fixed at its range's middle in them).
std::string mapping_text(bool spreadsheet, int frames)
{
  const std::string cells = spreadsheet
    ? R"({ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5 },)"
    : "";
  return R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [)" + cells + R"({ "type": "dynamic", "range": [0, 1] }],
    "x5": [{ "type": "dynamic", "range": [0, 1] },
           { "type": "audio", "parameter": "pitch", "range": [0, 1], "target": [220, 440] }] },
  "animation": { "duration": )" + std::to_string(frames) + R"(, "fps": 1,
    "path": { "coordinates": ["x4", "x5"], "points": [[0, 0], [1, 0], [1, 1]] } },
  "world": { "resolution": 16 },
  "spreadsheet": { "cell_size": 48 },
  "render": { "width": 64, "height": 48 } })";
}

ProductionInputs inputs(const std::string& mapping, const std::string& model_text = Growing)
{
  ProductionInputs in;
  const frep::mapping::LoadResult loaded = frep::mapping::load_mapping(mapping);
  EXPECT_TRUE(loaded.errors.empty()) << frep::mapping::format_errors(loaded.errors);
  in.spec = loaded.spec;
  const frep::LoadedModel model =
    frep::load_model(frep::ModelSource::from_text(model_text, "grow.hf"));
  EXPECT_TRUE(model.ok()) << model.message();
  in.model = model.model;
  in.model_key = model_text;
  in.model_label = "grow.hf";
  in.mapping_label = "grow.json";
  return in;
}

/// The report's error with the mapping's problems, for failure messages.
std::string why(const ProductionReport& r)
{
  std::string text = r.error;
  for (const std::string& d : r.diagnostics)
  {
    text += "\n  " + d;
  }
  return text;
}

fs::path fresh(const std::string& name)
{
  const fs::path dir = fs::path(FREP_PRODUCTION_TEST_OUTPUT_DIR) / name;
  fs::remove_all(dir);
  return dir;
}

std::vector<std::string> temporaries(const fs::path& dir)
{
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
  {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos || name.find("partial") != std::string::npos)
    {
      found.push_back(entry.path().string());
    }
  }
  return found;
}

std::size_t frames_in(const fs::path& dir)
{
  std::size_t n = 0;
  for (const auto& entry : fs::directory_iterator(dir / "frames"))
  {
    n += entry.path().extension() == ".png";
  }
  return n;
}

const ProductionReport::Status Done = ProductionReport::Status::Done;

TEST(Production, MakesEveryFileAndAManifestThatListsThem)
{
  const fs::path out = fresh("all");
  ProductionOptions run;
  run.directory = out;
  run.stem = "grow";
  run.threads = 2;
  std::vector<double> seen;
  std::mutex seen_mutex;
  std::atomic<int> inside{ 0 };
  bool overlapped = false;
  run.progress = [&](double f)
  {
    overlapped = overlapped || ++inside > 1;
    {
      std::lock_guard<std::mutex> lock(seen_mutex);
      seen.push_back(f);
    }
    --inside;
    return true;
  };
  const ProductionReport report = frep::mapping::produce(inputs(mapping_text(true, 4)), run);
  ASSERT_EQ(report.status, Done) << why(report);
  for (const char* file : { "spreadsheet.png", "path.png", "grow.wav", "grow.mp4", "manifest.json",
         "frames/frame_00000.png", "frames/frame_00003.png" })
  {
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  }
  EXPECT_EQ(frames_in(out), 4u);
  EXPECT_TRUE(temporaries(out).empty());
  EXPECT_FALSE(overlapped) << "progress must be called one call at a time";
  ASSERT_FALSE(seen.empty());
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  EXPECT_GT(report.triangles, 0u);

  std::ifstream file(out / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(file);
  EXPECT_EQ(manifest.dump(2) + "\n", report.manifest);
  EXPECT_EQ(manifest["model"], "grow.hf");
  EXPECT_EQ(manifest["object"], "grow");
  EXPECT_EQ(manifest["dimension"], 5);
  std::vector<std::string> kinds;
  for (const auto& f : manifest["files"])
  {
    kinds.push_back(f["kind"]);
  }
  EXPECT_EQ(kinds,
    (std::vector<std::string>{ "spreadsheet", "path", "frames", "audio", "movie" }));
  EXPECT_EQ(manifest["files"][0]["cells"].size(), 3u);
  EXPECT_EQ(manifest["files"][2]["frames"].size(), 4u);
  for (const auto& stage : report.stages)
  {
    EXPECT_TRUE(manifest["seconds"].contains(stage.name)) << stage.name;
  }
}

TEST(Production, OnlyMakesWhatIsAskedAndTheManifestCanStayInTheReport)
{
  const fs::path out = fresh("only");
  ProductionOptions run;
  run.directory = out;
  run.only = { "spreadsheet" };
  run.write_manifest = false;
  const ProductionReport report = frep::mapping::produce(inputs(mapping_text(true, 2)), run);
  ASSERT_EQ(report.status, Done) << why(report);
  EXPECT_TRUE(fs::is_regular_file(out / "spreadsheet.png"));
  EXPECT_FALSE(fs::exists(out / "frames"));
  EXPECT_FALSE(fs::exists(out / "manifest.json"));
  EXPECT_NE(report.manifest.find("spreadsheet.png"), std::string::npos);

  run.only = { "sculpture" };
  const ProductionReport unknown = frep::mapping::produce(inputs(mapping_text(true, 2)), run);
  EXPECT_EQ(unknown.status, ProductionReport::Status::Failed);
  EXPECT_NE(unknown.error.find("sculpture"), std::string::npos) << unknown.error;
}

TEST(Production, AMappingThatDoesNotFitWritesNothing)
{
  const fs::path out = fresh("invalid");
  ProductionInputs in = inputs(mapping_text(false, 2));
  const frep::LoadedModel ball = frep::load_model(
    frep::ModelSource::from_text("ball(x[3], a[1]) { ball = 1 - x[1]^2 - x[2]^2 - x[3]^2; }"));
  ASSERT_TRUE(ball.ok());
  in.model = ball.model; // 3-D: the mapping's x4 and x5 do not exist
  ProductionOptions run;
  run.directory = out;
  const ProductionReport report = frep::mapping::produce(in, run);
  EXPECT_EQ(report.status, ProductionReport::Status::Invalid);
  EXPECT_FALSE(report.diagnostics.empty());
  EXPECT_NE(report.error.find("does not fit ball (3-D)"), std::string::npos) << report.error;
  EXPECT_FALSE(fs::exists(out));
}

// x5 projected over [0, 1]: the cells are cut from the projection (the ball at x5 = 1, the
// largest), and the manifest says which coordinates were projected over what.
TEST(Production, ProjectedCoordinatesAreCutFromTheProjectionAndListed)
{
  const fs::path out = fresh("projected");
  ProductionInputs in = inputs(R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "values": [0, 0.5] }],
    "x5": [{ "type": "projected", "range": [0, 1], "tolerance": 0.001 }] },
  "world": { "resolution": 16 },
  "spreadsheet": { "cell_size": 48 } })");
  ProductionOptions run;
  run.directory = out;
  run.threads = 2;
  const ProductionReport report = frep::mapping::produce(in, run);
  ASSERT_TRUE(report.ok()) << why(report);
  EXPECT_TRUE(fs::exists(out / "spreadsheet.png"));
  const nlohmann::json manifest = nlohmann::json::parse(report.manifest);
  ASSERT_TRUE(manifest.contains("projected")) << report.manifest;
  EXPECT_EQ(manifest["projected"]["x5"]["range"], nlohmann::json({ 0.0, 1.0 }));
  EXPECT_EQ(manifest["projected"]["x5"]["tolerance"], 0.001);
  EXPECT_EQ(manifest["object"], "grow"); // the model's, not the projection's wrapper
  EXPECT_TRUE(temporaries(out).empty());
  // Not the section at x5's middle (what the samples' value says): larger balls, more triangles.
  ProductionInputs middle = in;
  middle.spec.coordinates[4].channels[0].type = frep::mapping::Channel::Type::Fixed;
  middle.spec.coordinates[4].channels[0].value = 0.5;
  run.directory = fresh("projected_middle");
  const ProductionReport fixed = frep::mapping::produce(middle, run);
  ASSERT_TRUE(fixed.ok()) << why(fixed);
  EXPECT_GT(report.triangles, fixed.triangles + fixed.triangles / 4);
}

// The ghost (animation.ghost): a ball carried by x4, x5 along an L of the path is drawn as the
// union of the balls along it: ghost.png, listed in the manifest with its mesh; about three
// times the surface of the ghost of a path that hardly moves (one ball), and the stage's
// line names it. --only ghost makes it alone.
TEST(Production, TheGhostIsTheUnionOfEveryShapeOnThePath)
{
  const char* moved = R"(
moved(x[5], a[1]) { moved = 0.25 - ((x[1] - x[4])^2 + (x[2] - x[5])^2 + x[3]^2); }
)";
  const auto ghost_of = [&](const std::string& points, const std::string& name)
  {
    ProductionInputs in = inputs(R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "dynamic", "range": [0, 1] }],
    "x5": [{ "type": "dynamic", "range": [0, 1] }] },
  "animation": { "duration": 4, "fps": 1, "ghost": { "resolution": 24 },
    "path": { "coordinates": ["x4", "x5"], "points": )" + points + R"(,
              "interpolation": "polyline" } },
  "world": { "resolution": 16 },
  "render": { "width": 64, "height": 48 } })",
      moved);
    ProductionOptions run;
    run.directory = fresh(name);
    run.threads = 2;
    run.only = { "ghost" };
    const ProductionReport report = frep::mapping::produce(in, run);
    EXPECT_TRUE(report.ok()) << why(report);
    EXPECT_TRUE(fs::exists(run.directory / "ghost.png"));
    EXPECT_FALSE(fs::exists(run.directory / "frames"));
    EXPECT_TRUE(temporaries(run.directory).empty());
    const nlohmann::json manifest = nlohmann::json::parse(report.manifest);
    for (const nlohmann::json& f : manifest["files"])
      if (f["kind"] == "ghost")
      {
        EXPECT_EQ(f["file"], "ghost.png");
        EXPECT_EQ(f["resolution"], 24);
        EXPECT_EQ(f["coordinates"], nlohmann::json({ "x4", "x5" }));
        return f["triangles"].get<std::size_t>();
      }
    ADD_FAILURE() << "no ghost in " << report.manifest;
    return std::size_t{ 0 };
  };
  const std::size_t l = ghost_of("[[0, 0], [1, 0], [1, 1]]", "ghost_l");
  const std::size_t ball = ghost_of("[[0, 0], [0.001, 0]]", "ghost_ball");
  EXPECT_GT(ball, 100u);
  EXPECT_GT(l, 2 * ball);
  EXPECT_LT(l, 4 * ball);
}

// The map of the topology (topology): two balls of radius 0.45 whose centres x1 = +-c part as
// c = 0.3 + 0.4 x4 passes 0.45, at x4 = 0.375 (the grid has a point at the origin, where they
// meet); five cells of x4 from 0 to 1: one piece up to 0.25, two from 0.5, the change between
// those cells located within 1/64 of their step, and the spreadsheet drawn over.
TEST(Production, TheTopologyMapLocatesWhereTwoBallsPart)
{
  const char* balls = R"(
balls(x[4], a[1])
{
  c = 0.3 + 0.4 * x[4];
  balls = max(0.2025 - ((x[1] - c)^2 + x[2]^2 + x[3]^2), 0.2025 - ((x[1] + c)^2 + x[2]^2 + x[3]^2));
}
)";
  ProductionInputs in = inputs(R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.25 }] },
  "topology": { "resolution": 49, "bisections": 6 },
  "world": { "resolution": 16 },
  "spreadsheet": { "cell_size": 48 } })",
    balls);
  ProductionOptions run;
  run.directory = fresh("topology_cells");
  run.threads = 2;
  const ProductionReport report = frep::mapping::produce(in, run);
  ASSERT_TRUE(report.ok()) << why(report);
  EXPECT_TRUE(fs::exists(run.directory / "spreadsheet-topology.png"));
  EXPECT_FALSE(fs::exists(run.directory / "topology.png")); // no frames
  EXPECT_TRUE(temporaries(run.directory).empty());
  const nlohmann::json manifest = nlohmann::json::parse(report.manifest);
  const nlohmann::json& sheet = manifest["topology"]["spreadsheet"];
  ASSERT_EQ(sheet["cells"].size(), 5u) << report.manifest;
  const std::vector<int> pieces{ 1, 1, 2, 2, 2 };
  for (std::size_t i = 0; i < 5; ++i)
  {
    EXPECT_EQ(sheet["cells"][i]["pieces"], pieces[i]) << i;
    EXPECT_EQ(sheet["cells"][i]["genus"], 0) << i;
  }
  ASSERT_EQ(sheet["changes"].size(), 1u) << report.manifest;
  const nlohmann::json& change = sheet["changes"][0];
  EXPECT_EQ(change["cells"], nlohmann::json({ { 1, -1, -1 }, { 2, -1, -1 } })); // as the spreadsheet entry
  EXPECT_EQ(change["before"]["pieces"], 1);
  EXPECT_EQ(change["after"]["pieces"], 2);
  const double lo = change["values"]["x4"][0], hi = change["values"]["x4"][1];
  EXPECT_LE(lo, 0.375);
  EXPECT_GE(hi, 0.375);
  EXPECT_NEAR(hi - lo, 0.25 / 64, 1e-12);
  bool listed = false;
  for (const nlohmann::json& f : manifest["files"])
    listed = listed || f["file"] == "spreadsheet-topology.png";
  EXPECT_TRUE(listed) << report.manifest;
}

// 2-D sections (two world coordinates: contours) are mapped alike: two discs parting at
// x3 = 0.375, their loops counted.
TEST(Production, TheTopologyMapCountsTheLoopsOfContours)
{
  const char* discs = R"(
discs(x[3], a[1])
{
  c = 0.3 + 0.4 * x[3];
  discs = max(0.2025 - ((x[1] - c)^2 + x[2]^2), 0.2025 - ((x[1] + c)^2 + x[2]^2));
}
)";
  ProductionInputs in = inputs(R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.25 }] },
  "topology": { "resolution": 49, "bisections": 6 },
  "spreadsheet": { "cell_size": 48 } })",
    discs);
  ProductionOptions run;
  run.directory = fresh("topology_contours");
  const ProductionReport report = frep::mapping::produce(in, run);
  ASSERT_TRUE(report.ok()) << why(report);
  const nlohmann::json sheet = nlohmann::json::parse(report.manifest)["topology"]["spreadsheet"];
  ASSERT_EQ(sheet["cells"].size(), 5u);
  const std::vector<int> loops{ 1, 1, 2, 2, 2 };
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(sheet["cells"][i]["pieces"], loops[i]) << i;
  ASSERT_EQ(sheet["changes"].size(), 1u);
  const double lo = sheet["changes"][0]["values"]["x3"][0], hi = sheet["changes"][0]["values"]["x3"][1];
  EXPECT_LE(lo, 0.375);
  EXPECT_GE(hi, 0.375);
  bool stage = false;
  for (const auto& s : report.stages)
    stage = stage || (s.name == "topology" && s.detail.find("at 49^2") != std::string::npos);
  EXPECT_TRUE(stage);
}

// Along the animation: a torus (R = 1) whose tube radius 0.7 + 0.8 x4 reaches R at x4 = 0.375
// closes its hole there (genus 1 -> 0, one piece throughout); x4 runs over the frames. The
// change is between the frames either side of it, its x4 interval holds 0.375, topology.png is
// written, and --only topology makes the map alone (no frames).
TEST(Production, TheTopologyMapFollowsTheAnimation)
{
  const char* torus = R"(
torus(x[4], a[1])
{
  r = 0.7 + 0.8 * x[4];
  torus = r^2 - ((sqrt(x[1]^2 + x[2]^2) - 1)^2 + x[3]^2);
}
)";
  ProductionInputs in = inputs(R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-3, 3] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-3, 3] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-3, 3] }],
    "x4": [{ "type": "dynamic", "range": [0, 1] }] },
  "animation": { "duration": 6, "fps": 1 },
  "topology": { "resolution": 61, "bisections": 5 },
  "world": { "resolution": 16 },
  "render": { "width": 64, "height": 48 } })",
    torus);
  ProductionOptions run;
  run.directory = fresh("topology_frames");
  run.threads = 2;
  run.only = { "topology" };
  const ProductionReport report = frep::mapping::produce(in, run);
  ASSERT_TRUE(report.ok()) << why(report);
  EXPECT_TRUE(fs::exists(run.directory / "topology.png"));
  EXPECT_FALSE(fs::exists(run.directory / "frames"));
  const nlohmann::json manifest = nlohmann::json::parse(report.manifest);
  const nlohmann::json& frames = manifest["topology"]["frames"];
  const std::size_t n = frames["pieces"].size();
  ASSERT_GE(n, 3u) << report.manifest;
  ASSERT_EQ(frames["genus"].size(), n);
  EXPECT_EQ(frames["genus"][0], 1);
  EXPECT_EQ(frames["genus"][n - 1], 0);
  for (std::size_t k = 0; k < n; ++k)
    EXPECT_EQ(frames["pieces"][k], 1) << k;
  ASSERT_EQ(frames["changes"].size(), 1u) << report.manifest;
  const nlohmann::json& change = frames["changes"][0];
  EXPECT_EQ(change["before"]["genus"], 1);
  EXPECT_EQ(change["after"]["genus"], 0);
  const double lo = change["values"]["x4"][0], hi = change["values"]["x4"][1];
  EXPECT_LE(lo, 0.375);
  EXPECT_GE(hi, 0.375);
  const double frame_lo = change["frames"][0], frame_hi = change["frames"][1];
  EXPECT_LT(frame_lo, frame_hi);
  EXPECT_EQ(std::floor(frame_lo), std::floor(frame_hi - 1e-9)); // within one step
}

TEST(Production, FramesAreKeptOnlyForTheSameInputs)
{
  const fs::path out = fresh("resume");
  ProductionOptions run;
  run.directory = out;
  run.only = { "frames" };
  const ProductionReport first = frep::mapping::produce(inputs(mapping_text(false, 3)), run);
  ASSERT_EQ(first.status, Done) << why(first);
  auto frames_stage = [](const ProductionReport& r)
  {
    for (const auto& s : r.stages)
    {
      if (s.name == "frames")
      {
        return s.detail;
      }
    }
    return std::string();
  };
  const ProductionReport again = frep::mapping::produce(inputs(mapping_text(false, 3)), run);
  EXPECT_NE(frames_stage(again).find("3 kept from an earlier run"), std::string::npos)
    << frames_stage(again);

  // Another model text (the key), the same mapping: every frame is drawn again.
  const std::string other = std::string(Growing) + "\n-- edited\n";
  const ProductionReport edited = frep::mapping::produce(inputs(mapping_text(false, 3), other), run);
  EXPECT_EQ(frames_stage(edited).find("kept"), std::string::npos) << frames_stage(edited);

  // force: drawn again too.
  run.force = true;
  const ProductionReport forced = frep::mapping::produce(inputs(mapping_text(false, 3), other), run);
  EXPECT_EQ(frames_stage(forced).find("kept"), std::string::npos) << frames_stage(forced);
}

TEST(Production, CancellingKeepsWhatFinishedAndLeavesNoTemporary)
{
  const fs::path out = fresh("cancel");
  ProductionOptions run;
  run.directory = out;
  run.threads = 1;
  std::atomic<int> done{ 0 };
  run.progress = [&](double) { return ++done < 3; }; // false on the third unit: stop
  const ProductionReport report = frep::mapping::produce(inputs(mapping_text(false, 40)), run);
  ASSERT_EQ(report.status, ProductionReport::Status::Cancelled) << why(report);
  EXPECT_NE(report.error.find("cancelled"), std::string::npos);
  const std::size_t kept = frames_in(out);
  EXPECT_GE(kept, 2u);
  EXPECT_LT(kept, 40u);
  EXPECT_FALSE(fs::exists(out / "animation.mp4"));
  EXPECT_FALSE(fs::exists(out / "manifest.json"));
  EXPECT_TRUE(temporaries(out).empty());

  // Cancelled from the start: nothing drawn.
  const fs::path none = fresh("cancel-at-once");
  run.directory = none;
  run.progress = nullptr;
  run.cancel = [] { return true; };
  const ProductionReport stopped = frep::mapping::produce(inputs(mapping_text(false, 4)), run);
  EXPECT_EQ(stopped.status, ProductionReport::Status::Cancelled);
  EXPECT_FALSE(fs::exists(none / "frames" / "frame_00000.png"));
}

TEST(Production, MappedObjectPrefersTheRequestThenTheMapping)
{
  frep::mapping::Spec spec;
  spec.object = "meta5d";
  EXPECT_EQ(frep::mapping::mapped_object(spec, "cat"), "cat");
  EXPECT_EQ(frep::mapping::mapped_object(spec, ""), "meta5d");
  EXPECT_EQ(frep::mapping::mapped_object(frep::mapping::Spec{}, ""), "");
}

} // namespace
