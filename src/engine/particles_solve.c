/* Implicit solves on particle systems. The force Jacobians are analytic and
 * complete: springs (stiffness and the damping term, including how the
 * damping force turns with the spring), linear drag, central attraction.
 * (I - c·J) z = r reduces to the velocity system
 *     (M - c·Fv - c²·Fx) z_v = M·r_v + c·Fx·r_x,   z_x = r_x + c·z_v,
 * which is banded when particles are numbered along their springs (a chain
 * has bandwidth one particle). It is solved by banded LU with partial
 * pivoting: exact, and correct where a compressed spring makes the matrix
 * indefinite or damping makes it non-symmetric — there conjugate gradients,
 * Baraff and Witkin's choice, break down. The system reads the forces only
 * through the particle accessors. Invariant: the solve allocates nothing;
 * the band is sized once by sw_particles_solver_prepare. */
#include "engine/particles_solve.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/linalg.h"
#include "stepwise/base.h"

/* Largest band accepted, in doubles (256 MiB). */
#define BAND_MAX ((size_t)1 << 25)

struct sw_particles_solver {
    double *diag;          /* 8 per particle: Fx (2x2) and Fv (2x2) of per-particle forces */
    double *sblock;        /* 8 per spring: ∂f_a/∂d and ∂f_a/∂(dv), d = x_a - x_b */
    int nsprings;          /* springs the blocks have room for */
    double *rhs;           /* 2n: the velocity system's right-hand side */
    double *band;          /* the velocity system's band, or NULL before prepare */
    int *piv;
    int half_band;         /* in dof: 2·(largest particle distance along a spring) + 1 */
};

int sw_particles_solver_init(sw_particles *p)
{
    p->solver = calloc(1, sizeof *p->solver);
    if (!p->solver)
        return SW_ENOMEM;
    p->solver->diag = calloc((size_t)8 * p->n, sizeof *p->solver->diag);
    p->solver->rhs = calloc((size_t)2 * p->n, sizeof *p->solver->rhs);
    return p->solver->diag && p->solver->rhs ? SW_OK : SW_ENOMEM;
}

int sw_particles_solver_springs(sw_particles *p, int nsprings)
{
    double *blocks = realloc(p->solver->sblock, (size_t)nsprings * 8 * sizeof *blocks);
    if (!blocks)
        return SW_ENOMEM;
    p->solver->sblock = blocks;
    p->solver->nsprings = nsprings;
    return SW_OK;
}

void sw_particles_solver_free(sw_particles *p)
{
    if (p->solver) {
        free(p->solver->diag);
        free(p->solver->sblock);
        free(p->solver->rhs);
        free(p->solver->band);
        free(p->solver->piv);
        free(p->solver);
    }
    p->solver = NULL;
}

int sw_particles_solver_prepare(void *ctx, char *err, size_t errlen)
{
    sw_particles *p = ctx;
    struct sw_particles_solver *s = p->solver;
    int far = 0, count = sw_particles_spring_count(p);
    for (int j = 0; j < count; j++) {
        sw_spring sp;
        sw_particles_spring(p, j, &sp);
        if (sp.b >= 0 && abs(sp.a - sp.b) > far)
            far = abs(sp.a - sp.b);
    }
    int kb = 2 * far + 1, n2 = 2 * p->n;
    size_t len = sw_band_doubles(n2, kb, kb);
    if (len > BAND_MAX) {
        snprintf(err, errlen, "the implicit solve needs the springs to join particles with nearby "
                 "numbers; here they span %d particles, a band of %zu MiB", far,
                 len * sizeof(double) >> 20);
        return SW_EINVAL;
    }
    if (s->band && s->half_band == kb)
        return SW_OK;
    double *band = realloc(s->band, len * sizeof *band);
    int *piv = band ? realloc(s->piv, (size_t)n2 * sizeof *piv) : NULL;
    if (band)
        s->band = band;
    if (!band || !piv) {
        snprintf(err, errlen, "out of memory for the implicit solve (%zu MiB)", len * sizeof(double) >> 20);
        return SW_ENOMEM;
    }
    s->piv = piv;
    s->half_band = kb;
    return SW_OK;
}

/* 2x2 blocks are row-major (xx, xy, yx, yy). */

