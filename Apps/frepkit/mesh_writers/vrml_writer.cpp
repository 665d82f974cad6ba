#include "vrml_writer.h"

#include "text_numbers.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace frepkit
{
namespace
{

template<typename T>
void append_triple(std::string& text, const T* values)
{
  append_number(text, values[0]);
  text += ' ';
  append_number(text, values[1]);
  text += ' ';
  append_number(text, values[2]);
}

} // namespace

std::string vrml_identifier(const std::string& name)
{
  std::string id;
  for (char c : name)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    const bool forbidden = u <= 0x20 || u == 0x7f || c == '"' || c == '#' || c == '\'' ||
                           c == ',' || c == '.' || c == '[' || c == '\\' || c == ']' || c == '{' ||
                           c == '}';
    id += forbidden ? '_' : c;
  }
  if (id.empty() || (id[0] >= '0' && id[0] <= '9') || id[0] == '+' || id[0] == '-')
  {
    id.insert(id.begin(), '_');
  }
  return id;
}

void write_vrml(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  const std::string id = vrml_identifier(mesh.name);
  std::string text = "#VRML V2.0 utf8\n\n#Produced by frepkit (HyperFun polygonizer format)\n\n";
  text += "#From Model: " + mesh.source + "  Object: " + mesh.name + "\n\n";

  // Look down -z at the box centre from where the whole box is in the 45 degree field of view.
  double centre[3];
  double half = 0;
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.5 * (mesh.box_lo[k] + mesh.box_hi[k]);
    half = std::max(half, 0.5 * (mesh.box_hi[k] - mesh.box_lo[k]));
  }
  const double field_of_view = 0.785398;
  const double position[3] = { centre[0],
    centre[1],
    centre[2] + 0.5 * (mesh.box_hi[2] - mesh.box_lo[2]) +
      1.2 * half / std::tan(field_of_view / 2) };
  text += "DEF Start Viewpoint {\n  position ";
  append_triple(text, position);
  text += "\n  orientation 0 0 1 0\n  fieldOfView 0.785398\n  description \"Start\"\n  }\n";

  text += "DEF " + id + " Transform {\n  translation 0 0 0\n  children [\n    Shape {\n";
  text += "      appearance Appearance {\n        material Material {\n          diffuseColor ";
  append_triple(text, mesh.face_colour.data());
  text += "\n          specularColor 1 1 1\n          shininess 0.45\n          }\n        }\n";
  text += "      geometry DEF " + id + "-FACES IndexedFaceSet {\n        ccw TRUE\n";
  text += "        solid FALSE\n";

  text += "        coord DEF " + id + "-COORD Coordinate {\n          point [\n";
  for (std::size_t p = 0; p < surface.point_count(); ++p)
  {
    text += "            ";
    append_triple(text, &surface.points[3 * p]);
    text += '\n';
    flush_if_large(text, out);
  }
  text += "            ]\n          }\n";

  if (mesh.has_normals())
  {
    text += "        normal Normal {\n          vector [\n";
    for (std::size_t p = 0; p < surface.point_count(); ++p)
    {
      text += "            ";
      append_triple(text, &surface.normals[3 * p]);
      text += '\n';
      flush_if_large(text, out);
    }
    text += "            ]\n          }\n        normalPerVertex TRUE\n";
  }

  text += "        coordIndex [\n";
  for (std::size_t t = 0; t < surface.cell_count(); ++t)
  {
    text += "          ";
    for (std::size_t corner = 0; corner < 3; ++corner)
    {
      append_number(text, static_cast<unsigned long long>(surface.cells[3 * t + corner]));
      text += ", ";
    }
    text += "-1,\n";
    flush_if_large(text, out);
  }
  text += "          ]\n";

  if (mesh.has_colours())
  {
    text += "        colorPerVertex TRUE\n        color Color { color [\n";
    for (const Rgb& colour : mesh.colours)
    {
      text += "          ";
      append_triple(text, colour.data());
      text += ",\n";
      flush_if_large(text, out);
    }
    text += "          ]}\n";
  }
  text += "        }\n      }\n    ]\n  }\n";
  out << text;
}

} // namespace frepkit
