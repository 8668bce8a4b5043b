/* The particle derivative over forces compiled by kind into flat arrays:
 * springs as index pairs plus parameters (and anchored springs apart), the
 * per-particle forces fused with the inverse mass and the copy of v into
 * one last pass. It models only what the system has: no damping work when
 * every c is 0, no spring pass without springs. Invariant: evaluation
 * allocates nothing, and gives the numbers of the lecture's plain
 * clear-accumulate-divide loop (the same operations in the same order) for
 * every force order the scenes use; see swp_model_compile for the order. */
#include "engine/particles_deriv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

/* Springs are evaluated BLOCK at a time: gather the differences, compute the
 * forces in a loop without indices (which the compiler vectorises: square
 * root and divisions two or more at a time), scatter them. */
#define BLOCK 128

struct sw_particles_model {
    int compiled;             /* the arrays below match the description */
    int cap;                  /* room for springs */
    /* springs: [0, npair) join particles a and b; [npair, npair + nanchor)
     * tie particle a to the fixed point (ax, ay) */
    int npair, nanchor;
    int *a, *b;
    double *k, *c, *rest, *ax, *ay;
    int damped;               /* some spring has c != 0 */
    double *scratch;          /* 6 BLOCK-long rows: dx, dy, dvx, dvy (then fx, fy in dx, dy) */
    /* one gravity and one drag, fused into the last pass */
    int gravity, drag;
    double gx, gy, kdrag;
    /* every other per-particle force (central fields, a second gravity or
     * drag): a pass each, in the order added, before the last pass */
    int nextra;
    int extra[SW_MAX_FORCES]; /* indices into p->forces */
};

int swp_model_init(sw_particles *p)
{
    p->model = calloc(1, sizeof *p->model);
    if (!p->model)
        return SW_ENOMEM;
    p->model->scratch = malloc(6 * BLOCK * sizeof *p->model->scratch);
    return p->model->scratch ? SW_OK : SW_ENOMEM;
}

int swp_model_springs(sw_particles *p, int nsprings)
{
    struct sw_particles_model *m = p->model;
    size_t n = (size_t)nsprings;
    int *a = realloc(m->a, n * sizeof *a), *b = a ? realloc(m->b, n * sizeof *b) : NULL;
    if (a)
        m->a = a;
    if (b)
        m->b = b;
    double **rows[] = { &m->k, &m->c, &m->rest, &m->ax, &m->ay };
    for (size_t r = 0; b && r < sizeof rows / sizeof rows[0]; r++) {
        double *q = realloc(*rows[r], n * sizeof *q);
        if (!q)
            return SW_ENOMEM;
        *rows[r] = q;
    }
    if (!a || !b)
        return SW_ENOMEM;
    m->cap = nsprings;
    m->compiled = 0;
    return SW_OK;
}

void swp_model_free(sw_particles *p)
{
    struct sw_particles_model *m = p->model;
    if (m) {
        free(m->a), free(m->b), free(m->k), free(m->c), free(m->rest), free(m->ax), free(m->ay);
        free(m->scratch);
        free(m);
    }
    p->model = NULL;
}

void swp_model_touch(sw_particles *p)
{
    if (p->model)
        p->model->compiled = 0;
}

/* Copy spring sp into slot j of the flat arrays. */
static void put_spring(struct sw_particles_model *m, int j, const sw_spring *sp)
{
    m->a[j] = sp->a;
    m->b[j] = sp->b;
    m->k[j] = sp->k;
    m->c[j] = sp->c;
    m->rest[j] = sp->rest;
    m->ax[j] = sp->ax;
    m->ay[j] = sp->ay;
    m->damped |= sp->c != 0;
}

/* The order of summation: springs (paired, then anchored, each in the order
 * added), then the extra per-particle passes, then gravity, then drag. The
 * plain loop sums in the order forces were added; the two agree bit for bit
 * whenever no particle gets more than two spring forces before a gravity or
 * drag — every scene in the catalog (springs are added before gravity, and
 * gravity before drag). Elsewhere they differ by rounding. */
