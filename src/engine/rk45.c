/* Dormand–Prince 5(4): the adaptive explicit method with an embedded
 * fourth-order error estimate, FSAL, and rtol/atol step control. Each stage
 * is one loop over the state (over L1-sized slices on pointwise systems);
 * nothing is copied on an accepted step. The arithmetic, and so every
 * result, is that of a plain whole-state implementation: its lecture form,
 * sw_ref_rk45 in reference_adaptive.c (read it first). */
#include "engine/adaptive.h"
#include "engine/rk45_tableau.h"

#include <math.h>

#include "stepwise/base.h"

/* Slots: k1 and k7 alternate between 0 and 6 (FSAL). */
enum { S_K2 = 1, S_K3, S_K4, S_K5, S_K6, S_K7, S_YT, S_SAVED, RK45_VECTORS };

/* The stages over len components, every vector a restrict parameter (so the stage
 * loops vectorise without overlap checks). Error norm: RMS of
 * h·e_i / (atol + rtol·max(|y0_i|, |y1_i|)). */
SW_INLINE void rk45_body(sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim, double atol,
                         double rtol, const double *restrict k1, double *restrict k2, double *restrict k3,
                         double *restrict k4, double *restrict k5, double *restrict k6, double *restrict k7,
                         double *restrict yt, double *restrict saved, sw_trial_sums *sums)
{
    int i;
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A21 * k1[i]);
    sw_eval_slice(ode, t + C2 * h, len, yt, k2);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i]);
    sw_eval_slice(ode, t + C3 * h, len, yt, k3);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
    sw_eval_slice(ode, t + C4 * h, len, yt, k4);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
    sw_eval_slice(ode, t + C5 * h, len, yt, k5);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
    sw_eval_slice(ode, t + h, len, yt, k6);
    unsigned long long over = 0, add = sw_beyond_add(elim);
    for (i = 0; i < len; i++) {
        double y0 = y[i], y1 = y0 + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i]);
        saved[i] = y0;
        y[i] = y1;
        over |= sw_beyond_bits(y1, add);
    }
    sw_eval_slice(ode, t + h, len, y, k7);
    double sum = sums->err; /* one chain in increasing i: the sum of a whole-state pass */
    for (i = 0; i < len; i++) {
        double e = E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i];
        double a0 = fabs(saved[i]), a1 = fabs(y[i]);
        double q = h * e / (atol + rtol * (a1 > a0 ? a1 : a0));
        sum += q * q;
    }
    sums->err = sum;
    sums->beyond |= sw_beyond_any(over);
}

/* Two entries to the body: any len, and len = 4 (one particle: each loop a
 * vector or two, no loop control). */
#define RK45_ARGS                                                                                  \
    sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim, double atol, double rtol, \
        const double *restrict k1, double *restrict k2, double *restrict k3, double *restrict k4,           \
        double *restrict k5, double *restrict k6, double *restrict k7, double *restrict yt,                 \
        double *restrict saved, sw_trial_sums *sums
#define RK45_PASS(len) ode, t, y, h, len, elim, atol, rtol, k1, k2, k3, k4, k5, k6, k7, yt, saved, sums

typedef void rk45_range_fn(RK45_ARGS);

SW_CLONES static void rk45_range(RK45_ARGS) { rk45_body(RK45_PASS(len)); }

/* Not cloned, as dop853_range4 (dop853.c) says why. */
static void rk45_range4(RK45_ARGS)
{
    (void)len;
    rk45_body(RK45_PASS(4));
}

/* The FSAL pair and the saved state are state-long (they outlive a slice);
 * the other stage vectors are slice-local. */
static void rk45_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                       unsigned elim, sw_trial_sums *sums)
{
    rk45_range_fn *range = hi - lo == 4 ? rk45_range4 : rk45_range;
    range(ode, t, y + lo, h, hi - lo, elim, s->atol, s->rtol, SW_WORK(s, s->fsal) + lo, SW_WORK(s, S_K2),
               SW_WORK(s, S_K3), SW_WORK(s, S_K4), SW_WORK(s, S_K5), SW_WORK(s, S_K6),
               SW_WORK(s, s->fsal ? 0 : S_K7) + lo, SW_WORK(s, S_YT), SW_WORK(s, S_SAVED) + lo, sums);
}

static const sw_adaptive rk45 = {
    .trial = rk45_trial,
    .evals = 6,
    .slice = 256,
    .fsal_other = S_K7,
    .saved = S_SAVED,
    .expo = 0.2,
    .safety = 0.9,
    .fac_min = 0.2,
    .fac_max = 5.0,
};

_Static_assert(RK45_VECTORS == 9, "rk45 needs 9 work vectors (integrators.c)");

/* One accepted Dormand–Prince step of at most h_max, with as many rejected
 * trial steps as the error control needs. */
int sw_step_rk45(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&rk45, s, ode, t, y, h_max);
}
