/* Balls under gravity and drag: the projectile with its closed form, balls
 * bouncing in a box (contact after each step), and fireworks. Gravity points
 * down (-y). None of these has springs or a central field. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"
#include "scenes/scenes.h"

int sw_scene_particles(sw_system *sys, int n, double m, char *err, size_t errlen)
{
    int rc = sw_particles_init(&sys->particles, n, m, err, errlen);
    if (rc != SW_OK)
        return rc;
    sys->kind = SW_SYS_PARTICLES;
    sys->n = n;
    sys->ode = &sys->particles.ode;
    sys->y = sys->particles.y;
    return SW_OK;
}

double sw_scene_particle_energy(const sw_system *sys, const double *y)
{
    return sw_particles_energy(&sys->particles, y);
}

/* (1 - e^{-γt})/γ and (t - φ1)/γ, with their γ → 0 limits t and t²/2. */
static void drag_phis(double gamma, double t, double *phi1, double *phi2)
{
    double z = gamma * t;
    if (fabs(z) < 1e-3) {
        /* series: φ1 = t(1 - z/2 + z²/6 - z³/24), φ2 = t²(1/2 - z/6 + z²/24 - z³/120) */
        *phi1 = t * (1 - z / 2 + z * z / 6 - z * z * z / 24);
        *phi2 = t * t * (0.5 - z / 6 + z * z / 24 - z * z * z / 120);
    } else {
        *phi1 = -expm1(-z) / gamma;
        *phi2 = (t - *phi1) / gamma;
    }
}

/* ---- projectile --------------------------------------------------------- */

enum { PR_G, PR_DRAG, PR_VX, PR_VY, PR_M };
static const sw_param projectile_params[] = {
    { "g", 9.81, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "drag", 0.1, 0.0, 10.0, 0, "1/s", "linear drag per unit mass: f = -drag m v" },
    { "vx", 5.0, -100.0, 100.0, 0, "m/s", "launch velocity, x" },
    { "vy", 10.0, -100.0, 100.0, 0, "m/s", "launch velocity, y" },
    { "m", 1.0, 0.001, 1000.0, 0, "kg", "mass of the ball" },
};

static int projectile_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int rc = sw_scene_particles(sys, 1, p[PR_M], err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_particles_add_gravity(&sys->particles, 0.0, -p[PR_G]);
    if (p[PR_DRAG] > 0)
        sw_particles_add_drag(&sys->particles, p[PR_DRAG] * p[PR_M]);
    sys->y[2] = p[PR_VX];
    sys->y[3] = p[PR_VY];
    return SW_OK;
}

/* x(t) = v0·φ1 + g·φ2,  v(t) = v0·e^{-γt} + g·φ1, with g = (0, -g). */
static int projectile_exact(const sw_system *sys, double t, double *y)
{
    const double *p = sys->p;
    double phi1, phi2, decay = exp(-p[PR_DRAG] * t);
    drag_phis(p[PR_DRAG], t, &phi1, &phi2);
    y[0] = p[PR_VX] * phi1;
    y[1] = p[PR_VY] * phi1 - p[PR_G] * phi2;
    y[2] = p[PR_VX] * decay;
    y[3] = p[PR_VY] * decay - p[PR_G] * phi1;
    return 0;
}

/* Time of flight back to y = 0 without drag (the report time), at least 1 s. */
static double flight_time(const double *p)
{
    return p[PR_G] > 0 && p[PR_VY] > 0 ? fmax(1.0, 2.0 * p[PR_VY] / p[PR_G]) : 2.0;
}

static sw_view projectile_view(const sw_system *sys)
{
    double y[4], T = flight_time(sys->p);
    sw_view v = { 0, 0, 0, 0 };
    for (int i = 0; i <= 64; i++) {
        projectile_exact(sys, T * i / 64.0, y);
        v.xmin = fmin(v.xmin, y[0]);
        v.xmax = fmax(v.xmax, y[0]);
        v.ymin = fmin(v.ymin, y[1]);
        v.ymax = fmax(v.ymax, y[1]);
    }
    double mx = 0.08 * (v.xmax - v.xmin) + 0.5, my = 0.08 * (v.ymax - v.ymin) + 0.5;
    return (sw_view){ v.xmin - mx, v.xmax + mx, v.ymin - my, v.ymax + my };
}