int swp_model_compile(sw_particles *p, char *err, size_t errlen)
{
    struct sw_particles_model *m = p->model;
    int rc = SW_OK, pass;
    m->npair = m->nanchor = m->damped = m->gravity = m->drag = m->nextra = 0;
    for (pass = 0; pass < 2; pass++) /* paired springs first, then anchored ones */
        for (int f = 0; f < p->nforces; f++) {
            const sw_force *fo = &p->forces[f];
            for (int j = 0; fo->kind == SW_FORCE_SPRINGS && j < fo->nsprings; j++) {
                const sw_spring *sp = &fo->springs[j];
                if (sp->a < 0 || sp->a >= p->n || sp->b < -1 || sp->b >= p->n) {
                    if (rc == SW_OK && err)
                        snprintf(err, errlen, "spring %d joins particles %d and %d; a system of %d "
                                 "particles allows 0 to %d (b = -1: a fixed anchor)",
                                 j, sp->a, sp->b, p->n, p->n - 1);
                    rc = SW_EINVAL;
                } else if ((sp->b >= 0) == (pass == 0)) {
                    put_spring(m, pass == 0 ? m->npair : m->npair + m->nanchor, sp);
                    pass == 0 ? m->npair++ : m->nanchor++;
                }
            }
        }
    for (int f = 0; f < p->nforces; f++) {
        const sw_force *fo = &p->forces[f];
        if (fo->kind == SW_FORCE_GRAVITY && !m->gravity && !m->drag) {
            m->gravity = 1;
            m->gx = fo->gx;
            m->gy = fo->gy;
        } else if (fo->kind == SW_FORCE_DRAG && !m->drag) {
            m->drag = 1;
            m->kdrag = fo->k;
        } else if (fo->kind != SW_FORCE_SPRINGS) {
            m->extra[m->nextra++] = f;
        }
    }
    m->compiled = 1;
    return rc;
}

/* Spring forces of a block from its differences, in place:
 *   f_a = -[k(|d| - rest) + c·(v_a - v_b)·d̂] d̂,  d̂ = d/|d|.
 * Where |d| = 0 the direction is undefined and the plain loop adds no force;
 * here d = 0 is divided by 1 instead (l + (l == 0), a select without a
 * branch, so the loop vectorises) and the force is ±0, which leaves f as it
 * is: f starts at +0 and a sum that starts at +0 is never -0. */
static void block_forces(int len, const double *restrict k, const double *restrict c,
                         const double *restrict rest, double *restrict dx, double *restrict dy,
                         const double *restrict dvx, const double *restrict dvy, int damped)
{
    if (damped)
        for (int j = 0; j < len; j++) {
            double l = sqrt(dx[j] * dx[j] + dy[j] * dy[j]), d = l + (l == 0);
            double ux = dx[j] / d, uy = dy[j] / d;
            double mag = k[j] * (l - rest[j]) + c[j] * (dvx[j] * ux + dvy[j] * uy);
            dx[j] = -mag * ux;
            dy[j] = -mag * uy;
        }
    else
        for (int j = 0; j < len; j++) {
            double l = sqrt(dx[j] * dx[j] + dy[j] * dy[j]), d = l + (l == 0);
            double ux = dx[j] / d, uy = dy[j] / d;
            double mag = k[j] * (l - rest[j]);
            dx[j] = -mag * ux;
            dy[j] = -mag * uy;
        }
}

/* Add every spring's force into f (2n, cleared). */
static void springs(const struct sw_particles_model *m, const double *x, const double *v, double *f)
{
    double *dx = m->scratch, *dy = dx + BLOCK, *dvx = dy + BLOCK, *dvy = dvx + BLOCK;
    int total = m->npair + m->nanchor;
    for (int lo = 0; lo < total; lo += BLOCK) {
        int hi = lo + BLOCK < total ? lo + BLOCK : total, mid = hi < m->npair ? hi : m->npair;
        for (int j = lo; j < mid; j++) { /* paired */
            int a = 2 * m->a[j], b = 2 * m->b[j];
            dx[j - lo] = x[a] - x[b];
            dy[j - lo] = x[a + 1] - x[b + 1];
            if (m->damped) {
                dvx[j - lo] = v[a] - v[b];
                dvy[j - lo] = v[a + 1] - v[b + 1];
            }
        }
        for (int j = mid > lo ? mid : lo; j < hi; j++) { /* anchored */
            int a = 2 * m->a[j];
            dx[j - lo] = x[a] - m->ax[j];
            dy[j - lo] = x[a + 1] - m->ay[j];
            if (m->damped) {
                dvx[j - lo] = v[a];
                dvy[j - lo] = v[a + 1];
            }
        }
        block_forces(hi - lo, m->k + lo, m->c + lo, m->rest + lo, dx, dy, dvx, dvy, m->damped);
        for (int j = lo; j < mid; j++) {
            int a = 2 * m->a[j], b = 2 * m->b[j];
            f[a] += dx[j - lo];
            f[a + 1] += dy[j - lo];
            f[b] -= dx[j - lo];
            f[b + 1] -= dy[j - lo];
        }
        for (int j = mid > lo ? mid : lo; j < hi; j++) {
            int a = 2 * m->a[j];
            f[a] += dx[j - lo];
            f[a + 1] += dy[j - lo];
        }
    }
}

