/* Damped springs between particles or to fixed anchors:
 *   f_a = -[k(|d| - rest) + c·(v_a - v_b)·d̂] d̂,  f_b = -f_a,  d = x_a - x_b,
 * no force where |d| = 0 (the direction is undefined). The derivative runs
 * them through particles_deriv.c's compiled loops; `add` is the lecture's
 * loop, the same numbers. */
#include "engine/forces.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "engine/clones.h"
#include "engine/lanes.h"
#include "engine/spring_line.h"

/* d = x_a - x_b (or the anchor) and dv = v_a - v_b of spring sp. */
static void differences(const sw_spring *sp, const double *x, const double *v, double d[2], double dv[2])
{
    double bx = sp->b >= 0 ? x[2 * sp->b] : sp->ax, by = sp->b >= 0 ? x[2 * sp->b + 1] : sp->ay;
    d[0] = x[2 * sp->a] - bx;
    d[1] = x[2 * sp->a + 1] - by;
    dv[0] = v[2 * sp->a] - (sp->b >= 0 ? v[2 * sp->b] : 0.0);
    dv[1] = v[2 * sp->a + 1] - (sp->b >= 0 ? v[2 * sp->b + 1] : 0.0);
}

/* |d|, with hypot where the squares lose their digits. */
static double length(const double d[2])
{
    double r2 = d[0] * d[0] + d[1] * d[1];
    return r2 >= 1e-290 ? sqrt(r2) : hypot(d[0], d[1]);
}

static void springs_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)p;
    for (int j = 0; j < fo->nsprings; j++) {
        sw_spring at = swp_spring_at(fo, j);
        const sw_spring *sp = &at;
        double d[2], dv[2];
        differences(sp, x, v, d, dv);
        double l = length(d);
        if (!(l > 0))
            continue;
        double ux = d[0] / l, uy = d[1] / l;
        double mag = sp->k * (l - sp->rest) + sp->c * (dv[0] * ux + dv[1] * uy);
        f[2 * sp->a] -= mag * ux;
        f[2 * sp->a + 1] -= mag * uy;
        if (sp->b >= 0) {
            f[2 * sp->b] += mag * ux;
            f[2 * sp->b + 1] += mag * uy;
        }
    }
}

static void springs_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    (void)p;
    for (int j = 0; j < fo->nsprings; j++) {
        sw_spring at = swp_spring_at(fo, j);
        const sw_spring *sp = &at;
        double bx = sp->b >= 0 ? x[2 * sp->b] : sp->ax, by = sp->b >= 0 ? x[2 * sp->b + 1] : sp->ay;
        double stretch = hypot(x[2 * sp->a] - bx, x[2 * sp->a + 1] - by) - sp->rest;
        *e += 0.5 * sp->k * stretch * stretch;
    }
}

static long springs_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    (void)p;
    *reach = 0;
    for (int j = 0; j < fo->nsprings; j++) {
        sw_spring sp = swp_spring_at(fo, j);
        if (sp.b >= 0 && abs(sp.a - sp.b) > *reach)
            *reach = abs(sp.a - sp.b);
    }
    return fo->nsprings;
}

/* ∂g/∂d and ∂g/∂(dv) of one damped spring, r = |d|, u = d/r, P = I - u uᵀ:
 *   Kx = -k u uᵀ - k (1 - rest/r) P - (c/r) [u (P dv)ᵀ + (dv·u) P],
 *   Kv = -c u uᵀ.
 * At r = 0 the force is defined as zero (its direction is undefined); the
 * blocks are then those of a zero-length spring, -k I and 0. */
