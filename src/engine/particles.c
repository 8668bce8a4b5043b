/* Particle systems: structure-of-arrays state y = [x | v] and the list of
 * force objects a scene adds (the description); contact and energy. The
 * derivative evaluates the forces compiled by kind (particles_deriv.c), the
 * implicit solve lives in particles_solve.c, the read-only questions about
 * the forces (which springs, which centre) in particles_query.c. Invariant: deriv allocates
 * nothing; all workspace is sized when the system and its springs are
 * created. */
#include "stepwise/particles.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/forces.h"
#include "engine/ode_fast.h"
#include "engine/particles_chain.h"
#include "engine/particles_deriv.h"
#include "engine/particles_small.h"
#include "engine/particles_solve.h"
#include "stepwise/base.h"

/* Whether every force ignores velocities (asked of each kind's descriptor):
 * what a Runge-Kutta-Nyström method needs. */
static int position_only(const void *ctx)
{
    const sw_particles *p = ctx;
    for (int k = 0; k < p->nforces; k++) {
        const swp_force_type *type = swp_force_type_of(p->forces[k].kind);
        if (type && type->uses_velocity && type->uses_velocity(&p->forces[k]))
            return 0;
    }
    return 1;
}

/* The orbit's field and particle, when the small path is that alone. */
static int central1(const void *ctx, sw_central1 *c)
{
    const sw_particles *p = ctx;
    return swp_deriv_is_small(p) && swp_small_central1(p, c);
}

/* The stiff spring's spring and particle, when the small path is that
 * alone and no resting contact adjusts the derivative. */
static int spring1(const void *ctx, sw_spring1 *s)
{
    const sw_particles *p = ctx;
    return swp_deriv_is_small(p) && !(p->walls.rest > 0 && (p->walls.sides & SW_WALL_FLOOR)) &&
           swp_small_spring1(p, s);
}

/* The particles' own derivatives read no t (the forces do not depend on
 * time); a scene that sets a derivative of its own is not vouched for. */
static int autonomous(const sw_ode *ode)
{
    return ode->deriv == swp_deriv || ode->deriv == swp_deriv_generic;
}

/* No slices: the facts above, the orbit's and the stiff spring's numbers,
 * and for a chain between two anchors its fused rk4 (compiling picks the
 * row: particles_deriv.c); a plugin's host (-DSW_FIELD_ONLY) keeps no
 * method, fused or not. */
#ifndef SW_FIELD_ONLY
#define CHAIN_RK4 swp_chain_rk4
#else
#define CHAIN_RK4 NULL
#endif
/* The two rows share every fact; the second adds the fused chain rk4. */
#define PARTICLES_FACTS                                                                                \
    .position_only = position_only, .central1 = central1, .spring1 = spring1, .autonomous = autonomous, \
    .solve_same = sw_particles_solve_same, .solve_new = sw_particles_solve_new
static const struct sw_ode_fast particles_fast[2] = {
    { PARTICLES_FACTS },
    { PARTICLES_FACTS, .fused_rk4 = CHAIN_RK4 },
};

int sw_particles_init(sw_particles *p, int n, double mass, char *err, size_t errlen)
{
    memset(p, 0, sizeof *p);
    if (n < 1) {
        snprintf(err, errlen, "a particle system needs at least one particle (got %d)", n);
        return SW_EINVAL;
    }
    if (!(mass > 0) || !isfinite(mass)) {
        snprintf(err, errlen, "particle mass must be positive and finite (got %g)", mass);
        return SW_EINVAL;
    }
    p->n = n;
    p->y = calloc((size_t)4 * n, sizeof *p->y);
    p->mass = malloc((size_t)n * sizeof *p->mass);
    p->inv_mass = malloc((size_t)n * sizeof *p->inv_mass);
    if (!p->y || !p->mass || !p->inv_mass || swp_model_init(p, particles_fast) != SW_OK || sw_particles_solver_init(p) != SW_OK) {
        sw_particles_free(p);
        snprintf(err, errlen, "out of memory for %d particles", n);
        return SW_ENOMEM;
    }
    for (int i = 0; i < n; i++) {
        p->mass[i] = mass;
        p->inv_mass[i] = 1.0 / mass;
    }
    p->ode.dim = 4 * n;
    p->ode.order = 2;
    p->ode.deriv = swp_deriv;
    p->ode.solve = sw_particles_solve;
    p->ode.prepare = sw_particles_solver_prepare;
    p->ode.ctx = p;
    p->ode.fast = &particles_fast[0];
    return SW_OK;
}

void sw_particles_free(sw_particles *p)
{
    for (int k = 0; k < p->nforces; k++) {
        free(p->forces[k].springs);
        free(p->forces[k].work);
    }
    free(p->y);
    free(p->mass);
    free(p->inv_mass);
    sw_particles_solver_free(p);
    swp_model_free(p);
    memset(p, 0, sizeof *p);
}

static sw_force *add_force(sw_particles *p, sw_force_kind kind)
{
    if (p->nforces == SW_MAX_FORCES)
        return NULL;
    sw_force *fo = &p->forces[p->nforces++];
    memset(fo, 0, sizeof *fo);
    swp_model_touch(p);
    fo->kind = kind;
    return fo;
}

