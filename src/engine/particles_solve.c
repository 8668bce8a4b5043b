/* Implicit solves on particle systems: the Jacobian blocks of the forces
 * (analytic for springs and drag, central differences for central
 * attraction) and the linear system implicit methods need. Invariant: the
 * solve allocates nothing; its workspace grows when particles or springs are
 * added. */
#include "engine/particles_solve.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"

struct sw_particles_solver {
    double *diag;          /* 6n: ∂f/∂x and ∂f/∂v blocks per particle */
    double *sblock;        /* 6 per spring: ∂f_a/∂x_a and ∂f_a/∂v_a */
    double *cg;            /* 6 vectors of 2n for conjugate gradients */
    int nsprings;          /* springs the blocks have room for */
    long cg_iters_last;    /* iterations of the last solve */
};

int sw_particles_solver_init(sw_particles *p)
{
    p->solver = calloc(1, sizeof *p->solver);
    if (!p->solver)
        return SW_ENOMEM;
    p->solver->diag = calloc((size_t)6 * p->n, sizeof *p->solver->diag);
    p->solver->cg = calloc((size_t)6 * 2 * p->n, sizeof *p->solver->cg);
    return p->solver->diag && p->solver->cg ? SW_OK : SW_ENOMEM;
}

int sw_particles_solver_springs(sw_particles *p, int nsprings)
{
    double *blocks = realloc(p->solver->sblock, (size_t)nsprings * 6 * sizeof *blocks);
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
        free(p->solver->cg);
        free(p->solver);
    }
    p->solver = NULL;
}

/* Symmetric 2x2 blocks are stored as (xx, xy, yy). */
static void sym_mul_add(const double m[3], double s, double wx, double wy, double *ox, double *oy)
{
    *ox += s * (m[0] * wx + m[1] * wy);
    *oy += s * (m[1] * wx + m[2] * wy);
}

/* ∂f_a/∂x_a and ∂f_a/∂v_a of one damped spring (Baraff & Witkin):
 *   Kx = -k [u uᵀ + (1 - rest/|d|)(I - u uᵀ)],  Kv = -c u uᵀ.
 * The damping force's dependence on x is left out, as Baraff & Witkin do,
 * to keep the system symmetric; it vanishes when motion is along the spring. */
static void spring_blocks(const sw_spring *sp, const double *x, double kx[3], double kv[3])
{
    double bx = sp->b >= 0 ? x[2 * sp->b] : sp->ax, by = sp->b >= 0 ? x[2 * sp->b + 1] : sp->ay;
    double dx = x[2 * sp->a] - bx, dy = x[2 * sp->a + 1] - by;
    double len = sqrt(dx * dx + dy * dy);
    if (!(len > 0)) {
        kx[0] = kx[2] = -sp->k;
        kx[1] = 0;
        kv[0] = kv[1] = kv[2] = 0;
        return;
    }
    double ux = dx / len, uy = dy / len, s = 1.0 - sp->rest / len;
    double uu[3] = { ux * ux, ux * uy, uy * uy };
    double id[3] = { 1, 0, 1 };
    for (int q = 0; q < 3; q++) {
        kx[q] = -sp->k * (uu[q] + s * (id[q] - uu[q]));
        kv[q] = -sp->c * uu[q];
    }
}

/* Central attraction has no analytic Jacobian here: central differences on
 * the force of this one particle (the finite-difference fallback). */
static void central_block_fd(const sw_particles *p, const sw_force *fo, const double *x, int i,
                             double kx[3])
{
    double px = x[2 * i] - fo->cx, py = x[2 * i + 1] - fo->cy;
    double r = sqrt(px * px + py * py);
    double h = 1e-6 * (r > 1e-3 ? r : 1e-3);
    double col[2][2];
    for (int d = 0; d < 2; d++) {
        double fp[2], fm[2];
        for (int sgn = 0; sgn < 2; sgn++) {
            double qx = px + (d == 0 ? (sgn ? -h : h) : 0);
            double qy = py + (d == 1 ? (sgn ? -h : h) : 0);
            double r2 = qx * qx + qy * qy;
            double s = -fo->mu * p->mass[i] / (r2 * sqrt(r2));
            double *out = sgn ? fm : fp;
            out[0] = s * qx;
            out[1] = s * qy;
        }
        col[d][0] = (fp[0] - fm[0]) / (2 * h);
        col[d][1] = (fp[1] - fm[1]) / (2 * h);
    }
    kx[0] = col[0][0];
    kx[1] = 0.5 * (col[1][0] + col[0][1]);
    kx[2] = col[1][1];
}

