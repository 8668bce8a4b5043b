/* rkn12, the Runge-Kutta-Nyström 12(10) pair, against theory: its tableau
 * against the order conditions of Nyström methods for x'' = f(x) (the
 * 12th-order solution and the embedded 10th-order one, in long double
 * from its 22-digit values; tests/support/nystrom.c), the observed orders
 * on the oscillator and the Kepler orbit against their closed forms, the
 * engine's step against the independent long double stepper, its two
 * entries' bits, the step control (error in proportion to the tolerance;
 * on the orbit at e = 0.9 fewer evaluations than rkn and dop853 at tight
 * tolerances), its evaluations, and its refusal of systems whose forces
 * read velocities. No expected value is read from the code under test. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "engine/ode_fast.h"
#include "engine/rkn12_tableau.h"
#include "engine/stepper.h"
#include "nystrom.h"
#include "nystrom_run.h"
#include "stepwise/base.h"

/* ---- the tableau, in long double ---------------------------------------------- */

enum { S = 17 };
#define F(j, w) [(j) - 1] = w##L,
#define T(j, w) [(j) - 1] = w##L,
#define ROW(i, c, terms) [(i) - 1] = { terms },
#define NODE(i, c, terms) [(i) - 1] = c##L,
static const nys_tableau TB = {
    .s = S,
    .c = { SW_RKN12_STAGES(NODE, F, T) },
    .a = { SW_RKN12_STAGES(ROW, F, T) },
};
static const long double BX[S] = { SW_RKN12_BX(F, T) }, BV[S] = { SW_RKN12_BV(F, T) };
static const long double EX[S] = { SW_RKN12_EX(F, T) }, EV[S] = { SW_RKN12_EV(F, T) };
#undef NODE
#undef ROW
#undef T
#undef F

/* The embedded weights B - E. */
static void embedded(long double hx[S], long double hv[S])
{
    for (int i = 0; i < S; i++) {
        hx[i] = BX[i] - EX[i];
        hv[i] = BV[i] - EV[i];
    }
}

/* ---- order conditions ------------------------------------------------------------ */

/* Order 12: the x conditions of every tree up to size 11 and the v ones up
 * to 12; the embedded solution, order 10: up to 9 and 10. Neither is of
 * the next order. The generator's counts of trees by size are checked by
 * hand in check_rkn up to size 7; beyond, only that it does not overflow
 * and that each size from 4 on has more trees than the one before.
 * Tolerance: the coefficients are 22-digit values rounded to long double
 * (1e-19), up to 49 in size; a condition sums at most a few hundred
 * products of them: 1e-15 is what that can leave; the bound is 1e-12
 * because valgrind runs long double at double precision (measured: at
 * most 7e-19 natively, 2.3e-15 under valgrind, both the row sums). A miss
 * is anything above 1e-10 (the conditions one order up are off by 1.8e-8,
 * x at size 12, and 6.9e-7, the embedded x at size 10). */
START_TEST(order_conditions)
{
    int count[NYS_MAX_RHO + 1];
    ck_assert_int_eq(nys_make_trees(&TB, 12, count), 0);
    for (int r = 2; r <= 12; r++)
        ck_assert_msg(count[r] > count[r - 1] || r < 4, "%d trees of size %d after %d", count[r], r, count[r - 1]);
    long double hx[S], hv[S];
    embedded(hx, hv);
    const long double tol = 1e-12L, miss = 1e-10L;
    ck_assert_msg(nys_residual(BX, 0, 1, 11) < tol, "x, order 12: %Lg", nys_residual(BX, 0, 1, 11));
    ck_assert_msg(nys_residual(BV, 1, 1, 12) < tol, "v, order 12: %Lg", nys_residual(BV, 1, 1, 12));
    ck_assert_msg(nys_residual(BX, 0, 12, 12) > miss, "order 13 met? %Lg", nys_residual(BX, 0, 12, 12));
    ck_assert_msg(nys_residual(hx, 0, 1, 9) < tol, "embedded x, order 10: %Lg", nys_residual(hx, 0, 1, 9));
    ck_assert_msg(nys_residual(hv, 1, 1, 10) < tol, "embedded v, order 10: %Lg", nys_residual(hv, 1, 1, 10));
    ck_assert_msg(nys_residual(hx, 0, 10, 10) > miss || nys_residual(hv, 1, 11, 11) > miss,
                  "embedded order 11 met?");
    ck_assert_msg(nys_row_sums(&TB) < tol, "rows: %Lg", nys_row_sums(&TB));
}
END_TEST

/* ---- the engine against the tableau ---------------------------------------------- */

