/* What a method does, measured rather than claimed: its order of accuracy
 * and its stability limit on the undamped spring, where the exact solution
 * and the theory (x'' = -ω²x) are known. Used to put a plugin's measured
 * figures beside the ones it claims (check, try). */
#ifndef SW_MEASURE_MEASURE_H
#define SW_MEASURE_MEASURE_H

#include <stddef.h>

#include "measure/bench.h"
#include "stepwise/sim.h"

/* The measuring problem: spring with c = 0 (k 10, m 1: ω = √10), to t = 2. */
#define SW_MEASURE_T 2.0
/* The sweep: from ω·dt = 0.51 (where an eighth-order error is still well
 * above round-off) down to dt = 0.16/2^11 = 7.8e-5 (where a first-order
 * one is below 1e-2 of the state for three halvings); stopped once four
 * points carry an order. */
#define SW_MEASURE_DT0 0.16
#define SW_MEASURE_POINTS 12
#define SW_MEASURE_SETTLED 4
#define SW_MEASURE_DIM 16 /* room for the spring's state (position and velocity in the plane: 4) */

/* Order: the largest error against the exact solution over the sample
 * times to SW_MEASURE_T (sw_truth_sample_time) for dt = SW_MEASURE_DT0
 * halved up to SW_MEASURE_POINTS - 1 times, until SW_MEASURE_SETTLED
 * points carry an order or the error reaches round-off; *order is the
 * order rule's (sw_bench_order_rule). *fit (NULL: not wanted) gets the
 * points and the fit. 0, or SW_EINVAL with err saying why: a run failed,
 * the plugin failed, or "no order: " and the rule's reason. */
int sw_measure_order(const sw_integrator *m, double *order, sw_bench_series *fit, char *err, size_t errlen);

/* Stability limit ω·dt on the same spring, from sw_stability_find. *kind
 * is its sw_stab_kind. 0, or a status with err filled. */
int sw_measure_stability(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                         size_t errlen);
/* The same for a built-in method measured as a plugin is: without
 * SW_SYMPLECTIC, which a plugin never has and which makes the stability
 * watch laxer (sim/watch.c), so that a plugin and its method compare like
 * for like (an honest symplectic Euler: 1.61 both, where the flag gives
 * the method 1.91). */
int sw_measure_stability_as_plugin(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                                   size_t errlen);

#endif
