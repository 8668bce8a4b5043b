/* The particle derivative over forces compiled by kind into flat arrays:
 * springs as index pairs plus parameters (and anchored springs apart),
 * evaluated in one loop without indices or branches; then one last pass per
 * particle that sums its springs' forces (each particle lists its springs:
 * no scatter, no cleared accumulator), adds gravity and drag, divides by
 * the mass and copies v. It models only what the system has: no damping
 * work when every c is 0, no spring work without springs. Invariant: evaluation
 * allocates nothing, and gives the numbers of the lecture's plain
 * clear-accumulate-divide loop (the same operations in the same order) for
 * every force order the scenes use; see swp_model_compile for the order. */
#include "engine/particles_deriv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/clones.h"
#include "engine/forces.h"
#include "engine/particles_chain.h"
#include "engine/particles_model.h"
#include "engine/particles_spring_force.h"
#include "engine/spring_line.h"
#include "engine/particles_small.h"
#include "stepwise/base.h"



int swp_model_init(sw_particles *p, const struct sw_ode_fast fast[2])
{
    p->model = calloc(1, sizeof *p->model);
    if (!p->model)
        return SW_ENOMEM;
    p->model->fast = fast;
    p->model->scratch = malloc(5 * BLOCK * sizeof *p->model->scratch);
    p->model->shared = malloc(3 * BLOCK * sizeof *p->model->shared);
    p->model->first = calloc((size_t)p->n + 1, sizeof *p->model->first);
    if (!p->model->scratch || !p->model->shared || !p->model->first)
        return SW_ENOMEM;
    for (int i = 0; i < 5 * BLOCK; i++) /* the padding's d = (1, 1): a length, never tiny */
        p->model->scratch[i] = 1.0;
    return SW_OK;
}

int swp_model_springs(sw_particles *p, int nsprings)
{
    struct sw_particles_model *m = p->model;
    size_t n = (size_t)nsprings, n4 = (n + 3) & ~(size_t)3; /* the force loop's padding */
    int **irows[] = { &m->a, &m->b, &m->spring };
    size_t ilen[] = { n, n, 2 * n };
    for (size_t r = 0; r < sizeof irows / sizeof irows[0]; r++) {
        int *q = realloc(*irows[r], ilen[r] * sizeof *q);
        if (!q)
            return SW_ENOMEM;
        *irows[r] = q;
    }
    double **rows[] = { &m->k, &m->c, &m->rest, &m->ax, &m->ay, &m->force, &m->sign };
    size_t len[] = { n4, n4, n4, n, n, 2 * n4, 2 * n };
    for (size_t r = 0; r < sizeof rows / sizeof rows[0]; r++) {
        double *q = realloc(*rows[r], len[r] * sizeof *q);
        if (!q)
            return SW_ENOMEM;
        *rows[r] = q;
    }
#ifndef SW_FIELD_ONLY /* (a plugin's host takes no fused step) */
    if (!m->tile) { /* the chain's fused rk4: a fixed few KiB */
        size_t size = swp_chain_work_size();
        if (!(m->tile = malloc(size * sizeof *m->tile)))
            return SW_ENOMEM;
        for (size_t i = 0; i < size; i++) /* block_forces' padding reads: lengths, never tiny */
            m->tile[i] = 1.0;
    }
#endif
    m->cap = nsprings;
    m->compiled = 0;
    m->small = NULL;
    m->line = NULL;
    return SW_OK;
}

void swp_model_free(sw_particles *p)
{
    struct sw_particles_model *m = p->model;
    if (m) {
        free(m->a), free(m->b), free(m->k), free(m->c), free(m->rest), free(m->ax), free(m->ay);
        free(m->scratch), free(m->shared), free(m->force), free(m->first), free(m->spring), free(m->sign);
        free(m->tile);
        free(m);
    }
    p->model = NULL;
}

