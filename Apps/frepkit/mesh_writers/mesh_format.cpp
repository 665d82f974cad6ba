#include "mesh_format.h"

#include "obj_writer.h"
#include "ply_writer.h"
#include "pov_writer.h"
#include "stl_writer.h"
#include "user_error.h"
#include "vrml_writer.h"
#include "vtp_writer.h"

#include <algorithm>
#include <cctype>

namespace frepkit
{
namespace
{

struct FormatEntry
{
  const char* extension;
  MeshFormat format;
};

constexpr FormatEntry kFormats[] = {
  { ".stl", MeshFormat::Stl },
  { ".obj", MeshFormat::Obj },
  { ".ply", MeshFormat::Ply },
  { ".wrl", MeshFormat::Vrml },
  { ".pov", MeshFormat::Pov },
  { ".vtp", MeshFormat::Vtp },
};

} // namespace

std::string lower_extension(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return {};
  }
  std::string extension = path.substr(dot);
  std::transform(extension.begin(),
    extension.end(),
    extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

std::optional<MeshFormat> mesh_format_for(const std::string& path)
{
  const std::string extension = lower_extension(path);
  for (const FormatEntry& entry : kFormats)
  {
    if (extension == entry.extension)
    {
      return entry.format;
    }
  }
  return std::nullopt;
}

std::string mesh_format_list()
{
  return ".stl (binary STL; ASCII with --ascii), .obj (Wavefront), .ply (binary PLY), "
         ".wrl (VRML 2.0), .pov (POV-Ray mesh2), .vtp (VTK XML PolyData)";
}

bool mesh_format_available(MeshFormat format)
{
#ifdef FREPKIT_HAVE_VTK
  (void)format;
  return true;
#else
  return format != MeshFormat::Vtp;
#endif
}

MeshFormat require_mesh_format(const std::string& path)
{
  const std::optional<MeshFormat> format = mesh_format_for(path);
  if (!format)
  {
    const std::string extension = lower_extension(path);
    throw UserError(path + ": unknown mesh format " +
                    (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
                    "; the output's extension chooses the format: " + mesh_format_list());
  }
  if (!mesh_format_available(*format))
  {
    throw UserError(path + ": .vtp (VTK XML) is not available in this build "
                           "(built with FREPKIT_ENABLE_VTK off)");
  }
  return *format;
}

void write_mesh(const MeshDocument& mesh, MeshFormat format, bool ascii, std::ostream& out)
{
  switch (format)
  {
    case MeshFormat::Stl:
      ascii ? write_stl_ascii(mesh, out) : write_stl_binary(mesh, out);
      return;
    case MeshFormat::Obj:
      write_obj(mesh, out);
      return;
    case MeshFormat::Ply:
      write_ply(mesh, out);
      return;
    case MeshFormat::Vrml:
      write_vrml(mesh, out);
      return;
    case MeshFormat::Pov:
      write_pov(mesh, out);
      return;
    case MeshFormat::Vtp:
      write_vtp(mesh, out);
      return;
  }
}

} // namespace frepkit
