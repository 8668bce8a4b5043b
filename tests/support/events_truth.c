/* Event location's independent truths, for tests/check_events.c and the
 * claims rows (tests/support/claims_events.c): the bounce without drag in
 * closed form (contact times from the quadratic of free flight), the spring
 * through its anchor piecewise harmonic about ±rest, and the observed
 * orders measured against them. */
#include "events_truth.h"

#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure/bench.h"
#include "util/num.h"

/* ---- the bounce without drag, in closed form ------------------------------ */

/* Horizontal: uniform motion between lo and hi, the speed times -e at each wall. */
void ev_walls_at(double x, double v, double lo, double hi, double e, double t, double *xo, double *vo,
                     double *hit, int *nhit)
{
    double t_abs = 0;
    int count = 0;
    for (int hits = 0; hits < 1000 && v != 0; hits++) {
        double tw = ((v > 0 ? hi : lo) - x) / v;
        if (tw >= t)
            break;
        t -= tw;
        t_abs += tw;
        if (hit && count < *nhit)
            hit[count] = t_abs;
        count++;
        x = v > 0 ? hi : lo;
        v = -e * v;
    }
    if (nhit)
        *nhit = count;
    *xo = x + v * t;
    *vo = v;
}

/* Vertical: y = y0 + v t - g t²/2 until it lands at the larger root of the
 * quadratic, t = (v + √(v² + 2 g y0)) / g; it leaves at e times the landing
 * speed, unless that speed would lift it less than 1 mm (v² < 2 g·1e-3,
 * the scene's resting contact): then it rests at y = 0. The landing times
 * go into land[] (up to nland). */
void ev_floor_at(double y, double v, double g, double e, double t, double *yo, double *vo,
                     double *land, int *nland)
{
    double t_abs = 0;
    int count = 0;
    for (int hops = 0; hops < 1000; hops++) {
        double tl = (v + sqrt(v * v + 2.0 * g * y)) / g;
        if (tl >= t)
            break;
        t -= tl;
        t_abs += tl;
        if (land && count < *nland)
            land[count] = t_abs;
        count++;
        v = e * (g * tl - v);
        y = 0;
        if (v * v < 2.0 * g * 1e-3) {
            v = 0;
            g = 0; /* resting: the floor holds it */
            break;
        }
    }
    if (nland)
        *nland = count;
    *yo = y + v * t - 0.5 * g * t * t;
    *vo = v - g * t;
}

/* The whole state at t from the initial state y0 (n balls in a 10 x 6 box). */
static void bounce_closed(const sw_system *sys, const double *y0, double t, double *y)
{
    int n = sys->n;
    const sw_walls *w = &sys->particles.walls;
    double g = sys->p[1], e = sys->p[2];
    for (int i = 0; i < n; i++) {
        ev_walls_at(y0[2 * i], y0[2 * n + 2 * i], w->xmin, w->xmax, e, t, &y[2 * i], &y[2 * n + 2 * i], NULL, NULL);
        ev_floor_at(y0[2 * i + 1], y0[2 * n + 2 * i + 1], g, e, t, &y[2 * i + 1], &y[2 * n + 2 * i + 1],
                 NULL, NULL);
    }
}

/* ---- the spring through its anchor, piecewise in closed form -------------- */

/* x'' = -ω²(x - c) with c = +rest for x > 0 and -rest for x < 0 (no
 * damping): on each side a harmonic motion about its centre, u = x - c =
 * R cos(ω τ - φ); it reaches the anchor (u = -c) first at
 * τ = (φ + acos(-c/R)) / ω (mod the period). */
void ev_spring_closed(double k, double m, double rest, double x, double v, double t, double *xo,
                          double *vo, double *cross, int *ncross)
{
    double w = sqrt(k / m), t_abs = 0;
    int count = 0;
    for (int sides = 0; sides < 10000; sides++) {
        double c = x > 0 || (x == 0 && v > 0) ? rest : -rest;
        double u = x - c, R = hypot(u, v / w), phi = atan2(v / w, u);
        double tau = INFINITY;
        if (R > fabs(c)) {
            /* ωτ - φ = ±acos(-c/R) + 2πj: the least τ > 0 */
            double a = acos(-c / R);
            for (int j = -1; j <= 2; j++)
                for (int s = -1; s <= 1; s += 2) {
                    double cand = (phi + s * a + 2 * SW_PI * j) / w;
                    if (cand > 1e-12 && cand < tau)
                        tau = cand;
                }
        }
        if (tau >= t) {
            double cs = cos(w * t), sn = sin(w * t);
            *xo = c + u * cs + (v / w) * sn;
            *vo = -u * w * sn + v * cs;
            break;
        }
        t -= tau;
        t_abs += tau;
        if (cross && count < *ncross)
            cross[count] = t_abs;
        count++;
        double cs = cos(w * tau), sn = sin(w * tau);
        v = -u * w * sn + v * cs;
        x = 0; /* at the anchor: the sign of v says which side is next */
    }
    if (ncross)
        *ncross = count;
}