void swp_model_touch(sw_particles *p)
{
    if (p->model) {
        p->model->compiled = 0;
        p->model->small = NULL;
        p->model->line = NULL;
        p->model->chain = 0;
        p->ode.fast = &p->model->fast[0];
    }
}

/* Visit the description's springs in the compiled order: paired ones first,
 * then anchored ones, each in the order added, as slots 0, 1, ...; springs
 * that name a particle that does not exist are left out, the first one
 * reported in err. SW_OK or SW_EINVAL. */
typedef void spring_visit(struct sw_particles_model *m, int j, const sw_spring *sp);

static int each_spring(const sw_particles *p, spring_visit *visit, char *err, size_t errlen)
{
    int rc = SW_OK, slot = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int f = 0; f < p->nforces; f++) {
            const sw_force *fo = &p->forces[f];
            for (int j = 0; fo->kind == SW_FORCE_SPRINGS && j < fo->nsprings; j++) {
                sw_spring at = swp_spring_at(fo, j);
                const sw_spring *sp = &at;
                if (sp->a < 0 || sp->a >= p->n || sp->b < -1 || sp->b >= p->n) {
                    if (rc == SW_OK && err)
                        snprintf(err, errlen, "spring %d joins particles %d and %d; a system of %d "
                                 "particles allows 0 to %d (b = -1: a fixed anchor)",
                                 j, sp->a, sp->b, p->n, p->n - 1);
                    rc = SW_EINVAL;
                } else if ((sp->b >= 0) == (pass == 0)) {
                    visit(p->model, slot++, sp);
                }
            }
        }
    return rc;
}

/* The survey, before any row is written: counts, damping, whether the
 * springs share k, c and rest, and whether the paired ones advance by one
 * particle a spring (the stride). */
static void survey_spring(struct sw_particles_model *m, int j, const sw_spring *sp)
{
    double kcr[3] = { sp->k, sp->c, sp->rest }, kcr0[3] = { m->k0, m->c0, m->rest0 };
    if (j == 0) {
        m->k0 = sp->k, m->c0 = sp->c, m->rest0 = sp->rest;
        m->uniform = 1;
    } else if (memcmp(kcr, kcr0, sizeof kcr) != 0) {
        m->uniform = 0;
    }
    m->damped |= sp->c != 0;
    if (sp->b < 0) {
        m->nanchor++;
        return;
    }
    if (j == 0)
        m->a0 = 2 * sp->a, m->b0 = 2 * sp->b;
    m->stride &= 2 * sp->a == m->a0 + 2 * j && 2 * sp->b == m->b0 + 2 * j;
    m->npair++;
}

/* Copy spring sp into slot j of the rows the passes read (see the struct). */
static void put_spring(struct sw_particles_model *m, int j, const sw_spring *sp)
{
    int anchored = sp->b < 0;
    if (m->full || !m->stride || anchored) {
        m->a[j] = 2 * sp->a;
        m->b[j] = 2 * sp->b;
    }
    if (m->full || !m->uniform) {
        m->k[j] = sp->k;
        m->c[j] = sp->c;
        m->rest[j] = sp->rest;
    }
    if (anchored) {
        m->ax[j] = sp->ax;
        m->ay[j] = sp->ay;
    }
}

/* The longest run of degree-2 particles whose springs lie at fixed
 * distances with fixed signs, searched in the lists. */
static void find_run(int n, struct sw_particles_model *m)
{
    m->run_lo = m->run_hi = 0;
    for (int i = 0; m->degree == 2 && i < n;) {
        int c0 = m->spring[2 * i] - 2 * i, c1 = m->spring[2 * i + 1] - 2 * i, e = i + 1;
        while (e < n && m->spring[2 * e] - 2 * e == c0 && m->spring[2 * e + 1] - 2 * e == c1 &&
               m->sign[2 * e] == m->sign[2 * i] && m->sign[2 * e + 1] == m->sign[2 * i + 1])
            e++;
        if (e - i > m->run_hi - m->run_lo) {
            m->run_lo = i;
            m->run_hi = e;
            m->run_c[0] = c0;
            m->run_c[1] = c1;
            m->run_s[0] = m->sign[2 * i];
            m->run_s[1] = m->sign[2 * i + 1];
        }
        i = e;
    }
}

