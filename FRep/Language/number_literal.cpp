#include "Language/detail/number_literal.h"

#include <cmath>

namespace frep
{
namespace
{

bool is_digit(std::string_view text, std::size_t i)
{
  return i < text.size() && text[i] >= '0' && text[i] <= '9';
}

char at(std::string_view text, std::size_t i)
{
  return i < text.size() ? text[i] : '\0';
}

} // namespace

NumberLiteral scan_number_literal(std::string_view text, std::size_t start)
{
  NumberLiteral out;
  std::size_t i = start;
  double value = 0.0;
  bool has_integer_part = false;

  if (at(text, i) != '.')
  {
    has_integer_part = true;
    value = at(text, i) - '0';
    ++i;
    // A leading zero followed by a digit is an error; the original stops right after the 0.
    if (text[start] == '0' && is_digit(text, i))
    {
      out.length = i - start;
      return out;
    }
    while (is_digit(text, i))
    {
      value = value * 10.0 + (text[i] - '0');
      ++i;
    }
  }

  if (at(text, i) == '.')
  {
    ++i;
    if (is_digit(text, i))
    {
      // The original divides by a power of ten grown by repeated multiplication; keep the
      // same order of operations so the sums round identically.
      double scale = 10.0;
      while (is_digit(text, i))
      {
        value = value + (text[i] - '0') / scale;
        scale = scale * 10.0;
        ++i;
      }
    }
    else if (!has_integer_part)
    {
      out.length = i - start; // lone '.'
      return out;
    }
  }

  if (at(text, i) == 'e' || at(text, i) == 'E')
  {
    ++i;
    double exponent = 1.0;
    if (at(text, i) == '-')
    {
      exponent = -1.0;
      ++i;
    }
    else if (at(text, i) == '+')
    {
      ++i;
    }
    if (!is_digit(text, i) || text[i] == '0')
    {
      out.length = i - start;
      return out;
    }
    // The original's bug, reproduced on purpose: the sign multiplies the first digit only and
    // later digits are added (so -12 becomes -1*10+2 = -8).
    exponent = exponent * (text[i] - '0');
    ++i;
    while (is_digit(text, i))
    {
      exponent = exponent * 10.0 + (text[i] - '0');
      ++i;
    }
    value = value * std::exp(exponent * std::log(10.0));
  }

  out.ok = true;
  out.value = value;
  out.length = i - start;
  return out;
}

std::optional<double> number_literal_value(std::string_view literal)
{
  if (literal.empty() || !(is_digit(literal, 0) || literal[0] == '.'))
  {
    return std::nullopt;
  }
  const NumberLiteral scanned = scan_number_literal(literal, 0);
  if (!scanned.ok || scanned.length != literal.size())
  {
    return std::nullopt;
  }
  return scanned.value;
}

int hf_round_size(double d)
{
  const double c = std::ceil(d);
  return static_cast<int>((c - d > 0.5) ? (c - 1) : c);
}

} // namespace frep
