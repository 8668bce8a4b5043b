/* DOP853: Dormand and Prince's explicit Runge-Kutta method of order 8 with
 * Hairer's error estimate from embedded 5th- and 3rd-order solutions and his
 * step-size control (Hairer, Nørsett & Wanner, Solving ODEs I, section II.10,
 * and the code DOP853). 12 stages; the derivative at the new state is the
 * next step's first stage (FSAL), so a step costs 12 evaluations. Each stage
 * is one loop over the state (over L1-sized slices on pointwise systems);
 * nothing is copied on an accepted step. Its lecture form, the same bits:
 * sw_ref_dop853 in reference_adaptive.c (read it first). */
#include "engine/adaptive.h"
#include "engine/dop853_tableau.h"
#include "engine/regularise.h"

#include <math.h>

#include "stepwise/base.h"

/* Workspace slots. k2 and k3 are dead after stage 5, so stages 11 and 12
 * reuse them; the FSAL derivative goes where k4 was (dead after stage 12),
 * and slots 0 and 3 swap the roles of k1 and k4 from step to step. */
enum { S_K2 = 1, S_K3 = 2, S_K4 = 3, S_K5 = 4, S_K6, S_K7, S_K8, S_K9, S_K10, S_YT, S_SAVED, DOP853_VECTORS };

/* Component i's 5th- and 3rd-order error estimates, scaled by 1/sk, from
 * b·k, the old state y0 and the new one y1. */
static inline void dop853_errors(int i, double bk, double y0, double y1, double atol, double rtol,
                                 const double *restrict k1, const double *restrict k2, const double *restrict k3,
                                 const double *restrict k6, const double *restrict k7, const double *restrict k8,
                                 const double *restrict k9, const double *restrict k10, double *e3, double *e5)
{
    double a0 = fabs(y0), a1 = fabs(y1);
    double r = 1.0 / (atol + rtol * (a1 > a0 ? a1 : a0));
    *e3 = (bk - DP8_BHH1 * k1[i] - DP8_BHH9 * k9[i] - DP8_BHH12 * k3[i]) * r;
    *e5 = (DP8_ER1 * k1[i] + DP8_ER6 * k6[i] + DP8_ER7 * k7[i] + DP8_ER8 * k8[i] + DP8_ER9 * k9[i] + DP8_ER10 * k10[i] +
           DP8_ER11 * k2[i] + DP8_ER12 * k3[i]) * r;
}

/* A stage's derivative: the system's, or (lc) that of one body alone in
 * Levi-Civita's variables inline (regularise.h: the same operations, the
 * same bits), so that a stage's state and slope need not pass through
 * memory and a call on their way to the next stage. */
SW_INLINE void dop853_eval(const sw_evaluator *f, int lc, double t, int len, const double *restrict y,
                           double *restrict k)
{
    if (lc)
        sw_lc_alone(y, k);
    else
        sw_eval_with(f, t, len, y, k);
}

/* for (i = 0; i < len; i++) stmt, unrolled where the derivative is inline
 * (lc): a stage's state then reaches its derivative in registers, not
 * through memory (dop853-lc's steps 14% faster). Not elsewhere: the
 * orbit's four-component entry, which calls its derivative, is slower
 * unrolled. The same operations either way. */
#define EACH_I(...)                                                        \
    do {                                                                   \
        if (lc) {                                                          \
            _Pragma("GCC unroll 8") for (i = 0; i < len; i++) __VA_ARGS__; \
        } else {                                                           \
            for (i = 0; i < len; i++)                                      \
                __VA_ARGS__;                                               \
        }                                                                  \
    } while (0)

/* The stages over len components. Every vector is a restrict parameter, so the
 * compiler knows they do not overlap and vectorises each stage loop
 * without run-time overlap checks. k11 and k12 are written into k2 and k3.
 * Inlined into the entries below: any len, one particle's four, six, and
 * dop853-lc's six with its derivative inline (lc). */