/* The run of a stride layout where every particle has two springs, known
 * before the lists: particle i is end a of paired spring (2i - a0)/2 and
 * end b of (2i - b0)/2, both paired when i lies in [max(a0, b0)/2,
 * min(a0, b0)/2 + npair); such a particle has no anchored spring (it would
 * have three), so its list is those two in spring order. 1 when found. */
static int stride_run(struct sw_particles_model *m)
{
    int lo = (m->a0 > m->b0 ? m->a0 : m->b0) / 2, hi = (m->a0 < m->b0 ? m->a0 : m->b0) / 2 + m->npair;
    if (!m->stride || m->degree != 2 || m->a0 == m->b0 || hi <= lo)
        return 0;
    int a_first = m->a0 > m->b0; /* end a's spring, i - a0/2, comes first */
    m->run_lo = lo;
    m->run_hi = hi;
    m->run_c[0] = a_first ? -m->a0 : -m->b0;
    m->run_c[1] = a_first ? -m->b0 : -m->a0;
    m->run_s[0] = a_first ? 1.0 : -1.0;
    m->run_s[1] = -m->run_s[0];
    return 1;
}

/* The state offset (2·particle) of spring j's end a (end 0) or b (end 1):
 * from the stride where a and b of paired springs were not written. */
static int end_offset(const struct sw_particles_model *m, int j, int end)
{
    if (j < m->npair && m->stride && !m->full)
        return (end ? m->b0 : m->a0) + 2 * j;
    return end ? m->b[j] : m->a[j];
}

/* A chain between two anchors (swp_chain_layout) with no extra pass and no
 * small path: every particle has two springs, the run is [1, n - 1), and
 * only the two end beads' lists are written, in spring order (bead 0:
 * spring 0 as its end b, then its anchor; bead n - 1: spring n - 2 as its
 * end a, then its anchor). `first` is not written: with degree 2 and no
 * extra pass no pass reads it (a million beads' 4 MB never resident).
 * 1 when so. */
static int line_lists(int n, struct sw_particles_model *m)
{
    if (m->full || m->nextra > 0 || !swp_chain_layout(m, n) || n < 3)
        return 0;
    m->degree = 2;
    m->skip_run = stride_run(m);
    int ends[4] = { 0, 2 * m->npair, 2 * (m->npair - 1), 2 * (m->npair + 1) };
    double signs[4] = { -1.0, 1.0, 1.0, 1.0 };
    for (int e = 0; e < 4; e++) {
        int at = e < 2 ? e : 2 * (n - 1) + e - 2;
        m->spring[at] = ends[e];
        m->sign[at] = signs[e];
    }
    return m->skip_run;
}

/* Each particle's list, in spring order: count, then place (but the run's,
 * when skip_run). */
