/* Water: a particle fluid in a box, smoothed-particle hydrodynamics after
 * Müller, Charypar and Gross (2003) (engine/force_sph.c) under gravity. The
 * particles start on a hexagonal lattice of spacing s filling the shape (a
 * dam about to break, a drop over a pool, a column at rest), each of mass
 * 1000 kg/m² times its share of the area, s²·√3/2; the rest density is the kernel sum at a lattice point
 * inside, so the lattice starts without pressure. The pressure's stiffness
 * sets the step: the sound speed c = √k limits an explicit step to about
 * C·h/c (the CFL condition). Modelled: pressure, viscosity, gravity, three
 * walls; no surface tension. */
#include <math.h>
#include <stdio.h>

#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/num.h"

enum { WA_N, WA_SHAPE, WA_H, WA_K, WA_NU, WA_G };
static const sw_param water_params[] = {
    { "n", 800, 4, 100000, 1, "", "about this many particles (a lattice filling the shape)" },
    { "shape", 0, 0, 2, 1, "", "0: a dam breaks; 1: a drop falls into a pool; 2: a column at rest" },
    { "h", 2.0, 1.2, 3.0, 0, "spacings", "kernel radius, in lattice spacings" },
    { "k", 400, 1, 100000, 0, "m^2/s^2", "stiffness: p = k (rho - rho0); the sound speed is sqrt(k)" },
    { "nu", 0.05, 0.0, 10.0, 0, "m^2/s", "kinematic viscosity" },
    { "g", 9.81, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
};

#define BOX_W 3.0      /* the box: walls x = 0, x = BOX_W, floor y = 0, m */
#define BOX_H 2.0      /* (open at the top; the view's height) */
#define RHO_WATER 1000.0 /* kg/m² of the lattice: each particle's mass is this times s² */

/* The shape's rectangles (x, y, w, h) and its disc (cx, cy, r; r = 0: none). */
typedef struct shape { double rect[4], disc[3]; } shape;

static shape shape_of(int which)
{
    switch (which) {
    case 0: return (shape){ { 0.0, 0.0, 0.6, 1.2 }, { 0, 0, 0 } };           /* Martin & Moyce's a × 2a column */
    case 1: return (shape){ { 0.0, 0.0, BOX_W, 0.4 }, { 1.5, 1.3, 0.25 } };  /* a pool, a drop above it */
    default: return (shape){ { 0.0, 0.0, BOX_W, 0.8 }, { 0, 0, 0 } };        /* a column at rest */
    }
}

/* The lattice: hexagonal (rows s·√3/2 apart, every other row shifted by
 * s/2), which a compressed fluid keeps (a square one buckles into it), with
 * s from the shape's area and n; its points, counted (xy NULL) or written.
 * Point (r, c) of a lattice centred at (cx, cy): (cx + (c + (r odd)/2)·s,
 * cy + r·s·√3/2). */
#define ROW 0.86602540378443865 /* √3/2 */

static double spacing(const shape *sh, double n)
{
    double area = sh->rect[2] * sh->rect[3] + SW_PI * sh->disc[2] * sh->disc[2];
    return sqrt(area / (ROW * n));
}

static int lattice(const shape *sh, double s, double *xy)
{
    int rows = (int)floor(sh->rect[3] / (ROW * s) + 1e-9), k = 0;
    for (int r = 0; r < rows; r++) {
        double shift = r % 2 ? 1.0 : 0.5;
        int cols = (int)floor((sh->rect[2] - (shift - 0.5) * s) / s + 1e-9);
        for (int c = 0; c < cols; c++, k++)
            if (xy) {
                xy[2 * k] = sh->rect[0] + (c + shift) * s;
                xy[2 * k + 1] = sh->rect[1] + (r + 0.5) * ROW * s;
            }
    }
    double R = sh->disc[2];
    int m = (int)ceil(R / (ROW * s)) + 1;
    for (int r = -m; r <= m; r++)
        for (int c = -m - 1; c <= m + 1; c++) {
            double dx = (c + (r & 1 ? 0.5 : 0.0)) * s, dy = r * ROW * s;
            if (R > 0 && dx * dx + dy * dy <= R * R) {
                if (xy) {
                    xy[2 * k] = sh->disc[0] + dx;
                    xy[2 * k + 1] = sh->disc[1] + dy;
                }
                k++;
            }
        }
    return k;
}

/* The kernel sum m Σ W6 over the lattice points within h of one of them
 * (itself included): the density of the lattice, taken as the rest density. */
static double lattice_density(double s, double h, double m)
{
    double sum = 0, h2 = h * h;
    int reach = (int)ceil(h / (ROW * s)) + 1;
    for (int r = -reach; r <= reach; r++)
        for (int c = -reach - 1; c <= reach + 1; c++) {
            double dx = (c + (r & 1 ? 0.5 : 0.0)) * s, dy = r * ROW * s, r2 = dx * dx + dy * dy;
            if (r2 < h2)
                sum += 4.0 / (SW_PI * h2 * h2 * h2 * h2) * (h2 - r2) * (h2 - r2) * (h2 - r2);
        }
    return m * sum;
}

/* The spiky gradient's constant renormalised on the lattice: C such that
 * Σ_b (m/ρ0)(y_b - y_a)² C (h - r)²/r = 1, so that the pressure force of a
 * linear pressure field is its exact gradient (the continuum's integral
 * gives C = 30/(π h⁵); a lattice of h = 2 s sums to about 15 % less). */
static double lattice_gradient(double s, double h, double m, double rho0)
{
    double sum = 0;
    int reach = (int)ceil(h / (ROW * s)) + 1;
    for (int r = -reach; r <= reach; r++)
        for (int c = -reach - 1; c <= reach + 1; c++) {
            double dx = (c + (r & 1 ? 0.5 : 0.0)) * s, dy = r * ROW * s, d = sqrt(dx * dx + dy * dy);
            if (d > 0 && d < h)
                sum += m / rho0 * dy * dy * (h - d) * (h - d) / d;
        }
    return 1.0 / sum;
}

static int water_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    shape sh = shape_of((int)p[WA_SHAPE]);
    double s = spacing(&sh, p[WA_N]), h = p[WA_H] * s, m = RHO_WATER * ROW * s * s;
    int n = lattice(&sh, s, NULL);
    int rc = sw_scene_particles(sys, n, m, err, errlen);
    if (rc != SW_OK)
        return rc;
    lattice(&sh, s, sys->y);
    sw_particles_add_gravity(&sys->particles, 0.0, -p[WA_G]);
    double rho0 = lattice_density(s, h, m);
    sw_force sph = { .kind = SW_FORCE_SPH, .h = h, .rho0 = rho0, .stiff = p[WA_K], .nu = p[WA_NU],
                     .box_w = BOX_W, .zone = 0.5 * ROW * s, .grad = lattice_gradient(s, h, m, rho0) };
    if ((rc = sw_particles_add_force(&sys->particles, &sph)) != SW_OK) {
        snprintf(err, errlen, "out of memory for the neighbour grid of %d particles", n);
        return rc;
    }
    /* No Jacobian beyond each particle's own estimate: implicit methods
     * would solve with the wrong matrix, so they are refused above the
     * dense fallback's size (sw_integrator_accepts says why). */
    sys->particles.ode.solve = NULL;
    sys->particles.ode.prepare = NULL;
    sw_walls *w = &sys->particles.walls; /* drawn only: the force pushes (no contact after a step) */
    w->active = 1;
    w->sides = SW_WALL_FLOOR | SW_WALL_LEFT | SW_WALL_RIGHT;
    w->xmax = BOX_W;
    w->ymax = BOX_H;
    return SW_OK;
}

