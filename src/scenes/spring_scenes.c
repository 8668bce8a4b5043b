/* Springs: one damped mass on a spring (exact in all three damping regimes),
 * the stiff-spring pendulum (a slow swing and a fast stretch in one system),
 * and a chain of masses between two anchors. Only springs, gravity when
 * asked for, and nothing else. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/particles_deriv.h"
#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/num.h"


/* ---- spring --------------------------------------------------------------- */

enum { SP_K, SP_M, SP_C, SP_REST, SP_STRETCH, SP_G };
static const sw_param spring_params[] = {
    { "k", 10.0, 0.001, 1e7, 0, "N/m", "spring stiffness" },
    { "m", 1.0, 0.001, 1000.0, 0, "kg", "mass" },
    { "c", 0.5, 0.0, 1e5, 0, "N s/m", "damping along the spring" },
    { "rest", 1.0, 0.0, 100.0, 0, "m", "rest length" },
    { "stretch", 0.5, -100.0, 100.0, 0, "m", "initial stretch beyond the rest length" },
    { "g", 0.0, -100.0, 100.0, 0, "m/s^2", "gravity, pointing down (0: none)" },
};

/* The particle derivative, with the side the mass is on when events are
 * located (sys->extra[0]: +1, -1; 0 when not) extended smoothly past the
 * anchor: there the engine's -k(|x| - rest)·sign(x) is corrected to
 * -k(x - rest·side), until the crossing's jump switches the side. */
static void spring_deriv(void *ctx, double t, const double *y, double *dydt)
{
    sw_system *sys = (sw_system *)(void *)((char *)ctx - offsetof(sw_system, particles));
    swp_deriv(ctx, t, y, dydt); /* the particle system's own, which this one wraps */
    double side = sys->extra[0];
    double now = y[0] > 0 ? 1.0 : y[0] < 0 ? -1.0 : 0.0;
    if (side != 0 && now != side)
        dydt[2] += sys->p[SP_K] * sys->p[SP_REST] * (side - now) * sys->particles.inv_mass[0];
}

static int spring_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    if (!(p[SP_REST] + p[SP_STRETCH] > 0)) {
        snprintf(err, errlen, "spring: rest + stretch must be positive (got %g + %g); "
                 "the mass starts at (rest + stretch, 0)", p[SP_REST], p[SP_STRETCH]);
        return SW_EINVAL;
    }
    int rc = sw_scene_particles(sys, 1, p[SP_M], err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_spring *s = sw_particles_add_springs(&sys->particles, 1);
    if (!s) {
        snprintf(err, errlen, "out of memory for a spring");
        return SW_ENOMEM;
    }
    *s = (sw_spring){ .a = 0, .b = -1, .k = p[SP_K], .c = p[SP_C], .rest = p[SP_REST] };
    if (p[SP_G] != 0)
        sw_particles_add_gravity(&sys->particles, 0.0, -p[SP_G]);
    sys->y[0] = p[SP_REST] + p[SP_STRETCH];
    sys->extra = calloc(1, sizeof *sys->extra); /* the side when events are located */
    if (!sys->extra) {
        snprintf(err, errlen, "out of memory for a spring");
        return SW_ENOMEM;
    }
    sys->nextra = 1;
    sys->particles.ode.deriv = spring_deriv;
    return SW_OK;
}

/* u = x - rest obeys m u'' + c u' + k u = 0 with u(0) = stretch, u'(0) = 0.
 * γ = c/2m, ω0 = √(k/m): under-damped (γ < ω0), critical, over-damped. */
