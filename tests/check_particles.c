/* The particle engine: derivative evaluation as the lecture describes it,
 * Jacobian blocks against independent finite differences and closed forms,
 * wall contact with restitution, and the flow-field solve. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/particles.h"
#include "engine/particles_solve.h"

/* Two particles, one spring between them and one to an anchor, gravity and
 * drag: deriv returns v and f/m with f summed as written in the test. */
START_TEST(derivative_sums_forces)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 2, 2.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 2);
    s[0] = (sw_spring){ .a = 0, .b = 1, .k = 3.0, .c = 0.5, .rest = 1.0 };
    s[1] = (sw_spring){ .a = 1, .b = -1, .k = 2.0, .c = 0.0, .rest = 0.5, .ax = 4.0, .ay = 0.0 };
    sw_particles_add_gravity(&p, 0.0, -9.81);
    sw_particles_add_drag(&p, 0.25);
    double y[8] = { 0, 0, 3, 4, /* v */ 1, 0, 0, 2 };
    double dy[8];
    p.ode.deriv(&p, 0.0, y, dy);
    /* spring 0: d = x0 - x1 = (-3, -4), |d| = 5, u = (-0.6, -0.8), dv = (1, -2),
     * mag = 3(5 - 1) + 0.5(dv·u) = 12 + 0.5(-0.6 + 1.6) = 12.5, f0 = -12.5 u. */
    double f0x = 7.5, f0y = 10.0;
    /* spring 1: d = x1 - (4, 0) = (-1, 4), |d| = √17, mag = 2(√17 - 0.5). */
    double L = sqrt(17.0), m1 = 2.0 * (L - 0.5);
    double f1x = -f0x - m1 * (-1 / L), f1y = -f0y - m1 * (4 / L);
    f0y += 2.0 * -9.81;
    f1y += 2.0 * -9.81;
    f0x -= 0.25 * 1;
    f1y -= 0.25 * 2;
    ck_assert_double_eq(dy[0], 1);
    ck_assert_double_eq(dy[3], 2);
    ck_assert_double_eq_tol(dy[4], f0x / 2, 1e-14);
    ck_assert_double_eq_tol(dy[5], f0y / 2, 1e-14);
    ck_assert_double_eq_tol(dy[6], f1x / 2, 1e-13);
    ck_assert_double_eq_tol(dy[7], f1y / 2, 1e-13);
    sw_particles_free(&p);
}
END_TEST

/* The analytic force Jacobians ∂f/∂x and ∂f/∂v against central differences
 * of the force itself, on two particles with every force at once: a damped
 * spring between them and one to an anchor (moving, so the damping force's
 * turning with the spring counts), drag, central attraction and gravity.
 * Step 1e-6 on forces of order 10: truncation ~1e-11, rounding ~1e-9; the
 * tolerance 1e-6 is far above both and far below any missing term (>= 0.1). */
START_TEST(force_jacobians_match_differences)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 2, 1.5, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 2);
    s[0] = (sw_spring){ .a = 1, .b = 0, .k = 7.0, .c = 0.8, .rest = 1.3 };
    s[1] = (sw_spring){ .a = 0, .b = -1, .k = 3.0, .c = 1.1, .rest = 0.4, .ax = 0.2, .ay = -0.1 };
    sw_particles_add_drag(&p, 0.3);
    sw_particles_add_central(&p, -1.0, 0.5, 2.0);
    sw_particles_add_gravity(&p, 0.0, -9.81);
    double y[8] = { 1.7, 0.9, 0.1, 2.2, 0.3, -0.7, 1.9, 0.4 };
    double fx[16], fv[16];
    sw_particles_jacobian(&p, y, fx, fv);
    double h = 1e-6;
    for (int col = 0; col < 8; col++) {
        double yp[8], ym[8], dp[8], dm[8];
        memcpy(yp, y, sizeof yp);
        memcpy(ym, y, sizeof ym);
        yp[col] += h;
        ym[col] -= h;
        p.ode.deriv(&p, 0.0, yp, dp);
        p.ode.deriv(&p, 0.0, ym, dm);
        for (int row = 0; row < 4; row++) {
            /* dydt[4 + row] = f_row / m: the force column is m·(dp - dm)/2h */
            double fd = 1.5 * (dp[4 + row] - dm[4 + row]) / (2 * h);
            double an = col < 4 ? fx[row * 4 + col] : fv[row * 4 + col - 4];
            ck_assert_msg(fabs(an - fd) < 1e-6, "d f%d / d y%d: analytic %.12g, differences %.12g", row,
                          col, an, fd);
        }
    }
    sw_particles_free(&p);
}
END_TEST

START_TEST(contact_restitution)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 2, 1.0, err, sizeof err), SW_OK);
    p.walls = (sw_walls){ .active = 1, .sides = SW_WALL_FLOOR | SW_WALL_RIGHT, .xmin = 0, .xmax = 5,
                          .ymin = 0, .ymax = 5, .e = 0.5 };
    double y[8] = { 1.0, -0.1, 5.2, 1.0, /* v */ 0.0, -2.0, -1.0, 0.0 };
    ck_assert_int_eq(sw_particles_contact(&p, y), 1);
    ck_assert_double_eq_tol(y[1], 0.05, 1e-15);
    ck_assert_double_eq_tol(y[5], 1.0, 1e-15);
    ck_assert_double_eq_tol(y[2], 4.9, 1e-15);
    ck_assert_double_eq(y[6], -1.0); /* already moving away: velocity kept */
    ck_assert_int_eq(sw_particles_contact(&p, y), 0);
    sw_particles_free(&p);
}
END_TEST

/* Energy: kinetic + gravity + spring + central, each from its formula. */
START_TEST(energy_terms)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 1, 2.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 1);
    *s = (sw_spring){ .a = 0, .b = -1, .k = 4.0, .rest = 1.0 };
    sw_particles_add_gravity(&p, 0.0, -10.0);
    sw_particles_add_central(&p, 0.0, 0.0, 0.5);
    double y[4] = { 0.0, 3.0, 1.0, 1.0 };
    double e = 0.5 * 2 * 2 + 2 * 10 * 3 + 0.5 * 4 * 4 - 0.5 * 2 / 3.0;
    ck_assert_double_eq_tol(sw_particles_energy(&p, y), e, 1e-13);
    sw_particles_free(&p);
}
END_TEST

Suite *make_particles_suite(void);
Suite *make_particles_suite(void)
{
    Suite *s = suite_create("particles");
    TCase *tc = tcase_create("engine");
    tcase_add_test(tc, derivative_sums_forces);
    tcase_add_test(tc, force_jacobians_match_differences);
    tcase_add_test(tc, contact_restitution);
    tcase_add_test(tc, energy_terms);
    suite_add_tcase(s, tc);
    return s;
}
