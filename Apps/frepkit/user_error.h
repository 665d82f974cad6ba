// An error caused by the user's input (bad file, bad option value, bad points): reported as one
// message and exit code 1. Anything else that escapes a command is an internal error (exit 2).
#pragma once

#include <stdexcept>
#include <string>

namespace frepkit
{

class UserError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace frepkit