const sw_scene sw_scene_projectile = {
    .name = "projectile",
    .kind = SW_SYS_PARTICLES,
    .summary = "one ball launched under gravity and linear drag; closed-form exact solution",
    .teaches = "Euler's global error is O(dt): halve the step and the miss distance halves.",
    .params = projectile_params,
    .nparams = SW_NPARAMS(projectile_params),
    .dt = 0.05,
    .integrator = "euler",
    .duration = 2.0,
    .build = projectile_build,
    .exact = projectile_exact,
    .energy = sw_scene_particle_energy,
    .reference = 1,
    .view = projectile_view,
};

/* ---- bounce: balls in a box, restitution at walls and floor ------------ */

enum { BO_N, BO_G, BO_E, BO_DRAG };
static const sw_param bounce_params[] = {
    { "n", 5, 1, 2000, 1, "", "number of balls" },
    { "g", 9.81, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "e", 0.8, 0.0, 1.0, 0, "", "coefficient of restitution at walls and floor" },
    { "drag", 0.0, 0.0, 10.0, 0, "1/s", "linear drag per unit mass" },
};

#define BOX_W 10.0
#define BOX_H 6.0
/* A hop off the floor lower than this is no hop: the ball rests (a
 * resting contact, as in Witkin & Baraff's notes), instead of bouncing
 * ever lower, a geometric series of flights that never ends in steps. */
#define REST_HOP 1e-3

/* The speed that would lift a ball REST_HOP: leaving slower, it rests. */
static double rest_speed(double g) { return g > 0 ? sqrt(2.0 * g * REST_HOP) : 0.0; }

double sw_scene_hash01(uint64_t a, uint64_t b)
{
    uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E5ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static void bounce_seed(int n, int i, double *s)
{
    s[0] = BOX_W * (i + 0.5) / n;
    s[1] = 2.0 + 3.5 * sw_scene_hash01(7, (uint64_t)i);
    s[2] = -4.0 + 8.0 * sw_scene_hash01(11, (uint64_t)i);
    s[3] = -2.0 + 4.0 * sw_scene_hash01(13, (uint64_t)i);
}

static int bounce_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int n = (int)p[BO_N];
    int rc = sw_scene_particles(sys, n, 1.0, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_particles_add_gravity(&sys->particles, 0.0, -p[BO_G]);
    if (p[BO_DRAG] > 0)
        sw_particles_add_drag(&sys->particles, p[BO_DRAG]);
    sw_walls *w = &sys->particles.walls;
    w->active = 1;
    w->sides = SW_WALL_FLOOR | SW_WALL_LEFT | SW_WALL_RIGHT;
    w->xmin = 0;
    w->xmax = BOX_W;
    w->ymin = 0;
    w->ymax = BOX_H;
    w->e = p[BO_E];
    w->rest = rest_speed(p[BO_G]);
    for (int i = 0; i < n; i++) {
        double s[4];
        bounce_seed(n, i, s);
        sys->y[2 * i] = s[0];
        sys->y[2 * i + 1] = s[1];
        sys->y[2 * n + 2 * i] = s[2];
        sys->y[2 * n + 2 * i + 1] = s[3];
    }
    return SW_OK;
}

static int bounce_post(sw_system *sys, double t, double *y)
{
    (void)t;
    return sw_particles_contact(&sys->particles, y);
}

/* Exact horizontal motion: uniform between two walls, speed times e at each hit. */
static void exact_walls(double x, double v, double lo, double hi, double e, double t, double *xo, double *vo)
{
    for (int hits = 0; hits < 100000 && v != 0; hits++) {
        double wall = v > 0 ? hi : lo, tw = (wall - x) / v;
        if (tw >= t)
            break;
        t -= tw;
        x = wall;
        v = -e * v;
    }
    *xo = x + v * t;
    *vo = v;
}

/* Exact vertical motion: parabolic hops off the floor, each launched at e
 * times the landing speed, until one would leave slower than the resting
 * speed: then the ball rests on the floor. */
static void exact_floor(double y, double v, double g, double e, double t, double *yo, double *vo)
{
    if (g <= 0) {
        exact_walls(y, v, 0.0, INFINITY, e, t, yo, vo);
        return;
    }
    for (int hops = 0; hops < 100000; hops++) {
        double tl = (v + sqrt(v * v + 2.0 * g * y)) / g; /* time to land */
        if (tl >= t) {
            *yo = y + v * t - 0.5 * g * t * t;
            *vo = v - g * t;
            return;
        }
        t -= tl;
        v = e * (g * tl - v);
        y = 0;
        if (v < rest_speed(g))
            break;
    }
    *yo = 0;
    *vo = 0;
}

static const char *bounce_exact_fails(const sw_system *sys)
{
    return sys->p[BO_DRAG] != 0 ? "with drag the flight between bounces has no closed form here" : NULL;
}

/* Resting on the floor (y = 0) is the least energy the balls can have. */
static double bounce_floor(const sw_system *sys)
{
    (void)sys;
    return 0.0;
}

/* Exact when there is no drag: the axes decouple, each a chain of events. */
static int bounce_exact(const sw_system *sys, double t, double *y)
{
    const double *p = sys->p;
    int n = sys->n;
    if (bounce_exact_fails(sys))
        return -1;
    for (int i = 0; i < n; i++) {
        double s[4];
        bounce_seed(n, i, s);
        exact_walls(s[0], s[2], 0.0, BOX_W, p[BO_E], t, &y[2 * i], &y[2 * n + 2 * i]);
        exact_floor(s[1], s[3], p[BO_G], p[BO_E], t, &y[2 * i + 1], &y[2 * n + 2 * i + 1]);
    }
    return 0;
}

static sw_view bounce_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ -0.3, BOX_W + 0.3, -0.3, BOX_H };
}

