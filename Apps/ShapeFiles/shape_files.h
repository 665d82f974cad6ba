// A shape file as a function a model calls by name: the `name=FILE[:ISO]` of the applications'
// --shape option. FILE is a closed triangle mesh (.stl, .obj, .ply, .vtp: signed distance, >= 0
// inside; minus the unsigned distance when asked) or a volume (.vti: its scalars minus ISO).
// Shared by frepkit and FRepStudio so that both read the same files with the same messages.
#pragma once

#include "Language/user_functions.h"

#include <string>
#include <vector>

namespace frepkit
{

/// Registers the shape `spec` (name=FILE[:ISO]) in `registry` as the function name(x). Returns
/// an empty string on success, otherwise the message, which starts with the name (or the spec
/// when it has none): "bunny: bunny.stl: the mesh has 12 open edges ...". Callers prefix the
/// option ("--shape ").
std::string add_shape_file(
  const std::string& spec, bool unsigned_distance, frep::UserFunctionRegistry& registry);

/// Loads the user libraries (frepkit_user.h) and then the shape files into `registry`: the
/// --library and --shape options of both programs. Empty on success, else the first failure's
/// message (the library and the function, or "--shape " and what add_shape_file says).
std::string add_user_inputs(const std::vector<std::string>& libraries,
  const std::vector<std::string>& shapes, bool unsigned_distance,
  frep::UserFunctionRegistry& registry);

/// What a model's values depend on besides its own text, as one string: each library's and shape
/// file's name and contents, and the unsigned-distance choice. An export's frames are kept from
/// an earlier run only when this is the same (frep::mapping::ProductionInputs::model_key), so a
/// changed mesh or library renders them again.
std::string user_inputs_key(const std::vector<std::string>& libraries,
  const std::vector<std::string>& shapes, bool unsigned_distance);

} // namespace frepkit