SW_INLINE void spring_block(const sw_spring *sp, const double *x, const double *v, double kx[4], double kv[4])
{
    /* on (x, y) pairs as two-lane values (engine/lanes.h: each lane the
     * scalar operation), Kx and Kv made by columns: column j is
     * -k (u u_j + s P_j) - (c/r) (u p_j + (dv·u) P_j), p = P dv */
    int a = sp->a, b = sp->b;
    v2d xb = { sp->ax, sp->ay }, vb = { 0.0, 0.0 };
    if (b >= 0) {
        xb = load2(x + 2 * b);
        vb = load2(v + 2 * b);
    }
    v2d d = load2(x + 2 * a) - xb, dv = load2(v + 2 * a) - vb, dd = d * d;
    double r2 = dd[0] + dd[1];
    double r = r2 >= 1e-290 ? sqrt(r2) : hypot(d[0], d[1]);
    if (!(r > 0)) {
        kx[0] = kx[3] = -sp->k;
        kx[1] = kx[2] = 0;
        kv[0] = kv[1] = kv[2] = kv[3] = 0;
        return;
    }
    v2d u = d / r, du = dv * u;
    double along = du[0] + du[1];
    v2d p = dv - along * u;
    double s = 1.0 - sp->rest / r, cr = sp->c / r, k = sp->k, c = sp->c;
    v2d u0 = u * u[0], u1 = u * u[1];                                 /* u uᵀ's columns */
    v2d q0 = (v2d){ 1.0, 0.0 } - u0, q1 = (v2d){ 0.0, 1.0 } - u1; /* P = I - u uᵀ */
    v2d k0 = -k * (u0 + s * q0) - cr * (u * p[0] + along * q0);
    v2d k1 = -k * (u1 + s * q1) - cr * (u * p[1] + along * q1);
    v2d c0 = -c * u0, c1 = -c * u1;
    store2(kx, (v2d){ k0[0], k1[0] }); /* by rows */
    store2(kx + 2, (v2d){ k0[1], k1[1] });
    store2(kv, (v2d){ c0[0], c1[0] });
    store2(kv + 2, (v2d){ c0[1], c1[1] });
}

/* Spring sp's ends and blocks into pair n of out's arrays. */
SW_INLINE void put_spring(const sw_spring *sp, const double *x, const double *v, const swp_blocks *out, long n)
{
    out->a[n] = sp->a;
    out->b[n] = sp->b;
    spring_block(sp, x, v, out->pair + 8 * n, out->pair + 8 * n + 4);
}

static SW_CLONES void springs_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                                     swp_blocks *out)
{
    (void)p;
    /* out's arrays and count in a copy of its own: read through out they
     * would be read again after every store */
    swp_blocks o = *out;
    long n = o.n;
    int ns = fo->nsprings, j = 0;
    if (!fo->springs && ns > 2) {
        /* a line (spring_line.h): its middle springs are line[1] a
         * particle on each, made so here, not fetched a spring at a time */
        sw_spring sp = swp_spring_at(fo, 0);
        put_spring(&sp, x, v, &o, n++);
        for (sp = swp_spring_at(fo, 1), j = 1; j < ns - 1; j++, sp.a++, sp.b++)
            put_spring(&sp, x, v, &o, n++);
    }
    for (; j < ns; j++) {
        sw_spring sp = swp_spring_at(fo, j);
        put_spring(&sp, x, v, &o, n++);
    }
    out->n = n;
}

static void springs_values(const sw_force *fo, char *buf, size_t len)
{
    sw_spring first = fo->nsprings > 0 ? swp_spring_at(fo, 0) : (sw_spring){ 0 };
    const sw_spring *sp = fo->nsprings > 0 ? &first : NULL;
    snprintf(buf, len, "%d spring%s%s k = %g, c = %g, rest = %g", fo->nsprings, fo->nsprings == 1 ? "" : "s",
             fo->nsprings == 1 ? ":" : ", the first:", sp ? sp->k : 0, sp ? sp->c : 0, sp ? sp->rest : 0);
}

/* Only a spring with damping (c != 0) reads the velocities. */
static int springs_use_velocity(const sw_force *fo)
{
    for (int j = 0; j < fo->nsprings; j++)
        if (swp_spring_at(fo, j).c != 0)
            return 1;
    return 0;
}

const swp_force_type swp_springs = {
    .name = "damped springs",
    .formula = "on a: f = -[k (|d| - rest) + c (v_a - v_b).d/|d|] d/|d|, d = x_a - x_b; b gets -f",
    .values = springs_values,
    .add = springs_add,
    .potential = springs_potential,
    .term = "spring potential",
    .term_formula = "½ k (|d| - rest)²",
    .term_half = 1,
    .pairs = springs_pairs,
    .blocks = springs_blocks,
    .pairs_only = 1,
    .uses_velocity = springs_use_velocity,
};
