// draw_sample (Scene/sample_picture.h), the one way a cell or frame becomes a picture: by the
// mesh method it is exactly make_section + render_sample (the pixels compared), by rays exactly
// raycast_sample; it counts the mesh's triangles, stops when cancelled with nothing drawn, and
// answers a bad request with an error instead of throwing.
#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"
#include "Scene/framing.h"
#include "Scene/pictures.h"
#include "Scene/sample_picture.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Compiler/load_model.h"
#include "Eval/thread_pool.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

namespace mapping = frep::mapping;

// A ball whose radius grows with x4, on a spreadsheet of three cells.
const char* const Ball4 = "m(x[4], a[1]) { m = 1 + x[4] - x[1]^2 - x[2]^2 - x[3]^2; }";
const char* const Mapping = R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-3, 3] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-3, 3] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-3, 3] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5 }] },
  "world": { "resolution": 32 },
  "render": { "width": 64, "height": 64 } })";

struct Sheet
{
  std::shared_ptr<const frep::Model> model =
    frep::load_model(frep::ModelSource::from_text(Ball4)).model;
  mapping::Spec spec;
  mapping::Plan plan;
  mapping::Framing framing;
  frep::imaging::Camera camera;

  Sheet()
  {
    const mapping::LoadResult loaded = mapping::load_mapping(Mapping);
    EXPECT_TRUE(loaded.errors.empty()) << mapping::format_errors(loaded.errors);
    spec = loaded.spec;
    mapping::PlanResult planned = mapping::make_plan(spec, mapping::hyperfun_coordinates(4));
    EXPECT_TRUE(planned.ok()) << mapping::format_errors(planned.errors);
    plan = planned.plan;
    framing = mapping::frame_solids(spec.render, *model, {}, plan);
    camera = mapping::plan_camera(plan, spec.render, 1.0, framing);
  }
};

void expect_same_pixels(const frep::imaging::Image& a, const frep::imaging::Image& b)
{
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_TRUE(a.rgba == b.rgba);
}

} // namespace

TEST(DrawSample, MeshMethodIsTheSectionRasterised)
{
  const Sheet s;
  ASSERT_EQ(s.plan.cells.size(), 3u);
  for (const mapping::Sample& cell : s.plan.cells)
  {
    const mapping::SamplePicture p = mapping::draw_sample(*s.model, {}, s.plan, cell, s.camera,
      64, 64, s.spec.render, mapping::RenderSettings::Method::Mesh, {}, s.framing);
    ASSERT_TRUE(p.ok()) << p.error;
    const mapping::Section section = mapping::make_section(*s.model, {}, s.plan, cell);
    ASSERT_TRUE(section.ok()) << section.error;
    EXPECT_EQ(p.triangles, section.surface.cell_count());
    EXPECT_GT(p.triangles, 100u);
    expect_same_pixels(p.image,
      mapping::render_sample(
        s.plan, section, cell, s.camera, 64, 64, s.spec.render, 1, nullptr, s.framing));
  }
  // Another grid: the options' samples reach the mesher.
  mapping::DrawOptions coarse;
  coarse.samples = { 8, 8, 8 };
  const mapping::SamplePicture few = mapping::draw_sample(*s.model, {}, s.plan, s.plan.cells[0],
    s.camera, 64, 64, s.spec.render, mapping::RenderSettings::Method::Mesh, coarse, s.framing);
  ASSERT_TRUE(few.ok()) << few.error;
  EXPECT_LT(few.triangles * 4, mapping::make_section(*s.model, {}, s.plan, s.plan.cells[0])
                                 .surface.cell_count());
}