int sw_particles_add_gravity(sw_particles *p, double gx, double gy)
{
    sw_force *fo = add_force(p, SW_FORCE_GRAVITY);
    if (!fo)
        return SW_EINVAL;
    fo->gx = gx;
    fo->gy = gy;
    return SW_OK;
}

int sw_particles_add_drag(sw_particles *p, double k)
{
    sw_force *fo = add_force(p, SW_FORCE_DRAG);
    if (!fo)
        return SW_EINVAL;
    fo->k = k;
    return SW_OK;
}

int sw_particles_add_force(sw_particles *p, const sw_force *given)
{
    if (!swp_force_type_of(given->kind) || given->kind == SW_FORCE_SPRINGS)
        return SW_EINVAL;
    sw_force *fo = add_force(p, given->kind);
    if (!fo)
        return SW_EINVAL;
    *fo = *given;
    fo->springs = NULL;
    fo->nsprings = 0;
    if (swp_force_prepare(p, fo) != SW_OK) {
        p->nforces--;
        return SW_ENOMEM;
    }
    return SW_OK;
}

int sw_particles_add_central(sw_particles *p, double cx, double cy, double mu)
{
    sw_force *fo = add_force(p, SW_FORCE_CENTRAL);
    if (!fo)
        return SW_EINVAL;
    fo->cx = cx;
    fo->cy = cy;
    fo->mu = mu;
    return SW_OK;
}

sw_spring *sw_particles_add_springs(sw_particles *p, int nsprings)
{
    if (nsprings < 1)
        return NULL;
    sw_spring *s = calloc((size_t)nsprings, sizeof *s);
    if (!s || swp_model_springs(p, p->nsprings_total + nsprings) != SW_OK) {
        free(s);
        return NULL;
    }
    sw_force *fo = add_force(p, SW_FORCE_SPRINGS);
    if (!fo) {
        free(s);
        return NULL;
    }
    fo->springs = s;
    fo->nsprings = nsprings;
    p->nsprings_total += nsprings;
    return s;
}

int sw_particles_add_spring_line(sw_particles *p, int nsprings, const sw_spring line[3])
{
    if (nsprings < 2 || p->nforces == SW_MAX_FORCES)
        return SW_EINVAL;
    if (swp_model_springs(p, p->nsprings_total + nsprings) != SW_OK)
        return SW_ENOMEM;
    sw_force *fo = add_force(p, SW_FORCE_SPRINGS);
    fo->nsprings = nsprings;
    memcpy(fo->line, line, sizeof fo->line);
    p->nsprings_total += nsprings;
    return SW_OK;
}

int sw_particles_finish(sw_particles *p, char *err, size_t errlen)
{
    sw_particles_solver_touch(p);
    return swp_model_compile(p, err, errlen);
}

/* Reflect a coordinate that crossed a wall back inside, losing the fraction
 * (1 - e) of its overshoot, and reverse its normal velocity scaled by e;
 * leaving slower than rest, it stays on the wall at rest (sw_walls.rest). */
static int bounce(double *x, double *v, double wall, double sign, double e, double rest)
{
    double over = sign * (*x - wall); /* > 0: outside */
    if (!(over > 0))
        return 0;
    *x = wall - sign * e * over;
    if (sign * *v > 0)
        *v = -e * *v;
    if (fabs(*v) < rest) {
        *x = wall;
        *v = 0;
    }
    return 1;
}

int sw_particles_contact(sw_particles *p, double *y)
{
    const sw_walls *w = &p->walls;
    if (!w->active)
        return 0;
    int changed = 0, n2 = 2 * p->n;
    for (int i = 0; i < p->n; i++) {
        double *x = y + 2 * i, *v = y + n2 + 2 * i;
        if (w->sides & SW_WALL_FLOOR)
            changed |= bounce(&x[1], &v[1], w->ymin, -1.0, w->e, w->rest);
        if (w->sides & SW_WALL_CEILING)
            changed |= bounce(&x[1], &v[1], w->ymax, 1.0, w->e, 0.0);
        if (w->sides & SW_WALL_LEFT)
            changed |= bounce(&x[0], &v[0], w->xmin, -1.0, w->e, 0.0);
        if (w->sides & SW_WALL_RIGHT)
            changed |= bounce(&x[0], &v[0], w->xmax, 1.0, w->e, 0.0);
    }
    return changed;
}

double sw_particles_energy(const sw_particles *p, const double *y)
{
    int n2 = 2 * p->n;
    const double *x = y, *v = y + n2;
    double e = 0;
    for (int i = 0; i < p->n; i++)
        e += 0.5 * p->mass[i] * (v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1]);
    for (int k = 0; k < p->nforces; k++) {
        const swp_force_type *type = swp_force_type_of(p->forces[k].kind);
        if (type->potential)
            type->potential(p, &p->forces[k], x, &e);
    }
    return e;
}

double sw_particles_energy_error(const sw_particles *p, const double *y)
{
    double bound = 0;
    for (int k = 0; k < p->nforces; k++) {
        const swp_force_type *type = swp_force_type_of(p->forces[k].kind);
        if (type->potential_error)
            bound += type->potential_error(p, &p->forces[k], y);
    }
    return bound;
}
