/* rkn, the Runge-Kutta-Nyström 6(4) pair, against theory: its tableau
 * against the order conditions of Nyström methods for x'' = f(x) (the
 * 6th-order solution and the embedded 4th-order one, in long double from
 * the exact fractions), the observed orders on the oscillator and the
 * Kepler orbit against their closed forms, the engine's step against an
 * independent stepper (tests/support/nystrom.c), the step control (error
 * in proportion to the tolerance; on the orbit at e = 0.9 the steps
 * shrink at perihelion), its evaluations, and its refusal of systems
 * whose forces read velocities. No expected value is read from the code
 * under test. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "engine/rkn_tableau.h"
#include "nystrom.h"
#include "nystrom_run.h"

/* ---- the tableau, in long double from its fractions ------------------------ */

#define X(name, p, q) static const long double L_##name = (long double)(p) / (long double)(q);
SW_RKN_TABLEAU(X)
#undef X

enum { S = 6 };
/* Row 6 of A is BX and c_6 = 1 (FSAL: rkn.c computes stage 6 as x1). */
static const nys_tableau TB = {
    .s = S,
    .c = { 0, L_C2, L_C3, L_C4, L_C5, 1 },
    .a = {
        { 0 },
        { L_A21 },
        { L_A31, L_A32 },
        { L_A41, L_A42, L_A43 },
        { L_A51, L_A52, L_A53, L_A54 },
        { L_BX1, L_BX2, L_BX3, L_BX4, L_BX5 },
    },
};
static const long double BX[S] = { L_BX1, L_BX2, L_BX3, L_BX4, L_BX5, 0 };
static const long double BV[S] = { L_BV1, L_BV2, L_BV3, L_BV4, L_BV5, L_BV6 };
static const long double HX[S] = { L_HX1, L_HX2, L_HX3, L_HX4, L_HX5, 0 };
static const long double HV[S] = { L_HV1, L_HV2, L_HV3, L_HV4, L_HV5, L_BV6 };

/* ---- order conditions (tests/support/nystrom.c) ---------------------------- */

enum { MAX_RHO = 7 };

/* The counts of trees by size, 1, 1, 2, 3, 6, 10, 20, are counted by hand
 * from the definition (size 7: the six nodes beside the root as leaves and
 * branches, a branch of k + 1 nodes holding one of the 1, 1, 2, 3, 6 trees
 * of size k = 1 .. 5: 20 multisets), so the generator misses none and
 * repeats none.
 * Tolerance: the coefficients are long double fractions (rounding 1e-19)
 * below 1.1 in size, and a condition sums at most a few dozen products of
 * them: 1e-16 is 1000 times that; the bound is 1e-14 because valgrind
 * runs long double at double precision. A miss is anything above 1e-8 (the
 * conditions one order up are off by 1e-4 .. 1e-2). */
START_TEST(order_conditions)
{
    int count[NYS_MAX_RHO + 1];
    ck_assert_int_eq(nys_make_trees(&TB, MAX_RHO, count), 0);
    const int literature[] = { 0, 1, 1, 2, 3, 6, 10, 20 };
    for (int r = 1; r <= MAX_RHO; r++)
        ck_assert_msg(count[r] == literature[r], "%d trees of size %d, not %d", count[r], r, literature[r]);
    const long double tol = 1e-14L, miss = 1e-8L;
    /* order 6: x up to size 5, v up to size 6; and not 7 */
    ck_assert_msg(nys_residual(BX, 0, 1, 5) < tol, "x, order 6: %Lg", nys_residual(BX, 0, 1, 5));
    ck_assert_msg(nys_residual(BV, 1, 1, 6) < tol, "v, order 6: %Lg", nys_residual(BV, 1, 1, 6));
    ck_assert_msg(nys_residual(BX, 0, 6, 6) > miss || nys_residual(BV, 1, 7, 7) > miss, "order 7 met?");
    /* the embedded pair: order 4, not 5 */
    ck_assert_msg(nys_residual(HX, 0, 1, 3) < tol, "embedded x, order 4: %Lg", nys_residual(HX, 0, 1, 3));
    ck_assert_msg(nys_residual(HV, 1, 1, 4) < tol, "embedded v, order 4: %Lg", nys_residual(HV, 1, 1, 4));
    ck_assert_msg(nys_residual(HX, 0, 4, 4) > miss || nys_residual(HV, 1, 5, 5) > miss, "embedded order 5 met?");
    /* the stages: Σ_j A_ij = c_i²/2 (the tree of size 2 with one branch) */
    ck_assert_msg(nys_row_sums(&TB) < tol, "rows: %Lg", nys_row_sums(&TB));
}
END_TEST

