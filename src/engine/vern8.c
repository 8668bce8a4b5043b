/* Verner's "most efficient" 8(7) pair, RKV87.IIa: an explicit Runge-Kutta
 * method of order 8, 13 stages, with an embedded 7th-order solution for
 * its error estimate, stepped by the controller dop853 uses (adaptive.c:
 * RMS norm, safety 0.9, factors 1/3 to 6, no growth after a rejection).
 * Not FSAL by design, but the derivative at the new state is the next
 * step's first stage: a step costs 13 evaluations (12 stages and that
 * one). Its coefficients (vern8_tableau.h) reach 123 in size; the stages
 * sum them in groups (vern8_body.h, bench/vern_gen.py) so that their
 * rounding to double leaves the order conditions within 5e-15 of true,
 * not 1e-13 (which stalls a run below rtol 5e-12). Each stage is one loop
 * over the whole state (never sliced). */
#include "engine/adaptive.h"
#include "engine/vern8_tableau.h"

#include <math.h>

#include "stepwise/base.h"

/* Workspace slots: k1 and the new state's derivative alternate between
 * slots 0 and V8_KN; k2..k13 in 1..12; the trial state, which the error
 * terms reuse once the stages are done; the old state for a retry. */
enum { V8_KN = 13, V8_YT, V8_SAVED, VERN8_VECTORS };

SW_CLONES static void vern8_range(sw_ode *ode, double t, double *restrict y, double h, int n, unsigned elim,
                                  double atol, double rtol, const double *restrict k1, double *restrict k2,
                                  double *restrict k3, double *restrict k4, double *restrict k5,
                                  double *restrict k6, double *restrict k7, double *restrict k8,
                                  double *restrict k9, double *restrict k10, double *restrict k11,
                                  double *restrict k12, double *restrict k13, double *restrict kn,
                                  double *restrict yt, double *restrict saved, sw_trial_sums *sums)
{
    sw_evaluator f = sw_evaluator_of(ode);
    int i;
#include "engine/vern8_body.h"
    /* The new state in place (the old one saved for a retry), its runaway
     * test, and the error term scaled by sk = atol + rtol·max(|y0|, |y1|)
     * and squared into yt (dead now), added by i mod 4 (adaptive.h). */
    unsigned long long over = 0, add = sw_beyond_add(elim);
    for (i = 0; i < n; i++) {
        double y0 = y[i], y1 = y0 + h * V8_BK, a0 = fabs(y0), a1 = fabs(y1);
        double e = h * V8_EK / (atol + rtol * (a1 > a0 ? a1 : a0));
        saved[i] = y0;
        y[i] = y1;
        over |= sw_beyond_bits(y1, add);
        yt[i] = e * e;
    }
    sums->err = sw_add_by4(sums->part[0], yt, n);
    sums->beyond |= sw_beyond_any(over);
    sw_eval_with(&f, t + h, n, y, kn);
}

static void vern8_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi, unsigned elim,
                        sw_trial_sums *sums)
{
    (void)lo, (void)hi;
    vern8_range(ode, t, y, h, ode->dim, elim, s->atol, s->rtol, SW_WORK(s, s->fsal), SW_WORK(s, 1), SW_WORK(s, 2),
                SW_WORK(s, 3), SW_WORK(s, 4), SW_WORK(s, 5), SW_WORK(s, 6), SW_WORK(s, 7), SW_WORK(s, 8),
                SW_WORK(s, 9), SW_WORK(s, 10), SW_WORK(s, 11), SW_WORK(s, 12), SW_WORK(s, s->fsal ? 0 : V8_KN),
                SW_WORK(s, V8_YT), SW_WORK(s, V8_SAVED), sums);
}

static const sw_adaptive vern8 = {
    .trial = vern8_trial,
    .evals = 13,
    .coupled = 1,
    .fsal_other = V8_KN,
    .saved = V8_SAVED,
    .expo = 1.0 / 8,
    .safety = 0.9,
    .fac_min = 1.0 / 3,
    .fac_max = 6.0,
    .hold = 1,
    .guess_first = 1,
};

/* Keep the table entry's workspace in step with the slots above. */
_Static_assert((int)VERN8_VECTORS == (int)SW_VERN8_VECTORS, "vern8's workspace (stepper.h, integrators.c)");

int sw_step_vern8(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&vern8, s, ode, t, y, h_max);
}
