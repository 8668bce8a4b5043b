/* The engine's Nyström methods (rkn, rkn12) in the tests' hands
 * (nystrom_run.h): a particle on a spring or an orbit, fixed or controlled
 * steps, the two entries' bits, the refusal of velocity forces. */
#include "nystrom_run.h"

#include <check.h>
#include <math.h>
#include <string.h>

#include "engine/ode_fast.h"
#include "engine/stepper.h"
#include "stepwise/flow.h"
#include "stepwise/particles.h"
#include "stepwise/sim.h"
#include "stepwise/stepwise.h"

void nys_oscillator(const long double x[2], long double a[2])
{
    a[0] = -x[0];
    a[1] = -x[1];
}

void nys_kepler(const long double x[2], long double a[2])
{
    long double r = sqrtl(x[0] * x[0] + x[1] * x[1]), r3 = r * r * r;
    a[0] = -x[0] / r3;
    a[1] = -x[1] / r3;
}

/* Kepler's ellipse (a = 1, μ = 1) of eccentricity e from perihelion
 * (1 - e, 0), anticlockwise, at time t: Newton on E - e sin E = t. */
void nys_kepler_exact(double e, double t, double out[4])
{
    double b = sqrt(1 - e * e), M = fmod(t, 2 * M_PI), E = M + e * sin(M);
    for (int i = 0; i < 100; i++)
        E -= (E - e * sin(E) - M) / (1 - e * cos(E));
    double den = 1 - e * cos(E);
    out[0] = cos(E) - e;
    out[1] = b * sin(E);
    out[2] = -sin(E) / den;
    out[3] = b * cos(E) / den;
}

/* The oscillator x = (cos t, 0) at t. */
void nys_oscillator_exact(double t, double out[4])
{
    out[0] = cos(t);
    out[1] = 0;
    out[2] = -sin(t);
    out[3] = 0;
}

double nys_max_err(const double *a, const long double *b)
{
    double m = 0;
    for (int i = 0; i < 4; i++)
        m = fmax(m, fabs(a[i] - (double)b[i]));
    return m;
}

/* Least-squares slope of log e against log h. */
double nys_slope(const double *h, const double *e, int n)
{
    double sx = 0, sy = 0, num = 0, den = 0;
    for (int j = 0; j < n; j++)
        sx += log(h[j]), sy += log(e[j]);
    for (int j = 0; j < n; j++) {
        num += (log(h[j]) - sx / n) * (log(e[j]) - sy / n);
        den += (log(h[j]) - sx / n) * (log(h[j]) - sx / n);
    }
    return num / den;
}

/* ---- the engine's method with fixed steps ----------------------------------- */

/* One particle of mass 1: on a zero-rest-length spring k = 1 (c = damping)
 * to the origin from (1, 0) at rest, or (kepler) about a central body μ = 1
 * from perihelion of the ellipse of eccentricity e. */
void nys_particle(sw_particles *p, int kepler_orbit, double e, double c)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(p, 1, 1.0, err, sizeof err), SW_OK);
    if (kepler_orbit) {
        ck_assert_int_eq(sw_particles_add_central(p, 0, 0, 1.0), SW_OK);
        p->y[0] = 1 - e;
        p->y[3] = sqrt((1 + e) / (1 - e));
    } else {
        sw_spring *sp = sw_particles_add_springs(p, 1);
        ck_assert_ptr_nonnull(sp);
        *sp = (sw_spring){ .a = 0, .b = -1, .k = 1.0, .c = c, .rest = 0.0 };
        p->y[0] = 1.0;
    }
    ck_assert_int_eq(sw_particles_finish(p, err, sizeof err), SW_OK);
}

void nys_fixed(const char *method, int kepler_orbit, double e, double h, long n, double y[4], long *evals)
{
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    nys_particle(&p, kepler_orbit, e, 0.0);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &p.ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = 1e300;
    s.h_next = h;
    double t = 0;
    for (long i = 0; i < n; i++) {
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, h), SW_OK);
        ck_assert_double_eq(s.h_last, h);
    }
    ck_assert_int_eq(s.rejected, 0);
    memcpy(y, p.y, 4 * sizeof *y);
    *evals = p.ode.evals;
    sw_stepper_free(&s);
    sw_particles_free(&p);
}

