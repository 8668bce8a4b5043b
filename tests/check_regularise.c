/* The Levi-Civita regularisation (engine/regularise.c) against what it must
 * keep: the change of variables both ways, the Kepler orbit against its
 * closed form (tests/support/nystrom_run.c solves Kepler's equation, not
 * the code under test), the particle's derivative never called where the
 * field is alone, the perturbed form against a direct run of the same
 * system, the landing on the report time, the evaluations it saves at
 * e = 0.9, a run going on in the variables only from the state it left,
 * and its refusals. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "engine/regularise.h"
#include "nystrom_run.h"
#include "stepwise/base.h"

/* Run the particle p from its state to T regularised with the adaptive
 * method at tol: the state into y; the evaluations of the regularised
 * system and of the particle's own into ev[0], ev[1]. */
static int lc_run(sw_particles *p, int central, const char *method, double tol, double T, double y[4], long ev[2])
{
    sw_lc lc;
    sw_stepper s;
    char err[SW_ERRLEN];
    double w[SW_LC_DIM];
    ck_assert_int_eq(central ? sw_lc_init_central(&lc, &p->ode, err, sizeof err)
                             : sw_lc_init(&lc, &p->ode, 0.0, 0.0, 1.0, err, sizeof err),
                     SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &lc.ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = tol;
    ck_assert_int_eq(sw_lc_from(&lc, 0.0, p->y, w), SW_OK);
    long base0 = p->ode.evals;
    int rc = sw_lc_run_until(&lc, &s, w, T, y);
    ev[0] = lc.ode.evals, ev[1] = p->ode.evals - base0;
    sw_stepper_free(&s);
    return rc;
}

static double max_err4(const double *a, const double *b)
{
    double e = 0;
    for (int i = 0; i < 4; i++)
        e = fmax(e, fabs(a[i] - b[i]));
    return e;
}

/* From [x | v] and back, in every quadrant and on both axes (the square
 * root's two branches and the negative real axis, where u is imaginary):
 * within 8 ulps of the largest component (a square, a square root and a
 * division each way). The energy is |v|²/2 - mu/r. */
START_TEST(change_of_variables_round_trip)
{
    sw_lc lc;
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 1, 1.0, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_lc_init(&lc, &p.ode, 0.25, -0.5, 2.0, err, sizeof err), SW_OK);
    const double pts[][4] = { { 1.3, 0.4, -0.2, 1.1 }, { -2.0, 0.7, 0.3, -0.9 }, { -1.5, -0.5, 1.0, 0.0 },
                              { 0.9, -1.7, 0.0, 0.0 }, { -3.0, -0.5, 0.5, 0.25 }, { 0.25, 2.5, -1.0, 0.0 },
                              { 0.25 + 1e-3, -0.5, 0.0, 40.0 } };
    for (size_t k = 0; k < sizeof pts / sizeof *pts; k++) {
        double w[SW_LC_DIM], y[4];
        ck_assert_int_eq(sw_lc_from(&lc, 1.5, pts[k], w), SW_OK);
        ck_assert(w[0] >= 0 && w[5] == 1.5);
        sw_lc_to(&lc, w, y);
        double scale = 0;
        for (int i = 0; i < 4; i++)
            scale = fmax(scale, fabs(pts[k][i]));
        ck_assert_msg(max_err4(y, pts[k]) <= 8 * 0x1p-52 * scale, "point %zu: off by %g", k, max_err4(y, pts[k]));
        double d1 = pts[k][0] - 0.25, d2 = pts[k][1] + 0.5;
        double h = 0.5 * (pts[k][2] * pts[k][2] + pts[k][3] * pts[k][3]) - 2.0 / hypot(d1, d2);
        ck_assert(fabs(w[4] - h) <= 4 * 0x1p-52 * fabs(h) + 1e-300);
    }
    double at_centre[4] = { 0.25, -0.5, 1.0, 0.0 }, w[SW_LC_DIM];
    ck_assert_int_eq(sw_lc_from(&lc, 0.0, at_centre, w), SW_EINVAL);
    sw_particles_free(&p);
}
END_TEST

