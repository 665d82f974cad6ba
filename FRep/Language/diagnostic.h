// Diagnostics: parse errors (many per file) and run-time errors (one per evaluated point).
#pragma once

#include "source_location.h"

#include <string>
#include <vector>

namespace frep
{

struct Diagnostic
{
  std::string file;        ///< file name as given by the user ("<string>" for in-memory text)
  SourceLocation location; ///< where the problem was found
  std::string message;     ///< what was expected and what was found

  /// "file:line:col: error: message" (the form compilers and editors understand).
  std::string format() const;
};

/// Formats every diagnostic on its own line.
std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics);

} // namespace frep
