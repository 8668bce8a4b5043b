/* Flow-field scenes: massless points carried by x' = g(x, t) (the lecture's
 * "particle in a flow field"). They have positions only: no masses, no
 * velocities, no forces. Seeds are pure functions of the index, so exact
 * paths and invariants can be recomputed without storing the start. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine/pointwise.h"
#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/num.h"


int sw_scene_flow(sw_system *sys, int n, const sw_point_field *pf, sw_field_jac_fn *jac, char *err,
                  size_t errlen)
{
    int rc = sw_flow_init(&sys->flow, n, pf->field, jac, sys->p, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_flow_fuse(&sys->flow, pf);
    sys->kind = SW_SYS_FLOW;
    sys->n = n;
    sys->ode = &sys->flow.ode;
    sys->y = sys->flow.y;
    return SW_OK;
}

/* ---- vortex: x' = ω·(-y, x); exact paths are circles -------------------- */

enum { VX_OMEGA, VX_N };
static const sw_param vortex_params[] = {
    { "omega", 1.0, -20.0, 20.0, 0, "rad/s", "angular speed of the rotation" },
    { "n", 200, 1, 1000000, 1, "", "number of particles, seeded on rings" },
};

/* Particle i sits on ring (i mod rings) at radius (k+1)/rings of 1. */
static void vortex_seed(int n, int i, double *x, double *y)
{
    int rings = n < 8 ? n : (int)ceil(sqrt(n / 8.0));
    if (rings > 24)
        rings = 24;
    int k = i % rings, per = (n + rings - 1) / rings, j = i / rings;
    double r = (k + 1.0) / rings, a = 2.0 * SW_PI * j / per + 0.3 * k;
    *x = r * cos(a);
    *y = r * sin(a);
}

typedef struct { double w; } vortex_coef;

static inline vortex_coef vortex_prep(const void *params, double t)
{
    (void)t;
    return (vortex_coef){ ((const double *)params)[VX_OMEGA] };
}

static inline void vortex_at(const vortex_coef *c, double px, double py, double *vx, double *vy)
{
    *vx = -c->w * py;
    *vy = c->w * px;
}

SW_POINT_FIELD(vortex, vortex_coef, vortex_prep, vortex_at);

static void vortex_jac(const void *params, double t, int n, const double *x, double *jac)
{
    (void)t;
    (void)x;
    double w = ((const double *)params)[VX_OMEGA];
    for (int i = 0; i < n; i++) {
        jac[4 * i] = 0;
        jac[4 * i + 1] = -w;
        jac[4 * i + 2] = w;
        jac[4 * i + 3] = 0;
    }
}

static int vortex_build(sw_system *sys, char *err, size_t errlen)
{
    int n = (int)sys->p[VX_N];
    int rc = sw_scene_flow(sys, n, &vortex_point, vortex_jac, err, errlen);
    for (int i = 0; rc == SW_OK && i < n; i++)
        vortex_seed(n, i, &sys->y[2 * i], &sys->y[2 * i + 1]);
    return rc;
}

/* Rotation of every seed by ω·t. */
static int vortex_exact(const sw_system *sys, double t, double *y)
{
    double a = sys->p[VX_OMEGA] * t, c = cos(a), s = sin(a);
    for (int i = 0; i < sys->n; i++) {
        double x0, y0;
        vortex_seed(sys->n, i, &x0, &y0);
        y[2 * i] = c * x0 - s * y0;
        y[2 * i + 1] = s * x0 + c * y0;
    }
    return 0;
}

/* Largest change of any particle's radius: 0 on circles. */
static double vortex_drift(const sw_system *sys, const double *y)
{
    double m = 0;
    for (int i = 0; i < sys->n; i++) {
        double x0, y0;
        vortex_seed(sys->n, i, &x0, &y0);
        double d = fabs(hypot(y[2 * i], y[2 * i + 1]) - hypot(x0, y0));
        if (!(d <= m))
            m = d;
    }
    return m;
}

static sw_view vortex_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ -1.4, 1.4, -1.4, 1.4 };
}

