// Numbers in text mesh formats: the shortest text that reads back to the same double or float
// (std::to_chars), so files are exact and no longer than they need to be.
#pragma once

#include <charconv>
#include <ostream>
#include <string>

namespace frepkit
{

inline void append_number(std::string& out, double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

inline void append_number(std::string& out, float value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

inline void append_number(std::string& out, unsigned long long value)
{
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

/// Text is built in a buffer and handed to the stream in large pieces.
constexpr std::size_t kTextFlushBytes = 1 << 20;

inline void flush_if_large(std::string& text, std::ostream& out)
{
  if (text.size() > kTextFlushBytes)
  {
    out << text;
    text.clear();
  }
}

} // namespace frepkit