/* The engine's step is the tableau's: 40 steps of 0.5 on the oscillator
 * and of 0.1 on the orbit at e = 0.5 agree with the long double stepper to
 * 1e-12 (double rounding over 40 steps of sums of 17 terms ~ 1e-14; a
 * weight wrong in its 16th digit moves the result by more than that only
 * through its product with h² a ~ 1e-2, so this catches a wrong entry,
 * not a last-digit one: the order conditions do that). One evaluation to
 * start, then 17 a step (16 stages and the new state's derivative). */
START_TEST(engine_is_the_tableau)
{
    const double h[2] = { 0.5, 0.1 };
    nys_engine_is_tableau("rkn12", &TB, BX, BV, h, 17, 1e-12);
}
END_TEST

/* rkn12 steps one particle through a body written in 2-lane vectors and
 * any larger state through the general one: the same bits (40 steps of
 * 0.05 on orbits at e = 0, 0.5, 0.9, one particle each and three side by
 * side). */
START_TEST(one_particle_entry_same_bits) { nys_one_particle_same_bits("rkn12"); }
END_TEST

/* On the stiff spring (one particle on one anchored spring alone) the
 * one-particle entry computes the spring inline: the same bits, steps,
 * rejections and evaluations as through the derivative. */
START_TEST(spring_inline_same_bits) { nys_spring_inline_same_bits("rkn12"); }
END_TEST

/* On the orbit (one particle in one central field alone) the one-particle
 * entry computes the field inline (sw_ode_fast's central1) instead of
 * calling the derivative: the same bits, steps and rejections as through
 * the derivative, on a field whose numbers are all distinct from 1 (mass
 * 2.5, μ = 1.7, centre (0.3, -0.2)), 300 steps under control at 1e-10,
 * the second run on a copy of the system with central1 taken away. And
 * only that system offers it: not with a second force, nor two particles. */
static void inline_field_run(int inline_field, double y[4], long counts[3])
{
    sw_particles p;
    sw_central1 c;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 1, 2.5, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_add_central(&p, 0.3, -0.2, 1.7), SW_OK);
    p.y[0] = 0.3 + 0.2, p.y[1] = -0.2, p.y[2] = 0.0, p.y[3] = 3.5;
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_ode_central1(&p.ode, &c), 1);
    ck_assert(c.cx == 0.3 && c.cy == -0.2 && c.mu == 1.7 && c.mass == 2.5 && c.inv == 1 / 2.5);
    nys_controlled_300("rkn12", &p, inline_field, y, counts);
    sw_particles_free(&p);
}

START_TEST(orbit_field_inline_same_bits)
{
    double a[4], b[4];
    long ca[3], cb[3];
    inline_field_run(1, a, ca);
    inline_field_run(0, b, cb);
    ck_assert_msg(memcmp(a, b, sizeof a) == 0, "inline (%.17g, %.17g), through the derivative (%.17g, %.17g)", a[0],
                  a[1], b[0], b[1]);
    ck_assert(ca[0] == cb[0] && ca[1] == cb[1] && ca[2] == cb[2]);
    ck_assert_int_gt(ca[1], 0); /* the run did reject trials: a path the two share too */
    sw_particles p;
    sw_central1 c;
    char err[SW_ERRLEN];
    for (int other = 0; other < 2; other++) {
        ck_assert_int_eq(sw_particles_init(&p, 1 + other, 1.0, err, sizeof err), SW_OK);
        ck_assert_int_eq(sw_particles_add_central(&p, 0, 0, 1.0), SW_OK);
        if (!other)
            ck_assert_int_eq(sw_particles_add_gravity(&p, 0.0, -1.0), SW_OK);
        p.y[0] = 1.0;
        p.y[2] = 2.0;
        ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
        ck_assert_int_eq(sw_ode_central1(&p.ode, &c), 0);
        sw_particles_free(&p);
    }
}
END_TEST

/* ---- observed orders --------------------------------------------------------------- */

/* The error at T with n steps: of the engine's rkn12 (order 12) or of the
 * embedded solution stepped in long double (order 10). */
static double error_at(int k, long n, int order)
{
    double T = k ? 2 * M_PI : 10.0;
    if (order == 12)
        return nys_engine_error("rkn12", k, 0.5, T, n);
    long double hx[S], hv[S];
    embedded(hx, hv);
    return nys_tableau_error(&TB, hx, hv, k, 0.5, T, n);
}

/* Observed orders against the closed forms, fitted over three step sizes
 * where the errors lie in [1e-12, 1e-4] (round-off here ~1e-14):
 * - the oscillator to t = 10 with 4, 6, 8 steps: the engine's 12th-order
 *   solution (errors 8e-9, 6.3e-11, 2.1e-12; local slopes 11.96, 11.85)
 *   and the embedded 10th-order one by the long double stepper (7.2e-7 ..
 *   6.8e-10; 10.06, 10.00);
 * - the orbit at e = 0.5 over one period with 30, 40, 60 steps: the
 *   embedded solution (4.7e-8 .. 4.6e-11; 9.8, 10.2). The 12th-order one
 *   is not fitted there: it is still pre-asymptotic while its error is
 *   above round-off (local slopes 10.3 .. 12.4 between 20 and 60 steps,
 *   6.6e-14 at 60).
 * Theory 12 and 10; ±0.5 for the error constant's drift over the range. */
