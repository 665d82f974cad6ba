#include "obj_writer.h"

#include "text_numbers.h"

#include <string>

namespace frepkit
{

void write_obj(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  const bool normals = mesh.has_normals();
  const bool colours = mesh.has_colours();
  std::string text = "# frepkit mesh of " + mesh.name;
  if (!mesh.source.empty())
  {
    text += " (" + mesh.source + ")";
  }
  text += "\n# ";
  append_number(text, static_cast<unsigned long long>(surface.point_count()));
  text += " points, ";
  append_number(text, static_cast<unsigned long long>(surface.cell_count()));
  text += " triangles\no " + mesh.name + "\n";

  for (std::size_t p = 0; p < surface.point_count(); ++p)
  {
    text += 'v';
    for (int k = 0; k < 3; ++k)
    {
      text += ' ';
      append_number(text, surface.points[3 * p + static_cast<std::size_t>(k)]);
    }
    if (colours)
    {
      for (float component : mesh.colours[p])
      {
        text += ' ';
        append_number(text, component);
      }
    }
    text += '\n';
    flush_if_large(text, out);
  }
  if (normals)
  {
    for (std::size_t p = 0; p < surface.point_count(); ++p)
    {
      text += "vn";
      for (int k = 0; k < 3; ++k)
      {
        text += ' ';
        append_number(text, surface.normals[3 * p + static_cast<std::size_t>(k)]);
      }
      text += '\n';
      flush_if_large(text, out);
    }
  }
  for (std::size_t t = 0; t < surface.cell_count(); ++t)
  {
    text += 'f';
    for (int corner = 0; corner < 3; ++corner)
    {
      const unsigned long long index =
        surface.cells[3 * t + static_cast<std::size_t>(corner)] + 1ULL;
      text += ' ';
      append_number(text, index);
      if (normals)
      {
        text += "//";
        append_number(text, index);
      }
    }
    text += '\n';
    flush_if_large(text, out);
  }
  out << text;
}

} // namespace frepkit
