// HyperFun number literals, scanned and valued exactly as the original scanner does
// (int_scanner.c), including its deviations from correctly rounded conversion.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace frep
{

struct NumberLiteral
{
  bool ok = false;        ///< false: the original rejects the literal (illegal token)
  double value = 0;       ///< valid when ok
  std::size_t length = 0; ///< bytes consumed (at least 1; on error, where the original stopped)
};

/// Scans the literal starting at text[start], which must be a digit or '.'.
/// Grammar: digits ['.' [digits]] [(e|E) [+|-] digits] | '.' digits [...].
/// The value is computed like the original: integer part v*10+d, fraction v + d/10^k with 10^k
/// built by repeated *10, exponent applied as v*exp(e*log(10)), where the exponent e is read
/// as sign*first_digit and then e*10+d for the following digits (so 1e-12 is 1e-8).
/// Rejected: a leading 0 followed by a digit, an exponent starting with 0, a missing exponent,
/// a lone '.'.
NumberLiteral scan_number_literal(std::string_view text, std::size_t start);

/// Convenience for tests: the value of a whole literal, or nullopt when it is rejected or does
/// not span the whole text.
std::optional<double> number_literal_value(std::string_view literal);

/// The original's HF_round (round half up via ceil) for values already known to be in int range.
int hf_round_size(double d);

} // namespace frep
