/* Particles with a life (the lecture's fire and explosion): each body
 * carries a temperature beside x and v. Of 2m particles, body i < m keeps
 * its temperature above ambient θ = T - T_AMB in the velocity of its heat
 * slot m + i (the force kind SW_FORCE_HEAT, engine/force_heat.c), with the
 * slot's second velocity r = 1 while the body lives, 0 once dead: every
 * state, and so every trace row, says which bodies are alive. Births and
 * deaths are events (a scheduled time, a temperature falling through the
 * cold limit): located with --events locate, met at the step's end
 * otherwise. Randomness is seeded (sw_scene_hash01): the same seed, the
 * same run, bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/num.h"

#define T_AMB 300.0   /* ambient temperature, K */
#define T_COLD 350.0  /* a flame below this is dead, K */
#define T_BURST 1500.0 /* mean temperature of a fragment at the burst, K */
#define SOURCE_W 1.0  /* the fire's source: a strip this wide at y = 0, m */
#define MAX_BODIES 20000
/* Why the error is not measured: a state mixes metres and kelvin-seconds. */
#define HOT_NO_TRUTH "no closed form, and a state holds temperatures and their integrals beside positions, " \
                     "so no distance between states is an error in metres"

/* The state of body i and its slot in y (n = 2m particles). */
typedef struct hot { double *x, *v, *dose, *theta; } hot;

static hot hot_at(const sw_system *sys, double *y, int i)
{
    int n = sys->n, m = n / 2;
    return (hot){ y + 2 * i, y + 2 * n + 2 * i, y + 2 * (m + i), y + 2 * n + 2 * (m + i) };
}

static int hot_alive(const sw_system *sys, const double *y, int i)
{
    hot h = hot_at(sys, (double *)y, i);
    return h.theta[1] != 0;
}

/* m bodies and their m slots, all of mass 1, under the heat force. */
static int hot_build(sw_system *sys, int m, const sw_force *heat, char *err, size_t errlen)
{
    int rc = sw_scene_particles(sys, 2 * m, 1.0, err, errlen);
    if (rc == SW_OK)
        rc = sw_particles_add_force(&sys->particles, heat);
    if (rc == SW_OK && !(sys->extra = calloc((size_t)2 * m, sizeof *sys->extra))) {
        snprintf(err, errlen, "out of memory for %d bodies", m);
        rc = SW_ENOMEM;
    }
    sys->nextra = 2 * m;
    return rc;
}

/* Drawn only the bodies, and of them the living. */
static int hot_shown(const sw_system *sys, double t, const double *y, int i)
{
    (void)t;
    return i < sys->n / 2 && hot_alive(sys, y, i);
}

/* θ over the hottest a body is born (1.2 of the mean above ambient). */
static double hot_heat(const sw_system *sys, const double *y, int i, double mean_above)
{
    return i < sys->n / 2 ? fmin(1.0, fmax(0.0, *hot_at(sys, (double *)y, i).theta / (1.2 * mean_above))) : 0.0;
}

/* ---- fire: an emitter at a stated rate -------------------------------- */

enum { FI_RATE, FI_LIFE, FI_KAPPA, FI_BUOY, FI_DRAG, FI_TEMP, FI_SEED };
static const sw_param fire_params[] = {
    { "rate", 60, 0.1, 5000, 0, "1/s", "births per second at the source" },
    { "life", 2.5, 0.1, 10.0, 0, "s", "the longest a flame particle lives" },
    { "kappa", 1.0, 0.0, 1000.0, 0, "1/s", "cooling rate: dT/dt = -kappa (T - 300 K)" },
    { "buoy", 0.005, 0.0, 1.0, 0, "m/s^2/K", "buoyancy per kelvin above ambient (300 K)" },
    { "drag", 1.0, 0.0, 10.0, 0, "1/s", "linear drag per unit mass" },
    { "temp", 1200, 400, 3000, 0, "K", "mean temperature at birth (each 0.8 to 1.2 of it above ambient)" },
    { "seed", 1, 0, 2147483647, 1, "", "random seed: the same seed gives the same fire" },
};

/* extra[i]: the time of body i's next scheduled change (its death by age
 * while alive, its birth while dead); extra[m + i]: the number q of its
 * current or next birth. Birth q happens at q/rate, to body q mod m. */
static double fire_born_at(const sw_system *sys, double q) { return q / sys->p[FI_RATE]; }

/* Birth q of body i: on the source strip, a little sideways, hot. */
static void fire_birth(sw_system *sys, double *y, int i)
{
    const double *p = sys->p;
    int m = sys->n / 2;
    uint64_t q = (uint64_t)sys->extra[m + i], seed = 4 * (uint64_t)p[FI_SEED];
    hot h = hot_at(sys, y, i);
    h.x[0] = SOURCE_W * (sw_scene_hash01(seed, q) - 0.5);
    h.x[1] = 0.0;
    h.v[0] = 0.6 * (sw_scene_hash01(seed + 1, q) - 0.5);
    h.v[1] = 0.4 * sw_scene_hash01(seed + 2, q);
    h.dose[0] = h.dose[1] = 0.0;
    h.theta[0] = (p[FI_TEMP] - T_AMB) * (0.8 + 0.4 * sw_scene_hash01(seed + 3, q));
    h.theta[1] = 1.0;
    sys->extra[i] = fire_born_at(sys, sys->extra[m + i]) + p[FI_LIFE];
}