/* The orbit at e = 0.5 and 0.9 over two periods (from perihelion to
 * perihelion, the hardest place to be measured), dop853 at 1e-12 in s,
 * against Kepler's closed form: within 1e-8 (the run's own error is about
 * 1e-10 at this tolerance; the bound leaves a factor of 100). Alone in the
 * field, the particle's own derivative is never called. */
START_TEST(kepler_against_closed_form)
{
    const double es[] = { 0.5, 0.9 };
    for (int k = 0; k < 2; k++) {
        sw_particles p;
        double y[4], ref[4], T = 4 * M_PI;
        long ev[2];
        nys_particle(&p, 1, es[k], 0.0);
        ck_assert_int_eq(lc_run(&p, 1, "dop853", 1e-12, T, y, ev), SW_OK);
        nys_kepler_exact(es[k], T, ref);
        ck_assert_msg(max_err4(y, ref) <= 1e-8, "e = %g: error %g", es[k], max_err4(y, ref));
        ck_assert_int_eq(ev[1], 0);
        ck_assert(ev[0] > 0);
        sw_particles_free(&p);
    }
}
END_TEST

/* Every report time is landed on: rk45 at 1e-10 to T = 1, 5.3 and 4π
 * (mid-orbit, near the apocentre, the pericentre) within 1e-6 of the
 * closed form (rk45's own error there is about 1e-8); the clock ends on T
 * exactly; and steps of at most dt in t never pass t + dt. */
