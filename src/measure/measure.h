/* What a method does, measured rather than claimed: its order of accuracy
 * and its stability limit on the undamped spring, where the exact solution
 * and the theory (x'' = -ω²x) are known. Used to put a plugin's measured
 * figures beside the ones it claims (check, try). */
#ifndef SW_MEASURE_MEASURE_H
#define SW_MEASURE_MEASURE_H

#include <stddef.h>

#include "stepwise/sim.h"

/* The measuring problem: spring with c = 0 (k 10, m 1: ω = √10), to t = 2. */
#define SW_MEASURE_T 2.0

/* Order: errors at t = SW_MEASURE_T against the exact solution for dt =
 * 0.02, 0.01, 0.005, 0.0025; *order is the slope of log error against
 * log dt, fitted by least squares over the steps whose error is above
 * round-off (1e-11). 0, or SW_EINVAL when a run blew up or failed (err says
 * why) or every error is at round-off. */
int sw_measure_order(const sw_integrator *m, double *order, char *err, size_t errlen);

/* Stability limit ω·dt on the same spring, from sw_stability_find. *kind
 * is its sw_stab_kind. 0, or a status with err filled. */
int sw_measure_stability(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                         size_t errlen);

#endif