static void damped(double m, double k, double c, double u0, double t, double *u, double *du)
{
    double g = c / (2 * m), w0 = sqrt(k / m), z = g / w0;
    double e = exp(-g * t);
    if (fabs(z - 1.0) < 1e-9) {
        double b = g * u0;
        *u = e * (u0 + b * t);
        *du = e * (b - g * (u0 + b * t));
    } else if (z < 1.0) {
        double wd = w0 * sqrt(1 - z * z), b = g * u0 / wd;
        double cs = cos(wd * t), sn = sin(wd * t);
        *u = e * (u0 * cs + b * sn);
        *du = e * ((-u0 * wd + b * (-g)) * sn + (b * wd - g * u0) * cs);
    } else {
        double s = w0 * sqrt(z * z - 1), r1 = -g + s, r2 = -g - s;
        double c1 = -r2 * u0 / (r1 - r2), c2 = u0 - c1;
        double e1 = exp(r1 * t), e2 = exp(r2 * t);
        *u = c1 * e1 + c2 * e2;
        *du = c1 * r1 * e1 + c2 * r2 * e2;
    }
}

/* The one-dimensional formula holds while the mass stays on its side of the
 * anchor. With u(0) = stretch, u'(0) = 0 the under-damped motion has its
 * extremes at t_k = kπ/ωd, u(t_k) = stretch·(-e^{-γπ/ωd})^k, so the nearest
 * approach is rest - stretch·e^{-γπ/ωd} (for a positive stretch); critical
 * and over-damped motion never crosses u = 0. A spring of rest length 0
 * pulls with -k·d through the anchor too: linear, so it always holds. */
static const char *spring_exact_fails(const sw_system *sys)
{
    const double *p = sys->p;
    if (p[SP_G] != 0)
        return "with gravity the mass swings sideways and the motion is two-dimensional";
    double m = p[SP_M], g = p[SP_C] / (2 * m), w0 = sqrt(p[SP_K] / m);
    if (p[SP_REST] == 0 || p[SP_STRETCH] <= 0 || g >= w0)
        return NULL;
    double wd = sqrt(w0 * w0 - g * g);
    if (p[SP_REST] - p[SP_STRETCH] * exp(-g * SW_PI / wd) > 0)
        return NULL;
    return "the mass swings through its anchor, where the spring force turns around and the "
           "one-dimensional formula no longer holds";
}

/* The resting state hangs straight down at r = rest + m·g/k: energy
 * ½k(mg/k)² - m·g·(rest + mg/k) = -m·g·rest - ½(mg)²/k (0 without gravity). */
static double hanging_floor(double k, double m, double g, double rest)
{
    return -m * g * rest - 0.5 * (m * g) * (m * g) / k;
}

static double spring_floor(const sw_system *sys)
{
    const double *p = sys->p;
    return hanging_floor(p[SP_K], p[SP_M], fabs(p[SP_G]), p[SP_REST]);
}

static int spring_exact(const sw_system *sys, double t, double *y)
{
    const double *p = sys->p;
    if (spring_exact_fails(sys))
        return -1;
    double u, du;
    damped(p[SP_M], p[SP_K], p[SP_C], p[SP_STRETCH], t, &u, &du);
    y[0] = p[SP_REST] + u;
    y[1] = 0;
    y[2] = du;
    y[3] = 0;
    return 0;
}

/* Event: without gravity the mass moves on the line through its anchor
 * (the origin), and where it passes the anchor the spring force -k(|x| -
 * rest)·sign(x) jumps by 2·k·rest. Nothing jumps in the state; the step
 * must end at the crossing so the next one starts on the smooth side, and
 * the "jump" switches which side's force the derivative extends. */
static int spring_event_count(const sw_system *sys)
{
    return sys->p[SP_G] == 0 && sys->p[SP_REST] > 0;
}

static double spring_event_g(const sw_system *sys, int k, double t, const double *y)
{
    (void)sys, (void)k, (void)t;
    return y[0];
}

static void spring_event_arm(sw_system *sys, const double *y, int locate)
{
    sys->extra[0] = locate && spring_event_count(sys) ? (y[0] >= 0 ? 1.0 : -1.0) : 0.0;
}

/* The mass is just past the anchor: from now on its force is the far side's. */
static void spring_event_jump(sw_system *sys, int k, double t, double *y)
{
    (void)k, (void)t;
    sys->extra[0] = y[0] > 0 ? 1.0 : -1.0;
}

