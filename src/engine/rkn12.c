/* Runge-Kutta-Nyström 12(10): rkn's high-accuracy sibling for x'' = f(t, x)
 * (accelerations from positions alone). 17 stages reach 12th order, with
 * an embedded 10th-order solution for the error; not first-same-as-last,
 * so a trial ends with the derivative at its new state (17 evaluations).
 * Where rkn (6th order, 5 evaluations) or dop853 (8th, 12) need many small
 * steps — tolerances of 1e-8 and tighter, a close encounter — its steps
 * are several times longer. Error control by the controller rk45, dop853
 * and rkn share (adaptive.c); nothing is copied on an accepted step. Its
 * lecture form, the same bits: sw_ref_rkn12 in reference_adaptive.c. */
#include "engine/adaptive.h"
#include "engine/clones.h"
#include "engine/nystrom2.h"

#include <math.h>
#include <string.h>

#include "engine/rkn12_tableau.h"
#include "stepwise/base.h"

enum { S = 17 };

/* Slots: stage i's derivative [v | a] in slot i - 1 for i ≥ 2 (only a is
 * read); a_1 in slot 0 or S_NEXT, alternating (the trial writes the new
 * state's derivative into the other); the stage state; the error norm's
 * squares; the saved old state. */
enum { S_NEXT = S, S_YT, S_SQ, S_SAVED, RKN12_VECTORS };

/* A weighted sum of accelerations at component i: the tableau lists a
 * sum's nonzero terms in stage order, the first as F, the rest as T, so
 * each sum is one expression added left to right. */
#define F(j, w) (w) * a##j[i]
#define T(j, w) +(w) * a##j[i]

/* The accelerations a_1 .. a_17 as restrict pointers, for a block that
 * reads them and writes only yt or the state: each loop then vectorises
 * with no overlap checks. Only inside such a block: a derivative writes
 * a_i between the blocks, and a restrict pointer promises that nothing
 * else writes its object where the pointer is used. A block uses some of
 * them. */
#define A_RESTRICT(d)                                                                                      \
    const double *restrict a1 A_USED = k[0] + (d), *restrict a2 A_USED = k[1] + (d),                      \
                           *restrict a3 A_USED = k[2] + (d), *restrict a4 A_USED = k[3] + (d),            \
                           *restrict a5 A_USED = k[4] + (d), *restrict a6 A_USED = k[5] + (d),            \
                           *restrict a7 A_USED = k[6] + (d), *restrict a8 A_USED = k[7] + (d),            \
                           *restrict a9 A_USED = k[8] + (d), *restrict a10 A_USED = k[9] + (d),           \
                           *restrict a11 A_USED = k[10] + (d), *restrict a12 A_USED = k[11] + (d),        \
                           *restrict a13 A_USED = k[12] + (d), *restrict a14 A_USED = k[13] + (d),        \
                           *restrict a15 A_USED = k[14] + (d), *restrict a16 A_USED = k[15] + (d),        \
                           *restrict a17 A_USED = k[16] + (d)
#define A_USED __attribute__((unused))

/* Stage i: X_i = x0 + c_i h v0 + h² Σ_j A_ij a_j into yt's x half (its v
 * half holds v0 throughout: the derivative reads a whole state, and a
 * position-only force ignores it), then a_i = f(t + c_i h, X_i). */
#define STAGE(st, c, terms)                                                                               \
    {                                                                                                     \
        A_RESTRICT(d);                                                                                    \
        for (i = 0; i < d; i++)                                                                           \
            yt[i] = x[i] + (c) * h * v[i] + hh * (terms);                                                 \
    }                                                                                                     \
    sw_eval_slice(ode, t + (c) * h, 2 * d, yt, k[(st) - 1]);

/* One trial over the whole state [x | v] (d = dim/2 each; the systems it
 * accepts offer no slices). Then x1 and v1 into the state, the derivative
 * at the new state, and the error norm's squares as rkn adds them: RMS of
 * e_i / (atol + rtol·max(|y0_i|, |y1_i|)), e = h² Σ EX a in x and h Σ EV a
 * in v, the squares added by i mod 4 over [x | v]. Inlined into two
 * entries: any d, and d = 2 (one particle). */
