/* Runge-Kutta-Nyström 6(4): the adaptive method for x'' = f(t, x), where
 * the acceleration depends on positions alone (no drag, no damping). It
 * integrates the second-order equation directly — stages are positions,
 * each needing one acceleration — so it reaches 6th order with 5 new
 * evaluations a step where a first-order Runge-Kutta method needs 7 or
 * more. Error control by the embedded 4th-order solution, through the
 * controller rk45 and dop853 share (adaptive.c); nothing is copied on an
 * accepted step. Its lecture form, the same bits: sw_ref_rkn in
 * reference_adaptive.c (read it first). */
#include "engine/adaptive.h"
#include "engine/clones.h"
#include "engine/nystrom2.h"

#include <math.h>

#include "engine/rkn_tableau.h"
#include "stepwise/base.h"

#define X(name, p, q) static const double RKN_##name = (double)(p) / (q);
SW_RKN_TABLEAU(X)
#undef X

/* Slots: each stage's derivative [v | a] (only a is read), the FSAL one
 * alternating between 0 and S_K6; the stage state; the saved old state. */
enum { S_K2 = 1, S_K3, S_K4, S_K5, S_K6, S_YT, S_SAVED, RKN_VECTORS };

/* The stage positions X = x0 + c h v0 + h² Σ A a into yt's first half (its
 * second half holds v0: the derivative reads a whole state, and a
 * position-only force ignores it), then a_i = f(t + c h, X). */
#define RKN_STAGE(C, K, EXPR)                                                                            \
    do {                                                                                                 \
        for (i = 0; i < d; i++)                                                                          \
            yt[i] = x[i] + (C) * h * v[i] + hh * (EXPR);                                                 \
        sw_eval_slice(ode, t + (C) * h, 2 * d, yt, (K));                                                 \
    } while (0)

/* One trial over the whole state [x | v] (d = dim/2 each; the method needs
 * both halves, so it never runs slice by slice: the systems it accepts
 * offer no slices). Error norm: RMS of e_i / (atol + rtol·max(|y0_i|,
 * |y1_i|)), e = h² Σ EX a in x and h Σ EV a in v; the squares are added
 * by i mod 4 over [x | v] (four chains of additions side by side, as
 * dop853 adds them), then the four sums pairwise. Every vector is a
 * restrict parameter, so each loop vectorises with no overlap checks; the
 * squares wait in yt, free once the last stage is evaluated. The pointers
 * into them (a_i, x, v, q) are plain: based on a restrict parameter, they
 * keep its promise, where restrict pointers of their own would promise
 * that nothing else touches their objects, and the derivative writes a_i
 * through k_i. Inlined into two entries: any d, and d = 2 (one particle). */
