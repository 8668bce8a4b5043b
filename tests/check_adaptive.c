/* The shared step-size controller (src/engine/adaptive.c) on a model trial
 * whose error is known in closed form: a trial of size h from t has the
 * error norm err = (h / H(t))^q, where H(t) = κ·(t_c - t) is the step that
 * just meets the tolerance there, shrinking as t nears t_c (an orbit
 * falling towards its pericentre: its time scale shrinks with the time
 * left). Accepted steps of h_n ≈ safety·H(t_n) then shrink H by the same
 * ratio ρ = 1 - safety·κ each step.
 *
 * Theory, with safety s and q = 1/expo:
 * - the standard proposal is h_{n+1} = s·err^(-1/q)·h_n = s·H(t_n): one
 *   step late, so its error is (s/ρ)^q, a rejection whenever ρ < s;
 * - Gustafsson's predictive proposal extrapolates the error constant
 *   H(t)^(-q) from the last two accepted steps: on a geometric sequence it
 *   is exact, h_{n+1} = s·ρ·H(t_n), and its error s^q < 1 is accepted;
 * - while the error constant stays the same (κ = 0: H constant) both
 *   proposals are the same number. */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "engine/adaptive.h"

enum { Q = 11, DIM = 2, ACCEPTED = 30 };

static double kappa, t_c; /* H(t) = κ (t_c - t); κ = 0: H = 1 */

static void model_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                        unsigned elim, sw_trial_sums *sums)
{
    (void)s, (void)ode, (void)y, (void)elim;
    double H = kappa > 0 ? kappa * (t_c - t) : 1.0, e = pow(h / H, Q);
    sums->err += e * e * (hi - lo); /* the controller's RMS over DIM components: e */
}

static void model_deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)ctx, (void)t, (void)y;
    dydt[0] = dydt[1] = 0;
}

typedef struct run {
    long accepted, rejected;
    double h[ACCEPTED];
} run;

/* ACCEPTED steps of the model from t = 0, the first trial of h0. */
static run model_run(int predict, double h0)
{
    const sw_adaptive m = {
        .trial = model_trial, .evals = 1, .coupled = 1, .fsal_other = 1, .saved = 2,
        .expo = 1.0 / Q, .safety = 0.9, .fac_min = 1.0 / 3, .fac_max = 6.0, .hold = 1, .predict = predict,
    };
    double work[3 * DIM] = { 0 }, y[DIM] = { 0 }, t = 0;
    sw_stepper s = { .dim = DIM, .work = work, .h_next = h0 };
    sw_ode ode = { .dim = DIM, .order = 1, .deriv = model_deriv };
    run r = { 0 };
    for (int i = 0; i < ACCEPTED; i++) {
        ck_assert_int_eq(sw_adaptive_step(&m, &s, &ode, &t, y, 1e9), 0);
        r.h[i] = s.h_last;
    }
    r.accepted = s.accepted;
    r.rejected = s.rejected;
    return r;
}

/* ρ = 0.55 < s = 0.9: the standard controller is rejected before nearly
 * every step (all but the first two, which start from h0 and from a step
 * that did not yet show the trend); the predictive one, once it has two
 * accepted steps to extrapolate from, never. */
START_TEST(predictive_follows_a_shrinking_scale)
{
    kappa = 0.5, t_c = 4.0; /* H(0) = 2 */
    run plain = model_run(0, 1.0), pred = model_run(1, 1.0);
    ck_assert_int_eq(plain.accepted, ACCEPTED);
    ck_assert_int_ge(plain.rejected, ACCEPTED - 2);
    ck_assert_int_le(pred.rejected, 2);
    /* from the third step on each accepted step is ρ = 0.55 times the last,
     * as the extrapolation is exact: to 1e-8, as t_c - t cancels while H
     * shrinks to 1e-8 of t_c (measured: 4e-10 at the last step) */
    for (int i = 2; i < ACCEPTED; i++)
        ck_assert_double_eq_tol(pred.h[i] / pred.h[i - 1], 1 - 0.9 * kappa, 1e-8);
}
END_TEST

/* H constant: the same steps with or without prediction, to rounding (the
 * two proposals are the same number computed two ways: 1e-12 relative). */
START_TEST(predictive_equals_standard_on_a_steady_scale)
{
    kappa = 0;
    run plain = model_run(0, 0.5), pred = model_run(1, 0.5);
    ck_assert_int_eq(plain.rejected, 0);
    ck_assert_int_eq(pred.rejected, 0);
    for (int i = 0; i < ACCEPTED; i++)
        ck_assert_double_eq_tol(pred.h[i], plain.h[i], 1e-12 * plain.h[i]);
    ck_assert_double_eq_tol(plain.h[ACCEPTED - 1], 0.9, 1e-12); /* s·H, the fixed point */
}
END_TEST

Suite *make_adaptive_suite(void);
Suite *make_adaptive_suite(void)
{
    Suite *s = suite_create("adaptive");
    TCase *tc = tcase_create("predictive");
    tcase_add_test(tc, predictive_follows_a_shrinking_scale);
    tcase_add_test(tc, predictive_equals_standard_on_a_steady_scale);
    suite_add_tcase(s, tc);
    return s;
}
