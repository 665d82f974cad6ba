#include "pov_writer.h"

#include "text_numbers.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace frepkit
{
namespace
{

template<typename T>
void append_vector(std::string& text, const T* values)
{
  text += '<';
  append_number(text, values[0]);
  text += ',';
  append_number(text, values[1]);
  text += ',';
  append_number(text, values[2]);
  text += '>';
}

} // namespace

void write_pov(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  std::string text = "// frepkit mesh of " + mesh.name;
  text += mesh.source.empty() ? "\n" : " (" + mesh.source + ")\n";
  text += "#declare FaceColour = texture {\n\tpigment { color rgb";
  append_vector(text, mesh.face_colour.data());
  text += " }\n\tfinish { ambient 0.2 diffuse 0.5 }\n}\n";

  double centre[3];
  double half = 0;
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.5 * (mesh.box_lo[k] + mesh.box_hi[k]);
    half = std::max(half, 0.5 * (mesh.box_hi[k] - mesh.box_lo[k]));
  }
  const double location[3] = {
    centre[0], centre[1], centre[2] + 0.5 * (mesh.box_hi[2] - mesh.box_lo[2]) + 3.0 * half
  };
  text += "camera {\n\tlocation ";
  append_vector(text, location);
  text += "\n\tlook_at ";
  append_vector(text, centre);
  text += "\n}\n";
  for (int corner = 0; corner < 8; ++corner)
  {
    const double position[3] = { (corner & 1) ? mesh.box_hi[0] : mesh.box_lo[0],
      (corner & 2) ? mesh.box_hi[1] : mesh.box_lo[1],
      (corner & 4) ? mesh.box_hi[2] : mesh.box_lo[2] };
    text += "light_source {\n\t";
    append_vector(text, position);
    text += "\n\tcolor 1\n}\n";
  }

  if (surface.cell_count() == 0)
  {
    // POV-Ray rejects a mesh2 without faces.
    text += "// no surface: the mesh is empty\n";
    out << text;
    return;
  }

  text += "mesh2 {\n\tvertex_vectors {\n\t\t";
  append_number(text, static_cast<unsigned long long>(surface.point_count()));
  for (std::size_t p = 0; p < surface.point_count(); ++p)
  {
    text += ",\n\t\t";
    append_vector(text, &surface.points[3 * p]);
    flush_if_large(text, out);
  }
  text += "\n\t}\n";
  if (mesh.has_normals())
  {
    text += "\tnormal_vectors {\n\t\t";
    append_number(text, static_cast<unsigned long long>(surface.point_count()));
    for (std::size_t p = 0; p < surface.point_count(); ++p)
    {
      text += ",\n\t\t";
      append_vector(text, &surface.normals[3 * p]);
      flush_if_large(text, out);
    }
    text += "\n\t}\n";
  }
  const bool colours = mesh.has_colours();
  if (colours)
  {
    text += "\ttexture_list {\n\t\t";
    append_number(text, static_cast<unsigned long long>(surface.point_count()));
    for (const Rgb& colour : mesh.colours)
    {
      text += ",\n\t\ttexture { pigment { color rgb";
      append_vector(text, colour.data());
      text += " } finish { ambient 0.2 diffuse 0.5 } }";
      flush_if_large(text, out);
    }
    text += "\n\t}\n";
  }
  text += "\tface_indices {\n\t\t";
  append_number(text, static_cast<unsigned long long>(surface.cell_count()));
  for (std::size_t t = 0; t < surface.cell_count(); ++t)
  {
    const std::uint32_t* corners = &surface.cells[3 * t];
    text += ",\n\t\t<";
    for (int corner = 0; corner < 3; ++corner)
    {
      append_number(text, static_cast<unsigned long long>(corners[corner]));
      text += corner < 2 ? "," : ">";
    }
    if (colours)
    {
      // One texture per corner: POV-Ray interpolates them over the triangle.
      for (int corner = 0; corner < 3; ++corner)
      {
        text += ',';
        append_number(text, static_cast<unsigned long long>(corners[corner]));
      }
    }
    flush_if_large(text, out);
  }
  text += "\n\t}\n";
  if (!colours)
  {
    text += "\ttexture { FaceColour }\n";
  }
  text += "}\n";
  out << text;
}

} // namespace frepkit