/* Dead: still, cold, not drawn, waiting for its next birth. */
static void fire_death(sw_system *sys, double *y, int i)
{
    int m = sys->n / 2;
    hot h = hot_at(sys, y, i);
    h.v[0] = h.v[1] = h.theta[0] = h.theta[1] = 0.0;
    sys->extra[m + i] += m;
    sys->extra[i] = fire_born_at(sys, sys->extra[m + i]);
}

static int fire_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    double pool = floor(p[FI_RATE] * p[FI_LIFE]) + 1; /* bodies alive at once, at most */
    if (pool > MAX_BODIES) {
        snprintf(err, errlen, "fire: rate x life = %g flames alive at once; at most %d (lower rate or life)",
                 p[FI_RATE] * p[FI_LIFE], MAX_BODIES - 1);
        return SW_EINVAL;
    }
    int m = (int)pool;
    sw_force heat = { .kind = SW_FORCE_HEAT, .k = p[FI_DRAG], .buoy = p[FI_BUOY], .cool = p[FI_KAPPA] };
    int rc = hot_build(sys, m, &heat, err, errlen);
    if (rc != SW_OK)
        return rc;
    for (int i = 0; i < m; i++) { /* all dead, body 0 born at t = 0 */
        sys->extra[m + i] = i;
        sys->extra[i] = fire_born_at(sys, i);
    }
    fire_birth(sys, sys->y, 0);
    return SW_OK;
}

/* Births and deaths due by t, met at the step's end (first order in time). */
static int fire_post(sw_system *sys, double t, double *y)
{
    int m = sys->n / 2, changed = 0;
    for (int i = 0; i < m; i++) {
        if (hot_alive(sys, y, i) && (t >= sys->extra[i] || *hot_at(sys, y, i).theta <= T_COLD - T_AMB)) {
            fire_death(sys, y, i);
            changed = 1;
        }
        if (!hot_alive(sys, y, i) && t >= sys->extra[i]) {
            fire_birth(sys, y, i);
            changed = 1;
        }
    }
    return changed;
}

/* Event 2i: body i's scheduled change (birth or death by age) falls due;
 * event 2i + 1: living body i cools through T_COLD. */
static int fire_event_count(const sw_system *sys) { return sys->n; }

static double fire_event_g(const sw_system *sys, int k, double t, const double *y)
{
    int i = k / 2;
    if (k % 2 == 0)
        return sys->extra[i] - t;
    return hot_alive(sys, y, i) ? *hot_at(sys, (double *)y, i).theta - (T_COLD - T_AMB) : 1.0;
}

static void fire_event_jump(sw_system *sys, int k, double t, double *y)
{
    (void)t;
    int i = k / 2;
    if (k % 2 == 0 && !hot_alive(sys, y, i))
        fire_birth(sys, y, i);
    else
        fire_death(sys, y, i);
}

static const char *fire_event_breaks(const sw_system *sys)
{
    (void)sys;
    return "a flame is born, or dies of age or cold, where a step ends unless the event is located: "
           "every method is limited to first order - see --events";
}

static const sw_scene_events fire_events = {
    .count = fire_event_count,
    .g = fire_event_g,
    .direction = -1,
    .jump = fire_event_jump,
    .breaks = fire_event_breaks,
};

static double fire_heat(const sw_system *sys, const double *y, int i)
{
    return hot_heat(sys, y, i, sys->p[FI_TEMP] - T_AMB);
}

static sw_view fire_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ -2.5, 2.5, -0.3, 5.0 };
}

const sw_scene sw_scene_fire = {
    .name = "fire",
    .kind = SW_SYS_PARTICLES,
    .summary = "flames born at a steady rate rise as they cool, dying cold or old",
    .teaches = "A stiff variable in a soft one: fast cooling (kappa dt) limits an explicit step while the "
               "motion is slow.",
    .params = fire_params,
    .nparams = SW_NPARAMS(fire_params),
    .dt = 0.02,
    .integrator = "symplectic-euler",
    .duration = 4.0,
    .build = fire_build,
    .view = fire_view,
    .post_step = fire_post,
    .alive = hot_shown,
    .events = &fire_events,
    .heat = fire_heat,
    .no_truth = HOT_NO_TRUTH,
};

/* ---- explosion: one burst, fragments that fall and bounce ------------- */

enum { EX_N, EX_T0, EX_SPEED, EX_G, EX_DRAG, EX_KAPPA, EX_E, EX_SEED };
static const sw_param explosion_params[] = {
    { "n", 200, 1, 10000, 1, "", "fragments" },
    { "t0", 1.0, 0.0, 10.0, 0, "s", "when the shell bursts (launched at g t0 up, its top then without drag)" },
    { "speed", 6.0, 0.0, 100.0, 0, "m/s", "largest radial speed a fragment gets at the burst" },
    { "g", 9.81, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "drag", 0.3, 0.0, 10.0, 0, "1/s", "linear drag per unit mass" },
    { "kappa", 0.5, 0.0, 1000.0, 0, "1/s", "cooling rate: dT/dt = -kappa (T - 300 K)" },
    { "e", 0.5, 0.0, 1.0, 0, "", "coefficient of restitution at the floor" },
    { "seed", 1, 0, 2147483647, 1, "", "random seed: the same seed gives the same burst" },
};