/* One per-particle force added into f, as its own pass. */
static void extra_pass(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    for (int i = 0; i < p->n; i++) {
        double m = p->mass[i];
        if (fo->kind == SW_FORCE_GRAVITY) {
            f[2 * i] += m * fo->gx;
            f[2 * i + 1] += m * fo->gy;
        } else if (fo->kind == SW_FORCE_DRAG) {
            f[2 * i] -= fo->k * v[2 * i];
            f[2 * i + 1] -= fo->k * v[2 * i + 1];
        } else { /* central: -μ m d/|d|³ */
            double dx = x[2 * i] - fo->cx, dy = x[2 * i + 1] - fo->cy;
            double r2 = dx * dx + dy * dy;
            double s = -fo->mu * m / (r2 * sqrt(r2));
            f[2 * i] += s * dx;
            f[2 * i + 1] += s * dy;
        }
    }
}

/* The last pass: dx/dt = v, and dv/dt = (f + m·g - k·v)/m with f the forces
 * so far (0 when `load` is 0), for the kinds present. Called with constant
 * flags, so each combination compiles to its own straight loop. */
static inline void last_pass(const sw_particles *p, const struct sw_particles_model *m, const double *restrict v,
                             double *restrict xdot, double *restrict f, int load, int gravity, int drag)
{
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass;
    double gx = m->gx, gy = m->gy, kd = m->kdrag;
    for (int i = 0; i < p->n; i++) {
        double fx = load ? f[2 * i] : 0.0, fy = load ? f[2 * i + 1] : 0.0;
        double vx = v[2 * i], vy = v[2 * i + 1];
        if (gravity) {
            fx += mass[i] * gx;
            fy += mass[i] * gy;
        }
        if (drag) {
            fx -= kd * vx;
            fy -= kd * vy;
        }
        xdot[2 * i] = vx;
        xdot[2 * i + 1] = vy;
        f[2 * i] = fx * inv[i];
        f[2 * i + 1] = fy * inv[i];
    }
}

void swp_deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)t;
    sw_particles *p = ctx;
    struct sw_particles_model *m = p->model;
    if (!m->compiled)
        swp_model_compile(p, NULL, 0);
    int n2 = 2 * p->n;
    const double *x = y, *v = y + n2;
    double *f = dydt + n2;
    int load = m->npair + m->nanchor > 0 || m->nextra > 0;
    if (load)
        memset(f, 0, (size_t)n2 * sizeof *f);
    if (m->npair + m->nanchor > 0)
        springs(m, x, v, f);
    for (int e = 0; e < m->nextra; e++)
        extra_pass(p, &p->forces[m->extra[e]], x, v, f);
    switch (load | m->gravity << 1 | m->drag << 2) {
    case 0: last_pass(p, m, v, dydt, f, 0, 0, 0); break;
    case 1: last_pass(p, m, v, dydt, f, 1, 0, 0); break;
    case 2: last_pass(p, m, v, dydt, f, 0, 1, 0); break;
    case 3: last_pass(p, m, v, dydt, f, 1, 1, 0); break;
    case 4: last_pass(p, m, v, dydt, f, 0, 0, 1); break;
    case 5: last_pass(p, m, v, dydt, f, 1, 0, 1); break;
    case 6: last_pass(p, m, v, dydt, f, 0, 1, 1); break;
    default: last_pass(p, m, v, dydt, f, 1, 1, 1); break;
    }
}