static const char *spring_event_breaks(const sw_system *sys)
{
    if (!spring_exact_fails(sys))
        return NULL; /* the mass stays on its side */
    return "the force jumps where the mass passes its anchor: every method is limited to first "
           "order unless steps end at the crossing - see --events";
}

static const sw_scene_events spring_events = {
    .count = spring_event_count,
    .g = spring_event_g,
    .direction = 0,
    .jump = spring_event_jump,
    .arm = spring_event_arm,
    .breaks = spring_event_breaks,
};

static sw_view spring_view(const sw_system *sys)
{
    const double *p = sys->p;
    double r = p[SP_REST] + fabs(p[SP_STRETCH]) + 0.3;
    double sag = p[SP_G] != 0 ? fabs(p[SP_G]) * p[SP_M] / p[SP_K] : 0.0;
    double ext = fmax(r + sag, 0.6 * r);
    return (sw_view){ -0.3 - (p[SP_G] != 0 ? ext : 0), ext, -ext * 0.5 - sag, ext * 0.5 };
}

const sw_scene sw_scene_spring = {
    .name = "spring",
    .kind = SW_SYS_PARTICLES,
    .summary = "one mass on a damped spring to a fixed anchor; exact in every damping regime",
    .teaches = "Undamped, explicit Euler gains energy every step: (1 + (w dt)^2) per step.",
    .params = spring_params,
    .nparams = SW_NPARAMS(spring_params),
    .dt = 0.02,
    .integrator = "euler",
    .duration = 10.0,
    .build = spring_build,
    .exact = spring_exact,
    .exact_fails = spring_exact_fails,
    .energy = sw_scene_particle_energy,
    .energy_floor = spring_floor,
    .reference = 1,
    .view = spring_view,
    .events = &spring_events,
};

/* ---- stiff-spring: a pendulum on a very stiff spring ------------------- */

enum { SS_K, SS_M, SS_REST, SS_G, SS_ANGLE };
static const sw_param stiff_params[] = {
    { "k", 1e4, 1.0, 1e9, 0, "N/m", "spring stiffness (large: stiff)" },
    { "m", 1.0, 0.001, 1000.0, 0, "kg", "mass of the bob" },
    { "rest", 1.0, 0.05, 100.0, 0, "m", "rest length of the spring" },
    { "g", 9.81, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "angle", 30.0, -179.0, 179.0, 0, "deg", "starting angle from straight down" },
};

static int stiff_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int rc = sw_scene_particles(sys, 1, p[SS_M], err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_spring *s = sw_particles_add_springs(&sys->particles, 1);
    if (!s) {
        snprintf(err, errlen, "out of memory for a spring");
        return SW_ENOMEM;
    }
    *s = (sw_spring){ .a = 0, .b = -1, .k = p[SS_K], .c = 0.0, .rest = p[SS_REST] };
    sw_particles_add_gravity(&sys->particles, 0.0, -p[SS_G]);
    /* Start at rest, stretched by the static sag m g / k, at the given angle. */
    double len = p[SS_REST] + p[SS_M] * p[SS_G] / p[SS_K], a = p[SS_ANGLE] * SW_PI / 180.0;
    sys->y[0] = len * sin(a);
    sys->y[1] = -len * cos(a);
    return SW_OK;
}

static double stiff_floor(const sw_system *sys)
{
    const double *p = sys->p;
    return hanging_floor(p[SS_K], p[SS_M], p[SS_G], p[SS_REST]);
}

static sw_view stiff_view(const sw_system *sys)
{
    double r = sys->p[SS_REST] * 1.25 + 0.1;
    return (sw_view){ -r, r, -r, 0.25 * r };
}

const sw_scene sw_scene_stiff_spring = {
    .name = "stiff-spring",
    .kind = SW_SYS_PARTICLES,
    .summary = "a pendulum hung on a very stiff spring: a slow swing and a fast stretch",
    .teaches = "Stiffness: explicit methods need w dt below their limit; backward Euler does not, "
               "and implicit midpoint gains energy on this nonlinear spring above dt 0.19.",
    .params = stiff_params,
    .nparams = SW_NPARAMS(stiff_params),
    .dt = 0.005,
    .integrator = "verlet",
    .duration = 2.0,
    .build = stiff_build,
    .energy = sw_scene_particle_energy,
    .energy_floor = stiff_floor,
    .reference = 1,
    .view = stiff_view,
};