SW_INLINE void rkn12_body(sw_ode *ode, double t, double *restrict y, double h, int d, unsigned elim,
                          double atol, double rtol, double *const k[S + 1], double *restrict yt,
                          double *restrict q, double *restrict saved, sw_trial_sums *sums)
{
    const double hh = h * h;
    double *x = y, *v = y + d;
    int i;
    for (i = 0; i < d; i++)
        yt[d + i] = v[i];
    SW_RKN12_STAGES(STAGE, F, T)
    unsigned long long over = 0, add = sw_beyond_add(elim);
    A_RESTRICT(d);
    for (i = 0; i < d; i++) {
        double x0 = x[i], v0 = v[i];
        double x1 = x0 + h * v0 + hh * (SW_RKN12_BX(F, T)), v1 = v0 + h * (SW_RKN12_BV(F, T));
        double ex = hh * (SW_RKN12_EX(F, T)), ev = h * (SW_RKN12_EV(F, T));
        double mx = fabs(x0) > fabs(x1) ? fabs(x0) : fabs(x1), mv = fabs(v0) > fabs(v1) ? fabs(v0) : fabs(v1);
        double rx = ex / (atol + rtol * mx), rv = ev / (atol + rtol * mv);
        saved[i] = x0;
        saved[d + i] = v0;
        x[i] = x1;
        v[i] = v1;
        q[i] = rx * rx;
        q[d + i] = rv * rv;
        over |= sw_beyond_bits(x1, add) | sw_beyond_bits(v1, add);
    }
    sw_eval_slice(ode, t + h, 2 * d, y, k[S]);
    sums->err = sw_add_by4(sums->part[0], q, 2 * d);
    sums->beyond |= sw_beyond_any(over);
}

#undef STAGE
#undef A_USED
#undef A_RESTRICT
#undef T
#undef F

#define RKN12_ARGS                                                                                          \
    sw_ode *ode, double t, double *restrict y, double h, int d, unsigned elim, double atol, double rtol,   \
        double *const k[S + 1], double *restrict yt, double *restrict q, double *restrict saved,          \
        sw_trial_sums *sums
#define RKN12_PASS(d) ode, t, y, h, d, elim, atol, rtol, k, yt, q, saved, sums

typedef void rkn12_range_fn(RKN12_ARGS);

SW_CLONES static void rkn12_range(RKN12_ARGS) { rkn12_body(RKN12_PASS(d)); }

/* One particle (d = 2), in 2-lane vectors: each a_j is loaded once, after
 * its evaluation, and each sum kept in registers (the loops of the general
 * body are not vectorised at d = 2). Lane-wise IEEE operations, in the
 * same order as rkn12_body's: the same bits (one_particle_entry_same_bits
 * in tests/check_rkn12.c). Not cloned, as rkn_range2 is not.
 *
 * On the orbit (one particle in one central field alone) a stage computes
 * a_j inline with the derivative's own arithmetic (engine/central.h), so
 * a stage's state and acceleration stay in registers: no call, no trip
 * through memory between the stages' sums and the field; the same bits
 * again (orbit_field_inline_same_bits). */
/* a at X: inline from the field or the spring, or through the derivative
 * into k. */
SW_INLINE v2d accel2(sw_ode *ode, const sw_central1 *field, int canon, const sw_spring1 *spring, double t,
                     double *yt, v2d X, double *k)
{
    if (field || spring) {
        double ax, ay;
        if (field)
            sw_central1_accel(field, canon, X[0], X[1], &ax, &ay);
        else
            sw_spring1_accel(spring, X[0], X[1], &ax, &ay);
        return (v2d){ ax, ay };
    }
    memcpy(yt, &X, sizeof X);
    sw_eval_slice(ode, t, 4, yt, k);
    return load2(k + 2);
}

#define F(j, w) (v2d){ (w), (w) } * A##j
#define T(j, w) +(v2d){ (w), (w) } * A##j
#define STAGE(st, c, terms)                                                                               \
    const v2d X##st = x + (v2d){ (c) * h, (c) * h } * v + hh * (terms);                                  \
    const v2d A##st = accel2(ode, field, canon, spring, t + (c) * h, yt, X##st, k[(st) - 1]);

/* field and spring: NULL (call the derivative), or the orbit's field or the
 * stiff spring's (at most one), canon a constant. */
