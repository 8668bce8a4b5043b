/* The mistaken methods the explainer runs (see mistakes.h): Runge-Kutta
 * stages at the wrong time or from the wrong step, and the Verlet variants
 * students write from textbooks. Each is a step function with the
 * arithmetic a student's program would have, so a trace made that way
 * matches it to rounding. */
#include "engine/mistakes.h"

#include "engine/stepper.h"

/* ---- Runge-Kutta stages ---------------------------------------------------- */

/* Midpoint with its second stage at t instead of t + h/2. */
static int mid_at_t(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *k = SW_WORK(s, 0), *m = SW_WORK(s, 1);
    sw_ode_eval(ode, *t, y, k);
    sw_axpy(n, m, y, 0.5 * h, k);
    sw_ode_eval(ode, *t, m, k);
    sw_axpy(n, y, y, h, k);
    *t += h;
    return 0;
}

/* Heun with its second stage at t instead of t + h. */
static int heun_at_t(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *k1 = SW_WORK(s, 0), *k2 = SW_WORK(s, 1), *m = SW_WORK(s, 2);
    sw_ode_eval(ode, *t, y, k1);
    sw_axpy(n, m, y, h, k1);
    sw_ode_eval(ode, *t, m, k2);
    for (int i = 0; i < n; i++)
        y[i] += 0.5 * h * (k1[i] + k2[i]);
    *t += h;
    return 0;
}

/* RK4 with stage times c2, c3, c4, k3 from a step of k3_step·h along k2,
 * the outer weights w (1 as it should be, 2 swapped with the inner ones),
 * and in place: each stage's state built in y itself, from where the last
 * one left it, instead of from the step's own y. */
static int rk4_variant(sw_stepper *s, sw_ode *ode, double *t, double *y, double h, double c2,
                       double c3, double c4, double k3_step, double w, int in_place)
{
    int n = ode->dim;
    double *k1 = SW_WORK(s, 0), *k2 = SW_WORK(s, 1), *k3 = SW_WORK(s, 2), *k4 = SW_WORK(s, 3),
           *m = in_place ? y : SW_WORK(s, 4);
    sw_ode_eval(ode, *t, y, k1);
    sw_axpy(n, m, y, 0.5 * h, k1);
    sw_ode_eval(ode, *t + c2 * h, m, k2);
    sw_axpy(n, m, y, k3_step * h, k2);
    sw_ode_eval(ode, *t + c3 * h, m, k3);
    sw_axpy(n, m, y, h, k3);
    sw_ode_eval(ode, *t + c4 * h, m, k4);
    double v = 3.0 - w; /* the inner weight */
    for (int i = 0; i < n; i++)
        y[i] += h / 6.0 * (w * k1[i] + v * k2[i] + v * k3[i] + w * k4[i]);
    *t += h;
    return 0;
}

static int rk4_weights(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return rk4_variant(s, ode, t, y, h, 0.5, 0.5, 1.0, 0.5, 2.0, 0);
}

static int rk4_in_place(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return rk4_variant(s, ode, t, y, h, 0.5, 0.5, 1.0, 0.5, 1.0, 1);
}

static int rk4_at_t(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return rk4_variant(s, ode, t, y, h, 0.0, 0.0, 0.0, 0.5, 1.0, 0);
}

static int rk4_k3_full(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return rk4_variant(s, ode, t, y, h, 0.5, 0.5, 1.0, 1.0, 1.0, 0);
}

/* ---- Verlet ---------------------------------------------------------------- */

/* Velocity Verlet as stepwise has it (docs/scenes.md, "Stepping"), with two
 * switches: fresh evaluates a0 = a(t, x, v) every step instead of keeping
 * a1; half_v evaluates a1 at (x1, v½) instead of (x1, v + h·a0). With
 * forces that do not depend on v both give verlet's numbers. */
static int verlet_variant(sw_stepper *s, sw_ode *ode, double *t, double *y, double h, int fresh,
                          int half_v)
{
    int half = ode->dim / 2;
    double *cache = SW_WORK(s, 0), *yt = SW_WORK(s, 1);
    double *x = y, *v = y + half, *a0 = cache + half;
    if (fresh || !s->have_cache)
        sw_ode_eval(ode, *t, y, cache);
    for (int i = 0; i < half; i++) {
        double vh = v[i] + 0.5 * h * a0[i];
        yt[i] = x[i] + h * vh;
        yt[half + i] = half_v ? vh : v[i] + h * a0[i];
        x[i] = yt[i];
        v[i] = vh;
    }
    sw_ode_eval(ode, *t + h, yt, cache);
    sw_axpy(half, v, v, 0.5 * h, a0);
    s->have_cache = 1;
    *t += h;
    return 0;
}

static int verlet_half_v(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return verlet_variant(s, ode, t, y, h, 0, 1);
}

static int verlet_fresh(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return verlet_variant(s, ode, t, y, h, 1, 0);
}

static int verlet_fresh_half_v(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return verlet_variant(s, ode, t, y, h, 1, 1);
}

/* Position Verlet, drift-kick-drift: x½ = x + (h/2) v; a = a(t + h/2, x½, v);
 * v1 = v + h a; x1 = x½ + (h/2) v1. */
static int verlet_dkd(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int half = ode->dim / 2;
    double *k = SW_WORK(s, 0), *ym = SW_WORK(s, 1);
    double *x = y, *v = y + half;
    for (int i = 0; i < half; i++) {
        ym[i] = x[i] + 0.5 * h * v[i];
        ym[half + i] = v[i];
    }
    sw_ode_eval(ode, *t + 0.5 * h, ym, k);
    for (int i = 0; i < half; i++) {
        v[i] += h * k[half + i];
        x[i] = ym[i] + 0.5 * h * v[i];
    }
    *t += h;
    return 0;
}

