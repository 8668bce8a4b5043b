/* Particle systems in structure-of-arrays form with force objects (Witkin &
 * Baraff). The state is one flat array y = [x(2n) | v(2n)]; derivative
 * evaluation is the lecture's three steps: clear forces, accumulate, return
 * v and f/m. Contact (walls, ground) is applied after a step, not as a force. */
#ifndef STEPWISE_PARTICLES_H
#define STEPWISE_PARTICLES_H

#include <stddef.h>
#include "stepwise/ode.h"

typedef enum sw_force_kind {
    SW_FORCE_GRAVITY,  /* f = m·g */
    SW_FORCE_DRAG,     /* f = -k·v */
    SW_FORCE_SPRINGS,  /* damped springs between particles or to anchors */
    SW_FORCE_CENTRAL,  /* f = -μ·m·d/|d|³ toward a fixed point */
    SW_FORCE_MUTUAL,   /* f_i = -Σ_j μ·m_i·m_j·d_ij/(|d_ij|² + soft²)^(3/2): softened gravity */
    SW_FORCE_TREE,     /* the same, Barnes-Hut: far groups as their centre of mass, opening angle theta */
    SW_FORCE_HEAT,     /* hot bodies (the first n/2) and their heat slots (the last n/2): see sw_force */
    SW_FORCE_SPH       /* smoothed-particle hydrodynamics (Müller et al. 2003) in a box: see sw_force */
} sw_force_kind;
#define SW_FORCE_KINDS (SW_FORCE_SPH + 1) /* the last kind + 1 */

/* A damped spring: f_a = -[k(|d| - rest) + c·(v_a - v_b)·d̂] d̂, d = x_a - x_b;
 * b < 0 ties a to the fixed anchor (ax, ay). */
typedef struct sw_spring {
    int a, b;
    double k, c, rest;
    double ax, ay;
} sw_spring;

typedef struct sw_force {
    sw_force_kind kind;
    double gx, gy;       /* gravity acceleration */
    double k;            /* drag coefficient */
    double cx, cy, mu;   /* central attraction; mu = G for mutual gravity */
    double soft;         /* mutual gravity's softening length */
    double theta;        /* Barnes-Hut opening angle: a cell of side s at distance d is one body when s < theta·d */
    /* SW_FORCE_HEAT: of 2m particles, body i < m carries a temperature in
     * its slot m + i, whose velocity is (θ_i, r_i): θ = T - T_ambient, r = 1
     * while the body lives (the slot's position, (∫θ dt, age), follows).
     * Body: f = m(gx, gy) + m·buoy·θ·ŷ - m·k·v; slot: f = (-m·cool·θ, 0). */
    double buoy;         /* buoyancy per kelvin above ambient, m/s^2/K */
    double cool;         /* cooling rate κ in dθ/dt = -κ θ, 1/s */
    /* SW_FORCE_SPH (engine/force_sph.c): kernel radius h, rest density
     * rho0, pressure p = stiff·max(ρ - rho0, 0), kinematic viscosity nu,
     * and walls x = 0, x = box_w, y = 0 pushing within `zone` of them. */
    double h, rho0, stiff, nu, box_w, zone;
    double grad;         /* SW_FORCE_SPH: C in ∇Wspiky = -C (h - r)² d/r; 0: the continuum's 30/(π h⁵) */
    sw_spring *springs;  /* owned by the particle system; NULL for a line (below) */
    int nsprings;
    sw_spring line[3];   /* springs == NULL: the line's first spring, its second (a and b advance by
                            one particle a spring after it) and its last (sw_particles_add_spring_line) */
    void *work;          /* what the kind sizes when added (the tree's node pool); owned by the system */
} sw_force;

/* Axis-aligned walls, applied after each step: a particle that crossed a wall
 * is reflected back across it and its normal velocity scaled by -e. */