/* The default step, from the two limits the truth module finds on the
 * dam at rest for symplectic Euler: the pressure's, about 0.56 h/c (sound
 * crossing the kernel radius), and the viscosity's, about 0.095 h²/ν
 * (diffusion across it); with both, a little under the smaller. The step
 * 1/(2.2 c/h + 13 ν/h²) is some 0.8 of either alone and less with both, so
 * more particles (h shrinks as 1/√n), stiffer or more viscous water start
 * stable. At the defaults (n = 800) it is 1.19 ms, above the scene's 1 ms,
 * which stays the step (sw_scene_dt takes the smaller). */
static double water_step(const double *p)
{
    shape sh = shape_of((int)p[WA_SHAPE]);
    double h = p[WA_H] * spacing(&sh, p[WA_N]);
    return 1.0 / (2.2 * sqrt(p[WA_K]) / h + 13.0 * p[WA_NU] / (h * h));
}

static sw_view water_view(const sw_system *sys)
{
    (void)sys;
    return (sw_view){ -0.1, BOX_W + 0.1, -0.1, BOX_H };
}

const sw_scene sw_scene_water = {
    .name = "water",
    .kind = SW_SYS_PARTICLES,
    .summary = "a particle fluid in a box (SPH): dam break, drop, column at rest",
    .teaches = "The pressure's stiffness sets the step: dt below about C h/c (CFL), c = sqrt(k); Euler explodes.",
    .params = water_params,
    .nparams = SW_NPARAMS(water_params),
    .dt = 0.001,
    .step = water_step,
    .integrator = "symplectic-euler",
    .duration = 1.0,
    .build = water_build,
    .view = water_view,
    .no_truth = "no closed form, and a tight reference run of a fluid this size would cost more than the run",
};
