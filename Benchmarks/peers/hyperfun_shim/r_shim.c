/* The R functions the original HyperFun sources call, for a build without R (see R.h), and a
 * hfR() that refuses: it calls back into an R session, which a benchmark has not got. */
#include "R.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void error(const char* format, ...)
{
  va_list args;
  va_start(args, format);
  fputs("hyperfun: error: ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
  va_end(args);
  exit(3);
}

void REprintf(const char* format, ...)
{
  va_list args;
  va_start(args, format);
  vfprintf(stderr, format, args);
  va_end(args);
}

double hfR(double* f_a, void* str_param)
{
  (void)f_a;
  (void)str_param;
  error("hfR calls R, which this build has not got");
  return 0.0;
}

void GetRNGstate(void) {}
void PutRNGstate(void) {}
double unif_rand(void)
{
  return rand() / (RAND_MAX + 1.0);
}
