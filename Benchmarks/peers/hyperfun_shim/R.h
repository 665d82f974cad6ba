/* Stand-in for R's <R.h> so the original HyperFun sources (pmur002/hyperfun src/, an R package)
 * build without R: only what those sources call. Ours, not R's. */
#ifndef FREPKIT_PEERS_R_SHIM_H
#define FREPKIT_PEERS_R_SHIM_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* R's error(): print and stop the program (the benchmark drivers have no R session to return to). */
void error(const char* format, ...);
#define Rprintf printf
void REprintf(const char* format, ...);

/* R's random numbers (hfA_noisep, hfA_turbulence: attribute noise, not used by the workloads):
 * C's rand() here, so those attributes differ from an R session's. */
void GetRNGstate(void);
void PutRNGstate(void);
double unif_rand(void);

typedef void* SEXP; /* only named in declarations the drivers never call */

#ifdef __cplusplus
}
#endif

#endif