/* ∂f_a/∂d and ∂f_a/∂(dv) of one damped spring, d = x_a - x_b, r = |d|,
 * u = d/r, P = I - u uᵀ, dv = v_a - v_b:
 *   Kx = -k u uᵀ - k (1 - rest/r) P - (c/r) [u (P dv)ᵀ + (dv·u) P],
 *   Kv = -c u uᵀ.
 * At r = 0 the force is defined as zero (its direction is undefined); the
 * blocks are then those of a zero-length spring, -k I and 0. */
static void spring_blocks(const sw_spring *sp, const double *x, const double *v, double kx[4], double kv[4])
{
    double bx = sp->b >= 0 ? x[2 * sp->b] : sp->ax, by = sp->b >= 0 ? x[2 * sp->b + 1] : sp->ay;
    double dx = x[2 * sp->a] - bx, dy = x[2 * sp->a + 1] - by;
    double r2 = dx * dx + dy * dy, r = r2 >= 1e-290 ? sqrt(r2) : hypot(dx, dy);
    if (!(r > 0)) {
        kx[0] = kx[3] = -sp->k;
        kx[1] = kx[2] = 0;
        kv[0] = kv[1] = kv[2] = kv[3] = 0;
        return;
    }
    double u[2] = { dx / r, dy / r };
    double dv[2] = { v[2 * sp->a] - (sp->b >= 0 ? v[2 * sp->b] : 0.0),
                     v[2 * sp->a + 1] - (sp->b >= 0 ? v[2 * sp->b + 1] : 0.0) };
    double along = dv[0] * u[0] + dv[1] * u[1];
    double pdv[2] = { dv[0] - along * u[0], dv[1] - along * u[1] };
    double s = 1.0 - sp->rest / r, cr = sp->c / r;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            double uu = u[i] * u[j], proj = (i == j) - uu;
            kx[2 * i + j] = -sp->k * (uu + s * proj) - cr * (u[i] * pdv[j] + along * proj);
            kv[2 * i + j] = -sp->c * uu;
        }
}

/* ∂f/∂x of central attraction on particle i: -μm (I/r³ - 3 d dᵀ/r⁵). */
static void central_block(double mu_m, double dx, double dy, double kx[4])
{
    double r2 = dx * dx + dy * dy, r = sqrt(r2), r3 = r2 * r, r5 = r3 * r2;
    if (!(r > 0)) {
        kx[0] = kx[1] = kx[2] = kx[3] = 0;
        return;
    }
    kx[0] = -mu_m * (1 / r3 - 3 * dx * dx / r5);
    kx[1] = kx[2] = -mu_m * (-3 * dx * dy / r5);
    kx[3] = -mu_m * (1 / r3 - 3 * dy * dy / r5);
}

/* Fill the per-particle and per-spring blocks at state y. */
static void assemble(sw_particles *p, const double *y)
{
    struct sw_particles_solver *s = p->solver;
    const double *x = y, *v = y + 2 * p->n;
    double drag = sw_particles_drag(p), cx, cy, mu;
    int central = sw_particles_central(p, &cx, &cy, &mu);
    for (int i = 0; i < p->n; i++) {
        double *d = s->diag + 8 * i;
        memset(d, 0, 8 * sizeof *d);
        if (central)
            central_block(mu * p->mass[i], x[2 * i] - cx, x[2 * i + 1] - cy, d);
        d[4] = d[7] = -drag;
    }
    int count = sw_particles_spring_count(p);
    for (int j = 0; j < count; j++) {
        sw_spring sp;
        sw_particles_spring(p, j, &sp);
        spring_blocks(&sp, x, v, s->sblock + 8 * j, s->sblock + 8 * j + 4);
    }
}

/* Scatter the blocks as a·Fx + b·Fv into the sink: one call per 2x2 block
 * at particle rows pi, columns pj. */
typedef void block_sink(void *ctx, int pi, int pj, double s, const double *blk);