/* extra[0]: 1 once the shell has burst. */
static void explosion_burst(sw_system *sys, double *y)
{
    const double *p = sys->p;
    int m = sys->n / 2;
    uint64_t seed = 4 * (uint64_t)p[EX_SEED];
    for (int i = 0; i < m; i++) {
        hot h = hot_at(sys, y, i);
        double a = 2.0 * SW_PI * (i + sw_scene_hash01(seed, (uint64_t)i)) / m;
        double s = p[EX_SPEED] * (0.5 + 0.5 * sw_scene_hash01(seed + 1, (uint64_t)i));
        h.v[0] += s * cos(a);
        h.v[1] += s * sin(a);
        h.theta[0] = (T_BURST - T_AMB) * (0.8 + 0.4 * sw_scene_hash01(seed + 2, (uint64_t)i));
    }
    sys->extra[0] = 1;
}

static int explosion_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int m = (int)p[EX_N];
    sw_force heat = { .kind = SW_FORCE_HEAT, .gy = -p[EX_G], .k = p[EX_DRAG], .cool = p[EX_KAPPA] };
    int rc = hot_build(sys, m, &heat, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_walls *w = &sys->particles.walls; /* a floor: the slots' second position (age) never goes below it */
    w->active = 1;
    w->sides = SW_WALL_FLOOR;
    w->xmin = -1e300;
    w->xmax = 1e300;
    w->ymin = 0;
    w->ymax = 1e300;
    w->e = p[EX_E];
    for (int i = 0; i < m; i++) { /* one cold shell, launched up from the floor */
        hot h = hot_at(sys, sys->y, i);
        h.v[1] = p[EX_G] * p[EX_T0];
        h.theta[1] = 1.0;
    }
    if (p[EX_T0] == 0)
        explosion_burst(sys, sys->y);
    return SW_OK;
}

static int explosion_post(sw_system *sys, double t, double *y)
{
    int burst = sys->extra[0] == 0 && t >= sys->p[EX_T0];
    if (burst)
        explosion_burst(sys, y);
    return sw_particles_contact(&sys->particles, y) | burst;
}

/* Event i < m: fragment i falls through the floor; event m: the burst. */
static int explosion_event_count(const sw_system *sys) { return sys->n / 2 + 1; }

static double explosion_event_g(const sw_system *sys, int k, double t, const double *y)
{
    if (k == sys->n / 2)
        return sys->extra[0] != 0 ? 1.0 : sys->p[EX_T0] - t;
    return y[2 * k + 1];
}

/* At the floor: the overshoot reflected and the fall reversed, times e. */
static void explosion_event_jump(sw_system *sys, int k, double t, double *y)
{
    (void)t;
    if (k == sys->n / 2) {
        explosion_burst(sys, y);
        return;
    }
    hot h = hot_at(sys, y, k);
    double e = sys->p[EX_E];
    if (h.x[1] < 0)
        h.x[1] *= -e;
    if (h.v[1] < 0)
        h.v[1] *= -e;
}

static const char *explosion_event_breaks(const sw_system *sys)
{
    (void)sys;
    return "the burst and each bounce jump the velocity where a step ends unless located: every method "
           "is limited to first order - see --events";
}

static const sw_scene_events explosion_events = {
    .count = explosion_event_count,
    .g = explosion_event_g,
    .direction = -1,
    .jump = explosion_event_jump,
    .breaks = explosion_event_breaks,
};

static double explosion_heat(const sw_system *sys, const double *y, int i)
{
    return hot_heat(sys, y, i, T_BURST - T_AMB);
}

static sw_view explosion_view(const sw_system *sys)
{
    const double *p = sys->p;
    double half = 2.0 + 1.5 * p[EX_SPEED];
    double top = 1.0 + 0.5 * p[EX_G] * p[EX_T0] * p[EX_T0] + 0.5 * p[EX_SPEED] * p[EX_SPEED] / fmax(p[EX_G], 1.0);
    return (sw_view){ -half, half, -0.5, top };
}

const sw_scene sw_scene_explosion = {
    .name = "explosion",
    .kind = SW_SYS_PARTICLES,
    .summary = "a shell bursts at t0 into hot fragments that fall, cool and bounce",
    .teaches = "The burst and every bounce are events: stepped over they cost every method its order.",
    .params = explosion_params,
    .nparams = SW_NPARAMS(explosion_params),
    .dt = 0.01,
    .integrator = "verlet",
    .duration = 3.0,
    .build = explosion_build,
    .view = explosion_view,
    .post_step = explosion_post,
    .alive = hot_shown,
    .events = &explosion_events,
    .heat = explosion_heat,
    .no_truth = HOT_NO_TRUTH,
};