SW_INLINE void rkn12_one(RKN12_ARGS, const sw_central1 *field, int canon, const sw_spring1 *spring)
{
    (void)d, (void)q; /* (the squares wait in registers: sw_nys2_finish) */
    const v2d hh = { h * h, h * h }, hv = { h, h }, x = load2(y), v = load2(y + 2);
    const v2d A1 = load2(k[0] + 2);
    memcpy(yt + 2, &v, sizeof v);
    SW_RKN12_STAGES(STAGE, F, T)
    const v2d x1 = x + hv * v + hh * (SW_RKN12_BX(F, T)), v1 = v + hv * (SW_RKN12_BV(F, T));
    const v2d ex = hh * (SW_RKN12_EX(F, T)), ev = hv * (SW_RKN12_EV(F, T));
    sw_nys2_finish(x, v, x1, v1, ex, ev, atol, rtol, elim, 0, y, saved, sums);
    if (field || spring) { /* [v | a] at the new state, as the derivative writes it */
        memcpy(k[S], &v1, sizeof v1);
        const v2d a1 = accel2(ode, field, canon, spring, t + h, yt, x1, k[S]);
        memcpy(k[S] + 2, &a1, sizeof a1);
    } else {
        sw_eval_slice(ode, t + h, 4, y, k[S]);
    }
}

/* Four entries, not inlined, so that the one a run takes holds only its
 * own code (each some 7 KB). */
#define ONE_ENTRY static __attribute__((noinline)) void
ONE_ENTRY rkn12_called(RKN12_ARGS) { rkn12_one(RKN12_PASS(d), NULL, 0, NULL); }
ONE_ENTRY rkn12_field(RKN12_ARGS, const sw_central1 *f) { rkn12_one(RKN12_PASS(d), f, 0, NULL); }
ONE_ENTRY rkn12_canon(RKN12_ARGS, const sw_central1 *f) { rkn12_one(RKN12_PASS(d), f, 1, NULL); }
ONE_ENTRY rkn12_spring(RKN12_ARGS, const sw_spring1 *sp) { rkn12_one(RKN12_PASS(d), NULL, 0, sp); }
#undef ONE_ENTRY

static void rkn12_range2(RKN12_ARGS)
{
    sw_central1 field;
    sw_spring1 spring;
    if (sw_ode_spring1(ode, &spring))
        rkn12_spring(RKN12_PASS(d), &spring);
    else if (!sw_ode_central1(ode, &field))
        rkn12_called(RKN12_PASS(d));
    else if (sw_central1_canon(&field))
        rkn12_canon(RKN12_PASS(d), &field);
    else
        rkn12_field(RKN12_PASS(d), &field);
}

#undef STAGE
#undef T
#undef F

static void rkn12_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                        unsigned elim, sw_trial_sums *sums)
{
    const int d = (hi - lo) / 2;
    double *k[S + 1];
    k[0] = SW_WORK(s, s->fsal);
    for (int i = 1; i < S; i++)
        k[i] = SW_WORK(s, i);
    k[S] = SW_WORK(s, s->fsal ? 0 : S_NEXT);
    rkn12_range_fn *range = d == 2 ? rkn12_range2 : rkn12_range;
    range(ode, t, y, h, d, elim, s->atol, s->rtol, k, SW_WORK(s, S_YT), SW_WORK(s, S_SQ), SW_WORK(s, S_SAVED),
          sums);
}

static const sw_adaptive rkn12 = {
    .trial = rkn12_trial,
    .evals = S,
    .coupled = 1, /* never sliced: the systems it accepts offer no slices, and it needs [x | v] whole */
    .fsal_other = S_NEXT,
    .saved = S_SAVED,
    .expo = 1.0 / 11, /* the embedded solution is 10th order: local error ∝ h^11 */
    .safety = 0.9,
    .fac_min = 1.0 / 3,
    .fac_max = 6.0,
    .hold = 1,
    .guess_first = 1,
    .predict = 1, /* fewer rejections where the scale shrinks fast (issue 26) */
};

_Static_assert(RKN12_VECTORS == 21, "rkn12 needs 21 work vectors (integrators.c)");

/* One accepted RKN12(10) step of at most h_max. */
int sw_step_rkn12(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&rkn12, s, ode, t, y, h_max);
}