/* Störmer's form: x1 = 2x - x_prev + h² a(t, x, v), the first step from
 * x1 = x + h v + (h²/2) a; the velocity written is (x1 - x)/h. x_prev is
 * kept in workspace vector 1 (valid while have_cache is set). */
static int verlet_stormer(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int half = ode->dim / 2;
    double *k = SW_WORK(s, 0), *prev = SW_WORK(s, 1);
    double *x = y, *v = y + half, *a = k + half;
    sw_ode_eval(ode, *t, y, k);
    for (int i = 0; i < half; i++) {
        double now = x[i];
        double next = s->have_cache ? 2.0 * now - prev[i] + h * h * a[i]
                                    : now + h * v[i] + 0.5 * h * h * a[i];
        prev[i] = now;
        x[i] = next;
        v[i] = (next - now) / h;
    }
    s->have_cache = 1;
    *t += h;
    return 0;
}

/* ---- the lists, one per method, each named in the method's row ---------- */

#define MISTAKE(shown, ord, n_evals, work, fn) \
    { .name = shown, .label = "", .order = ord, .evals = n_evals, .flags = SW_EXPLICIT, \
      .work_vectors = work, .step = fn, .summary = "" }
#define VERLET(shown, n_evals, fn) \
    { .name = shown, .label = "", .order = 2, .evals = n_evals, \
      .flags = SW_EXPLICIT | SW_NEEDS_SECOND_ORDER, .work_vectors = 2, .step = fn, .summary = "" }

static const char velocity_verlet[] = "the assignment's verlet is velocity Verlet: v½ = v + "
    "(h/2)*a0, x1 = x + h*v½, a1 = a(x1, v + h*a0), v1 = v½ + (h/2)*a1 (docs/scenes.md, "
    "'Stepping')";

const sw_mistake sw_mistakes_midpoint[] = {
    { .kind = "stage-time", .time_only = 1, .method = MISTAKE("midpoint (stage at t)", 2, 2, 2, mid_at_t),
      .hint = "midpoint with its second stage evaluated at t instead of t + h/2" },
    { .kind = NULL },
};

const sw_mistake sw_mistakes_heun[] = {
    { .kind = "stage-time", .time_only = 1, .method = MISTAKE("heun (stage at t)", 2, 2, 3, heun_at_t),
      .hint = "Heun with its second stage evaluated at t instead of t + h" },
    { .kind = NULL },
};

const sw_mistake sw_mistakes_rk4[] = {
    { .kind = "stage-time", .time_only = 1, .method = MISTAKE("rk4 (stages at t)", 4, 4, 5, rk4_at_t),
      .hint = "rk4 with every stage evaluated at the step's start t: k2 and k3 belong at t + h/2, "
              "k4 at t + h" },
    { .kind = "k3-full-step", .method = MISTAKE("rk4 (k3 from a full step)", 4, 4, 5, rk4_k3_full),
      .hint = "rk4 with k3 taken at y + h*k2 instead of y + h/2*k2" },
    { .kind = "rk4-weights", .method = MISTAKE("rk4 (weights swapped)", 4, 4, 5, rk4_weights),
      .hint = "rk4 with its weights swapped: h/6*(2*k1 + k2 + k3 + 2*k4) instead of "
              "h/6*(k1 + 2*k2 + 2*k3 + k4)" },
    { .kind = "rk4-in-place", .method = MISTAKE("rk4 (y moved in place)", 4, 4, 4, rk4_in_place),
      .hint = "rk4 that moves y itself through its stages: k2, k3 and k4 must each start from the "
              "step's own y (y + h/2*k1, y + h/2*k2, y + h*k3), kept unchanged until the last line" },
    { .kind = NULL },
};

const sw_mistake sw_mistakes_verlet[] = {
    { .kind = "verlet-half-step", .method = VERLET("verlet (a1 at v½)", 1, verlet_half_v),
      .hint = "textbook velocity Verlet, with a1 = a(x1, v½) taken at the half-step velocity",
      .fix = "this scene's forces depend on v (damping or drag), and verlet takes a1 at the "
             "predicted velocity v + h*a0 instead: a1 = a(x1, v + h*a0) (docs/scenes.md, 'Stepping')" },
    { .kind = "verlet-recomputed", .method = VERLET("verlet (a0 recomputed)", 2, verlet_fresh),
      .hint = "velocity Verlet that recomputes a0 = a(x, v) at the start of every step",
      .fix = "verlet keeps the a1 of the last step as the next a0 (one evaluation a step; it "
             "differs from a(x, v) because this scene's forces depend on v): reuse a1 instead of "
             "evaluating again (docs/scenes.md, 'Stepping')" },
    { .kind = "verlet-half-step", .method = VERLET("verlet (a0 recomputed, a1 at v½)", 2, verlet_fresh_half_v),
      .hint = "velocity Verlet that recomputes a0 = a(x, v) every step and takes a1 at the "
              "half-step velocity v½",
      .fix = "verlet takes a1 = a(x1, v + h*a0) and keeps it as the next step's a0 (it matters "
             "because this scene's forces depend on v; docs/scenes.md, 'Stepping')" },
    { .kind = "position-verlet", .method = VERLET("position verlet", 1, verlet_dkd),
      .hint = "drift-kick-drift position Verlet: x moved h/2 with v, v moved h with a at that "
              "midpoint, then x the other h/2 with the new v",
      .fix = velocity_verlet },
    { .kind = "position-verlet", .method = VERLET("stormer verlet", 1, verlet_stormer),
      .hint = "Störmer's position Verlet, x_next = 2x - x_prev + h^2*a with v written as "
              "(x_next - x)/h",
      .fix = velocity_verlet },
    { .kind = NULL },
};