TEST(DrawSample, RayMethodIsRaycastSampleOnAnyPool)
{
  const Sheet s;
  const mapping::Sample& cell = s.plan.cells[2];
  const mapping::RaycastPicture rays =
    mapping::raycast_sample(*s.model, {}, s.plan, cell, s.camera, 64, 64);
  ASSERT_TRUE(rays.ok()) << rays.error;
  mapping::DrawOptions on_pool;
  on_pool.pool = std::make_shared<frep::ThreadPool>(2);
  for (const mapping::DrawOptions& options : { mapping::DrawOptions{}, on_pool })
  {
    const mapping::SamplePicture p = mapping::draw_sample(*s.model, {}, s.plan, cell, s.camera,
      64, 64, s.spec.render, mapping::RenderSettings::Method::Raycast, options, s.framing);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.triangles, 0u);
    expect_same_pixels(p.image, rays.image);
  }
}

TEST(DrawSample, CancelledOrBadRequestsDrawNothing)
{
  const Sheet s;
  mapping::DrawOptions stop;
  stop.cancel = [] { return true; };
  for (const auto method :
    { mapping::RenderSettings::Method::Mesh, mapping::RenderSettings::Method::Raycast })
  {
    const mapping::SamplePicture p = mapping::draw_sample(*s.model, {}, s.plan, s.plan.cells[0],
      s.camera, 64, 64, s.spec.render, method, stop, s.framing);
    EXPECT_TRUE(p.cancelled);
    EXPECT_FALSE(p.ok());
    EXPECT_TRUE(p.error.empty()) << p.error;
    EXPECT_TRUE(p.image.empty());
  }
  const mapping::SamplePicture no_pixels = mapping::draw_sample(*s.model, {}, s.plan,
    s.plan.cells[0], s.camera, 0, 64, s.spec.render, mapping::RenderSettings::Method::Mesh);
  EXPECT_NE(no_pixels.error.find("pixel"), std::string::npos);
  // A sample of another model (one value short) is an error, not a crash.
  mapping::Sample wrong = s.plan.cells[0];
  wrong.values.pop_back();
  const mapping::SamplePicture bad = mapping::draw_sample(*s.model, {}, s.plan, wrong, s.camera,
    64, 64, s.spec.render, mapping::RenderSettings::Method::Mesh);
  EXPECT_FALSE(bad.ok());
  EXPECT_FALSE(bad.error.empty());
  EXPECT_TRUE(bad.image.empty());
}
// The framing keeps each cell's solid bounds (the ray caster's search, done once for the
// camera); draw_sample hands them on, so they must be the cell's own, and only for the
// parameters they were found with.
TEST(DrawSample, FramedSolidsAreEachCellsOwnBounds)
{
  const Sheet s;
  std::vector<double> widths;
  for (const mapping::Sample& cell : s.plan.cells)
  {
    const frep::mesh::SolidBounds* framed = s.framing.solid_of(s.plan, cell, {});
    ASSERT_NE(framed, nullptr);
    const frep::mesh::SolidBounds own = frep::raycast::solid_bounds(
      s.model->specialise(mapping::section_specialisation(s.plan, cell, {})),
      std::vector<frep::Interval>{ { -3, 3 }, { -3, 3 }, { -3, 3 } });
    ASSERT_TRUE(own.bounded());
    for (std::size_t k = 0; k < 3; ++k)
    {
      EXPECT_EQ(framed->box[k].lo, own.box[k].lo) << cell.label;
      EXPECT_EQ(framed->box[k].hi, own.box[k].hi) << cell.label;
    }
    widths.push_back(own.box[0].hi - own.box[0].lo);
    EXPECT_EQ(s.framing.solid_of(s.plan, cell, { 1.0 }), nullptr); // other a[]: another tape
    mapping::Plan wider = s.plan; // another model box: other bounds
    wider.model_box[0].hi = 4;
    EXPECT_EQ(s.framing.solid_of(wider, cell, {}), nullptr);
  }
  ASSERT_EQ(widths.size(), 3u); // the ball grows with x4: three different bounds
  EXPECT_LT(widths[0], widths[1]);
  EXPECT_LT(widths[1], widths[2]);
}