SW_INLINE void dop853_body(sw_ode *ode, int lc, double t, double *restrict y, double h, int len, unsigned elim,
                         double atol, double rtol, const double *restrict k1, double *restrict k2,
                         double *restrict k3, double *restrict k4, double *restrict k5, double *restrict k6,
                         double *restrict k7, double *restrict k8, double *restrict k9, double *restrict k10,
                         double *restrict yt, double *restrict saved, sw_trial_sums *sums)
{
    int i;
    sw_evaluator f = sw_evaluator_of(ode);
    EACH_I(yt[i] = y[i] + h * (DP8_A2_1 * k1[i]));
    dop853_eval(&f, lc, t + DP8_C2 * h, len, yt, k2);
    EACH_I(yt[i] = y[i] + h * (DP8_A3_1 * k1[i] + DP8_A3_2 * k2[i]));
    dop853_eval(&f, lc, t + DP8_C3 * h, len, yt, k3);
    EACH_I(yt[i] = y[i] + h * (DP8_A4_1 * k1[i] + DP8_A4_3 * k3[i]));
    dop853_eval(&f, lc, t + DP8_C4 * h, len, yt, k4);
    EACH_I(yt[i] = y[i] + h * (DP8_A5_1 * k1[i] + DP8_A5_3 * k3[i] + DP8_A5_4 * k4[i]));
    dop853_eval(&f, lc, t + DP8_C5 * h, len, yt, k5);
    EACH_I(yt[i] = y[i] + h * (DP8_A6_1 * k1[i] + DP8_A6_4 * k4[i] + DP8_A6_5 * k5[i]));
    dop853_eval(&f, lc, t + DP8_C6 * h, len, yt, k6);
    EACH_I(yt[i] = y[i] + h * (DP8_A7_1 * k1[i] + DP8_A7_4 * k4[i] + DP8_A7_5 * k5[i] + DP8_A7_6 * k6[i]));
    dop853_eval(&f, lc, t + DP8_C7 * h, len, yt, k7);
    EACH_I(yt[i] = y[i] + h * (DP8_A8_1 * k1[i] + DP8_A8_4 * k4[i] + DP8_A8_5 * k5[i] + DP8_A8_6 * k6[i] +
                               DP8_A8_7 * k7[i]));
    dop853_eval(&f, lc, t + DP8_C8 * h, len, yt, k8);
    EACH_I(yt[i] = y[i] + h * (DP8_A9_1 * k1[i] + DP8_A9_4 * k4[i] + DP8_A9_5 * k5[i] + DP8_A9_6 * k6[i] +
                               DP8_A9_7 * k7[i] + DP8_A9_8 * k8[i]));
    dop853_eval(&f, lc, t + DP8_C9 * h, len, yt, k9);
    EACH_I(yt[i] = y[i] + h * (DP8_A10_1 * k1[i] + DP8_A10_4 * k4[i] + DP8_A10_5 * k5[i] + DP8_A10_6 * k6[i] +
                               DP8_A10_7 * k7[i] + DP8_A10_8 * k8[i] + DP8_A10_9 * k9[i]));
    dop853_eval(&f, lc, t + DP8_C10 * h, len, yt, k10);
    EACH_I(yt[i] = y[i] + h * (DP8_A11_1 * k1[i] + DP8_A11_4 * k4[i] + DP8_A11_5 * k5[i] + DP8_A11_6 * k6[i] +
                               DP8_A11_7 * k7[i] + DP8_A11_8 * k8[i] + DP8_A11_9 * k9[i] + DP8_A11_10 * k10[i]));
    dop853_eval(&f, lc, t + DP8_C11 * h, len, yt, k2); /* k11 */
    EACH_I(yt[i] = y[i] + h * (DP8_A12_1 * k1[i] + DP8_A12_4 * k4[i] + DP8_A12_5 * k5[i] + DP8_A12_6 * k6[i] +
                               DP8_A12_7 * k7[i] + DP8_A12_8 * k8[i] + DP8_A12_9 * k9[i] + DP8_A12_10 * k10[i] +
                               DP8_A12_11 * k2[i]));
    dop853_eval(&f, lc, t + h, len, yt, k3); /* k12 */
    /* The new state in place (the old one saved for a retry), its runaway
     * test, and both error terms, each scaled by sk = atol + rtol·max(|y0|,
     * |y1|) and squared, into k5 and k4 (free until the FSAL evaluation
     * below): one loop that vectorises. The sums add the terms by i mod 4
     * (four chains of additions side by side, as the four lanes of one
     * vector: lane-wise IEEE additions, the bits of four scalar chains;
     * slices start at multiples of 4, so a sliced pass adds in the same
     * order as a whole-state one). */
    unsigned long long over = 0, add = sw_beyond_add(elim);
    EACH_I({
        double y0 = y[i], e3, e5;
        double bk = DP8_B1 * k1[i] + DP8_B6 * k6[i] + DP8_B7 * k7[i] + DP8_B8 * k8[i] + DP8_B9 * k9[i] +
                    DP8_B10 * k10[i] + DP8_B11 * k2[i] + DP8_B12 * k3[i];
        double y1 = y0 + h * bk;
        saved[i] = y0;
        y[i] = y1;
        over |= sw_beyond_bits(y1, add);
        dop853_errors(i, bk, y0, y1, atol, rtol, k1, k2, k3, k6, k7, k8, k9, k10, &e3, &e5);
        k5[i] = e5 * e5;
        k4[i] = e3 * e3;
    });
    sums->err = sw_add_by4(sums->part[0], k5, len);
    sums->err3 = sw_add_by4(sums->part[1], k4, len);
    sums->beyond |= sw_beyond_any(over);
    dop853_eval(&f, lc, t + h, len, y, k4); /* FSAL: the next step's k1 */
}