SW_INLINE void rkn_body(sw_ode *ode, double t, double *restrict y, double h, int d, unsigned elim, double atol,
                        double rtol, double *restrict k1, double *restrict k2, double *restrict k3,
                        double *restrict k4, double *restrict k5, double *restrict k6, double *restrict yt,
                        double *restrict saved, sw_trial_sums *sums)
{
    const double hh = h * h;
    const double *a1 = k1 + d, *a2 = k2 + d, *a3 = k3 + d, *a4 = k4 + d, *a5 = k5 + d, *a6 = k6 + d;
    double *x = y, *v = y + d, *q = yt;
    int i;
    for (i = 0; i < d; i++)
        yt[d + i] = v[i];
    RKN_STAGE(RKN_C2, k2, RKN_A21 * a1[i]);
    RKN_STAGE(RKN_C3, k3, RKN_A31 * a1[i] + RKN_A32 * a2[i]);
    RKN_STAGE(RKN_C4, k4, RKN_A41 * a1[i] + RKN_A42 * a2[i] + RKN_A43 * a3[i]);
    RKN_STAGE(RKN_C5, k5, RKN_A51 * a1[i] + RKN_A52 * a2[i] + RKN_A53 * a3[i] + RKN_A54 * a4[i]);
    /* Stage 6 is x1 (FSAL): written into the state, whose v half is still v0. */
    unsigned long long over = 0, add = sw_beyond_add(elim);
    for (i = 0; i < d; i++) {
        double x0 = x[i];
        double ba = RKN_BX1 * a1[i] + RKN_BX2 * a2[i] + RKN_BX3 * a3[i] + RKN_BX4 * a4[i] + RKN_BX5 * a5[i];
        double x1 = x0 + h * v[i] + hh * ba;
        double e = hh * ((RKN_BX1 - RKN_HX1) * a1[i] + (RKN_BX2 - RKN_HX2) * a2[i] + (RKN_BX3 - RKN_HX3) * a3[i] +
                         (RKN_BX4 - RKN_HX4) * a4[i] + (RKN_BX5 - RKN_HX5) * a5[i]);
        double m0 = fabs(x0), m1 = fabs(x1), r = e / (atol + rtol * (m1 > m0 ? m1 : m0));
        saved[i] = x0;
        x[i] = x1;
        q[i] = r * r;
        over |= sw_beyond_bits(x1, add);
    }
    sw_eval_slice(ode, t + h, 2 * d, y, k6);
    for (i = 0; i < d; i++) {
        double v0 = v[i];
        double v1 = v0 + h * (RKN_BV1 * a1[i] + RKN_BV2 * a2[i] + RKN_BV3 * a3[i] + RKN_BV4 * a4[i] +
                              RKN_BV5 * a5[i] + RKN_BV6 * a6[i]);
        double e = h * ((RKN_BV1 - RKN_HV1) * a1[i] + (RKN_BV2 - RKN_HV2) * a2[i] + (RKN_BV3 - RKN_HV3) * a3[i] +
                        (RKN_BV4 - RKN_HV4) * a4[i] + (RKN_BV5 - RKN_HV5) * a5[i]);
        double m0 = fabs(v0), m1 = fabs(v1), r = e / (atol + rtol * (m1 > m0 ? m1 : m0));
        saved[d + i] = v0;
        v[i] = v1;
        k6[i] = v1; /* k6 = f(t + h, [x1 | v1]) exactly: a does not depend on v */
        q[d + i] = r * r;
        over |= sw_beyond_bits(v1, add);
    }
    sums->err = sw_add_by4(sums->part[0], q, 2 * d);
    sums->beyond |= sw_beyond_any(over);
}

#define RKN_ARGS                                                                                          \
    sw_ode *ode, double t, double *restrict y, double h, int d, unsigned elim, double atol, double rtol, \
        double *restrict k1, double *restrict k2, double *restrict k3, double *restrict k4,               \
        double *restrict k5, double *restrict k6, double *restrict yt, double *restrict saved,            \
        sw_trial_sums *sums
#define RKN_PASS(d) ode, t, y, h, d, elim, atol, rtol, k1, k2, k3, k4, k5, k6, yt, saved, sums

typedef void rkn_range_fn(RKN_ARGS);

SW_CLONES static void rkn_range(RKN_ARGS) { rkn_body(RKN_PASS(d)); }

/* The stiff spring (one particle on one anchored spring alone): rkn_body's
 * arithmetic in 2-lane vectors (lane-wise IEEE operations in the same
 * order), each stage's acceleration computed inline with the derivative's
 * own arithmetic (engine/spring1.h), so that a stage's state and
 * acceleration stay in registers: no call, no trip through memory from
 * one stage to the next; the same bits (spring_inline_same_bits in
 * tests/check_rkn.c). As rkn12's one-particle entry does for the orbit. */
static inline v2d spring_accel2(const sw_spring1 *sp, v2d X)
{
    double ax, ay;
    sw_spring1_accel(sp, X[0], X[1], &ax, &ay);
    return (v2d){ ax, ay };
}

#define W(c) ((v2d){ (c), (c) })
#define STAGE2(C, EXPR) spring_accel2(sp, x + W((C) * h) * v + hh * (EXPR))

