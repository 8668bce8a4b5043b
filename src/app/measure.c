/* What the app measures about accuracy and stability: the ghost's state
 * (exact, or a tight rk45 reference run in lockstep), the live error, the
 * error at the report time after a dt change, and the growth per step of
 * the stiffest mode. Moved here from app.c unchanged; the truth module in
 * sim/ is to answer these questions for every front end. */
#include "app/measure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "stepwise/base.h"

#define REF_RTOL 1e-11
#define REF_ATOL 1e-13
/* Largest headless measurement run (state components × steps) on a key press. */
#define MEASURE_BUDGET 4e7

/* Start the reference run a ghost or an error needs when there is no exact
 * solution: rk45 at tight tolerance, advanced in lockstep with the main sim. */
void sw_app_ensure_ref(sw_app *a)
{
    if (a->have_ref || !a->scene->reference || a->exact_ok)
        return;
    char err[SW_ERRLEN];
    if (sw_sim_init(&a->ref, a->scene, a->p, sw_integrator_find("rk45"), a->scene->dt, err, sizeof err) != SW_OK)
        return;
    sw_sim_set_tolerances(&a->ref, REF_RTOL, REF_ATOL);
    a->have_ref = 1;
}

/* The state the ghost shows at time t: exact, or the reference advanced to t.
 * Returns 0 when there is neither. */
static int ghost_state(sw_app *a, double t, const double **y)
{
    if (a->exact_ok) {
        if (a->ghost_t != t) { /* once per time, shared by the ghost and every error */
            a->scene->exact(&a->sims[0].sys, t, a->ghost_y);
            a->ghost_t = t;
        }
        *y = a->ghost_y;
        return 1;
    }
    sw_app_ensure_ref(a);
    if (!a->have_ref)
        return 0;
    if (a->ref.t > t + 1e-12) {
        char err[SW_ERRLEN];
        sw_sim_reset(&a->ref, err, sizeof err);
    }
    sw_sim_run_until(&a->ref, t);
    if (a->ref.blown || fabs(a->ref.t - t) > 1e-9 * fmax(1.0, t))
        return 0;
    *y = a->ref.sys.y;
    return 1;
}

const double *sw_app_ghost(sw_app *a)
{
    const double *g;
    return ghost_state(a, a->sims[0].t, &g) ? g : NULL;
}

double sw_app_error(sw_app *a, int i)
{
    const sw_sim *s = &a->sims[i];
    const double *g;
    if (s->blown || !ghost_state(a, s->t, &g))
        return NAN;
    double m = 0;
    for (int k = 0; k < s->sys.ode->dim; k++) {
        double d = fabs(s->sys.y[k] - g[k]);
        if (!(d <= m))
            m = d;
    }
    return m;
}

/* Reference state at the report time, from a fresh tight rk45 run. */
static int reference_at(const sw_app *a, double T, double *out)
{
    sw_sim r;
    char err[SW_ERRLEN];
    if (sw_sim_init(&r, a->scene, a->p, sw_integrator_find("rk45"), a->scene->dt, err, sizeof err) != SW_OK)
        return 0;
    sw_sim_set_tolerances(&r, REF_RTOL, REF_ATOL);
    int ok = sw_sim_run_until(&r, T) == 0;
    if (ok)
        memcpy(out, r.sys.y, (size_t)r.sys.ode->dim * sizeof *out);
    sw_sim_free(&r);
    return ok;
}

double sw_app_measure(sw_app *a, const sw_integrator *m, double dt)
{
    const sw_scene *sc = a->scene;
    double T = sc->duration;
    int dim = a->sims[0].sys.ode->dim;
    if (!(dt > 0) || (double)dim * (T / dt) * (m->evals > 0 ? m->evals : 1) > MEASURE_BUDGET)
        return NAN;
    int exact = a->exact_ok;
    if (!exact && !sc->reference)
        return NAN;
    double *want = malloc((size_t)dim * sizeof *want);
    sw_sim s;
    char err[SW_ERRLEN];
    double e = NAN;
    if (want && sw_sim_init(&s, sc, a->p, m, dt, err, sizeof err) == SW_OK) {
        if (sw_sim_run_until(&s, T) == 0 &&
            (exact ? sc->exact(&s.sys, s.t, want) == 0 : reference_at(a, s.t, want))) {
            e = 0;
            for (int k = 0; k < dim; k++)
                e = fmax(e, fabs(s.sys.y[k] - want[k]));
        }
        sw_sim_free(&s);
    }
    free(want);
    return e;
}

