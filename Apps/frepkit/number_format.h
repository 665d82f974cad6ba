// Printing doubles so that they round-trip: %.17g, with nan/inf/-inf spelled as the conformance
// files spell them (no "-nan").
#pragma once

#include <string>

namespace frepkit
{

std::string format_double(double value);

} // namespace frepkit