static void build_lists(int n, struct sw_particles_model *m)
{
    int total = m->npair + m->nanchor;
    if (line_lists(n, m))
        return;
    memset(m->first, 0, (size_t)(n + 1) * sizeof *m->first);
    for (int j = 0; j < total; j++) {
        m->first[end_offset(m, j, 0) / 2 + 1]++;
        if (j < m->npair)
            m->first[end_offset(m, j, 1) / 2 + 1]++;
    }
    for (int i = 0; i < n; i++)
        m->first[i + 1] += m->first[i];
    m->degree = total > 0 ? m->first[1] : 0;
    for (int i = 1; i < n && m->degree; i++)
        if (m->first[i + 1] - m->first[i] != m->degree)
            m->degree = 0;
    m->skip_run = !m->full && m->nextra == 0 && stride_run(m);
    for (int j = 0; j < total; j++) {
        for (int end = 0; end < (j < m->npair ? 2 : 1); end++) {
            int i = end_offset(m, j, end) / 2, e = m->first[i]++;
            if (m->skip_run && i >= m->run_lo && i < m->run_hi)
                continue;
            m->spring[e] = 2 * j;
            m->sign[e] = end ? -1.0 : 1.0;
        }
    }
    for (int i = n; i > 0; i--) /* placing advanced each first[i] to first[i + 1] */
        m->first[i] = m->first[i - 1];
    m->first[0] = 0;
    if (!m->skip_run)
        find_run(n, m);
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
    m->npair = m->nanchor = m->damped = m->gravity = m->drag = m->nextra = 0;
    m->uniform = 0;
    m->stride = 1;
    m->a0 = m->b0 = 0;
    int rc = each_spring(p, survey_spring, err, errlen);
    m->stride &= m->npair > 0;
    for (int f = 0; f < p->nforces; f++) {
        const sw_force *fo = &p->forces[f];
        /* springs are compiled above; the first gravity (before any drag)
         * and the first drag are fused into the last pass; every other
         * force, of any kind, is a pass of its own through its descriptor */
        if (fo->kind == SW_FORCE_SPRINGS)
            continue;
        if (fo->kind == SW_FORCE_GRAVITY && !m->gravity && !m->drag) {
            m->gravity = 1;
            m->gx = fo->gx;
            m->gy = fo->gy;
        } else if (fo->kind == SW_FORCE_DRAG && !m->drag) {
            m->drag = 1;
            m->kdrag = fo->k;
        } else {
            m->extra[m->nextra++] = f;
        }
    }
    swp_small_fn *small = swp_small_pick(p); /* (reads the counts and kinds alone) */
    m->full = small != NULL;
    each_spring(p, put_spring, NULL, 0);
    int total = m->npair + m->nanchor;
    for (int j = total; (m->full || !m->uniform) && j < ((total + 3) & ~3); j++) /* the padding: no force */
        m->k[j] = m->c[j] = m->rest[j] = 0.0;
    for (int j = 0; m->uniform && j < BLOCK; j++) {
        m->shared[j] = m->k0;
        m->shared[BLOCK + j] = m->c0;
        m->shared[2 * BLOCK + j] = m->rest0;
    }
    build_lists(p->n, m);
    m->small = small;
    m->chain = swp_chain_shaped(p);
    m->line = swp_line_pick(p);
    p->ode.fast = &m->fast[m->chain];
    m->compiled = 1;
    return rc;
}

/* d = x_a - x_b (or - anchor) for springs [lo, hi) of which [lo, mid) are
 * paired; and dv = v_a - v_b (v_a for anchored ones) when damped. */
SW_INLINE void block_differences(const struct sw_particles_model *m, const double *restrict x,
                                 const double *restrict v, int lo, int mid, int hi, double *restrict d,
                                 double *restrict dv)
{
    const int *restrict ia = m->a, *restrict ib = m->b;
    const double *restrict ax = m->ax, *restrict ay = m->ay;
    if (m->stride) {
        /* neighbours in order: two contiguous reads, in whole vectors (the
         * two components past the last are the next particle's, or the
         * velocities' first: x is the first half of the state; what they
         * write is the anchored springs' or the padding's, below) */
        const double *restrict xa = x + m->a0 + 2 * lo, *restrict xb = x + m->b0 + 2 * lo;
        for (int t = 0, len4 = (2 * (mid - lo) + 3) & ~3; t < len4; t++)
            d[t] = xa[t] - xb[t];
    } else {
        for (int j = lo; j < mid; j++)
            store2(d + 2 * (j - lo), load2(x + ia[j]) - load2(x + ib[j]));
    }
    for (int j = mid; j < hi; j++) {
        d[2 * (j - lo)] = x[ia[j]] - ax[j];
        d[2 * (j - lo) + 1] = x[ia[j] + 1] - ay[j];
    }
    if (!m->damped)
        return;
    if (m->stride) {
        const double *restrict va = v + m->a0 + 2 * lo, *restrict vb = v + m->b0 + 2 * lo;
        for (int t = 0; t < 2 * (mid - lo); t++)
            dv[t] = va[t] - vb[t];
    } else {
        for (int j = lo; j < mid; j++)
            store2(dv + 2 * (j - lo), load2(v + ia[j]) - load2(v + ib[j]));
    }
    for (int j = mid; j < hi; j++) /* v_a - 0 = v_a */
        store2(dv + 2 * (j - lo), load2(v + ia[j]));
}