START_TEST(runs_land_on_the_report_time)
{
    const double Ts[] = { 1.0, 5.3, 4 * M_PI };
    for (int k = 0; k < 3; k++) {
        sw_particles p;
        double y[4], ref[4];
        long ev[2];
        nys_particle(&p, 1, 0.9, 0.0);
        ck_assert_int_eq(lc_run(&p, 1, "rk45", 1e-10, Ts[k], y, ev), SW_OK);
        nys_kepler_exact(0.9, Ts[k], ref);
        ck_assert_msg(max_err4(y, ref) <= 1e-6, "T = %g: error %g", Ts[k], max_err4(y, ref));
        sw_particles_free(&p);
    }
    sw_particles p;
    sw_lc lc;
    sw_stepper s;
    char err[SW_ERRLEN];
    double w[SW_LC_DIM];
    nys_particle(&p, 1, 0.9, 0.0);
    ck_assert_int_eq(sw_lc_init_central(&lc, &p.ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("dop853"), &lc.ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_lc_from(&lc, 0.0, p.y, w), SW_OK);
    int landed = 0;
    for (int j = 1; j <= 400; j++) {
        double t0 = w[5];
        ck_assert_int_eq(sw_lc_step(&lc, &s, w, 0.05), SW_OK);
        ck_assert(w[5] > t0 && w[5] <= t0 + 0.05);
        landed += w[5] == t0 + 0.05;
    }
    ck_assert(landed > 0 && w[5] > 1.0);
    sw_stepper_free(&s);
    sw_particles_free(&p);
}
END_TEST

/* With another force the perturbed equations run (the particle's own
 * derivative called once per evaluation): a Kepler orbit at e = 0.7 under
 * a uniform pull (0.05, -0.1) and drag 0.02, to T = 7, regularised at
 * 1e-12 against a direct dop853 run at 1e-13. Within 1e-7: each run's
 * error is about 1e-10, and the bound leaves a factor of 1000 for the
 * close pass. The pure field alone gives the same orbit through either
 * form (sw_lc_init with the field's own centre and mu). */
START_TEST(perturbed_against_direct_run)
{
    sw_particles p, q;
    char err[SW_ERRLEN];
    double y[4], T = 7.0;
    long ev[2];
    nys_particle(&p, 1, 0.7, 0.0);
    ck_assert_int_eq(sw_particles_add_gravity(&p, 0.05, -0.1), SW_OK);
    ck_assert_int_eq(sw_particles_add_drag(&p, 0.02), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    nys_particle(&q, 1, 0.7, 0.0);
    ck_assert_int_eq(sw_particles_add_gravity(&q, 0.05, -0.1), SW_OK);
    ck_assert_int_eq(sw_particles_add_drag(&q, 0.02), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&q, err, sizeof err), SW_OK);
    ck_assert_int_eq(lc_run(&p, 0, "dop853", 1e-12, T, y, ev), SW_OK);
    ck_assert_int_eq(ev[1], ev[0]);
    sw_stepper s;
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("dop853"), &q.ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = 1e-13;
    double t = 0;
    while (t < T)
        ck_assert_int_eq(sw_stepper_step(&s, &q.ode, &t, q.y, T - t), SW_OK);
    ck_assert_msg(max_err4(y, q.y) <= 1e-7, "perturbed: %g", max_err4(y, q.y));
    /* the drag took energy: the orbit is not the unperturbed one */
    double ref[4];
    nys_kepler_exact(0.7, T, ref);
    ck_assert(max_err4(y, ref) > 1e-3);
    sw_stepper_free(&s);
    sw_particles_free(&p);
    sw_particles_free(&q);
}
END_TEST

/* What it is for: on the orbit at e = 0.9 to 4π at equal tolerance (1e-9,
 * 1e-6), dop853 regularised needs under a third of the evaluations dop853
 * needs on the orbit itself, and its error is the smaller (the bench's
 * equal-error comparison is in docs/performance.md; issue 26). */
START_TEST(fewer_evaluations_at_the_close_pass)
{
    const double tols[] = { 1e-6, 1e-9 };
    for (int k = 0; k < 2; k++) {
        sw_particles p, q;
        double y[4], ref[4], T = 4 * M_PI, t = 0;
        long ev[2];
        char err[SW_ERRLEN];
        nys_particle(&p, 1, 0.9, 0.0);
        ck_assert_int_eq(lc_run(&p, 1, "dop853", tols[k], T, y, ev), SW_OK);
        nys_particle(&q, 1, 0.9, 0.0);
        sw_stepper s;
        ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("dop853"), &q.ode, err, sizeof err), SW_OK);
        s.rtol = s.atol = tols[k];
        while (t < T)
            ck_assert_int_eq(sw_stepper_step(&s, &q.ode, &t, q.y, T - t), SW_OK);
        nys_kepler_exact(0.9, T, ref);
        ck_assert_msg(3 * ev[0] < q.ode.evals, "tol %g: %ld regularised, %ld direct", tols[k], ev[0], q.ode.evals);
        ck_assert_msg(max_err4(y, ref) < max_err4(q.y, ref), "tol %g: errors %g regularised, %g direct", tols[k],
                      max_err4(y, ref), max_err4(q.y, ref));
        sw_stepper_free(&s);
        sw_particles_free(&p);
        sw_particles_free(&q);
    }
}
END_TEST

/* A run goes on in the variables only from the state its last step left
 * (sw_lc_resume): with the same system, field, time and state, bit for
 * bit, it keeps w (here an energy 1e-9 off the one [x | v] gives, as a
 * step's error leaves it), once; one ulp off in the state or the time,
 * another system, or a field not alone, and w is taken from the particle. */