/* Events: ball i meets the floor (k = 3i), the left wall (3i + 1) and the
 * right wall (3i + 2) where its distance to it falls through zero. */
static int bounce_event_count(const sw_system *sys) { return 3 * sys->n; }

static double bounce_event_g(const sw_system *sys, int k, double t, const double *y)
{
    (void)t;
    const sw_walls *w = &sys->particles.walls;
    const double *x = y + 2 * (k / 3);
    switch (k % 3) {
    case 0: return x[1] - w->ymin;
    case 1: return x[0] - w->xmin;
    default: return w->xmax - x[0];
    }
}

/* At the contact (the ball a rounding error past the wall): the normal
 * velocity reversed and scaled by e, the overshoot reflected as the
 * step-boundary contact does, so the ball resumes inside; at the floor,
 * leaving slower than the resting speed, it rests on it (g = 0 exactly
 * there starts no event: the next steps' contacts keep it there). */
static void bounce_event_jump(sw_system *sys, int k, double t, double *y)
{
    (void)t;
    const sw_walls *w = &sys->particles.walls;
    int n = sys->n, i = k / 3, axis = k % 3 == 0;
    double wall = k % 3 == 0 ? w->ymin : k % 3 == 1 ? w->xmin : w->xmax;
    double sign = k % 3 == 2 ? 1.0 : -1.0; /* outward normal along the axis */
    double *x = &y[2 * i + axis], *v = &y[2 * n + 2 * i + axis];
    double over = sign * (*x - wall);
    if (over > 0)
        *x = wall - sign * w->e * over;
    if (sign * *v > 0)
        *v = -w->e * *v;
    if (axis && fabs(*v) < w->rest) { /* resting contact: on the floor, at rest */
        *x = wall;
        *v = 0;
    }
}

static const char *bounce_event_breaks(const sw_system *sys)
{
    (void)sys;
    return "the velocity jumps where a ball meets a wall or the floor: every method is limited "
           "to first order unless steps end at the contact - see --events";
}

static const sw_scene_events bounce_events = {
    .count = bounce_event_count,
    .g = bounce_event_g,
    .direction = -1,
    .jump = bounce_event_jump,
    .breaks = bounce_event_breaks,
};

const sw_scene sw_scene_bounce = {
    .name = "bounce",
    .kind = SW_SYS_PARTICLES,
    .summary = "balls in a box bouncing off the walls and floor with restitution e",
    .teaches = "A collision inside a step breaks every method's order: error becomes O(dt).",
    .params = bounce_params,
    .nparams = SW_NPARAMS(bounce_params),
    .dt = 0.01,
    .integrator = "verlet",
    .duration = 3.0,
    .build = bounce_build,
    .exact = bounce_exact,
    .exact_fails = bounce_exact_fails,
    .energy = sw_scene_particle_energy,
    .energy_floor = bounce_floor,
    .view = bounce_view,
    .post_step = bounce_post,
    .events = &bounce_events,
};

/* ---- fireworks: bursts of particles with lifetimes ----------------------- */

enum { FW_BURSTS, FW_N, FW_G, FW_DRAG, FW_SEED };
static const sw_param fireworks_params[] = {
    { "bursts", 5, 1, 50, 1, "", "number of bursts per show" },
    { "n", 150, 1, 20000, 1, "", "particles per burst" },
    { "g", 3.0, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "drag", 0.6, 0.0, 10.0, 0, "1/s", "linear drag per unit mass" },
    { "seed", 1, 0, 2147483647, 1, "", "random seed: the same seed gives the same show" },
};