static __attribute__((noinline)) void rkn_spring(RKN_ARGS, const sw_spring1 *sp)
{
    (void)ode, (void)t, (void)d, (void)k2, (void)k3, (void)k4, (void)k5, (void)yt;
    const v2d hh = W(h * h), hv = W(h), x = load2(y), v = load2(y + 2), a1 = load2(k1 + 2);
    const v2d a2 = STAGE2(RKN_C2, W(RKN_A21) * a1);
    const v2d a3 = STAGE2(RKN_C3, W(RKN_A31) * a1 + W(RKN_A32) * a2);
    const v2d a4 = STAGE2(RKN_C4, W(RKN_A41) * a1 + W(RKN_A42) * a2 + W(RKN_A43) * a3);
    const v2d a5 = STAGE2(RKN_C5, W(RKN_A51) * a1 + W(RKN_A52) * a2 + W(RKN_A53) * a3 + W(RKN_A54) * a4);
    const v2d x1 = x + hv * v + hh * (W(RKN_BX1) * a1 + W(RKN_BX2) * a2 + W(RKN_BX3) * a3 + W(RKN_BX4) * a4 +
                                      W(RKN_BX5) * a5);
    const v2d ex = hh * (W(RKN_BX1 - RKN_HX1) * a1 + W(RKN_BX2 - RKN_HX2) * a2 + W(RKN_BX3 - RKN_HX3) * a3 +
                         W(RKN_BX4 - RKN_HX4) * a4 + W(RKN_BX5 - RKN_HX5) * a5);
    const v2d a6 = spring_accel2(sp, x1);
    const v2d v1 = v + hv * (W(RKN_BV1) * a1 + W(RKN_BV2) * a2 + W(RKN_BV3) * a3 + W(RKN_BV4) * a4 +
                             W(RKN_BV5) * a5 + W(RKN_BV6) * a6);
    const v2d ev = hv * (W(RKN_BV1 - RKN_HV1) * a1 + W(RKN_BV2 - RKN_HV2) * a2 + W(RKN_BV3 - RKN_HV3) * a3 +
                         W(RKN_BV4 - RKN_HV4) * a4 + W(RKN_BV5 - RKN_HV5) * a5);
    sw_nys2_finish(x, v, x1, v1, ex, ev, atol, rtol, elim, 1, y, saved, sums);
    memcpy(k6, &v1, sizeof v1); /* [v | a] at the new state, as the derivative writes it */
    memcpy(k6 + 2, &a6, sizeof a6);
}

#undef STAGE2
#undef W

/* One particle: every loop one or two 16-byte vectors, or the stiff spring
 * inline. Not cloned, for the reason dop853_range4 is not (store forwarding
 * from the small derivative). */
static void rkn_range2(RKN_ARGS)
{
    sw_spring1 sp;
    (void)d;
    if (sw_ode_spring1(ode, &sp))
        rkn_spring(RKN_PASS(2), &sp);
    else
        rkn_body(RKN_PASS(2));
}

static void rkn_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                      unsigned elim, sw_trial_sums *sums)
{
    const int d = (hi - lo) / 2;
    rkn_range_fn *range = d == 2 ? rkn_range2 : rkn_range;
    range(ode, t, y, h, d, elim, s->atol, s->rtol, SW_WORK(s, s->fsal), SW_WORK(s, S_K2), SW_WORK(s, S_K3),
          SW_WORK(s, S_K4), SW_WORK(s, S_K5), SW_WORK(s, s->fsal ? 0 : S_K6), SW_WORK(s, S_YT),
          SW_WORK(s, S_SAVED), sums);
}

static const sw_adaptive rkn = {
    .trial = rkn_trial,
    .evals = 5,
    .slice = 256, /* (never used: see rkn_trial) */
    .fsal_other = S_K6,
    .saved = S_SAVED,
    .expo = 0.2, /* the embedded solution is 4th order: local error ∝ h^5 */
    .safety = 0.9,
    .fac_min = 0.2,
    .fac_max = 5.0,
};

_Static_assert(RKN_VECTORS == 8, "rkn needs 8 work vectors (integrators.c)");

/* One accepted RKN6(4) step of at most h_max. */
int sw_step_rkn(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&rkn, s, ode, t, y, h_max);
}
