/* A galaxy: stars in a disc around a heavy core, every body pulling every
 * other (softened mutual gravity, G = 1) — the lecture's last example. With
 * discs = 2 a second galaxy falls past the first. No closed form; energy,
 * momentum and angular momentum are conserved exactly, so their drift is
 * the integrator's. Modelled: mutual gravity only (no gas, no dark halo),
 * by direct sum or, with theta > 0, a Barnes-Hut tree. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/num.h"

enum { GX_N, GX_DISC, GX_SOFT, GX_DISCS, GX_THETA };
static const sw_param galaxy_params[] = {
    { "n", 100, 2, 100000, 1, "", "stars per disc (above 2000 only with theta > 0)" },
    { "disc", 0.05, 0.0, 1.0, 0, "", "a disc's mass over its core's (core mass 1)" },
    { "soft", 0.1, 0.001, 0.5, 0, "", "softening length: gravity at distance r is G m m'/(r^2 + soft^2)" },
    { "discs", 1, 1, 2, 1, "", "galaxies: 1, or 2 (the second falls past the first)" },
    { "theta", 0, 0, 1, 0, "", "Barnes-Hut opening angle: 0 sums every pair; > 0 takes a far cell as one body" },
};

/* The disc's radii: stars from R_IN to R_OUT around their core. */
#define R_IN 0.3
#define R_OUT 1.0
/* The second galaxy starts at (X2, Y2) moving at (0, V2): a bound,
 * eccentric fall past the first (it comes within about 1.5). */
#define X2 4.0
#define Y2 -2.0
#define V2 0.45

/* One disc of n stars and its core at particle `first`, centred at
 * (cx, cy) moving at (vx, vy): star k at radius R_IN + (R_OUT - R_IN)(k +
 * ½)/n and angle k times the golden angle, on the circular orbit about the
 * core and the disc mass inside it (counterclockwise) under the softened
 * pull M r/(r² + ε²)^(3/2). */
static void put_disc(sw_system *sys, int first, int n, double cx, double cy, double vx, double vy)
{
    sw_particles *p = &sys->particles;
    double md = sys->p[GX_DISC], e2 = sys->p[GX_SOFT] * sys->p[GX_SOFT], golden = SW_PI * (3.0 - sqrt(5.0)), *x = sys->y, *v = sys->y + 2 * p->n;
    p->mass[first] = 1.0;
    p->inv_mass[first] = 1.0;
    x[2 * first] = cx, x[2 * first + 1] = cy, v[2 * first] = vx, v[2 * first + 1] = vy;
    for (int k = 0; k < n; k++) {
        int i = first + 1 + k;
        double r = R_IN + (R_OUT - R_IN) * (k + 0.5) / n, a = k * golden;
        double inside = 1.0 + md * (k + 0.5) / n, speed = sqrt(inside * r * r / pow(r * r + e2, 1.5));
        p->mass[i] = md > 0 ? md / n : 1e-12;
        p->inv_mass[i] = 1.0 / p->mass[i];
        x[2 * i] = cx + r * cos(a);
        x[2 * i + 1] = cy + r * sin(a);
        v[2 * i] = vx - speed * sin(a);
        v[2 * i + 1] = vy + speed * cos(a);
    }
}

/* Total angular momentum about the origin, Σ m (x vy - y vx). */
static double angular_momentum(const sw_system *sys, const double *y)
{
    const sw_particles *p = &sys->particles;
    const double *v = y + 2 * p->n;
    double L = 0;
    for (int i = 0; i < p->n; i++)
        L += p->mass[i] * (y[2 * i] * v[2 * i + 1] - y[2 * i + 1] * v[2 * i]);
    return L;
}

/* Above this many stars a disc is summed by the tree only: the direct sum
 * at n = 1e5 is 5e9 pairs an evaluation, some 17 s here. */
#define DIRECT_MAX 2000

static int galaxy_build(sw_system *sys, char *err, size_t errlen)
{
    int n = (int)sys->p[GX_N], discs = (int)sys->p[GX_DISCS], rc;
    if (n > DIRECT_MAX && !(sys->p[GX_THETA] > 0)) {
        snprintf(err, errlen, "galaxy: n = %d with theta = 0 sums all %.2g pairs every evaluation; above n = %d "
                 "set theta > 0 (--set theta=0.5: the Barnes-Hut tree)", n, 0.5 * discs * (n + 1.0) * (discs * (n + 1.0) - 1),
                 DIRECT_MAX);
        return SW_EINVAL;
    }
    if ((rc = sw_scene_particles(sys, discs * (n + 1), 1.0, err, errlen)) != SW_OK)
        return rc;
    double theta = sys->p[GX_THETA];
    sw_force g = { .kind = theta > 0 ? SW_FORCE_TREE : SW_FORCE_MUTUAL, .mu = 1.0, .soft = sys->p[GX_SOFT],
                   .theta = theta };
    if ((rc = sw_particles_add_force(&sys->particles, &g)) != SW_OK)
        return rc;
    if (discs == 1)
        put_disc(sys, 0, n, 0.0, 0.0, 0.0, 0.0);
    else { /* the pair's centre of mass at rest at the origin */
        put_disc(sys, 0, n, -X2 / 2, -Y2 / 2, 0.0, -V2 / 2);
        put_disc(sys, n + 1, n, X2 / 2, Y2 / 2, 0.0, V2 / 2);
    }
    if (!(sys->extra = malloc(sizeof *sys->extra)))
        return SW_ENOMEM;
    sys->nextra = 1;
    sys->extra[0] = angular_momentum(sys, sys->y); /* L at the start */
    return SW_OK;
}

/* |L - L0|: the total angular momentum's drift (exact paths keep it). */
static double galaxy_drift(const sw_system *sys, const double *y)
{
    return fabs(angular_momentum(sys, y) - sys->extra[0]);
}

/* The tree's bound on the energy's error (0 while it sums exactly). */
static double galaxy_energy_error(const sw_system *sys, const double *y)
{
    return sw_particles_energy_error(&sys->particles, y);
}

static sw_view galaxy_view(const sw_system *sys)
{
    double h = sys->p[GX_DISCS] > 1 ? 4.0 : 1.3;
    return (sw_view){ -h, h, -h, h };
}

const sw_scene sw_scene_galaxy = {
    .name = "galaxy",
    .kind = SW_SYS_PARTICLES,
    .summary = "stars around a heavy core, every body pulling every other (N-body)",
    .teaches = "Verlet keeps the angular momentum to rounding (theta = 0, every pair summed; the tree's "
               "forces break it); RK4 lets it drift.",
    .params = galaxy_params,
    .nparams = SW_NPARAMS(galaxy_params),
    .dt = 0.01,
    .integrator = "verlet",
    .duration = 2.0,
    .build = galaxy_build,
    .energy = sw_scene_particle_energy,
    .energy_error = galaxy_energy_error,
    .drift = galaxy_drift,
    .drift_name = "angular-momentum drift",
    .reference = 1,
    .view = galaxy_view,
};
