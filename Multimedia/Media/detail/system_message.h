// The text of an errno value, for the media writers' messages. Private to Media.
#pragma once

#include <string>
#include <system_error>

namespace frep::media::detail
{

/// strerror's text, thread-safe (strerror is not).
inline std::string system_message(int error_number)
{
  return std::generic_category().message(error_number);
}

} // namespace frep::media::detail