const sw_scene sw_scene_vortex = {
    .name = "vortex",
    .kind = SW_SYS_FLOW,
    .summary = "points circling in a rotating flow x' = w(-y, x); exact paths are circles",
    .teaches = "Euler spirals outward: every step multiplies the radius by sqrt(1 + (w dt)^2).",
    .params = vortex_params,
    .nparams = SW_NPARAMS(vortex_params),
    .dt = 0.05,
    .integrator = "euler",
    .duration = 2 * SW_PI,
    .build = vortex_build,
    .exact = vortex_exact,
    .drift = vortex_drift,
    .drift_name = "radius drift",
    .reference = 1,
    .view = vortex_view,
};

/* ---- river: uniform flow U past a round rock of radius R ---------------- */

enum { RV_U, RV_R, RV_N };
static const sw_param river_params[] = {
    { "U", 1.0, 0.01, 10.0, 0, "m/s", "speed of the river far from the rock" },
    { "R", 0.5, 0.05, 1.5, 0, "m", "radius of the rock at the origin" },
    { "n", 60, 1, 1000000, 1, "", "number of floating particles" },
};

/* Seeds: a block upstream, columns at x in [-3.5, -2.5], rows in y in (-1.6, 1.6). */
static void river_seed(int n, int i, double *x, double *y)
{
    int cols = n < 6 ? 1 : (int)ceil(sqrt(n / 6.0));
    int rows = (n + cols - 1) / cols;
    int c = i % cols, r = i / cols;
    *x = -3.5 + (cols > 1 ? (double)c / (cols - 1) : 0.5);
    *y = -1.6 + 3.2 * (r + 0.5) / rows;
}

/* Potential flow past a cylinder, w(z) = U(z + R²/z):
 *   u = U(1 - R²(x² - y²)/r⁴),  v = -2U R² x y / r⁴. */
typedef struct { double U, R2; } river_coef;

static inline river_coef river_prep(const void *params, double t)
{
    (void)t;
    const double *p = params;
    return (river_coef){ p[RV_U], p[RV_R] * p[RV_R] };
}

static inline void river_at(const river_coef *c, double px, double py, double *vx, double *vy)
{
    double r2 = px * px + py * py, r4 = r2 * r2;
    *vx = c->U * (1.0 - c->R2 * (px * px - py * py) / r4);
    *vy = -2.0 * c->U * c->R2 * px * py / r4;
}

SW_POINT_FIELD(river, river_coef, river_prep, river_at);

/* Stream function ψ = U·y·(1 - R²/r²), constant along every exact path. */
static double river_psi(const double *p, double x, double y)
{
    return p[RV_U] * y * (1.0 - p[RV_R] * p[RV_R] / (x * x + y * y));
}

static int river_build(sw_system *sys, char *err, size_t errlen)
{
    int n = (int)sys->p[RV_N];
    int rc = sw_scene_flow(sys, n, &river_point, NULL, err, errlen);
    for (int i = 0; rc == SW_OK && i < n; i++)
        river_seed(n, i, &sys->y[2 * i], &sys->y[2 * i + 1]);
    return rc;
}

static double river_drift(const sw_system *sys, const double *y)
{
    double m = 0;
    for (int i = 0; i < sys->n; i++) {
        double x0, y0;
        river_seed(sys->n, i, &x0, &y0);
        double d = fabs(river_psi(sys->p, y[2 * i], y[2 * i + 1]) - river_psi(sys->p, x0, y0));
        if (!(d <= m))
            m = d;
    }
    return m;
}

static sw_view river_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ -3.8, 3.8, -2.0, 2.0 };
}

const sw_scene sw_scene_river = {
    .name = "river",
    .kind = SW_SYS_FLOW,
    .summary = "a river flowing past a round rock; exact paths keep the stream function constant",
    .teaches = "Error shows up as particles leaving their streamline, even cutting into the rock.",
    .params = river_params,
    .nparams = SW_NPARAMS(river_params),
    .dt = 0.05,
    .integrator = "rk4",
    .duration = 3.0,
    .build = river_build,
    .drift = river_drift,
    .drift_name = "stream-function drift",
    .reference = 1,
    .view = river_view,
};

/* ---- gyre: the time-dependent double gyre (Shadden et al.) ------------- */