#undef EACH_I

#define DOP853_ARGS                                                                                \
    sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim, double atol, double rtol, \
        const double *restrict k1, double *restrict k2, double *restrict k3, double *restrict k4,           \
        double *restrict k5, double *restrict k6, double *restrict k7, double *restrict k8,                 \
        double *restrict k9, double *restrict k10, double *restrict yt, double *restrict saved,             \
        sw_trial_sums *sums
#define DOP853_PASS(lc, len) ode, lc, t, y, h, len, elim, atol, rtol, k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, yt, saved, sums

typedef void dop853_range_fn(DOP853_ARGS);

SW_CLONES static void dop853_range(DOP853_ARGS) { dop853_body(DOP853_PASS(0, len)); }

/* Not cloned: the baseline's 16-byte loads and stores meet the small
 * derivative's (particles_small.c) one for one, so each load is forwarded
 * from the store that wrote it; a 32-byte load of a k that two 16-byte
 * stores wrote waits for both to reach the cache (~10 cycles, on the
 * path from one evaluation to the next: 1.2x GSL's time on the orbit,
 * against 0.9x without). */
static void dop853_range4(DOP853_ARGS)
{
    (void)len;
    dop853_body(DOP853_PASS(0, 4));
}

/* Six components (Levi-Civita's regularised state with a perturbation,
 * or any other six): loops of a known length (the same operations as any
 * len). */
static void dop853_range6(DOP853_ARGS)
{
    (void)len;
    dop853_body(DOP853_PASS(0, 6));
}

/* The same where the six are one body alone in Levi-Civita's variables
 * (dop853-lc): its derivative inline in each stage, every loop unrolled. */
static void dop853_range_lc(DOP853_ARGS)
{
    (void)len;
    dop853_body(DOP853_PASS(1, 6));
}

/* The FSAL pair (k1 and k4's slots) and the saved state are state-long
 * (they outlive a slice); the other stage vectors are slice-local. */
static void dop853_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                         unsigned elim, sw_trial_sums *sums)
{
    dop853_range_fn *range = hi - lo == 4   ? dop853_range4
                             : hi - lo != 6 ? dop853_range
                             : ode->deriv == sw_lc_deriv_alone ? dop853_range_lc
                                                               : dop853_range6;
    range(ode, t, y + lo, h, hi - lo, elim, s->atol, s->rtol, SW_WORK(s, s->fsal) + lo, SW_WORK(s, S_K2),
                 SW_WORK(s, S_K3), SW_WORK(s, s->fsal ? 0 : S_K4) + lo, SW_WORK(s, S_K5), SW_WORK(s, S_K6),
                 SW_WORK(s, S_K7), SW_WORK(s, S_K8), SW_WORK(s, S_K9), SW_WORK(s, S_K10), SW_WORK(s, S_YT),
                 SW_WORK(s, S_SAVED) + lo, sums);
}

static const sw_adaptive dop853 = {
    .trial = dop853_trial,
    .evals = 12,
    .slice = 256,
    .fsal_other = S_K4,
    .saved = S_SAVED,
    .expo = 1.0 / 8,
    .safety = 0.9,
    .fac_min = 1.0 / 3,
    .fac_max = 6.0,
    .hairer_norm = 1,
    .hold = 1,
    .guess_first = 1,
};

/* Keep the table entry's workspace in step with the slots above. */
_Static_assert(DOP853_VECTORS == 12, "dop853 needs 12 work vectors (integrators.c)");

int sw_step_dop853(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&dop853, s, ode, t, y, h_max);
}
