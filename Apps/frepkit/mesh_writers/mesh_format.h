// The mesh formats by file extension, and writing a mesh to a file through AtomicOutput (a
// temporary name renamed when complete: a failure leaves nothing behind).
#pragma once

#include "mesh_document.h"

#include <optional>
#include <string>

namespace frepkit
{

enum class MeshFormat
{
  Stl, ///< binary, or ASCII with --ascii
  Obj,
  Ply,
  Vrml, ///< .wrl
  Pov,  ///< POV-Ray mesh2 scene
  Vtp   ///< VTK XML PolyData (VTK builds only)
};

/// The extension of the file name in `path`, lower-case, with its dot (".stl"), or "".
std::string lower_extension(const std::string& path);

/// The format for `path`'s extension (case-insensitive), or nullopt.
std::optional<MeshFormat> mesh_format_for(const std::string& path);

/// ".stl, .obj, .ply, .wrl, .pov, .vtp" (for error messages and help)
std::string mesh_format_list();

/// The format from the extension; throws UserError for an unknown extension (listing the formats)
/// or a format this build cannot write. Called before any work is done.
MeshFormat require_mesh_format(const std::string& path);

/// Whether this build can write the format (.vtp needs VTK).
bool mesh_format_available(MeshFormat format);

/// Writes `mesh` to the stream in `format` (`ascii` selects ASCII STL).
void write_mesh(const MeshDocument& mesh, MeshFormat format, bool ascii, std::ostream& out);

} // namespace frepkit