/* After a dt change: measure the error at the report time at both steps and
 * tell the student the ratio (≈ 2^order when the step halves). */
void sw_app_measure_dt_change(sw_app *a, double old_dt)
{
    const sw_integrator *m = a->sims[0].method;
    double e_old = sw_app_measure(a, m, old_dt), e_new = sw_app_measure(a, m, a->dt);
    a->meas_method[0] = a->meas_method[1] = m;
    a->meas_dt[0] = old_dt;
    a->meas_err[0] = e_old;
    a->meas_dt[1] = a->dt;
    a->meas_err[1] = e_new;
    a->nmeas = 2;
    double big = old_dt > a->dt ? e_old : e_new, small = old_dt > a->dt ? e_new : e_old;
    a->error_ratio = big / small;
    if (isfinite(a->error_ratio) && small > 0)
        snprintf(a->message, sizeof a->message,
                 "dt=%g: error at t=%.3g is %.3g (was %.3g at dt=%g): ratio %.3g, order ~%.2f",
                 a->dt, a->scene->duration, e_new, e_old, old_dt, a->error_ratio, log2(a->error_ratio));
    else
        snprintf(a->message, sizeof a->message, "dt=%g", a->dt);
}

/* Spectral radius of one step of method m on x'' = -2γx' - ω²x: step the two
 * unit states, read the 2x2 one-step matrix, take its largest |eigenvalue|.
 * Exact for every method that is linear on linear problems (all built-ins);
 * NaN for adaptive methods, whose step is not fixed. */
static double growth_per_step(const sw_integrator *m, double w, double g, double dt)
{
    if (m->flags & SW_ADAPTIVE)
        return NAN;
    sw_particles p;
    sw_stepper st;
    char err[SW_ERRLEN];
    double mat[2][2], rho = NAN;
    if (sw_particles_init(&p, 1, 1.0, err, sizeof err) != SW_OK)
        return NAN;
    sw_spring *sp = sw_particles_add_springs(&p, 1);
    if (sp && sw_stepper_init(&st, m, &p.ode, err, sizeof err) == SW_OK) {
        /* anchored 10 to the left at rest length 10: along x the force is
         * exactly -ω²x - 2γx', with a direction defined at x = 0 */
        *sp = (sw_spring){ .a = 0, .b = -1, .k = w * w, .c = 2 * g, .rest = 10.0, .ax = -10.0 };
        int ok = 1;
        for (int col = 0; col < 2 && ok; col++) {
            double t = 0;
            memset(p.y, 0, 4 * sizeof *p.y);
            p.y[col ? 2 : 0] = 1e-3;
            sw_stepper_touch(&st);
            ok = sw_stepper_step(&st, &p.ode, &t, p.y, dt) == SW_OK;
            mat[0][col] = p.y[0] / 1e-3;
            mat[1][col] = p.y[2] / 1e-3;
        }
        if (ok) {
            double tr = mat[0][0] + mat[1][1], det = mat[0][0] * mat[1][1] - mat[0][1] * mat[1][0];
            double disc = tr * tr / 4 - det;
            rho = disc >= 0 ? fabs(tr / 2) + sqrt(disc) : sqrt(fabs(det));
        }
        sw_stepper_free(&st);
    }
    sw_particles_free(&p);
    return rho;
}

int sw_app_stability(sw_app *a, double *omega_dt, double *limit, double *growth)
{
    const sw_sim *s = &a->sims[0];
    if (!a->scene->omega_max)
        return 0;
    double w = a->scene->omega_max(&s->sys), g = a->scene->damping ? a->scene->damping(&s->sys) : 0.0;
    *omega_dt = w * a->dt;
    *limit = s->method->stability;
    if (a->growth_method != s->method || a->growth_w != w || a->growth_g != g || a->growth_dt != a->dt) {
        a->growth_method = s->method;
        a->growth_w = w;
        a->growth_g = g;
        a->growth_dt = a->dt;
        a->growth = growth_per_step(s->method, w, g, a->dt);
    }
    *growth = a->growth;
    return 1;
}
