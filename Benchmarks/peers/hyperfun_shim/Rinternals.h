/* Stand-in for R's <Rinternals.h>: see R.h next to it. */
#include "R.h"