/* Every spring's force on its particle a, into m->force. */
SW_INLINE void spring_forces(const struct sw_particles_model *m, const double *x, const double *v)
{
    double *d = m->scratch, *dv = d + 2 * BLOCK, *len2 = dv + 2 * BLOCK;
    int total = m->npair + m->nanchor;
    for (int lo = 0; lo < total; lo += BLOCK) {
        int hi = lo + BLOCK < total ? lo + BLOCK : total, mid = hi < m->npair ? hi : m->npair;
        block_differences(m, x, v, lo, mid > lo ? mid : lo, hi, d, dv);
        /* uniform: every block reads the one block of shared rows */
        const double *k = m->uniform ? m->shared : m->k + lo, *c = m->uniform ? m->shared + BLOCK : m->c + lo,
                     *rest = m->uniform ? m->shared + 2 * BLOCK : m->rest + lo;
        if (m->damped) /* (constant arguments: a loop each) */
            block_forces(hi - lo, k, c, rest, d, dv, m->force + 2 * lo, len2, 1);
        else
            block_forces(hi - lo, k, c, rest, d, dv, m->force + 2 * lo, len2, 0);
    }
}

/* Where the last pass finds the forces so far. */
enum { FROM_NONE, FROM_SPRINGS, FROM_F };

/* Particle i's spring forces: Σ ±F over its list, from +0 in spring order
 * (±1·F is exact, so each step is f + F or f - F, as a scatter would add). */
static inline v2d spring_sum(const int *restrict first, const int *restrict spring, const double *restrict sign,
                             const double *restrict force, int i)
{
    v2d f = { 0.0, 0.0 };
    for (int e = first[i]; e < first[i + 1]; e++)
        f += sign[e] * load2(force + spring[e]);
    return f;
}

/* The last pass over particles [i0, i1): dx/dt = v, and dv/dt = (f + m·g -
 * k·v)/m, with f the sum of the particle's spring forces (from =
 * FROM_SPRINGS; read at the run's fixed distances when regular), the forces
 * so far in f (FROM_F) or 0 (FROM_NONE), for the kinds present. Called with
 * constant arguments, so each combination compiles to its own loop. */
SW_INLINE void last_range(const sw_particles *p, const struct sw_particles_model *m, const double *restrict v,
                          double *restrict xdot, double *restrict f, int from, int gravity, int drag, int i0, int i1,
                          int regular)
{
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass, *restrict sign = m->sign,
                           *restrict force = m->force;
    const int *restrict first = m->first, *restrict spring = m->spring;
    v2d g = { m->gx, m->gy };
    double kd = m->kdrag, s0 = m->run_s[0], s1 = m->run_s[1];
    int c0 = m->run_c[0], c1 = m->run_c[1]; /* (offsets, not pointers: c0 may be negative) */
    for (int i = i0; i < i1; i++) {
        v2d fi = { 0.0, 0.0 }, vi = load2(v + 2 * i);
        if (from == FROM_SPRINGS && regular) /* the same sum as below, read in order */
            fi = (fi + s0 * load2(force + (2 * i + c0))) + s1 * load2(force + (2 * i + c1));
        else if (from == FROM_SPRINGS && m->degree == 2) /* chains, rings: the same sum, unrolled */
            fi = (fi + sign[2 * i] * load2(force + spring[2 * i])) + sign[2 * i + 1] * load2(force + spring[2 * i + 1]);
        else if (from == FROM_SPRINGS)
            fi = spring_sum(first, spring, sign, force, i);
        else if (from == FROM_F)
            fi = load2(f + 2 * i);
        if (gravity)
            fi += mass[i] * g;
        if (drag)
            fi -= kd * vi;
        store2(xdot + 2 * i, vi);
        store2(f + 2 * i, fi * inv[i]);
    }
}

