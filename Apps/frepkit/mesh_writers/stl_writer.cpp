#include "stl_writer.h"

#include "binary_output.h"
#include "text_numbers.h"
#include "triangle_geometry.h"

#include <algorithm>
#include <string>

namespace frepkit
{

void write_stl_binary(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  // The 80-byte header must not start with "solid" (readers would take the file for ASCII).
  std::string header = "frepkit binary STL: " + mesh.name;
  header.resize(80, '\0');
  LittleEndianBuffer buffer(out);
  buffer.bytes(header.data(), 80);
  buffer.u32(static_cast<std::uint32_t>(surface.cell_count()));
  for (std::size_t t = 0; t < surface.cell_count(); ++t)
  {
    for (double component : facet_normal(surface, t))
    {
      buffer.f32(static_cast<float>(component));
    }
    for (int corner = 0; corner < 3; ++corner)
    {
      for (double component : triangle_corner(surface, t, corner))
      {
        buffer.f32(static_cast<float>(component));
      }
    }
    buffer.u16(0); // attribute byte count
  }
  buffer.flush();
}

void write_stl_ascii(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  // The solid name is one word in most readers.
  std::string name = mesh.name;
  std::replace_if(
    name.begin(),
    name.end(),
    [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; },
    '_');
  std::string text = "solid " + name + "\n";
  for (std::size_t t = 0; t < surface.cell_count(); ++t)
  {
    text += " facet normal";
    for (double component : facet_normal(surface, t))
    {
      text += ' ';
      append_number(text, static_cast<float>(component));
    }
    text += "\n  outer loop\n";
    for (int corner = 0; corner < 3; ++corner)
    {
      text += "   vertex";
      for (double component : triangle_corner(surface, t, corner))
      {
        text += ' ';
        append_number(text, static_cast<float>(component));
      }
      text += '\n';
    }
    text += "  endloop\n endfacet\n";
    flush_if_large(text, out);
  }
  text += "endsolid " + name + "\n";
  out << text;
}

} // namespace frepkit
