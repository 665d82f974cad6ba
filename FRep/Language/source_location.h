// A position in HyperFun source text, as the original reports it.
#pragma once

namespace frep
{

/// 1-based line (counting LF characters) and 1-based byte column (TAB and CR count as one).
/// A default-constructed location (0, 0) means "no position".
struct SourceLocation
{
  int line = 0;
  int column = 0;

  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
  bool valid() const { return line > 0; }
};

} // namespace frep
