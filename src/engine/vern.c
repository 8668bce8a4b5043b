/* Verner's "most efficient" pairs: RKV87.IIa, an explicit Runge-Kutta
 * method of order 8 in 13 stages with an embedded 7th-order solution
 * (vern8), and RKV98.IIa, order 9 in 16 stages with an embedded 8th
 * (vern9), each stepped by the controller dop853 uses (adaptive.c: RMS
 * norm, safety 0.9, factors 1/3 to 6, no growth after a rejection,
 * Hairer's first step). Neither is FSAL by design, but the derivative at
 * the new state is the next step's first stage: a step costs 13 and 16
 * evaluations. Their trial steps (vern_body.h) are written out by
 * bench/vern_gen.py from vern_tableau.h, each stage one loop over the
 * whole state (never sliced). vern8's coefficients reach 123 in size: its
 * stages sum them in groups, so that their rounding to double leaves the
 * order conditions within 5e-15 of true, not 1e-13 (see the script). */
#include "engine/adaptive.h"
#include "engine/vern_tableau.h"

#include <math.h>

#include "stepwise/base.h"

#include "engine/vern_body.h"

/* A pair of S stages, its range function T_range over the work slots:
 * k1 and the new state's derivative alternate between slots 0 and S;
 * k2..kS in 1..S-1; then the trial state (which the error terms reuse once
 * the stages are done) and the old state for a retry: S + 3 vectors. */
#define VERN(name, T, range, S, Q)                                                                              \
    static void name##_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,          \
                             unsigned elim, sw_trial_sums *sums)                                                 \
    {                                                                                                            \
        double *k[S + 1];                                                                                        \
        (void)lo, (void)hi;                                                                                      \
        for (int j = 1; j < S; j++)                                                                              \
            k[j] = SW_WORK(s, j);                                                                                \
        k[0] = SW_WORK(s, s->fsal);                                                                              \
        k[S] = SW_WORK(s, s->fsal ? 0 : S);                                                                      \
        range(ode, t, y, h, ode->dim, elim, s->atol, s->rtol, T##_KS(k), SW_WORK(s, S + 1), SW_WORK(s, S + 2),   \
              sums);                                                                                             \
    }                                                                                                            \
    static const sw_adaptive name = { .trial = name##_trial, .evals = S, .coupled = 1, .fsal_other = S,          \
                                      .saved = S + 2, .expo = 1.0 / (Q + 1), .safety = 0.9,                     \
                                      .fac_min = 1.0 / 3, .fac_max = 6.0, .hold = 1, .guess_first = 1 };        \
    _Static_assert(S + 3 == SW_##T##_VECTORS, #name "'s workspace (stepper.h, integrators.c)");

VERN(vern8, V8, v8_range, 13, 7)
VERN(vern9, V9, v9_range, 16, 8)

int sw_step_vern8(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&vern8, s, ode, t, y, h_max);
}

int sw_step_vern9(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&vern9, s, ode, t, y, h_max);
}