typedef struct sw_walls {
    int active;
    unsigned sides;      /* SW_WALL_* bits */
    double xmin, xmax, ymin, ymax;
    double e;            /* restitution, 0..1 */
    double rest;         /* floor only: a ball leaving it slower than this is set at rest on it, a
                            resting contact (Witkin & Baraff), not ever smaller bounces; 0: none */
} sw_walls;

enum { SW_WALL_FLOOR = 1, SW_WALL_LEFT = 2, SW_WALL_RIGHT = 4, SW_WALL_CEILING = 8 };

#define SW_MAX_FORCES 6

typedef struct sw_particles {
    sw_ode ode;            /* first member: the solver's view, ctx = this */
    int n;
    double *y;             /* [x(2n) | v(2n)], owned */
    double *mass;          /* n */
    double *inv_mass;      /* n */
    sw_force forces[SW_MAX_FORCES];
    int nforces;
    sw_walls walls;
    int nsprings_total;
    struct sw_particles_solver *solver; /* implicit-solve workspace (private) */
    struct sw_particles_model *model;   /* the forces compiled by kind for the derivative (private) */
} sw_particles;

/* Allocate a system of n particles of mass `mass`, all at rest at the origin. */
int sw_particles_init(sw_particles *p, int n, double mass, char *err, size_t errlen);
void sw_particles_free(sw_particles *p);
/* Add forces; each returns 0 or SW_EINVAL when the force table is full. */
int sw_particles_add_gravity(sw_particles *p, double gx, double gy);
int sw_particles_add_drag(sw_particles *p, double k);
int sw_particles_add_central(sw_particles *p, double cx, double cy, double mu);
/* Any force given whole (fo->kind and its parameters; not springs, which
 * sw_particles_add_springs adds): 0, SW_EINVAL when the table is full or
 * the kind is not one, or SW_ENOMEM when its workspace (a tree's node pool,
 * sized for the system's n) cannot be had. */
int sw_particles_add_force(sw_particles *p, const sw_force *fo);
/* Reserve room for nsprings springs; fill the returned array (NULL on ENOMEM). */
sw_spring *sw_particles_add_springs(sw_particles *p, int nsprings);
/* A line of nsprings >= 2 springs stored as three: line[0] first, then
 * nsprings - 2 springs like line[1] with a and b advanced by one particle
 * a spring (spring j: a + j - 1, b + j - 1), then line[2] (a chain between
 * two anchors). Nothing n-long is written. SW_OK, SW_EINVAL (nsprings < 2,
 * or no room for another force) or SW_ENOMEM. */
int sw_particles_add_spring_line(sw_particles *p, int nsprings, const sw_spring line[3]);
/* Compile the forces for the derivative once the system is built (the
 * springs filled in); call again after changing a force or a spring. 0, or
 * SW_EINVAL when a spring names a particle that does not exist (err says
 * which; the derivative leaves such springs out). Without this call the
 * derivative compiles on first use. */
int sw_particles_finish(sw_particles *p, char *err, size_t errlen);
/* Every spring of the system, numbered 0 .. count-1 across spring forces:
 * spring j is copied to *out (a < 0 when there is no spring j). */
int sw_particles_spring_count(const sw_particles *p);
void sw_particles_spring(const sw_particles *p, int j, sw_spring *out);
/* The central attraction: 1 with its centre (*cx, *cy) and μ, or 0 when none. */
int sw_particles_central(const sw_particles *p, double *cx, double *cy, double *mu);
/* Apply wall contact to y after a step; returns 1 when anything changed. */
int sw_particles_contact(sw_particles *p, double *y);

/* Kinetic + potential energy of the conservative forces at y. */
double sw_particles_energy(const sw_particles *p, const double *y);
/* A bound on |sw_particles_energy - the exact energy| at y: 0 where every
 * potential is summed exactly (a Barnes-Hut tree above 4002 bodies is not). */
double sw_particles_energy_error(const sw_particles *p, const double *y);

#endif
