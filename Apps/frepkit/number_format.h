// Printing doubles so that they round-trip: %.17g, with nan/inf/-inf spelled as the conformance
// files spell them (no "-nan").
#pragma once

#include <string>

namespace frepkit
{

std::string format_double(double value);

/// The shortest text that reads back to the same double (for messages and reports).
std::string format_short(double value);

} // namespace frepkit