START_TEST(goes_on_only_from_the_state_left)
{
    sw_particles p, q;
    sw_lc lc, other;
    sw_lc_left left = { 0 };
    char err[SW_ERRLEN];
    double y[4], w[SW_LC_DIM];
    nys_particle(&p, 1, 0.9, 0.0);
    nys_particle(&q, 1, 0.9, 0.0);
    ck_assert_int_eq(sw_lc_init_central(&lc, &p.ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_lc_init_central(&other, &q.ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_lc_resume(&left, &lc, 0.0, p.y), 0); /* nothing left yet */
    ck_assert_int_eq(sw_lc_from(&lc, 0.0, p.y, w), SW_OK);
    ck_assert(memcmp(left.w, w, sizeof w) == 0);
    left.w[4] += 1e-9;
    left.w[5] = 0.5;
    double kept[SW_LC_DIM];
    memcpy(kept, left.w, sizeof kept);
    sw_lc_leave(&left, &lc, y);
    ck_assert_int_eq(sw_lc_resume(&left, &lc, 0.5, y), 1);
    ck_assert(memcmp(left.w, kept, sizeof kept) == 0);
    ck_assert_int_eq(sw_lc_from(&lc, 0.5, y, w), SW_OK);
    ck_assert(fabs(w[4] - kept[4]) > 5e-10); /* what the particle would have given */
    ck_assert_int_eq(sw_lc_resume(&left, &lc, 0.5, y), 0); /* the key is spent */
    for (int k = 0; k < 4; k++) {
        memcpy(left.w, kept, sizeof kept);
        sw_lc_leave(&left, &lc, y);
        double t = 0.5, z[4];
        memcpy(z, y, sizeof z);
        sw_lc *in = &lc;
        if (k == 0)
            z[0] = nextafter(z[0], 2.0);
        else if (k == 1)
            t = nextafter(t, 1.0);
        else if (k == 2)
            in = &other;
        else
            lc.alone = 0;
        ck_assert_int_eq(sw_lc_resume(&left, in, t, z), 0);
        ck_assert_int_eq(sw_lc_from(in, t, z, w), SW_OK);
        ck_assert_msg(memcmp(left.w, w, sizeof w) == 0, "case %d: not the particle's w", k);
    }
    sw_particles_free(&p);
    sw_particles_free(&q);
}
END_TEST

/* Refused, with a message: more than one particle, no field, mu <= 0. */
START_TEST(refusals_say_what_fits)
{
    sw_particles p;
    sw_lc lc;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 2, 1.0, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_add_central(&p, 0, 0, 1.0), SW_OK);
    ck_assert_int_eq(sw_lc_init(&lc, &p.ode, 0, 0, 1.0, err, sizeof err), SW_EINVAL);
    ck_assert(strstr(err, "one particle") != NULL);
    sw_particles_free(&p);
    ck_assert_int_eq(sw_particles_init(&p, 1, 1.0, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_add_gravity(&p, 0, -1), SW_OK);
    ck_assert_int_eq(sw_lc_init_central(&lc, &p.ode, err, sizeof err), SW_EINVAL);
    ck_assert(strstr(err, "central field") != NULL);
    ck_assert_int_eq(sw_lc_init(&lc, &p.ode, 0, 0, -1.0, err, sizeof err), SW_EINVAL);
    ck_assert(strstr(err, "mu > 0") != NULL);
    ck_assert_int_eq(sw_lc_init(&lc, &p.ode, 0, 0, 1.0, err, sizeof err), SW_OK);
    ck_assert_int_eq(lc.alone, 0);
    sw_particles_free(&p);
}
END_TEST

Suite *make_regularise_suite(void);
Suite *make_regularise_suite(void)
{
    Suite *s = suite_create("regularise");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, change_of_variables_round_trip);
    tcase_add_test(tc, kepler_against_closed_form);
    tcase_add_test(tc, runs_land_on_the_report_time);
    tcase_add_test(tc, perturbed_against_direct_run);
    tcase_add_test(tc, fewer_evaluations_at_the_close_pass);
    tcase_add_test(tc, goes_on_only_from_the_state_left);
    tcase_add_test(tc, refusals_say_what_fits);
    suite_add_tcase(s, tc);
    return s;
}
