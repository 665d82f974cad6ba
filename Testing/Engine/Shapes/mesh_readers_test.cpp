// The mesh readers: each format read back to the same closed cube (STL's repeated corners
// merged), and bad files refused with a message instead of a crash.
#include "Shapes/mesh_readers.h"

#include "shape_test_meshes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

namespace frep::shapes
{
namespace
{

using testing::cube_mesh;

std::string binary_stl(const TriangleMesh& m)
{
  std::string s(80, ' ');
  const std::uint32_t n = static_cast<std::uint32_t>(m.triangle_count());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (std::size_t t = 0; t < n; ++t)
  {
    float normal[3] = { 0, 0, 0 };
    s.append(reinterpret_cast<const char*>(normal), 12);
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t id = m.triangles[3 * t + k];
      for (int c = 0; c < 3; ++c)
      {
        const float v = static_cast<float>(m.points[3 * id + c]);
        s.append(reinterpret_cast<const char*>(&v), 4);
      }
    }
    s.append(2, '\0');
  }
  return s;
}

std::string ascii_stl(const TriangleMesh& m)
{
  std::ostringstream o;
  o << "solid cube\n";
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
  {
    o << " facet normal 0 0 0\n  outer loop\n";
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t id = m.triangles[3 * t + k];
      o << "   vertex " << m.points[3 * id] << " " << m.points[3 * id + 1] << " " << m.points[3 * id + 2] << "\n";
    }
    o << "  endloop\n endfacet\n";
  }
  o << "endsolid cube\n";
  return o.str();
}

void expect_closed_cube(const MeshReadResult& r, const char* what)
{
  ASSERT_TRUE(r.ok()) << what << ": " << r.error;
  EXPECT_EQ(r.mesh.point_count(), 8u) << what;
  EXPECT_EQ(r.mesh.triangle_count(), 12u) << what;
  EXPECT_TRUE(count_edges(r.mesh).closed()) << what;
}

TEST(MeshReaders, StlBinaryAndAscii)
{
  const TriangleMesh cube = cube_mesh(1.0);
  expect_closed_cube(read_stl(binary_stl(cube)), "binary");
  expect_closed_cube(read_stl(ascii_stl(cube)), "ascii");
  std::string truncated = binary_stl(cube);
  truncated.resize(truncated.size() - 7);
  EXPECT_FALSE(read_stl(truncated).ok());
  EXPECT_FALSE(read_stl("garbage").ok());
  EXPECT_FALSE(read_stl("solid x\n vertex 1 2\n").ok());
}

TEST(MeshReaders, ObjWithPolygonsAndNegativeIndices)
{
  const std::string obj =
    "# a cube as quads\nv -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1/1 5/1 7/1 3/1\nf -7//1 -5//1 -1//1 -3//1\n";
  expect_closed_cube(read_obj(obj), "obj");
  EXPECT_FALSE(read_obj("v 1 2 3\nf 1 2 9\n").ok());
  EXPECT_FALSE(read_obj("v 1 2\n").ok());
  EXPECT_FALSE(read_obj("v 1 2 3\nf 1 1\n").ok());
}

TEST(MeshReaders, PlyAsciiAndBinary)
{
  const TriangleMesh cube = cube_mesh(1.0);
  std::ostringstream a;
  a << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 12\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < 8; ++i)
  {
    a << cube.points[3 * i] << " " << cube.points[3 * i + 1] << " " << cube.points[3 * i + 2] << "\n";
  }
  for (std::size_t t = 0; t < 12; ++t)
  {
    a << "3 " << cube.triangles[3 * t] << " " << cube.triangles[3 * t + 1] << " " << cube.triangles[3 * t + 2] << "\n";
  }
  expect_closed_cube(read_ply(a.str()), "ascii ply");

  std::string b = "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty double x\n"
                  "property double y\nproperty double z\nproperty uchar red\nelement face 12\n"
                  "property list uchar uint vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < 8; ++i)
  {
    b.append(reinterpret_cast<const char*>(&cube.points[3 * i]), 24);
    b.push_back('\x7f');
  }
  for (std::size_t t = 0; t < 12; ++t)
  {
    b.push_back('\3');
    b.append(reinterpret_cast<const char*>(&cube.triangles[3 * t]), 12);
  }
  expect_closed_cube(read_ply(b), "binary ply");
  b.resize(b.size() - 5);
  EXPECT_FALSE(read_ply(b).ok()) << "truncated";
  EXPECT_FALSE(read_ply("ply\nformat weird 1.0\nend_header\n").ok());
  EXPECT_FALSE(read_ply("not a ply").ok());
}

TEST(MeshReaders, FilesByExtension)
{
  EXPECT_TRUE(is_mesh_file("a/b.STL"));
  EXPECT_FALSE(is_mesh_file("a/b.vtp"));
  const MeshReadResult missing = read_mesh_file("/nonexistent/x.stl");
  EXPECT_NE(missing.error.find("/nonexistent/x.stl: cannot open"), std::string::npos);
}

} // namespace
} // namespace frep::shapes