static void start(int kepler_orbit, double e, long double y[4])
{
    y[0] = kepler_orbit ? 1 - e : 1;
    y[1] = y[2] = 0;
    y[3] = kepler_orbit ? sqrtl((1 + (long double)e) / (1 - (long double)e)) : 0;
}

static double error_of(const double y[4], int kepler_orbit, double e, double T)
{
    double want[4], worst = 0;
    if (kepler_orbit)
        nys_kepler_exact(e, T, want);
    else
        nys_oscillator_exact(T, want);
    for (int i = 0; i < 4; i++)
        worst = fmax(worst, fabs(y[i] - want[i]));
    return worst;
}

double nys_engine_error(const char *method, int kepler_orbit, double e, double T, long n)
{
    double y[4];
    long evals;
    nys_fixed(method, kepler_orbit, e, T / n, n, y, &evals);
    return error_of(y, kepler_orbit, e, T);
}

double nys_tableau_error(const nys_tableau *tb, const long double *wx, const long double *wv, int kepler_orbit,
                         double e, double T, long n)
{
    long double ly[4];
    double y[4];
    start(kepler_orbit, e, ly);
    nys_steps(tb, kepler_orbit ? nys_kepler : nys_oscillator, wx, wv, (long double)T / n, n, ly);
    for (int i = 0; i < 4; i++)
        y[i] = (double)ly[i];
    return error_of(y, kepler_orbit, e, T);
}

void nys_engine_is_tableau(const char *method, const nys_tableau *tb, const long double *bx, const long double *bv,
                           const double h[2], int per_step, double tol)
{
    for (int k = 0; k < 2; k++) {
        double y[4];
        long double ly[4];
        long evals;
        nys_fixed(method, k, 0.5, h[k], 40, y, &evals);
        ck_assert_int_eq(evals, 1 + per_step * 40);
        start(k, 0.5, ly);
        nys_steps(tb, k ? nys_kepler : nys_oscillator, bx, bv, h[k], 40, ly);
        ck_assert_msg(nys_max_err(y, ly) < tol, "%s %s: engine and tableau differ by %g", method,
                      k ? "orbit" : "oscillator", nys_max_err(y, ly));
    }
}

/* The two entries of the step are one computation: the method steps a single
 * particle (state 4) through a copy of its body with d = 2 fixed, and any
 * larger state through the general one. Three particles about the same
 * centre, none acting on another, go through the general entry; each must
 * end on the very bits (no tolerance) of its own one-particle run, stepped
 * with the same fixed h (40 steps of 0.05; orbits at e = 0, 0.5, 0.9). */
void nys_one_particle_same_bits(const char *method)
{
    const double e[3] = { 0.0, 0.5, 0.9 }, h = 0.05;
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 3, 1.0, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_add_central(&p, 0, 0, 1.0), SW_OK);
    for (int i = 0; i < 3; i++) {
        p.y[2 * i] = 1 - e[i];
        p.y[6 + 2 * i + 1] = sqrt((1 + e[i]) / (1 - e[i]));
    }
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &p.ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = 1e300;
    s.h_next = h;
    double t = 0;
    for (int j = 0; j < 40; j++)
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, h), SW_OK);
    for (int i = 0; i < 3; i++) {
        double one[4];
        long evals;
        nys_fixed(method, 1, e[i], h, 40, one, &evals);
        const double many[4] = { p.y[2 * i], p.y[2 * i + 1], p.y[6 + 2 * i], p.y[6 + 2 * i + 1] };
        ck_assert_msg(memcmp(one, many, sizeof one) == 0, "e = %g: one particle (%.17g, %.17g) but in three (%.17g, %.17g)",
                      e[i], one[0], one[1], many[0], many[1]);
    }
    sw_stepper_free(&s);
    sw_particles_free(&p);
}

/* The method under error control at rtol = atol = tol over [0, T]; the error
 * against the closed form at T, the evaluations, and (if not NULL) the
 * smallest and largest accepted step with the radius where each was taken. */