/* The last pass over the regular run [i0, i1), two particles at a time
 * (each lane the same operations as last_range's, so the same bits); an
 * odd last one by last_range. */
SW_INLINE void last_run(const sw_particles *p, const struct sw_particles_model *m, const double *restrict v,
                        double *restrict xdot, double *restrict f, int gravity, int drag, int i0, int i1)
{
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass;
    const double *restrict force = m->force;
    int c0 = m->run_c[0], c1 = m->run_c[1]; /* (offsets, not pointers: c0 may be negative) */
    v4d s0 = { m->run_s[0], m->run_s[0], m->run_s[0], m->run_s[0] };
    v4d s1 = { m->run_s[1], m->run_s[1], m->run_s[1], m->run_s[1] };
    v4d g = { m->gx, m->gy, m->gx, m->gy }, zero = { 0.0, 0.0, 0.0, 0.0 };
    double kd = m->kdrag;
    int i = i0;
    for (; i + 2 <= i1; i += 2) {
        v4d vi, a, b;
        memcpy(&vi, v + 2 * i, sizeof vi);
        memcpy(&a, force + (2 * i + c0), sizeof a);
        memcpy(&b, force + (2 * i + c1), sizeof b);
        v4d fi = (zero + s0 * a) + s1 * b;
        if (gravity)
            fi += (v4d){ mass[i], mass[i], mass[i + 1], mass[i + 1] } * g;
        if (drag)
            fi -= kd * vi;
        fi *= (v4d){ inv[i], inv[i], inv[i + 1], inv[i + 1] };
        memcpy(xdot + 2 * i, &vi, sizeof vi);
        memcpy(f + 2 * i, &fi, sizeof fi);
    }
    last_range(p, m, v, xdot, f, FROM_SPRINGS, gravity, drag, i, i1, 1);
}

/* The last pass over every particle, the regular run apart. */
SW_INLINE void last_pass(const sw_particles *p, const struct sw_particles_model *m, const double *restrict v,
                         double *restrict xdot, double *restrict f, int from, int gravity, int drag)
{
    int lo = m->run_lo, hi = m->run_hi;
    if (from != FROM_SPRINGS || hi == lo) {
        last_range(p, m, v, xdot, f, from, gravity, drag, 0, p->n, 0);
        return;
    }
    last_range(p, m, v, xdot, f, from, gravity, drag, 0, lo, 0);
    last_run(p, m, v, xdot, f, gravity, drag, lo, hi);
    last_range(p, m, v, xdot, f, from, gravity, drag, hi, p->n, 0);
}

/* (compiled twice, engine/clones.h; swp_deriv is its one entry; one pass:
 * the last pass's copy of v into dx/dt stays in it, not a memcpy call of
 * its own, SW_ONE_PASS) */
