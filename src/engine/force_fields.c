/* The force kinds that act on each particle alone: uniform gravity f = m·g,
 * linear drag f = -k·v, and central attraction f = -μ·m·d/|d|³ toward a
 * fixed point (d = x - c). */
#include "engine/forces.h"

#include <math.h>
#include <stdio.h>

#include "engine/central.h"

static long no_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    (void)p, (void)fo;
    *reach = 0;
    return 0;
}

static void gravity_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)x, (void)v;
    for (int i = 0; i < p->n; i++) {
        f[2 * i] += p->mass[i] * fo->gx;
        f[2 * i + 1] += p->mass[i] * fo->gy;
    }
}

static void gravity_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    for (int i = 0; i < p->n; i++)
        *e -= p->mass[i] * (fo->gx * x[2 * i] + fo->gy * x[2 * i + 1]);
}

static void gravity_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                           swp_blocks *out)
{
    (void)p, (void)fo, (void)x, (void)v, (void)out; /* constant: no derivative */
}

static void gravity_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "g = (%g, %g)", fo->gx, fo->gy);
}

const swp_force_type swp_gravity = {
    .name = "gravity",
    .formula = "f = m g",
    .values = gravity_values,
    .add = gravity_add,
    .potential = gravity_potential,
    .term = "gravity potential",
    .term_formula = "m g y",
    .pairs = no_pairs,
    .blocks = gravity_blocks,
    .pairs_only = 1,
};

static void drag_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)x;
    for (int i = 0; i < p->n; i++) {
        f[2 * i] -= fo->k * v[2 * i];
        f[2 * i + 1] -= fo->k * v[2 * i + 1];
    }
}

static void drag_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                        swp_blocks *out)
{
    (void)x, (void)v;
    for (int i = 0; i < p->n; i++) {
        out->diag[8 * i + 4] -= fo->k;
        out->diag[8 * i + 7] -= fo->k;
    }
}

static void drag_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "k = %g", fo->k);
}

static int drag_uses_velocity(const sw_force *fo) { return fo->k != 0; }

const swp_force_type swp_drag = {
    .name = "drag",
    .formula = "f = -k v",
    .values = drag_values,
    .add = drag_add,
    .pairs = no_pairs,
    .blocks = drag_blocks,
    .uses_velocity = drag_uses_velocity,
};

static void central_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)v;
    for (int i = 0; i < p->n; i++) {
        double fx, fy;
        sw_central_force(fo->cx, fo->cy, fo->mu, p->mass[i], x[2 * i], x[2 * i + 1], &fx, &fy);
        f[2 * i] += fx;
        f[2 * i + 1] += fy;
    }
}

static void central_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    for (int i = 0; i < p->n; i++)
        *e -= fo->mu * p->mass[i] / hypot(x[2 * i] - fo->cx, x[2 * i + 1] - fo->cy);
}

static void central_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                           swp_blocks *out)
{
    (void)v;
    for (int i = 0; i < p->n; i++) {
        double blk[4], *d = out->diag + 8 * i;
        swp_inverse_square_block(fo->mu * p->mass[i], x[2 * i] - fo->cx, x[2 * i + 1] - fo->cy, 0.0, blk);
        for (int k = 0; k < 4; k++)
            d[k] += blk[k];
    }
}

static void central_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "mu = %g, centre (%g, %g)", fo->mu, fo->cx, fo->cy);
}

const swp_force_type swp_central = {
    .name = "central body",
    .formula = "f = -mu m d/|d|^3, d = x - centre",
    .values = central_values,
    .add = central_add,
    .potential = central_potential,
    .term = "central potential",
    .term_formula = "- μ m/|x|",
    .pairs = no_pairs,
    .blocks = central_blocks,
};