/* ---- runs ------------------------------------------------------------------ */

void ev_sim_of(sw_sim *s, const char *scene, const double *p, const char *method, double dt,
                   sw_events_mode mode)
{
    char err[SW_ERRLEN];
    const sw_integrator *m = sw_integrator_find(method);
    ck_assert_ptr_nonnull(m);
    ck_assert_msg(sw_sim_init(s, sw_scene_find(scene), p, m, dt, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(sw_sim_set_events(s, mode, err, sizeof err), SW_OK);
}

/* Largest state error at T of a run against truth (dim doubles). */
double ev_run_error(const char *scene, const double *p, const char *method, double dt,
                        sw_events_mode mode, double T, const double *truth)
{
    sw_sim s;
    ev_sim_of(&s, scene, p, method, dt, mode);
    ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    double err = 0;
    for (int i = 0; i < s.sys.ode->dim; i++)
        err = fmax(err, fabs(s.sys.y[i] - truth[i]));
    sw_sim_free(&s);
    return err;
}

/* Stepped over: six halvings of dt from 0.01 through bench's order rule
 * (sw_bench_fit, issue 38: monotone errors, local slopes that agree),
 * the same rule every printed order goes through; NaN when it refuses
 * (the errors need not fall steadily when crossings are stepped over).
 * The floor is bench's, scale·(1e-13 + 4e-16·steps), scale = max(1, |truth|). */
double ev_step_order(const char *scene, const double *p, const char *method, double T,
                         const double *truth)
{
    static sw_bench_report r;
    memset(&r, 0, sizeof r);
    r.scale = 1;
    sw_sim s;
    ev_sim_of(&s, scene, p, method, 0.01, SW_EVENTS_STEP);
    for (int i = 0; i < s.sys.ode->dim; i++)
        r.scale = fmax(r.scale, fabs(truth[i]));
    sw_sim_free(&s);
    sw_bench_series *se = &r.series[0];
    se->method = sw_integrator_find(method);
    se->npoints = 6;
    for (int j = 0; j < 6; j++) {
        sw_bench_point *pt = &se->points[j];
        pt->dt = pt->h = 0.01 / (1 << j);
        pt->error = ev_run_error(scene, p, method, pt->dt, SW_EVENTS_STEP, T, truth);
        pt->steps = (long)ceil(T / pt->dt);
        pt->floor = r.scale * (1e-13 + 4e-16 * (double)pt->steps);
    }
    double order = sw_bench_fit(&r, se);
    if (getenv("SW_CLAIMS_PRINT"))
        fprintf(stderr, "stepped over: %s %s: %.3f %s (errors %.3g %.3g %.3g %.3g %.3g %.3g)\n", scene, method, order,
                sw_bench_no_order_text(se), se->points[0].error, se->points[1].error, se->points[2].error,
                se->points[3].error, se->points[4].error, se->points[5].error);
    return order;
}

enum { B_N, B_G, B_E, B_DRAG };

/* The truth for a bounce: the closed form without drag, else dop853 at
 * rtol 1e-13 with its events located (its error, ~1e-12, is far below the
 * smallest error measured against it, ~1e-9). */
void ev_bounce_truth(const double *p, double T, double *truth)
{
    sw_sim s;
    if (p[B_DRAG] == 0) {
        ev_sim_of(&s, "bounce", p, "rk4", 0.01, SW_EVENTS_STEP);
        double y0[64];
        memcpy(y0, s.sys.y, (size_t)s.sys.ode->dim * sizeof *y0);
        bounce_closed(&s.sys, y0, T, truth);
    } else {
        ev_sim_of(&s, "bounce", p, "dop853", 0.05, SW_EVENTS_LOCATE);
        sw_sim_set_tolerances(&s, 1e-13, 1e-15);
        ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
        memcpy(truth, s.sys.y, (size_t)s.sys.ode->dim * sizeof *truth);
    }
    sw_sim_free(&s);
}

/* The observed order from errors at dt, dt/2, dt/4: the mean of log2 of
 * the two ratios (each is the order where the error is p-th order). */
double ev_observed_order(const char *scene, const double *p, const char *method, double dt,
                         sw_events_mode mode, double T, const double *truth, double *errs)
{
    for (int i = 0; i < 3; i++)
        errs[i] = ev_run_error(scene, p, method, dt / (1 << i), mode, T, truth);
    return 0.5 * (log2(errs[0] / errs[1]) + log2(errs[1] / errs[2]));
}

void ev_spring_truth(const double *p, double T, double *truth)
{
    truth[1] = truth[3] = 0;
    ev_spring_closed(p[0], p[1], p[3], p[3] + p[4], 0, T, &truth[0], &truth[2], NULL, NULL);
}
