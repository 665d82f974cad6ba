#include "diagnostic.h"

namespace frep
{

std::string Diagnostic::format() const
{
  std::string out = file.empty() ? std::string("<input>") : file;
  if (location.valid())
  {
    out += ':' + std::to_string(location.line) + ':' + std::to_string(location.column);
  }
  out += ": error: ";
  out += message;
  return out;
}

std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics)
{
  std::string out;
  for (const Diagnostic& d : diagnostics)
  {
    out += d.format();
    out += '\n';
  }
  return out;
}

} // namespace frep