double nys_controlled(const char *method, int kepler_orbit, double e, double T, double tol, long *evals,
                      double steps[4])
{
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    nys_particle(&p, kepler_orbit, e, 0.0);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &p.ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = tol;
    double t = 0, want[4];
    if (steps)
        steps[0] = INFINITY, steps[2] = 0;
    while (T - t > 1e-12) {
        double r = hypot(p.y[0], p.y[1]);
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, T - t), SW_OK);
        if (steps && T - t > 1e-12) { /* (the last step is cut to land on T) */
            if (s.h_last < steps[0])
                steps[0] = s.h_last, steps[1] = r;
            if (s.h_last > steps[2])
                steps[2] = s.h_last, steps[3] = r;
        }
    }
    if (kepler_orbit)
        nys_kepler_exact(e, t, want);
    else
        nys_oscillator_exact(t, want);
    double m = 0;
    for (int i = 0; i < 4; i++)
        m = fmax(m, fabs(p.y[i] - want[i]));
    *evals = p.ode.evals;
    sw_stepper_free(&s);
    sw_particles_free(&p);
    return m;
}

/* A damped spring, drag, and a flow field are refused with a message that
 * says why and what to use; the same spring undamped, and drag of k = 0,
 * are accepted. */
void nys_refuses_velocity_forces(const char *method)
{
    const sw_integrator *m = sw_integrator_find(method);
    ck_assert_ptr_nonnull(m);
    char err[SW_ERRLEN];
    sw_stepper s;
    sw_particles p;
    nys_particle(&p, 0, 0, 0.5);
    err[0] = '\0';
    ck_assert_int_eq(sw_stepper_init(&s, m, &p.ode, err, sizeof err), SW_EINVAL);
    ck_assert_msg(strstr(err, "velocities") && strstr(err, "dop853") && !strchr(err, '\n'), "message: %s", err);
    sw_particles_free(&p);

    nys_particle(&p, 1, 0.5, 0);
    ck_assert_int_eq(sw_particles_add_drag(&p, 0.1), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, m, &p.ode, err, sizeof err), SW_EINVAL);
    sw_particles_free(&p);

    nys_particle(&p, 1, 0.5, 0);
    ck_assert_int_eq(sw_particles_add_drag(&p, 0.0), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, m, &p.ode, err, sizeof err), SW_OK);
    sw_stepper_free(&s);
    sw_particles_free(&p);

    nys_particle(&p, 0, 0, 0.0);
    ck_assert_int_eq(sw_stepper_init(&s, m, &p.ode, err, sizeof err), SW_OK);
    sw_stepper_free(&s);
    sw_particles_free(&p);

    /* scenes: the damped spring (its default) refused, the orbit accepted */
    sw_sim sim;
    ck_assert_int_eq(sw_sim_init(&sim, sw_scene_find("spring"), NULL, m, 0.01, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_sim_init(&sim, sw_scene_find("orbit"), NULL, m, 0.01, err, sizeof err), SW_OK);
    sw_sim_free(&sim);
    ck_assert_int_eq(sw_sim_init(&sim, sw_scene_find("vortex"), NULL, m, 0.01, err, sizeof err), SW_EINVAL);
    ck_assert_msg(strstr(err, "first-order"), "flow message: %s", err);
}

void nys_tolerance_proportional(const char *method, double tol0)
{
    for (int k = 0; k < 2; k++) {
        double prev = NAN;
        for (int j = 0; j < 4; j++) {
            double tol = tol0 * pow(1e-2, j);
            long evals;
            double e = nys_controlled(method, k, 0.5, k ? 2 * M_PI : 30.0, tol, &evals, NULL);
            ck_assert_msg(e <= 100 * tol, "%s, %s tol %g: error %g", method, k ? "orbit" : "oscillator", tol, e);
            if (j > 0)
                ck_assert_msg(e < prev / 20 && e > prev / 1000, "%s, %s tol %g: error %g after %g", method,
                              k ? "orbit" : "oscillator", tol, e, prev);
            prev = e;
        }
    }
}

