/* Broken user libraries for the loader's tests, one per way of failing, chosen at build time
 * by BAD_KIND: 1 a bad arity, 2 a name registered twice, 3 a library function's name, 4 the
 * entry point fails, 5 no entry point at all. */
#include "Language/frepkit_user.h"

#if BAD_KIND <= 3
static int one(void* user, const double* args, const int* sizes, int argc, double* value)
{
  (void)user;
  (void)args;
  (void)sizes;
  (void)argc;
  *value = 1;
  return 0;
}
#endif

#if BAD_KIND != 5
int frepkit_user_register(const frepkit_user_api* api)
{
  static const int kinds[1] = { FREPKIT_ARG_REAL };
#if BAD_KIND == 1
  const frepkit_user_function f = { "wide", 11, kinds, 0, one, 0, 0, 0 };
  return api->add(api->context, &f);
#elif BAD_KIND == 2
  const frepkit_user_function f = { "twin", 1, kinds, 0, one, 0, 0, 0 };
  api->add(api->context, &f);
  return api->add(api->context, &f);
#elif BAD_KIND == 3
  const frepkit_user_function f = { "hfSphere", 1, kinds, 0, one, 0, 0, 0 };
  return api->add(api->context, &f);
#else
  (void)api;
  (void)kinds;
  return 7;
#endif
}
#else
int not_the_entry(void) { return 0; }
#endif
