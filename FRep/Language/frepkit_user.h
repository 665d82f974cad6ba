/* FRepKit user libraries: the C ABI a shared library implements to add its own functions to
 * HyperFun programs (frepkit --library libmyshapes.so). Plain C, no FRepKit header needed.
 *
 * The library exports one function, frepkit_user_register (FREPKIT_USER_ENTRY), which FRepKit
 * calls once after loading it. It calls api->add once per function. Every callback must be safe
 * to call from several threads at once; `user` is passed back unchanged. A callback returns 0 on
 * success and anything else when the point fails (a run-time error of that point).
 *
 * Arguments reach the callbacks flattened: a real is one double, an array its items, in the
 * order of `kinds` (sizes of arrays are given in `sizes`, one per argument, 1 for reals).
 * Example: Examples/user-library/shapes.c. */
#ifndef FREPKIT_USER_H
#define FREPKIT_USER_H

#ifdef __cplusplus
extern "C" {
#endif

#define FREPKIT_USER_ABI_VERSION 1
#define FREPKIT_USER_ENTRY "frepkit_user_register"

/* Argument kinds: kinds[i] of frepkit_user_function. */
#define FREPKIT_ARG_REAL 0
#define FREPKIT_ARG_ARRAY 1

/* value = f(args) */
typedef int (*frepkit_point_fn)(void* user, const double* args, const int* sizes, int argc,
  double* value);
/* An enclosure of f over a box: lo[i] <= args[i] <= hi[i]. Set *may_fail when a point of the
 * box may fail. Optional (NULL: the whole line). */
typedef int (*frepkit_interval_fn)(void* user, const double* lo, const double* hi,
  const int* sizes, int argc, double* value_lo, double* value_hi, int* may_fail);
/* value and d value / d args[i] for every flattened item i. Optional (NULL: differences). */
typedef int (*frepkit_gradient_fn)(void* user, const double* args, const int* sizes, int argc,
  double* value, double* gradient);

typedef struct frepkit_user_function
{
  const char* name;         /* letters, digits, '_'; not a library function's name */
  int argc;                 /* 0..10 */
  const int* kinds;         /* argc entries: FREPKIT_ARG_REAL or FREPKIT_ARG_ARRAY */
  const int* array_sizes;   /* argc entries (0: any size) or NULL */
  frepkit_point_fn point;   /* required */
  frepkit_interval_fn interval; /* optional */
  frepkit_gradient_fn gradient; /* optional */
  void* user;
} frepkit_user_function;

typedef struct frepkit_user_api
{
  int abi_version; /* FREPKIT_USER_ABI_VERSION */
  void* context;   /* FRepKit's: pass it back to add */
  /* Registers one function (the struct is copied; name and arrays are copied too). Returns 0,
   * or nonzero when refused (FRepKit reports why, naming the library and the function). */
  int (*add)(void* context, const frepkit_user_function* function);
} frepkit_user_api;

/* The entry point: return 0 on success. */
typedef int (*frepkit_user_register_fn)(const frepkit_user_api* api);

#ifdef __cplusplus
}
#endif

#endif