#define FW_GAP 1.2   /* seconds between bursts */
#define FW_LIFE 2.5  /* seconds a spark lives */
#define FW_SPEED 4.0 /* largest launch speed */

static double fw_period(const double *p) { return p[FW_BURSTS] * FW_GAP + FW_LIFE; }

/* Burst b of show k: where it explodes. */
static void fw_origin(const double *p, int b, long k, double *x, double *y)
{
    uint64_t key = ((uint64_t)p[FW_SEED] << 20) ^ ((uint64_t)k << 8) ^ (uint64_t)b;
    *x = 2.0 + 6.0 * sw_scene_hash01(key, 1);
    *y = 4.0 + 3.0 * sw_scene_hash01(key, 2);
}

/* Which show and burst own particle i at time t, and how old it is. */
static double fw_age(const double *p, int i, double t, long *show, int *burst)
{
    int per = (int)p[FW_N];
    *burst = i / per;
    double period = fw_period(p), born = *burst * FW_GAP;
    *show = (long)floor((t - born) / period);
    return t - born - (double)*show * period;
}

static int fireworks_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int n = (int)(p[FW_BURSTS] * p[FW_N]);
    int rc = sw_scene_particles(sys, n, 1.0, err, errlen);
    if (rc != SW_OK || n < 1)
        return rc != SW_OK ? rc : SW_EINVAL;
    sw_particles_add_gravity(&sys->particles, 0.0, -p[FW_G]);
    if (p[FW_DRAG] > 0)
        sw_particles_add_drag(&sys->particles, p[FW_DRAG]);
    /* Everything waits, parked, at its burst's origin. */
    for (int i = 0; i < n; i++) {
        long show;
        int b;
        fw_age(p, i, 0.0, &show, &b);
        fw_origin(p, b, show < 0 ? 0 : show, &sys->y[2 * i], &sys->y[2 * i + 1]);
    }
    sys->extra = calloc((size_t)n, sizeof *sys->extra); /* show each spark was born for */
    if (!sys->extra) {
        snprintf(err, errlen, "out of memory for %d sparks", n);
        return SW_ENOMEM;
    }
    sys->nextra = n;
    for (int i = 0; i < n; i++)
        sys->extra[i] = -1;
    return SW_OK;
}

/* Sparks are born at the first step on or after their burst time with a
 * seeded velocity; once dead they are parked at the next burst's origin. */
static int fireworks_post(sw_system *sys, double t, double *y)
{
    const double *p = sys->p;
    int n = sys->n, changed = 0;
    for (int i = 0; i < n; i++) {
        long show;
        int b;
        double age = fw_age(p, i, t, &show, &b);
        double *x = y + 2 * i, *v = y + 2 * n + 2 * i;
        if (show < 0 || age > FW_LIFE) {
            fw_origin(p, b, show + 1, &x[0], &x[1]);
            v[0] = v[1] = 0;
            changed = 1;
        } else if (sys->extra[i] != (double)show) {
            uint64_t key = ((uint64_t)p[FW_SEED] << 32) ^ ((uint64_t)show << 20) ^ (uint64_t)i;
            double ang = 2.0 * 3.14159265358979323846 * sw_scene_hash01(key, 3);
            double spd = FW_SPEED * sqrt(sw_scene_hash01(key, 4));
            fw_origin(p, b, show, &x[0], &x[1]);
            v[0] = spd * cos(ang);
            v[1] = spd * sin(ang);
            sys->extra[i] = (double)show;
            changed = 1;
        }
    }
    return changed;
}

static int fireworks_alive(const sw_system *sys, double t, const double *y, int i)
{
    (void)y;
    long show;
    int b;
    double age = fw_age(sys->p, i, t, &show, &b);
    return show >= 0 && age <= FW_LIFE && sys->extra[i] == (double)show;
}

static sw_view fireworks_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ 0.0, 10.0, 0.0, 9.0 };
}

const sw_scene sw_scene_fireworks = {
    .name = "fireworks",
    .kind = SW_SYS_PARTICLES,
    .summary = "bursts of sparks under gravity and drag, each living a few seconds",
    .teaches = "A particle system: many independent particles, born and dying, one seeded show.",
    .params = fireworks_params,
    .nparams = SW_NPARAMS(fireworks_params),
    .dt = 0.02,
    .integrator = "symplectic-euler",
    .duration = 8.5,
    .build = fireworks_build,
    .view = fireworks_view,
    .post_step = fireworks_post,
    .alive = fireworks_alive,
};