SW_CLONES SW_ONE_PASS static void deriv(void *ctx, const double *y, double *dydt)
{
    sw_particles *p = ctx;
    struct sw_particles_model *m = p->model;
    if (!m->compiled)
        swp_model_compile(p, NULL, 0);
    int n2 = 2 * p->n;
    const double *x = y, *v = y + n2;
    double *f = dydt + n2;
    int springs = m->npair + m->nanchor > 0, from = springs ? FROM_SPRINGS : FROM_NONE;
    if (springs)
        spring_forces(m, x, v);
    if (m->nextra > 0) { /* central fields, mutual gravity: the forces so far into f, then a pass each */
        for (int i = 0; i < p->n; i++) {
            v2d fi = { 0.0, 0.0 };
            if (springs)
                fi = spring_sum(m->first, m->spring, m->sign, m->force, i);
            store2(f + 2 * i, fi);
        }
        for (int e = 0; e < m->nextra; e++) {
            const sw_force *fo = &p->forces[m->extra[e]];
            swp_force_type_of(fo->kind)->add(p, fo, x, v, f);
        }
        from = FROM_F;
    }
    switch (from | m->gravity << 2 | m->drag << 3) {
    case FROM_NONE: last_pass(p, m, v, dydt, f, FROM_NONE, 0, 0); break;
    case FROM_SPRINGS: last_pass(p, m, v, dydt, f, FROM_SPRINGS, 0, 0); break;
    case FROM_F: last_pass(p, m, v, dydt, f, FROM_F, 0, 0); break;
    case FROM_NONE | 4: last_pass(p, m, v, dydt, f, FROM_NONE, 1, 0); break;
    case FROM_SPRINGS | 4: last_pass(p, m, v, dydt, f, FROM_SPRINGS, 1, 0); break;
    case FROM_F | 4: last_pass(p, m, v, dydt, f, FROM_F, 1, 0); break;
    case FROM_NONE | 8: last_pass(p, m, v, dydt, f, FROM_NONE, 0, 1); break;
    case FROM_SPRINGS | 8: last_pass(p, m, v, dydt, f, FROM_SPRINGS, 0, 1); break;
    case FROM_F | 8: last_pass(p, m, v, dydt, f, FROM_F, 0, 1); break;
    case FROM_NONE | 12: last_pass(p, m, v, dydt, f, FROM_NONE, 1, 1); break;
    case FROM_SPRINGS | 12: last_pass(p, m, v, dydt, f, FROM_SPRINGS, 1, 1); break;
    default: last_pass(p, m, v, dydt, f, FROM_F, 1, 1); break;
    }
}

/* Resting contact (sw_walls.rest): a ball on the floor at rest, exactly
 * (the contact put it there), is held by the floor's normal force, which
 * cancels whatever pulls it down; pulled up, it leaves. Every stage of a
 * step then leaves it where it is, so it stays at rest exactly. */
static void hold_resting(const sw_particles *p, const double *y, double *dydt)
{
    int n2 = 2 * p->n;
    double floor = p->walls.ymin;
    for (int i = 0; i < p->n; i++)
        if (y[2 * i + 1] == floor && y[n2 + 2 * i + 1] == 0 && dydt[n2 + 2 * i + 1] < 0)
            dydt[n2 + 2 * i + 1] = 0;
}

/* The small path and the small chain's (particles_chain.c) are set only
 * while the compiled form is current (swp_model_touch clears them), and the
 * generic one compiles first when it is not; a floor with resting contact
 * then holds the balls on it. */
void swp_deriv(void *ctx, double t, const double *y, double *dydt)
{
    const sw_particles *p = ctx;
    (void)t;
    if (p->model->small)
        p->model->small(p, y, dydt);
    else if (!p->model->line || !p->model->line(p, y, dydt))
        deriv(ctx, y, dydt);
    if (p->walls.rest > 0 && (p->walls.sides & SW_WALL_FLOOR))
        hold_resting(p, y, dydt);
}

void swp_deriv_generic(void *ctx, double t, const double *y, double *dydt)
{
    const sw_particles *p = ctx;
    (void)t;
    deriv(ctx, y, dydt);
    if (p->walls.rest > 0 && (p->walls.sides & SW_WALL_FLOOR))
        hold_resting(p, y, dydt);
}

int swp_deriv_is_small(const sw_particles *p)
{
    if (!p->model->compiled)
        swp_model_compile((sw_particles *)p, NULL, 0);
    return p->model->small != NULL;
}
