// What a model may call besides the library, given as on frepkit's command line: user libraries
// (--library FILE, frepkit_user.h) and shape files (--shape name=FILE[:ISO], a mesh or a volume
// as the function name(x); --unsigned-distance accepts open meshes). The window loads them into
// its registry and hands them, as absolute paths, to the animation export (whose frames are
// kept from an earlier export only while these files are unchanged).
#pragma once

#include <QStringList>

namespace frepstudio
{

struct UserInputs
{
  QStringList libraries;         ///< shared objects implementing frepkit_user.h
  QStringList shapes;            ///< name=FILE[:ISO] (.stl, .obj, .ply, .vtp, .vti)
  bool unsignedDistance = false; ///< open or non-manifold meshes: minus the unsigned distance
};

/// The same inputs with every file absolute (a volume's ":ISO" suffix kept).
UserInputs absoluteUserInputs(const UserInputs& inputs);

} // namespace frepstudio