/* ---- chain: n masses joined by n + 1 springs between two anchors ------- */

enum { CH_N, CH_K, CH_M, CH_C, CH_REST, CH_G, CH_PLUCK };
static const sw_param chain_params[] = {
    { "n", 10, 1, 1000000, 1, "", "number of masses" },
    { "k", 100.0, 0.001, 1e7, 0, "N/m", "stiffness of each spring" },
    { "m", 1.0, 0.001, 1000.0, 0, "kg", "mass of each bead" },
    { "c", 0.0, 0.0, 1e4, 0, "N s/m", "damping of each spring" },
    { "rest", 1.0, 0.01, 100.0, 0, "m", "rest length of each spring (and the spacing)" },
    { "g", 0.0, -100.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "pluck", 0.5, -10.0, 10.0, 0, "m", "initial sideways displacement of the middle mass" },
};

static int chain_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int n = (int)p[CH_N];
    int rc = sw_scene_particles(sys, n, p[CH_M], err, errlen);
    if (rc != SW_OK)
        return rc;
    /* spring j joins mass j-1 (or the left anchor) and mass j (or the
     * right): a line, stored as its first, second and last springs */
    double L = p[CH_REST];
    sw_spring line[3] = {
        { .a = 0, .b = -1, .k = p[CH_K], .c = p[CH_C], .rest = L, .ax = 0.0, .ay = 0.0 },
        { .a = 1, .b = 0, .k = p[CH_K], .c = p[CH_C], .rest = L },
        { .a = n - 1, .b = -1, .k = p[CH_K], .c = p[CH_C], .rest = L, .ax = (n + 1) * L, .ay = 0.0 },
    };
    if (sw_particles_add_spring_line(&sys->particles, n + 1, line) != SW_OK) {
        snprintf(err, errlen, "out of memory for %d springs", n + 1);
        return SW_ENOMEM;
    }
    if (p[CH_G] != 0)
        sw_particles_add_gravity(&sys->particles, 0.0, -p[CH_G]);
    for (int i = 0; i < n; i++)
        sys->y[2 * i] = (i + 1) * L;
    sys->y[2 * (n / 2) + 1] = p[CH_PLUCK];
    return SW_OK;
}

/* At rest the chain lies straight with every spring at its rest length:
 * energy 0. With gravity it sags, and the truth module finds the resting
 * state numerically (NaN here). */
static double chain_floor(const sw_system *sys) { return sys->p[CH_G] == 0 ? 0.0 : NAN; }

static sw_view chain_view(const sw_system *sys)
{
    const double *p = sys->p;
    double w = (p[CH_N] + 1) * p[CH_REST], h = fmax(fabs(p[CH_PLUCK]) * 1.4, 0.15 * w);
    double sag = p[CH_G] != 0 ? fmin(w, fabs(p[CH_G]) * p[CH_M] * p[CH_N] * p[CH_N] / (8 * p[CH_K]) + 0.3) : 0;
    return (sw_view){ -0.05 * w, 1.05 * w, -h - (p[CH_G] > 0 ? sag : 0), h + (p[CH_G] < 0 ? sag : 0) };
}

const sw_scene sw_scene_chain = {
    .name = "chain",
    .kind = SW_SYS_PARTICLES,
    .summary = "n masses in a line joined by springs between two fixed anchors",
    .teaches = "The stiffest mode sets the step: w_max dt must stay below each method's limit.",
    .params = chain_params,
    .nparams = SW_NPARAMS(chain_params),
    .dt = 0.01,
    .integrator = "verlet",
    .duration = 5.0,
    .build = chain_build,
    .energy = sw_scene_particle_energy,
    .energy_floor = chain_floor,
    .reference = 1,
    .view = chain_view,
};