/* Fill the per-particle (diag) and per-spring (sblock) Jacobian blocks at x. */
static void assemble(sw_particles *p, const double *x)
{
    memset(p->solver->diag, 0, (size_t)p->n * 6 * sizeof *p->solver->diag);
    int js = 0;
    for (int k = 0; k < p->nforces; k++) {
        const sw_force *fo = &p->forces[k];
        if (fo->kind == SW_FORCE_DRAG) {
            for (int i = 0; i < p->n; i++) {
                p->solver->diag[6 * i + 3] -= fo->k;
                p->solver->diag[6 * i + 5] -= fo->k;
            }
        } else if (fo->kind == SW_FORCE_CENTRAL) {
            for (int i = 0; i < p->n; i++) {
                double kx[3];
                central_block_fd(p, fo, x, i, kx);
                for (int q = 0; q < 3; q++)
                    p->solver->diag[6 * i + q] += kx[q];
            }
        } else if (fo->kind == SW_FORCE_SPRINGS) {
            for (int j = 0; j < fo->nsprings; j++, js++)
                spring_blocks(&fo->springs[j], x, p->solver->sblock + 6 * js, p->solver->sblock + 6 * js + 3);
        }
    }
}

void sw_particles_jacobian_diag(sw_particles *p, const double *y, int i, double dfdx[3], double dfdv[3])
{
    assemble(p, y);
    for (int q = 0; q < 3; q++) {
        dfdx[q] = p->solver->diag[6 * i + q];
        dfdv[q] = p->solver->diag[6 * i + 3 + q];
    }
    int js = 0;
    for (int k = 0; k < p->nforces; k++) {
        const sw_force *fo = &p->forces[k];
        if (fo->kind != SW_FORCE_SPRINGS)
            continue;
        for (int j = 0; j < fo->nsprings; j++, js++) {
            const sw_spring *sp = &fo->springs[j];
            if (sp->a != i && sp->b != i)
                continue;
            for (int q = 0; q < 3; q++) {
                dfdx[q] += p->solver->sblock[6 * js + q];
                dfdv[q] += p->solver->sblock[6 * js + 3 + q];
            }
        }
    }
}

/* out = (a·Fx + b·Fv)·w using the assembled blocks, plus m·w when with_mass. */
static void jac_apply(const sw_particles *p, double a, double b, int with_mass, const double *w, double *out)
{
    for (int i = 0; i < p->n; i++) {
        const double *d = p->solver->diag + 6 * i;
        double m = with_mass ? p->mass[i] : 0.0;
        double ox = m * w[2 * i], oy = m * w[2 * i + 1];
        sym_mul_add(d, a, w[2 * i], w[2 * i + 1], &ox, &oy);
        sym_mul_add(d + 3, b, w[2 * i], w[2 * i + 1], &ox, &oy);
        out[2 * i] = ox;
        out[2 * i + 1] = oy;
    }
    int js = 0;
    for (int k = 0; k < p->nforces; k++) {
        const sw_force *fo = &p->forces[k];
        if (fo->kind != SW_FORCE_SPRINGS)
            continue;
        for (int j = 0; j < fo->nsprings; j++, js++) {
            const sw_spring *sp = &fo->springs[j];
            const double *blk = p->solver->sblock + 6 * js;
            double wx = w[2 * sp->a] - (sp->b >= 0 ? w[2 * sp->b] : 0.0);
            double wy = w[2 * sp->a + 1] - (sp->b >= 0 ? w[2 * sp->b + 1] : 0.0);
            double sx = 0, sy = 0;
            sym_mul_add(blk, a, wx, wy, &sx, &sy);
            sym_mul_add(blk + 3, b, wx, wy, &sx, &sy);
            out[2 * sp->a] += sx;
            out[2 * sp->a + 1] += sy;
            if (sp->b >= 0) {
                out[2 * sp->b] -= sx;
                out[2 * sp->b + 1] -= sy;
            }
        }
    }
}

static double dot(int n, const double *a, const double *b)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        s += a[i] * b[i];
    return s;
}

/* (I - c·J) z = r for J = [[0, I], [M⁻¹Fx, M⁻¹Fv]]. Eliminating z_x = r_x + c·z_v
 * leaves the symmetric system (M - c·Fv - c²·Fx) z_v = M·r_v + c·Fx·r_x, solved
 * by Jacobi-preconditioned conjugate gradients. */
