#include "Eval/detail/batch_scalar_lanes.h"

#include "Semantics/detail/op_semantics.h"

namespace frep::eval
{

namespace hf = frep::semantics;

void hf_pow_lanes(double* out, const double* base, const double* exponent, int n)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = hf::hf_pow(base[i], exponent[i]);
  }
}

void hf_pow_int_lanes(double* out, const double* base, int exponent, int n)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = hf::hf_pow_int(base[i], exponent);
  }
}

void hf_mod_lanes(double* out, const double* a, const double* b, int n)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = hf::hf_mod(a[i], b[i]);
  }
}

void hf_round_lanes(double* out, const double* a, int n)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = static_cast<double>(hf::hf_round(a[i]));
  }
}

} // namespace frep::eval
