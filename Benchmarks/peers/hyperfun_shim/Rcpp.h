// Stand-in for Rcpp.h so the original hfp sources build without R: Rcpp::Rcout is std::cout and
// Rcpp::stop(format, args...) throws std::runtime_error with the printf-style message.
#pragma once

#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace Rcpp
{

inline std::ostream& Rcout = std::cout;

namespace detail
{
inline void format_into(std::ostringstream& out, const char* f)
{
  out << f;
}

template <typename T, typename... Rest>
void format_into(std::ostringstream& out, const char* f, const T& value, const Rest&... rest)
{
  for (; *f; ++f)
  {
    if (f[0] == '%' && f[1] == '%')
    {
      out << '%';
      ++f;
    }
    else if (f[0] == '%')
    {
      ++f;
      while (*f && std::string("sdifgeulxc").find(*f) == std::string::npos)
      {
        ++f; // flags, width, precision
      }
      out << value;
      format_into(out, *f ? f + 1 : f, rest...);
      return;
    }
    else
    {
      out << *f;
    }
  }
}
} // namespace detail

template <typename... Args>
[[noreturn]] void stop(const char* format, const Args&... args)
{
  std::ostringstream out;
  detail::format_into(out, format, args...);
  throw std::runtime_error(out.str());
}

} // namespace Rcpp