/* The engine's step is the tableau's: 40 steps of 0.25 on the oscillator
 * and of 0.05 on the orbit at e = 0.5 agree with the long double stepper
 * above to 1e-13 (double rounding over 40 steps of sums of 6 terms ~ 1e-15;
 * the method's own error there is 1e-8 .. 1e-6, so a wrong weight shows).
 * One evaluation to start, then 5 a step (FSAL). */
START_TEST(engine_is_the_tableau)
{
    const double h[2] = { 0.25, 0.05 };
    nys_engine_is_tableau("rkn", &TB, BX, BV, h, 5, 1e-13);
}
END_TEST

/* The two entries of the step are one computation: rkn steps a single
 * particle (state 4) through a copy of its body with d = 2 fixed, and any
 * larger state through the general one. Three particles about the same
 * centre, none acting on another, go through the general entry; each must
 * end on the very bits (no tolerance) of its own one-particle run, stepped
 * with the same fixed h (40 steps of 0.05; orbits at e = 0, 0.5, 0.9). */
START_TEST(one_particle_entry_same_bits) { nys_one_particle_same_bits("rkn"); }
END_TEST

/* On the stiff spring (one particle on one anchored spring alone) the
 * one-particle entry computes the spring inline: the same bits, steps,
 * rejections and evaluations as through the derivative. */
START_TEST(spring_inline_same_bits) { nys_spring_inline_same_bits("rkn"); }
END_TEST

/* Observed orders against the closed forms, fitted over three step sizes
 * halving, where the errors are far above round-off (1e-14 here) and past
 * the pre-asymptotic range:
 * - the 6th-order solution, by the engine: the oscillator to t = 10 with
 *   20, 40, 80 steps (errors 2.5e-7 .. 6e-11; local slopes 6.02), the
 *   orbit at e = 0.5 over one period with 100, 200, 400 (2.3e-7 .. 7e-11;
 *   local slopes 5.81, 5.91: with 40 steps it is still 5.5);
 * - the embedded 4th-order one (the engine uses it only to estimate the
 *   error), by the long double stepper: the oscillator as above (2e-5 ..
 *   9e-8; 3.97), the orbit with 400, 800, 1600 (with 100 steps its local
 *   slopes are still 4.5 and 4.3).
 * Theory 6 and 4; ±0.3 allows the error constant to drift over the range. */
/* The error at T with n steps: of the engine's rkn (order 6) or of the
 * embedded solution stepped in long double (order 4). */
static double error_at(int k, long n, int order)
{
    double T = k ? 2 * M_PI : 10.0;
    return order == 6 ? nys_engine_error("rkn", k, 0.5, T, n) : nys_tableau_error(&TB, HX, HV, k, 0.5, T, n);
}