static void order_fit(int k, const long n[3], int order, double want)
{
    const char *what = k ? "orbit" : "oscillator";
    double h[3], e[3];
    for (int j = 0; j < 3; j++) {
        h[j] = (k ? 2 * M_PI : 10.0) / n[j];
        e[j] = error_at(k, n[j], order);
    }
    double p = nys_slope(h, e, 3);
    ck_assert_msg(e[2] > 1e-12 && e[0] < 1e-4, "%s, order %d: errors %g .. %g", what, order, e[0], e[2]);
    ck_assert_msg(fabs(p - want) <= 0.5, "%s: order %.3f, not %g (errors %g %g %g)", what, p, want, e[0], e[1], e[2]);
}

START_TEST(observed_orders)
{
    static const long n_osc[3] = { 4, 6, 8 }, n_orb[3] = { 30, 40, 60 };
    order_fit(0, n_osc, 12, 12);
    order_fit(0, n_osc, 10, 10);
    order_fit(1, n_orb, 10, 10);
}
END_TEST

/* ---- step control ------------------------------------------------------------------ */

/* Tolerance proportionality: over tol = 1e-5 .. 1e-11 (steps of 100) the
 * error at the end falls with the tolerance: each 100× tighter tolerance
 * cuts it by 20 .. 1000× (theory: the controller holds the 10th-order
 * estimate, ∝ h^11, near tol, so h ∝ tol^(1/11) and the 12th-order error
 * ∝ h^12 ∝ tol^(12/11), a factor 150; measured 39, 93, 222 on the
 * oscillator over t = 30 and 51, 245, 69 on the orbit at e = 0.5 over one
 * period, the last error 3.3e-13, above round-off). The error stays below
 * 100 × tol (measured at most 0.15 × tol, the oscillator at 1e-9). */
START_TEST(tolerance_proportional) { nys_tolerance_proportional("rkn12", 1e-5); }
END_TEST

/* Where it is for: two orbits at e = 0.9 at tol = 1e-10 and 1e-12. Its
 * steps are longer than rkn's and dop853's by more than its extra
 * evaluations: fewer evaluations in all, and the error no larger than
 * theirs by more than 10× (measured: 1515 evaluations against rkn's 2791
 * and dop853's 2378 at 1e-10, 2178 against 6976 and 3158 at 1e-12; its
 * errors 1.8e-8 and 3.5e-11, theirs 9.7e-8 .. 5.8e-9). */
START_TEST(fewer_evaluations_when_tight)
{
    const char *other[2] = { "rkn", "dop853" };
    for (int j = 0; j < 2; j++) {
        double tol = j ? 1e-12 : 1e-10;
        long mine, theirs;
        double e = nys_controlled("rkn12", 1, 0.9, 4 * M_PI, tol, &mine, NULL);
        for (int o = 0; o < 2; o++) {
            double eo = nys_controlled(other[o], 1, 0.9, 4 * M_PI, tol, &theirs, NULL);
            ck_assert_msg(mine < theirs, "tol %g: rkn12 %ld evaluations, %s %ld", tol, mine, other[o], theirs);
            ck_assert_msg(e < 10 * eo + 1e-13, "tol %g: rkn12 error %g, %s %g", tol, e, other[o], eo);
        }
    }
}
END_TEST

/* A damped spring, drag, and a flow field are refused with a message that
 * says why and what to use; the same spring undamped, and drag of k = 0,
 * are accepted. */
START_TEST(refuses_velocity_forces) { nys_refuses_velocity_forces("rkn12"); }
END_TEST

Suite *make_rkn12_suite(void);
Suite *make_rkn12_suite(void)
{
    Suite *s = suite_create("rkn12");
    TCase *tc = tcase_create("theory");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, order_conditions);
    tcase_add_test(tc, engine_is_the_tableau);
    tcase_add_test(tc, one_particle_entry_same_bits);
    tcase_add_test(tc, spring_inline_same_bits);
    tcase_add_test(tc, orbit_field_inline_same_bits);
    tcase_add_test(tc, observed_orders);
    tcase_add_test(tc, tolerance_proportional);
    tcase_add_test(tc, fewer_evaluations_when_tight);
    tcase_add_test(tc, refuses_velocity_forces);
    suite_add_tcase(s, tc);
    return s;
}
