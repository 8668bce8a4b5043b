/* The particle engine: derivative evaluation as the lecture describes it,
 * Jacobian blocks against independent finite differences and closed forms,
 * wall contact with restitution, and the flow-field solve. */
#include <check.h>
#include <math.h>

#include "stepwise/stepwise.h"
#include "stepwise/particles.h"

/* Force on particle i from the derivative (a·m), for finite differences. */
static void force_on(sw_particles *p, const double *y, int i, double f[2])
{
    double dy[16];
    p->ode.deriv(p, 0.0, y, dy);
    f[0] = dy[2 * p->n + 2 * i] * p->mass[i];
    f[1] = dy[2 * p->n + 2 * i + 1] * p->mass[i];
}

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

/* Analytic ∂f/∂x of a stretched anchor spring against central differences of
 * the force (no damping, so the Baraff-Witkin form is the full Jacobian);
 * ∂f/∂v against the closed form -c u uᵀ, and drag's -k I. Tolerance 1e-6:
 * central differences with h = 1e-5 on forces of order 10. */
START_TEST(spring_and_drag_jacobians)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 1, 1.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 1);
    *s = (sw_spring){ .a = 0, .b = -1, .k = 7.0, .c = 0.0, .rest = 1.3, .ax = 0.2, .ay = -0.1 };
    double y[4] = { 1.7, 0.9, 0, 0 }, jx[3], jv[3];
    sw_particles_jacobian_diag(&p, y, 0, jx, jv);
    double h = 1e-5, fd[2][2];
    for (int d = 0; d < 2; d++) {
        double yp[4] = { y[0], y[1], 0, 0 }, ym[4] = { y[0], y[1], 0, 0 }, fp[2], fm[2];
        yp[d] += h;
        ym[d] -= h;
        force_on(&p, yp, 0, fp);
        force_on(&p, ym, 0, fm);
        fd[0][d] = (fp[0] - fm[0]) / (2 * h);
        fd[1][d] = (fp[1] - fm[1]) / (2 * h);
    }
    ck_assert_double_eq_tol(jx[0], fd[0][0], 1e-6);
    ck_assert_double_eq_tol(jx[1], fd[0][1], 1e-6);
    ck_assert_double_eq_tol(jx[1], fd[1][0], 1e-6);
    ck_assert_double_eq_tol(jx[2], fd[1][1], 1e-6);
    sw_particles_free(&p);

    ck_assert_int_eq(sw_particles_init(&p, 1, 1.0, err, sizeof err), SW_OK);
    s = sw_particles_add_springs(&p, 1);
    *s = (sw_spring){ .a = 0, .b = -1, .k = 1.0, .c = 2.0, .rest = 0.0 };
    sw_particles_add_drag(&p, 0.5);
    double y2[4] = { 3.0, 4.0, 0, 0 };
    sw_particles_jacobian_diag(&p, y2, 0, jx, jv);
    /* u = (0.6, 0.8): -c u uᵀ - k_drag I */
    ck_assert_double_eq_tol(jv[0], -2.0 * 0.36 - 0.5, 1e-15);
    ck_assert_double_eq_tol(jv[1], -2.0 * 0.48, 1e-15);
    ck_assert_double_eq_tol(jv[2], -2.0 * 0.64 - 0.5, 1e-15);
    sw_particles_free(&p);
}
END_TEST

/* The finite-difference block for central attraction against its closed form
 * ∂f/∂x = -μm (I/r³ - 3 x xᵀ/r⁵). */
START_TEST(central_jacobian_fd)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 1, 2.0, err, sizeof err), SW_OK);
    sw_particles_add_central(&p, 0.0, 0.0, 3.0);
    double y[4] = { 0.6, -0.8, 0, 0 }, jx[3], jv[3];
    sw_particles_jacobian_diag(&p, y, 0, jx, jv);
    double r = 1.0, mm = 3.0 * 2.0;
    double xx = -mm * (1 / (r * r * r) - 3 * 0.36 / pow(r, 5)), xy = -mm * (-3 * -0.48 / pow(r, 5)),
           yy = -mm * (1 / (r * r * r) - 3 * 0.64 / pow(r, 5));
    ck_assert_double_eq_tol(jx[0], xx, 1e-6);
    ck_assert_double_eq_tol(jx[1], xy, 1e-6);
    ck_assert_double_eq_tol(jx[2], yy, 1e-6);
    sw_particles_free(&p);
}
END_TEST

/* Contact: a ball 0.1 below the floor moving down at 2 with e = 0.5 comes back
 * to 0.05 above it moving up at 1; a ball leaving the wall is only moved. */
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
    tcase_add_test(tc, spring_and_drag_jacobians);
    tcase_add_test(tc, central_jacobian_fd);
    tcase_add_test(tc, contact_restitution);
    tcase_add_test(tc, energy_terms);
    suite_add_tcase(s, tc);
    return s;
}