START_TEST(observed_orders)
{
    for (int k = 0; k < 2; k++) {
        const char *what = k ? "orbit" : "oscillator";
        double h6[3], h4[3], e6[3], e4[3];
        for (int j = 0; j < 3; j++) {
            long n6 = (k ? 100L : 20L) << j, n4 = (k ? 400L : 20L) << j;
            h6[j] = (k ? 2 * M_PI : 10.0) / n6;
            h4[j] = (k ? 2 * M_PI : 10.0) / n4;
            e6[j] = error_at(k, n6, 6);
            e4[j] = error_at(k, n4, 4);
        }
        double p6 = nys_slope(h6, e6, 3), p4 = nys_slope(h4, e4, 3);
        ck_assert_msg(e6[2] > 1e-12 && e6[0] < 1e-3, "%s: errors %g .. %g", what, e6[0], e6[2]);
        ck_assert_msg(e4[2] > 1e-12 && e4[0] < 1e-3, "%s: embedded errors %g .. %g", what, e4[0], e4[2]);
        ck_assert_msg(fabs(p6 - 6) <= 0.3, "%s: order %.3f (errors %g %g %g)", what, p6, e6[0], e6[1], e6[2]);
        ck_assert_msg(fabs(p4 - 4) <= 0.3, "%s, embedded: order %.3f (errors %g %g %g)", what, p4, e4[0], e4[1],
                      e4[2]);
    }
}
END_TEST

/* ---- step control ------------------------------------------------------------- */

/* Tolerance proportionality: over tol = 1e-4 .. 1e-10 (steps of 100) the
 * error at the end falls with the tolerance: each 100× tighter tolerance
 * cuts it by 20 .. 1000× (theory: the controller holds the 4th-order
 * estimate h^5 near tol, so h ∝ tol^(1/5) and the 6th-order error
 * ∝ h^6 ∝ tol^(6/5), a factor 250; measured 250-460 on the oscillator
 * over t = 30, 90-205 on the orbit at e = 0.5 over one period). The
 * error stays below 100 × tol (measured at most 16 × tol). */
START_TEST(tolerance_proportional) { nys_tolerance_proportional("rkn", 1e-4); }
END_TEST

/* On the orbit at e = 0.9 (radius 0.1 at perihelion, 1.9 at aphelion) the
 * controller takes its smallest steps near perihelion and its largest
 * near aphelion: the motion's time scale goes as r^(3/2), a ratio of 83
 * between the two; the test asks for the smallest step at r < 0.3, the
 * largest at r > 1.5 and a ratio above 20 (measured: 0.0028 at r = 0.100,
 * 0.27 at r = 1.88, a ratio of 97). Two periods, tol = 1e-8; the error,
 * 3.9e-6, must stay below 1e-5. */
START_TEST(steps_shrink_at_perihelion)
{
    long evals;
    double st[4];
    double e = nys_controlled("rkn", 1, 0.9, 4 * M_PI, 1e-8, &evals, st);
    ck_assert_msg(st[1] < 0.3, "smallest step %g at r = %g", st[0], st[1]);
    ck_assert_msg(st[3] > 1.5, "largest step %g at r = %g", st[2], st[3]);
    ck_assert_msg(st[2] > 20 * st[0], "steps %g .. %g", st[0], st[2]);
    ck_assert_msg(e < 1e-5, "error %g at e = 0.9", e);
}
END_TEST

/* ---- refusal ------------------------------------------------------------------ */

/* A damped spring, drag, and a flow field are refused with a message that
 * says why and what to use; the same spring undamped, and drag of k = 0,
 * are accepted. */
START_TEST(refuses_velocity_forces) { nys_refuses_velocity_forces("rkn"); }
END_TEST

Suite *make_rkn_suite(void);
Suite *make_rkn_suite(void)
{
    Suite *s = suite_create("rkn");
    TCase *tc = tcase_create("theory");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, order_conditions);
    tcase_add_test(tc, engine_is_the_tableau);
    tcase_add_test(tc, one_particle_entry_same_bits);
    tcase_add_test(tc, spring_inline_same_bits);
    tcase_add_test(tc, observed_orders);
    tcase_add_test(tc, tolerance_proportional);
    tcase_add_test(tc, steps_shrink_at_perihelion);
    tcase_add_test(tc, refuses_velocity_forces);
    suite_add_tcase(s, tc);
    return s;
}
