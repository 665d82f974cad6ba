// Unit tests of frepkit's parts that do not need a model run: the mesh writers on a hand-made
// tetrahedron, closing contours along the box (CLI layers), hfp's argument grammar, --axes/--fix
// parsing and the --box/--grid rules.
#include "Compiler/attribute_rgb.h"
#include "section_axes.h"
#include "hfp_arguments.h"
#include "mesh_writers/mesh_format.h"
#include "sampling_grid.h"
#include "section_writers/cli_writer.h"
#include "section_writers/contour_loops.h"
#include "Imaging/png_writer.h"
#include "user_error.h"

#include <gtest/gtest.h>

#if defined(FREPKIT_TEST_PNG)
#include <png.h>
#endif

#include <cstring>
#include <sstream>

namespace frepkit
{
namespace
{

/// A tetrahedron with outward winding, normals and s[1..3].
frep::mesh::Surface tetrahedron()
{
  frep::mesh::Surface s;
  s.points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  s.cells = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
  s.normals = { -1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  s.attribute_count = 3;
  s.attributes = { 1, 0, 0, 0, 1, 0, 0, 0, 1, 2, -1, 0.5 };
  return s;
}

std::string write(const MeshDocument& mesh, MeshFormat format, bool ascii = false)
{
  std::ostringstream out;
  write_mesh(mesh, format, ascii, out);
  return out.str();
}

std::size_t count(const std::string& text, const std::string& needle)
{
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
  {
    ++n;
  }
  return n;
}

TEST(MeshWriters, BinaryStlHasTheSizeAndFacetNormals)
{
  const frep::mesh::Surface surface = tetrahedron();
  MeshDocument mesh;
  mesh.surface = &surface;
  const std::string stl = write(mesh, MeshFormat::Stl);
  ASSERT_EQ(stl.size(), 84u + 50u * 4u);
  EXPECT_NE(stl.rfind("solid", 0), 0u) << "a binary header must not start with 'solid'";
  std::uint32_t n = 0;
  std::memcpy(&n, stl.data() + 80, 4);
  EXPECT_EQ(n, 4u);
  float normal[3];
  std::memcpy(normal, stl.data() + 84, 12); // triangle 0,2,1 lies in z = 0, outward is -z
  EXPECT_FLOAT_EQ(normal[2], -1.0f);
}

TEST(MeshWriters, AsciiStlObjPlyAreComplete)
{
  const frep::mesh::Surface surface = tetrahedron();
  MeshDocument mesh;
  mesh.surface = &surface;
  mesh.name = "tet";
  const std::string ascii = write(mesh, MeshFormat::Stl, true);
  EXPECT_EQ(ascii.rfind("solid tet\n", 0), 0u);
  EXPECT_EQ(count(ascii, "facet normal"), 4u);
  EXPECT_EQ(count(ascii, "vertex "), 12u);
  EXPECT_NE(ascii.find("endsolid tet\n"), std::string::npos);

  const std::string obj = write(mesh, MeshFormat::Obj);
  EXPECT_EQ(count(obj, "\nv "), 4u);
  EXPECT_EQ(count(obj, "\nvn "), 4u);
  EXPECT_NE(obj.find("\nf 1//1 3//3 2//2\n"), std::string::npos) << "1-based indices";

  mesh.colours = frep::attribute_colours(
    surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
  const std::string ply = write(mesh, MeshFormat::Ply);
  EXPECT_NE(ply.find("element vertex 4\n"), std::string::npos);
  EXPECT_NE(ply.find("property uchar red\n"), std::string::npos);
  EXPECT_NE(ply.find("property float nx\n"), std::string::npos);
  const std::size_t body = ply.find("end_header\n") + 11;
  EXPECT_EQ(ply.size() - body, 4u * (12 + 12 + 3) + 4u * 13);
}

TEST(MeshWriters, ColoursFollowHfpCtClamped)
{
  const frep::mesh::Surface surface = tetrahedron();
  const std::vector<Rgb> colours = frep::attribute_colours(
    surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
  ASSERT_EQ(colours.size(), 4u);
  EXPECT_EQ(colours[0], (Rgb{ 1, 0, 0 }));
  EXPECT_EQ(colours[3], (Rgb{ 1, 0, 0.5f })) << "s[] outside [0, 1] is clamped";
  EXPECT_EQ(frep::colour_byte(0.5f), 128);
}

TEST(MeshWriters, VrmlCarriesNormalsAndColours)
{
  const frep::mesh::Surface surface = tetrahedron();
  MeshDocument mesh;
  mesh.surface = &surface;
  mesh.name = "2bad name";
  const std::string plain = write(mesh, MeshFormat::Vrml);
  EXPECT_EQ(plain.rfind("#VRML V2.0 utf8\n", 0), 0u);
  EXPECT_NE(plain.find("DEF _2bad_name Transform"), std::string::npos);
  EXPECT_NE(plain.find("normalPerVertex TRUE"), std::string::npos);
  EXPECT_EQ(plain.find("colorPerVertex"), std::string::npos);
  EXPECT_EQ(count(plain, ", -1,"), 4u);
  mesh.colours = frep::attribute_colours(
    surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
  mesh.normals = false;
  const std::string coloured = write(mesh, MeshFormat::Vrml);
  EXPECT_NE(coloured.find("colorPerVertex TRUE"), std::string::npos);
  EXPECT_EQ(coloured.find("normalPerVertex"), std::string::npos);
}

TEST(MeshWriters, PovMesh2)
{
  const frep::mesh::Surface surface = tetrahedron();
  MeshDocument mesh;
  mesh.surface = &surface;
  mesh.colours = frep::attribute_colours(
    surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
  const std::string pov = write(mesh, MeshFormat::Pov);
  EXPECT_NE(pov.find("mesh2 {"), std::string::npos);
  EXPECT_NE(pov.find("vertex_vectors {\n\t\t4,"), std::string::npos);
  EXPECT_NE(pov.find("texture_list {\n\t\t4,"), std::string::npos);
  EXPECT_NE(pov.find("face_indices {\n\t\t4,\n\t\t<0,2,1>,0,2,1"), std::string::npos);
  EXPECT_EQ(count(pov, "light_source"), 8u);
  frep::mesh::Surface empty;
  mesh.surface = &empty;
  mesh.colours.clear();
  EXPECT_EQ(write(mesh, MeshFormat::Pov).find("mesh2"), std::string::npos)
    << "POV-Ray rejects a mesh2 without faces";
}

TEST(MeshWriters, FormatFromExtension)
{
  EXPECT_EQ(mesh_format_for("a/b.STL"), MeshFormat::Stl);
  EXPECT_EQ(mesh_format_for("x.wrl"), MeshFormat::Vrml);
  EXPECT_FALSE(mesh_format_for("x.3ds"));
  EXPECT_FALSE(mesh_format_for("dir.stl/file"));
  EXPECT_THROW(require_mesh_format("x.3ds"), UserError);
}

/// A 2-D contour from points and segments (a, b) with the inside on the left.
frep::mesh::Surface contour(const std::vector<std::array<double, 2>>& points,
  const std::vector<std::uint32_t>& segments)
{
  frep::mesh::Surface s;
  s.dimension = 2;
  for (const auto& p : points)
  {
    s.points.insert(s.points.end(), { p[0], p[1], 0.0 });
  }
  s.cells = segments;
  return s;
}

TEST(ContourLoops, ClosedLoopsKeepTheirOrientation)
{
  // A counter-clockwise square and a clockwise hole inside it.
  const auto c = contour(
    { { -2, -2 }, { 2, -2 }, { 2, 2 }, { -2, 2 }, { -1, -1 }, { -1, 1 }, { 1, 1 }, { 1, -1 } },
    { 0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4 });
  const auto loops = close_contour_loops(c, { -5, -5 }, { 5, 5 }, false);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_DOUBLE_EQ(loops[0].signed_area, 16.0);
  EXPECT_DOUBLE_EQ(loops[1].signed_area, -4.0);
  EXPECT_EQ(loops[0].points.front(), loops[0].points.back());
}

TEST(ContourLoops, ChainsCutByTheBoxAreClosedAlongIt)
{
  // The half plane y < 0.5 in the box [0, 1]^2: one chain from the right side to the left side
  // (inside on its left), closed through the corners (0, 0) and (1, 0).
  const auto c = contour({ { 1, 0.5 }, { 0.5, 0.5 }, { 0, 0.5 } }, { 0, 1, 1, 2 });
  const auto loops = close_contour_loops(c, { 0, 0 }, { 1, 1 }, false);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_DOUBLE_EQ(loops[0].signed_area, 0.5);
  EXPECT_EQ(loops[0].points.size(), 6u);
  // Two chains crossing the box (a band 0.25 < y < 0.75): one loop of both chains.
  const auto band = contour({ { 1, 0.75 }, { 0, 0.75 }, { 0, 0.25 }, { 1, 0.25 } }, { 0, 1, 2, 3 });
  const auto band_loops = close_contour_loops(band, { 0, 0 }, { 1, 1 }, false);
  ASSERT_EQ(band_loops.size(), 1u);
  EXPECT_DOUBLE_EQ(band_loops[0].signed_area, 0.5);
}

TEST(ContourLoops, BoxInsideWithoutCrossingsIsTheBox)
{
  const auto hole =
    contour({ { 0.4, 0.4 }, { 0.4, 0.6 }, { 0.6, 0.6 }, { 0.6, 0.4 } }, { 0, 1, 1, 2, 2, 3, 3, 0 });
  const auto loops = close_contour_loops(hole, { 0, 0 }, { 1, 1 }, true);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_DOUBLE_EQ(loops[1].signed_area, 1.0);
  EXPECT_TRUE(close_contour_loops(frep::mesh::Surface{}, { 0, 0 }, { 1, 1 }, false).empty());
}

TEST(CliWriter, LayersAndPolylines)
{
  std::ostringstream out;
  write_cli_header(out);
  ContourLoop loop;
  loop.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 0 } };
  loop.signed_area = 0.5;
  write_cli_layer(out, 0.25, { loop });
  write_cli_end(out);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("$$HEADERSTART\n$$ASCII\n$$UNITS/1\n$$DATE/", 0), 0u);
  EXPECT_NE(text.find("$$GEOMETRYSTART\n$$LAYER/0.25\n$$POLYLINE/1,1,4,0,0,1,0,1,1,0,0\n"
                      "$$GEOMETRYEND\n"),
    std::string::npos);
}

HfpParseResult hfp(const std::vector<std::string>& args, std::string* messages = nullptr)
{
  std::ostringstream out;
  HfpParseResult result = parse_hfp_arguments(args, out);
  if (messages)
  {
    *messages = out.str();
  }
  return result;
}

TEST(HfpArguments, DefaultsAndStatus)
{
  EXPECT_EQ(hfp({}).status, HfpParseStatus::NoArguments);
  EXPECT_EQ(hfp({ "-h" }).status, HfpParseStatus::Help);
  EXPECT_EQ(hfp({ "-g", "50", "f.hf" }).status, HfpParseStatus::NoModel);
  const HfpArguments a = hfp({ "f.hf" }).arguments;
  EXPECT_EQ(a.model, "f.hf");
  EXPECT_EQ(a.object, "my_model");
  EXPECT_EQ(a.grid, (std::array<int, 3>{ 30, 30, 30 }));
  EXPECT_EQ(a.box, (std::array<double, 6>{ -10, -10, -10, 10, 10, 10 }));
  EXPECT_TRUE(a.use_dc);
  EXPECT_FALSE(a.wrl || a.stl || a.stlb || a.pov || a.cli);
}

TEST(HfpArguments, BoundingBoxForms)
{
  EXPECT_EQ(hfp({ "f", "-b", "5" }).arguments.box, (std::array<double, 6>{ -5, -5, -5, 5, 5, 5 }));
  EXPECT_EQ(hfp({ "f", "-b", "-5" }).arguments.box, (std::array<double, 6>{ -5, -5, -5, 5, 5, 5 }));
  EXPECT_EQ(
    hfp({ "f", "-b", "3,-1" }).arguments.box, (std::array<double, 6>{ -1, -1, -1, 3, 3, 3 }));
  EXPECT_EQ(
    hfp({ "f", "-b", "1,2,-3" }).arguments.box, (std::array<double, 6>{ -1, -2, -3, 1, 2, 3 }));
  EXPECT_EQ(hfp({ "f", "-b", "-5,-5,-5,5,5,5" }).arguments.box,
    (std::array<double, 6>{ -5, -5, -5, 5, 5, 5 }));
  std::string messages;
  EXPECT_EQ(hfp({ "f", "-b", "1,2,3,4" }, &messages).arguments.box,
    (std::array<double, 6>{ -10, -10, -10, 10, 10, 10 }));
  EXPECT_NE(messages.find("\"1,2,3,4\" is not a valid argument for <-b>.\nUsing default values.\n"),
    std::string::npos);
  EXPECT_EQ(hfp({ "f", "-b", "0,0,0,1,-1,1" }).arguments.box,
    (std::array<double, 6>{ -10, -10, -10, 10, 10, 10 }))
    << "min >= max falls back";
}

TEST(HfpArguments, GridIsClampedCells)
{
  std::string messages;
  EXPECT_EQ(hfp({ "f", "-g", "1" }, &messages).arguments.grid, (std::array<int, 3>{ 2, 2, 2 }));
  EXPECT_NE(messages.find("The value 1 in the <-g> argument is not within the specified range.\n"
                          "Clamping to 2.\n"),
    std::string::npos);
  EXPECT_EQ(hfp({ "f", "-g", "10,20,30" }).arguments.grid, (std::array<int, 3>{ 10, 20, 30 }));
  EXPECT_EQ(hfp({ "f", "-g", "100000" }).arguments.grid[0], kHfpGridMax);
  EXPECT_EQ(hfp({ "f", "-g", "10,20" }).arguments.grid, (std::array<int, 3>{ 30, 30, 30 }));
}

TEST(HfpArguments, MappingAsHfp)
{
  HfpArguments a = hfp({ "f", "-x", "X,Y,Z,0.25" }).arguments;
  EXPECT_EQ(a.xyz_mapping, (std::array<int, 3>{ 0, 1, 2 }));
  ASSERT_EQ(a.x_constants.size(), 4u);
  EXPECT_EQ(a.x_constants[3], 0.25);
  a = hfp({ "f", "-x", "0.5,Z,X,Y" }).arguments;
  EXPECT_EQ(a.xyz_mapping, (std::array<int, 3>{ 2, 3, 1 }));
  EXPECT_EQ(a.x_constants[0], 0.5);
  std::string messages;
  a = hfp({ "f", "-x", "X,X,Z" }, &messages).arguments; // Y keeps position 1 = X's: invalid
  EXPECT_EQ(a.xyz_mapping, (std::array<int, 3>{ 0, 1, 2 }));
  EXPECT_EQ(a.x_constants.size(), 3u);
  EXPECT_NE(
    messages.find("is not a valid argument for <-x>.\nUsing default value.\n"), std::string::npos);
}

TEST(HfpArguments, OutputsAndMissingValues)
{
  std::string messages;
  HfpArguments a = hfp({ "f", "-wrl", "-stlb", "-pov", "p.pov", "-cli" }, &messages).arguments;
  EXPECT_TRUE(a.wrl && a.stlb && a.pov && a.cli);
  EXPECT_EQ(a.wrl_name, "out.wrl");
  EXPECT_EQ(a.stl_name, "out.stl");
  EXPECT_EQ(a.pov_name, "p.pov");
  EXPECT_EQ(a.cli_name, "out.cli");
  EXPECT_NE(messages.find("-wrl requires an argument.\nUsing default value.\n"), std::string::npos);
  a = hfp({ "f", "-o", "-g", "40" }, &messages).arguments;
  EXPECT_EQ(a.object, "my_model");
  EXPECT_EQ(a.grid[0], 40);
  a = hfp({ "f", "-usedc", "-t" }).arguments; // -usedc takes the next token whatever it is
  EXPECT_FALSE(a.use_dc);
  EXPECT_FALSE(a.time_report);
  a = hfp({ "f", "--nope", "-ct", "-s", "0.01", "-d", "1", "-cf", "255,0,0" }, &messages).arguments;
  EXPECT_NE(messages.find("\"--nope\" is not a valid argument.\nIgnoring\n"), std::string::npos);
  EXPECT_TRUE(a.attributes);
  EXPECT_TRUE(a.search);
  EXPECT_DOUBLE_EQ(a.search_fraction, 0.01);
  EXPECT_FALSE(a.normals);
  EXPECT_EQ(a.face_colour, (std::array<double, 3>{ 1, 0, 0 }));
  a = hfp({ "f", "-a", "2.5,abc" }, &messages).arguments;
  EXPECT_EQ(a.parameters, (std::vector<double>{ 2.5, 0 }));
  EXPECT_NE(messages.find("\"abc\" is not a proper floating point value.\n"), std::string::npos);
}

TEST(SectionAxes, MapOption)
{
  const SectionAxes m = parse_axes_option("X,Y,Z,0.25", 5);
  EXPECT_EQ(m.free, (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(m.fixed[3], 0.25);
  EXPECT_EQ(m.fixed[4], 0.0);
  EXPECT_EQ(parse_axes_option("0.5,z,x,y", 4).free, (std::vector<int>{ 2, 3, 1 }));
  EXPECT_THROW(parse_axes_option("X,Y", 3), UserError);
  EXPECT_THROW(parse_axes_option("X,Y,Z,1", 3), UserError);
  EXPECT_THROW(parse_axes_option("X,Y,Y", 3), UserError);
  EXPECT_THROW(parse_axes_option("X,Y,Z,abc", 4), UserError);
}

TEST(SectionAxes, FixAndFree)
{
  SectionAxes m = parse_fix_free({ "x4=0.5", "x[5]=0.25" }, {}, 5);
  EXPECT_EQ(m.free, (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(m.fixed[4], 0.25);
  m = parse_fix_free({ "x1=0", "x4=1", "x5=1" }, { "x3", "x2" }, 5);
  EXPECT_EQ(m.free, (std::vector<int>{ 2, 1 }));
  EXPECT_THROW(parse_fix_free({ "x4=0.5" }, {}, 5), UserError) << "4 free";
  EXPECT_THROW(parse_fix_free({ "x9=1" }, {}, 5), UserError);
  EXPECT_THROW(parse_fix_free({ "x4" }, {}, 5), UserError);
  EXPECT_THROW(parse_fix_free({ "x4=1", "x5=1" }, { "x1", "x2" }, 5), UserError) << "x3 unplaced";
  EXPECT_THROW(parse_fix_free({ "x4=1", "x5=1" }, { "x1", "x4" }, 5), UserError);
}

TEST(SamplingGrid, BoxAndGridRules)
{
  frep::GridSpec g = make_grid({}, {}, 3);
  ASSERT_EQ(g.axes.size(), 3u);
  EXPECT_EQ(g.axes[2].samples, kDefaultSamples);
  EXPECT_EQ(g.axes[0].lo, -10.0);
  g = make_grid({ 0, 1, 2, 3, 4, 5 }, { 10, 20, 30 }, 3);
  EXPECT_EQ(g.axes[2].hi, 5.0);
  EXPECT_EQ(g.axes[1].samples, 20);
  EXPECT_EQ(describe_grid(g), "10 x 20 x 30 samples over [0, 3] x [1, 4] x [2, 5]");
  EXPECT_THROW(make_grid({ 0, 1, 2 }, {}, 3), UserError);
  EXPECT_THROW(make_grid({ 0, 0, 0, 1, 0, 1 }, {}, 3), UserError);
  EXPECT_THROW(make_grid({}, { 1 }, 3), UserError);
  EXPECT_THROW(make_grid({}, { 4, 4 }, 3), UserError);
  EXPECT_NO_THROW(make_grid({ 0, 0, 1, 1 }, { 4, 4 }, 2));
}

#if defined(FREPKIT_TEST_PNG)
/// The RGB pixels of a PNG in memory (libpng's simplified reader).
std::vector<std::uint8_t> decode_png(const std::string& bytes, int& colour_type)
{
  colour_type = static_cast<unsigned char>(bytes.at(25)); // IHDR's colour type
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()));
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> rgb(PNG_IMAGE_SIZE(image));
  EXPECT_TRUE(png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr));
  return rgb;
}

// Pictures of at most 256 colours (sign images) are written with a palette, the others as RGB;
// either way they decode to the same pixels.
TEST(PngWriter, FewColoursAsAPaletteManyAsRgbSamePixels)
{
  for (const int colours : { 3, 256, 257, 1000 })
  {
    const int width = 40, height = 30;
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width * height * 3));
    for (int p = 0; p < width * height; ++p)
    {
      const int c = (p * 7) % colours;
      rgb[3 * p] = static_cast<std::uint8_t>(c & 0xff);
      rgb[3 * p + 1] = static_cast<std::uint8_t>(c >> 8);
      rgb[3 * p + 2] = static_cast<std::uint8_t>(255 - (c & 0xff));
    }
    std::ostringstream out;
    frep::imaging::write_png(out, width, height, rgb);
    int colour_type = -1;
    EXPECT_EQ(decode_png(out.str(), colour_type), rgb) << colours;
    EXPECT_EQ(colour_type, colours <= 256 ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_RGB) << colours;
  }
}
#endif

} // namespace
} // namespace frepkit