void nys_controlled_300(const char *method, sw_particles *p, int inline_path, double y[4], long counts[3])
{
    sw_stepper s;
    char err[SW_ERRLEN];
    struct sw_ode_fast without = *p->ode.fast;
    without.central1 = NULL;
    without.spring1 = NULL;
    sw_ode ode = p->ode;
    if (!inline_path)
        ode.fast = &without;
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = 1e-10;
    double t = 0;
    for (int j = 0; j < 300; j++)
        ck_assert_int_eq(sw_stepper_step(&s, &ode, &t, p->y, 1e9), SW_OK);
    memcpy(y, p->y, 4 * sizeof *y);
    counts[0] = s.accepted, counts[1] = s.rejected, counts[2] = ode.evals;
    sw_stepper_free(&s);
}

/* One particle (mass 2.5) on one anchored spring (anchor (0.3, -0.2),
 * k = 4e4, rest 1.3) under gravity (0.7, -9.81), started off its rest
 * length and moving; `more`: 0 that alone, 1 a second spring, 2 the spring
 * damped, 3 a second particle, 4 a resting floor, 5 no gravity. */
static void spring1_particle(sw_particles *p, int more)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(p, more == 3 ? 2 : 1, 2.5, err, sizeof err), SW_OK);
    for (int j = 0; j < (more == 1 ? 2 : 1); j++) {
        sw_spring *sp = sw_particles_add_springs(p, 1);
        ck_assert_ptr_nonnull(sp);
        *sp = (sw_spring){ .a = 0, .b = -1, .k = 4e4, .c = more == 2 ? 0.5 : 0.0, .rest = 1.3, .ax = 0.3 + j,
                           .ay = -0.2 };
    }
    if (more != 5)
        ck_assert_int_eq(sw_particles_add_gravity(p, 0.7, -9.81), SW_OK);
    if (more == 4) {
        p->walls.sides = SW_WALL_FLOOR;
        p->walls.ymin = -10.0;
        p->walls.rest = 0.1;
    }
    p->y[0] = 0.3 + 0.9, p->y[1] = -0.2 - 1.0, p->y[2 * p->n] = 0.4, p->y[2 * p->n + 1] = -0.3;
    ck_assert_int_eq(sw_particles_finish(p, err, sizeof err), SW_OK);
}

/* 300 steps under control at 1e-10, with the spring inline or through the
 * derivative (a copy of the system with spring1 taken away). */
static void spring1_run(const char *method, int inline_spring, int gravity, double y[4], long counts[3])
{
    sw_particles p;
    sw_spring1 sp;
    spring1_particle(&p, gravity ? 0 : 5);
    ck_assert_int_eq(sw_ode_spring1(&p.ode, &sp), 1);
    ck_assert(sp.ax == 0.3 && sp.ay == -0.2 && sp.k == 4e4 && sp.rest == 1.3 && sp.inv == 1 / 2.5 &&
              sp.gravity == gravity);
    nys_controlled_300(method, &p, inline_spring, y, counts);
    sw_particles_free(&p);
}

void nys_spring_inline_same_bits(const char *method)
{
    for (int gravity = 0; gravity < 2; gravity++) {
        double a[4], b[4];
        long ca[3], cb[3];
        spring1_run(method, 1, gravity, a, ca);
        spring1_run(method, 0, gravity, b, cb);
        ck_assert_msg(memcmp(a, b, sizeof a) == 0, "inline (%.17g, %.17g, %.17g, %.17g), through the derivative "
                      "(%.17g, %.17g, %.17g, %.17g)", a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]);
        ck_assert(ca[0] == cb[0] && ca[1] == cb[1] && ca[2] == cb[2]);
        ck_assert_int_gt(ca[1], 0); /* the run did reject trials: a path the two share too */
    }
    for (int more = 1; more <= 4; more++) {
        sw_particles p;
        sw_spring1 sp;
        spring1_particle(&p, more);
        ck_assert_msg(sw_ode_spring1(&p.ode, &sp) == 0, "case %d offers the inline spring", more);
        sw_particles_free(&p);
    }
}
