// Loading user libraries: a shared library that implements frepkit_user.h adds its functions to
// a registry. Errors come back as values naming the library and the function; nothing here
// throws or exits.
#pragma once

#include "user_functions.h"

#include <string>
#include <vector>

namespace frep
{

struct UserLibraryResult
{
  /// Empty on success; else e.g. "user library libshapes.so: function 'ring': ...".
  std::string error;
  /// Names of the functions added.
  std::vector<std::string> added;
  bool ok() const { return error.empty(); }
};

/// Loads `path` (dlopen) and registers its functions in `registry`. On any error nothing is
/// added. The library stays loaded while any registry copy holds one of its functions.
UserLibraryResult load_user_library(const std::string& path, UserFunctionRegistry& registry);

} // namespace frep
