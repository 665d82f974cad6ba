/* An example FRepKit user library (frepkit_user.h): two primitives written in C that HyperFun
 * programs call by name once the library is loaded (frepkit --library libfrepkit_example_shapes.so).
 *
 *   ring(x, R, r)   a torus around the z axis, F = r^2 - (sqrt(x^2 + y^2) - R)^2 - z^2 (>= 0
 *                   inside), with an interval form (so meshing culls) and an exact gradient;
 *   waves(x, k)     sin(k x) + sin(k y) + sin(k z), point form only (the enclosure is then the
 *                   whole line); it fails (a run-time error of that point) when k is 0. */
#include "Language/frepkit_user.h"

#include <math.h>

static double sq(double v) { return v * v; }

static int ring_point(void* user, const double* args, const int* sizes, int argc, double* value)
{
  (void)user;
  (void)sizes;
  (void)argc;
  /* args: x1 x2 x3 R r */
  const double q = sqrt(sq(args[0]) + sq(args[1])) - args[3];
  *value = sq(args[4]) - sq(q) - sq(args[2]);
  return 0;
}

/* Bounds of v^2 for v in [lo, hi]. */
static void square_bounds(double lo, double hi, double* out_lo, double* out_hi)
{
  const double a = lo * lo;
  const double b = hi * hi;
  *out_hi = a > b ? a : b;
  *out_lo = (lo <= 0 && hi >= 0) ? 0 : (a < b ? a : b);
}

static int ring_interval(void* user, const double* lo, const double* hi, const int* sizes,
  int argc, double* value_lo, double* value_hi, int* may_fail)
{
  (void)user;
  (void)sizes;
  (void)argc;
  double x_lo, x_hi, y_lo, y_hi, z_lo, z_hi, r_lo, r_hi;
  square_bounds(lo[0], hi[0], &x_lo, &x_hi);
  square_bounds(lo[1], hi[1], &y_lo, &y_hi);
  square_bounds(lo[2], hi[2], &z_lo, &z_hi);
  square_bounds(lo[4], hi[4], &r_lo, &r_hi);
  /* q = rho - R with rho in [sqrt(x_lo + y_lo), sqrt(x_hi + y_hi)] */
  const double q_lo = sqrt(x_lo + y_lo) - hi[3];
  const double q_hi = sqrt(x_hi + y_hi) - lo[3];
  double q2_lo, q2_hi;
  square_bounds(q_lo, q_hi, &q2_lo, &q2_hi);
  /* Rounding: widen by a relative margin far above the few ulps of these operations. */
  const double lo_v = r_lo - q2_hi - z_hi;
  const double hi_v = r_hi - q2_lo - z_lo;
  *value_lo = lo_v - 1e-12 * (fabs(lo_v) + 1);
  *value_hi = hi_v + 1e-12 * (fabs(hi_v) + 1);
  *may_fail = 0;
  return 0;
}

static int ring_gradient(void* user, const double* args, const int* sizes, int argc,
  double* value, double* gradient)
{
  ring_point(user, args, sizes, argc, value);
  const double rho = sqrt(sq(args[0]) + sq(args[1]));
  const double q = rho - args[3];
  const double s = rho > 0 ? -2 * q / rho : 0;
  gradient[0] = s * args[0];
  gradient[1] = s * args[1];
  gradient[2] = -2 * args[2];
  gradient[3] = 2 * q;
  gradient[4] = 2 * args[4];
  return 0;
}

static int waves_point(void* user, const double* args, const int* sizes, int argc, double* value)
{
  (void)user;
  (void)sizes;
  (void)argc;
  const double k = args[3];
  if (k == 0)
  {
    return 1; /* a run-time error of this point */
  }
  *value = sin(k * args[0]) + sin(k * args[1]) + sin(k * args[2]);
  return 0;
}

int frepkit_user_register(const frepkit_user_api* api)
{
  if (api->abi_version != FREPKIT_USER_ABI_VERSION)
  {
    return 1;
  }
  static const int ring_kinds[3] = { FREPKIT_ARG_ARRAY, FREPKIT_ARG_REAL, FREPKIT_ARG_REAL };
  static const int ring_sizes[3] = { 3, 0, 0 };
  const frepkit_user_function ring = { "ring", 3, ring_kinds, ring_sizes, ring_point,
    ring_interval, ring_gradient, 0 };
  static const int waves_kinds[2] = { FREPKIT_ARG_ARRAY, FREPKIT_ARG_REAL };
  static const int waves_sizes[2] = { 3, 0 };
  const frepkit_user_function waves = { "waves", 2, waves_kinds, waves_sizes, waves_point, 0, 0,
    0 };
  if (api->add(api->context, &ring) != 0 || api->add(api->context, &waves) != 0)
  {
    return 1;
  }
  return 0;
}
