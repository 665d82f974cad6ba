#include "ply_writer.h"

#include "binary_output.h"

#include "Compiler/attribute_rgb.h"

#include <string>

namespace frepkit
{

void write_ply(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  const bool normals = mesh.has_normals();
  const bool colours = mesh.has_colours();
  std::string header =
    "ply\nformat binary_little_endian 1.0\ncomment frepkit mesh of " + mesh.name + "\n";
  header += "element vertex " + std::to_string(surface.point_count()) + "\n";
  header += "property float x\nproperty float y\nproperty float z\n";
  if (normals)
  {
    header += "property float nx\nproperty float ny\nproperty float nz\n";
  }
  if (colours)
  {
    header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  }
  header += "element face " + std::to_string(surface.cell_count()) + "\n";
  header += "property list uchar int vertex_indices\nend_header\n";

  LittleEndianBuffer buffer(out);
  buffer.bytes(header.data(), header.size());
  for (std::size_t p = 0; p < surface.point_count(); ++p)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      buffer.f32(static_cast<float>(surface.points[3 * p + k]));
    }
    if (normals)
    {
      for (std::size_t k = 0; k < 3; ++k)
      {
        buffer.f32(surface.normals[3 * p + k]);
      }
    }
    if (colours)
    {
      for (float component : mesh.colours[p])
      {
        buffer.u8(frep::colour_byte(component));
      }
    }
  }
  for (std::size_t t = 0; t < surface.cell_count(); ++t)
  {
    buffer.u8(3);
    for (std::size_t corner = 0; corner < 3; ++corner)
    {
      buffer.i32(static_cast<std::int32_t>(surface.cells[3 * t + corner]));
    }
  }
  buffer.flush();
}

} // namespace frepkit