int sw_particles_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t;
    sw_particles *p = ctx;
    int n2 = 2 * p->n;
    double *b = p->solver->cg, *res = b + n2, *dir = res + n2, *adir = dir + n2, *pre = adir + n2,
           *zv = z + n2;
    assemble(p, y);
    /* b = M r_v + c Fx r_x */
    jac_apply(p, c, 0.0, 0, r, b);
    for (int i = 0; i < p->n; i++) {
        b[2 * i] += p->mass[i] * r[n2 + 2 * i];
        b[2 * i + 1] += p->mass[i] * r[n2 + 2 * i + 1];
    }
    /* Jacobi preconditioner: the diagonal of A, via A·e_k summed per column
     * type; cheap form: particle blocks plus spring blocks' diagonals. */
    for (int i = 0; i < p->n; i++) {
        const double *d = p->solver->diag + 6 * i;
        pre[2 * i] = p->mass[i] - c * d[3] - c * c * d[0];
        pre[2 * i + 1] = p->mass[i] - c * d[5] - c * c * d[2];
    }
    int js = 0;
    for (int k = 0; k < p->nforces; k++) {
        const sw_force *fo = &p->forces[k];
        if (fo->kind != SW_FORCE_SPRINGS)
            continue;
        for (int j = 0; j < fo->nsprings; j++, js++) {
            const double *blk = p->solver->sblock + 6 * js;
            const sw_spring *sp = &fo->springs[j];
            double ex = -c * blk[3] - c * c * blk[0], ey = -c * blk[5] - c * c * blk[2];
            pre[2 * sp->a] += ex;
            pre[2 * sp->a + 1] += ey;
            if (sp->b >= 0) {
                pre[2 * sp->b] += ex;
                pre[2 * sp->b + 1] += ey;
            }
        }
    }
    for (int i = 0; i < n2; i++)
        pre[i] = pre[i] > 0 ? 1.0 / pre[i] : 1.0;
    /* The system is linear: solve for b / max|b| and scale back, so residual
     * norms neither underflow (a state damped to 1e-160) nor overflow. */
    double bscale = 0;
    for (int i = 0; i < n2; i++)
        bscale = fmax(bscale, fabs(b[i]));
    if (bscale > 0 && isfinite(bscale))
        for (int i = 0; i < n2; i++)
            b[i] /= bscale;
    else
        bscale = 1;

    /* PCG from z_v = 0. */
    memset(zv, 0, (size_t)n2 * sizeof *zv);
    memcpy(res, b, (size_t)n2 * sizeof *res);
    double bnorm = sqrt(dot(n2, b, b));
    p->solver->cg_iters_last = 0;
    if (bnorm > 0) {
        double *pz = adir; /* reuse: preconditioned residual before adir is needed */
        for (int i = 0; i < n2; i++)
            dir[i] = pre[i] * res[i];
        double rz = dot(n2, res, dir);
        int max_iter = 2 * n2 + 50;
        int it;
        for (it = 0; it < max_iter; it++) {
            jac_apply(p, -c * c, -c, 1, dir, adir);
            double pap = dot(n2, dir, adir);
            if (!(pap > 0))
                break;
            double alpha = rz / pap;
            for (int i = 0; i < n2; i++) {
                zv[i] += alpha * dir[i];
                res[i] -= alpha * adir[i];
            }
            double rn = sqrt(dot(n2, res, res));
            if (rn <= 1e-14 * bnorm) {
                it++;
                break;
            }
            for (int i = 0; i < n2; i++)
                pz[i] = pre[i] * res[i];
            double rz_new = dot(n2, res, pz);
            double beta = rz_new / rz;
            rz = rz_new;
            for (int i = 0; i < n2; i++)
                dir[i] = pz[i] + beta * dir[i];
        }
        p->solver->cg_iters_last = it;
        p->ode.solver_iters += it;
        /* Accept what rounding allows; refuse a solve that did not converge. */
        jac_apply(p, -c * c, -c, 1, zv, adir);
        double rn = 0;
        for (int i = 0; i < n2; i++)
            rn += (b[i] - adir[i]) * (b[i] - adir[i]);
        if (!(sqrt(rn) <= 1e-8 * bnorm))
            return SW_EDIVERGED;
    }
    for (int i = 0; i < n2; i++) {
        zv[i] *= bscale; /* z_v is the velocity half of z */
        z[i] = r[i] + c * zv[i];
    }
    return SW_OK;
}

