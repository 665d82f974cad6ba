// Lane loops of the batch kernel that must NOT be compiled with its vectorisation flags: they
// convert doubles to int (HF_round), where -fno-trapping-math lets GCC turn (double)(int)x into
// trunc(x), which keeps a -0 the original turns into +0. Compiled with the project's normal
// flags, one call per instruction and block; they are scalar loops anyway.
#pragma once

namespace frep::eval
{

void hf_pow_lanes(double* out, const double* base, const double* exponent, int n);
void hf_pow_int_lanes(double* out, const double* base, int exponent, int n);
void hf_mod_lanes(double* out, const double* a, const double* b, int n);
void hf_round_lanes(double* out, const double* a, int n);

} // namespace frep::eval