enum { GY_A, GY_EPS, GY_OMEGA, GY_N };
static const sw_param gyre_params[] = {
    { "A", 0.1, 0.0, 2.0, 0, "m/s", "strength of the gyres" },
    { "epsilon", 0.25, 0.0, 1.0, 0, "", "how far the dividing line swings" },
    { "omega", 0.6283185307179586, 0.0, 20.0, 0, "rad/s", "swing frequency (2 pi / 10 by default)" },
    { "n", 400, 1, 1000000, 1, "", "number of particles, seeded on a grid" },
};

static void gyre_seed(int n, int i, double *x, double *y)
{
    int cols = (int)ceil(sqrt(2.0 * n));
    int rows = (n + cols - 1) / cols;
    *x = 2.0 * ((i % cols) + 0.5) / cols;
    *y = ((i / cols) + 0.5) / rows;
}

/* ψ = A sin(π f(x, t)) sin(π y), f = a x² + b x, a = ε sin ωt, b = 1 - 2ε sin ωt;
 * u = -∂ψ/∂y, v = ∂ψ/∂x. */
typedef struct { double a, b, A; } gyre_coef;

static inline gyre_coef gyre_prep(const void *params, double t)
{
    const double *p = params;
    double s = p[GY_EPS] * sin(p[GY_OMEGA] * t);
    return (gyre_coef){ s, 1.0 - 2.0 * s, p[GY_A] };
}

static inline void gyre_at(const gyre_coef *c, double px, double py, double *vx, double *vy)
{
    double f = c->a * px * px + c->b * px, df = 2.0 * c->a * px + c->b;
    *vx = -SW_PI * c->A * sin(SW_PI * f) * cos(SW_PI * py);
    *vy = SW_PI * c->A * cos(SW_PI * f) * sin(SW_PI * py) * df;
}

SW_POINT_FIELD(gyre, gyre_coef, gyre_prep, gyre_at);

/* ∂(u, v)/∂(x, y) in closed form. Rosenbrock methods need the exact
 * Jacobian for their order: with the forward-difference one (perturbation
 * 1e-7, an error near 1e-8 relative) rodas4's error on the gyre fell only
 * as fast as the step below 5e-9 and read order 1.16 (issue 38). */
static void gyre_jac(const void *params, double t, int n, const double *x, double *jac)
{
    gyre_coef c = gyre_prep(params, t);
    double k = SW_PI * c.A;
    for (int i = 0; i < n; i++) {
        double px = x[2 * i], py = x[2 * i + 1];
        double f = c.a * px * px + c.b * px, df = 2.0 * c.a * px + c.b;
        double sf = sin(SW_PI * f), cf = cos(SW_PI * f), sy = sin(SW_PI * py), cy = cos(SW_PI * py);
        jac[4 * i] = -k * SW_PI * cf * df * cy;                       /* ∂u/∂x */
        jac[4 * i + 1] = k * SW_PI * sf * sy;                         /* ∂u/∂y */
        jac[4 * i + 2] = k * sy * (2.0 * c.a * cf - SW_PI * sf * df * df); /* ∂v/∂x */
        jac[4 * i + 3] = k * SW_PI * cf * cy * df;                    /* ∂v/∂y */
    }
}

static int gyre_build(sw_system *sys, char *err, size_t errlen)
{
    int n = (int)sys->p[GY_N];
    int rc = sw_scene_flow(sys, n, &gyre_point, gyre_jac, err, errlen);
    for (int i = 0; rc == SW_OK && i < n; i++)
        gyre_seed(n, i, &sys->y[2 * i], &sys->y[2 * i + 1]);
    return rc;
}

static sw_view gyre_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ 0.0, 2.0, 0.0, 1.0 };
}

const sw_scene sw_scene_gyre = {
    .name = "gyre",
    .kind = SW_SYS_FLOW,
    .summary = "the time-dependent double gyre: chaotic mixing with no closed form",
    .teaches = "Without an exact solution, error is measured against a tight-tolerance 8th-order "
               "(dop853) run.",
    .params = gyre_params,
    .nparams = SW_NPARAMS(gyre_params),
    .dt = 0.1,
    .integrator = "rk4",
    .duration = 10.0,
    .build = gyre_build,
    .reference = 1,
    .view = gyre_view,
};
