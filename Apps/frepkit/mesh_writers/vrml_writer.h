// VRML 2.0 (.wrl) in the layout of hfp -wrl: a Viewpoint, a Transform named after the object with
// one Shape (Material diffuseColor = the face colour), an IndexedFaceSet with per-point normals
// (normalPerVertex TRUE) and, when the mesh has colours, per-point colours (colorPerVertex TRUE).
// Differences from hfp: a Viewpoint that sees the box (hfp's fieldOfView was 0), no duplicated
// normalIndex (VRML then uses coordIndex), colours clamped to [0, 1].
#pragma once

#include "mesh_document.h"

#include <ostream>

namespace frepkit
{

void write_vrml(const MeshDocument& mesh, std::ostream& out);

/// `name` made a valid VRML identifier (for DEF).
std::string vrml_identifier(const std::string& name);

} // namespace frepkit