static void scatter(const sw_particles *p, double a, double b, block_sink *sink, void *ctx)
{
    const struct sw_particles_solver *s = p->solver;
    for (int i = 0; i < p->n; i++) {
        sink(ctx, i, i, a, s->diag + 8 * i);
        sink(ctx, i, i, b, s->diag + 8 * i + 4);
    }
    int count = sw_particles_spring_count(p);
    for (int j = 0; j < count; j++) {
        sw_spring sp;
        sw_particles_spring(p, j, &sp);
        const double *kx = s->sblock + 8 * j, *kv = kx + 4;
        /* f_a = g(d, dv), f_b = -g: ±K on the four blocks of (a, b). */
        int ends[2] = { sp.a, sp.b };
        for (int r = 0; r < 2; r++)
            for (int c = 0; c < 2; c++) {
                if (ends[r] < 0 || ends[c] < 0)
                    continue;
                double sgn = r == c ? 1.0 : -1.0;
                sink(ctx, ends[r], ends[c], sgn * a, kx);
                sink(ctx, ends[r], ends[c], sgn * b, kv);
            }
    }
}

static void band_sink(void *ctx, int pi, int pj, double s, const double *blk)
{
    if (s == 0)
        return;
    for (int r = 0; r < 2; r++)
        for (int c = 0; c < 2; c++)
            sw_band_add(ctx, 2 * pi + r, 2 * pj + c, s * blk[2 * r + c]);
}

/* out += s·K·w for one block: the product Fx·r_x without forming Fx. */
typedef struct apply_ctx { const double *w; double *out; } apply_ctx;

static void apply_sink(void *ctx, int pi, int pj, double s, const double *blk)
{
    apply_ctx *ac = ctx;
    if (s == 0)
        return;
    double wx = ac->w[2 * pj], wy = ac->w[2 * pj + 1];
    ac->out[2 * pi] += s * (blk[0] * wx + blk[1] * wy);
    ac->out[2 * pi + 1] += s * (blk[2] * wx + blk[3] * wy);
}

int sw_particles_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t;
    sw_particles *p = ctx;
    struct sw_particles_solver *s = p->solver;
    if (!s->band)
        return SW_EINVAL; /* not prepared: sw_stepper_init prepares implicit methods */
    int n2 = 2 * p->n;
    assemble(p, y);
    /* rhs = M r_v + c Fx r_x */
    apply_ctx ac = { r, s->rhs };
    for (int i = 0; i < p->n; i++) {
        s->rhs[2 * i] = p->mass[i] * r[n2 + 2 * i];
        s->rhs[2 * i + 1] = p->mass[i] * r[n2 + 2 * i + 1];
    }
    scatter(p, c, 0.0, apply_sink, &ac);
    /* A = M - c Fv - c² Fx */
    sw_band band;
    sw_band_init(&band, n2, s->half_band, s->half_band, s->band, s->piv);
    for (int i = 0; i < p->n; i++) {
        sw_band_add(&band, 2 * i, 2 * i, p->mass[i]);
        sw_band_add(&band, 2 * i + 1, 2 * i + 1, p->mass[i]);
    }
    scatter(p, -c * c, -c, band_sink, &band);
    if (sw_band_factor(&band) != 0)
        return SW_EDIVERGED;
    sw_band_solve(&band, s->rhs);
    for (int i = 0; i < n2; i++) {
        z[n2 + i] = s->rhs[i];
        z[i] = r[i] + c * s->rhs[i];
    }
    p->ode.solver_iters++;
    return SW_OK;
}

typedef struct dense_ctx { double *m; int n2; } dense_ctx;

static void dense_sink(void *ctx, int pi, int pj, double s, const double *blk)
{
    dense_ctx *dc = ctx;
    if (s == 0)
        return;
    for (int r = 0; r < 2; r++)
        for (int c = 0; c < 2; c++)
            dc->m[(size_t)(2 * pi + r) * dc->n2 + 2 * pj + c] += s * blk[2 * r + c];
}

void sw_particles_jacobian(sw_particles *p, const double *y, double *fx, double *fv)
{
    int n2 = 2 * p->n;
    assemble(p, y);
    memset(fx, 0, (size_t)n2 * n2 * sizeof *fx);
    memset(fv, 0, (size_t)n2 * n2 * sizeof *fv);
    dense_ctx cx = { fx, n2 }, cv = { fv, n2 };
    scatter(p, 1.0, 0.0, dense_sink, &cx);
    scatter(p, 0.0, 1.0, dense_sink, &cv);
}

void sw_particles_jacobian_apply(sw_particles *p, const double *y, double a, double b, const double *w,
                                 double *out, int assemble_first)
{
    if (assemble_first)
        assemble(p, y);
    memset(out, 0, (size_t)2 * p->n * sizeof *out);
    apply_ctx ac = { w, out };
    scatter(p, a, b, apply_sink, &ac);
}
