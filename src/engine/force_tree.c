/* Softened mutual gravity by a Barnes-Hut quadtree: for each body, a cell of
 * side s whose centre of mass lies at distance d (the body outside it) acts
 * as one body of the cell's mass there when s < θ·d, and is opened
 * otherwise; leaves are summed pair by pair as the direct sum does:
 *   f_i ≈ -G m_i Σ_cells M_c (x_i - X_c)/(|x_i - X_c|² + ε²)^(3/2).
 * The cells are those of a quadtree on 16-bit Morton keys in the bodies'
 * bounding square, kept only where they split (every inner node has two
 * children or more, so at most 2n - 1 nodes); a range of at most LEAF_MAX
 * bodies, or bodies sharing a cell 2^-16 of the box wide, is a leaf.
 * Invariant: an evaluation allocates nothing — the node pool and the sort
 * buffers are sized when the force is added (tree_work_new) — and is
 * deterministic (a stable radix sort; bodies and cells walked in a fixed
 * order). Only the force is approximated: the potential, the pairs and the
 * Jacobian blocks are the direct sum's (force_mutual.c), so energies and
 * implicit steps see exact softened gravity. Parameters: mu = G, soft = ε,
 * theta = θ. */
#include "engine/forces.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define KEY_BITS 16  /* per axis: the smallest cell is 2^-16 of the box */
#define LEAF_MAX 8   /* a range of at most this many bodies is summed directly */
#define STACK_MAX 64 /* a walk keeps at most 3 siblings per level, 17 levels, + 4 */

typedef struct tree_node {
    double mx, my, m; /* centre of mass and mass */
    double side;      /* the cell's side */
    int lo, hi;       /* its bodies, in sorted order */
    int first, count; /* its children (consecutive nodes); count 0: a leaf */
} tree_node;

typedef struct tree_work {
    int n, nnodes;
    tree_node *node;    /* 2n - 1 */
    double *bx, *by, *bm; /* the bodies in key order */
    uint32_t *key, *key2;
    int *idx, *idx2;    /* body numbers in key order; the sort's second buffer */
} tree_work;

static size_t round_up(size_t b) { return (b + 63) & ~(size_t)63; }

static void *tree_work_new(int n)
{
    size_t nodes = 2 * (size_t)n, head = round_up(sizeof(tree_work)), node_b = round_up(nodes * sizeof(tree_node)),
           dbl_b = round_up((size_t)n * sizeof(double)), key_b = round_up((size_t)n * sizeof(uint32_t)),
           idx_b = round_up((size_t)n * sizeof(int));
    char *block = calloc(1, head + node_b + 3 * dbl_b + 2 * key_b + 2 * idx_b);
    if (!block)
        return NULL;
    tree_work *w = (tree_work *)block;
    char *at = block + head;
    w->n = n;
    w->node = (tree_node *)at, at += node_b;
    w->bx = (double *)at, at += dbl_b;
    w->by = (double *)at, at += dbl_b;
    w->bm = (double *)at, at += dbl_b;
    w->key = (uint32_t *)at, at += key_b;
    w->key2 = (uint32_t *)at, at += key_b;
    w->idx = (int *)at, at += idx_b;
    w->idx2 = (int *)at;
    return w;
}

/* The 16 bits of v spread to the even bits of a 32-bit word. */
static uint32_t spread(uint32_t v)
{
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

/* Stable LSD radix sort of (key, idx) by key, 8 bits a pass; the result
 * ends in key/idx (four passes). */
static void sort_keys(tree_work *w)
{
    uint32_t *ka = w->key, *kb = w->key2;
    int *ia = w->idx, *ib = w->idx2;
    for (int shift = 0; shift < 32; shift += 8) {
        int count[257] = { 0 };
        for (int r = 0; r < w->n; r++)
            count[((ka[r] >> shift) & 255u) + 1]++;
        for (int d = 0; d < 256; d++)
            count[d + 1] += count[d];
        for (int r = 0; r < w->n; r++) {
            int to = count[(ka[r] >> shift) & 255u]++;
            kb[to] = ka[r];
            ib[to] = ia[r];
        }
        uint32_t *kt = ka;
        ka = kb, kb = kt;
        int *it = ia;
        ia = ib, ib = it;
    }
}

/* The first r in [lo, hi) whose digit at shift is >= d (digits rise along
 * the range: its keys share every bit above). */
static int digit_start(const uint32_t *key, int lo, int hi, int shift, unsigned d)
{
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (((key[mid] >> shift) & 3u) < d)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Fill node k with bodies [lo, hi) of a box of side `side`, and its
 * subtree (children taken from the pool in order). The cell is the one
 * its first and last keys share: depth D = (common leading bits) / 2. */
static void build(tree_work *w, int k, int lo, int hi, double side)
{
    tree_node *nd = &w->node[k];
    uint32_t diff = w->key[lo] ^ w->key[hi - 1];
    int depth = diff ? __builtin_clz(diff) / 2 : KEY_BITS;
    nd->lo = lo, nd->hi = hi;
    nd->side = ldexp(side, -depth);
    nd->count = 0;
    double m = 0, sx = 0, sy = 0;
    if (hi - lo <= LEAF_MAX || depth == KEY_BITS) {
        for (int r = lo; r < hi; r++) {
            m += w->bm[r];
            sx += w->bm[r] * w->bx[r];
            sy += w->bm[r] * w->by[r];
        }
    } else {
        int shift = 2 * (KEY_BITS - 1 - depth), start[5] = { lo, 0, 0, 0, hi };
        for (unsigned d = 1; d < 4; d++)
            start[d] = digit_start(w->key, start[d - 1], hi, shift, d);
        nd->first = w->nnodes;
        for (int d = 0; d < 4; d++)
            nd->count += start[d + 1] > start[d];
        w->nnodes += nd->count;
        for (int d = 0, c = nd->first; d < 4; d++) {
            if (start[d + 1] == start[d])
                continue;
            build(w, c, start[d], start[d + 1], side);
            nd = &w->node[k];
            m += w->node[c].m;
            sx += w->node[c].m * w->node[c].mx;
            sy += w->node[c].m * w->node[c].my;
            c++;
        }
    }
    nd->m = m;
    nd->mx = m > 0 ? sx / m : w->bx[lo];
    nd->my = m > 0 ? sy / m : w->by[lo];
}

/* The pull on sorted body r from the tree, as Σ M (x_r - X)/q³ (times
 * -G m_r by the caller). */
static void walk(const tree_work *w, int r, double theta2, double e2, double *fx, double *fy)
{
    int stack[STACK_MAX], top = 0;
    double xr = w->bx[r], yr = w->by[r], gx = 0, gy = 0;
    stack[top++] = 0;
    while (top > 0) {
        const tree_node *nd = &w->node[stack[--top]];
        double dx = xr - nd->mx, dy = yr - nd->my, d2 = dx * dx + dy * dy;
        int inside = r >= nd->lo && r < nd->hi;
        if (!inside && nd->side * nd->side < theta2 * d2) {
            double q2 = d2 + e2, s = nd->m / (q2 * sqrt(q2));
            gx += s * dx;
            gy += s * dy;
        } else if (nd->count == 0) {
            for (int j = nd->lo; j < nd->hi; j++) {
                if (j == r)
                    continue;
                double ex = xr - w->bx[j], ey = yr - w->by[j], q2 = ex * ex + ey * ey + e2;
                double s = w->bm[j] / (q2 * sqrt(q2));
                gx += s * ex;
                gy += s * ey;
            }
        } else {
            for (int c = nd->first + nd->count - 1; c >= nd->first; c--)
                stack[top++] = c; /* popped in order: first child first */
        }
    }
    *fx = gx, *fy = gy;
}

static void tree_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    tree_work *w = fo->work;
    int n = p->n;
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < n; i++) {
        xmin = fmin(xmin, x[2 * i]), xmax = fmax(xmax, x[2 * i]);
        ymin = fmin(ymin, x[2 * i + 1]), ymax = fmax(ymax, x[2 * i + 1]);
    }
    double side = fmax(xmax - xmin, ymax - ymin);
    int finite = 1;
    for (int i = 0; i < 2 * n && finite; i++)
        finite = isfinite(x[i]);
    if (!finite || !isfinite(side) || !w || w->n != n) { /* a blown-up state: the direct sum gives its NaNs */
        swp_mutual.add(p, fo, x, v, f);
        return;
    }
    if (!(side > 0))
        side = 1; /* every body at one point: one leaf */
    double per_unit = 65536.0 / side;
    for (int i = 0; i < n; i++) {
        double u = (x[2 * i] - xmin) * per_unit, t = (x[2 * i + 1] - ymin) * per_unit;
        uint32_t ix = u >= 65535.0 ? 65535u : (uint32_t)u, iy = t >= 65535.0 ? 65535u : (uint32_t)t;
        w->key[i] = spread(ix) << 1 | spread(iy);
        w->idx[i] = i;
    }
    sort_keys(w);
    for (int r = 0; r < n; r++) {
        int i = w->idx[r];
        w->bx[r] = x[2 * i], w->by[r] = x[2 * i + 1], w->bm[r] = p->mass[i];
    }
    w->nnodes = 1;
    build(w, 0, 0, n, side);
    double theta2 = fo->theta * fo->theta, e2 = fo->soft * fo->soft;
    for (int r = 0; r < n; r++) {
        double gx, gy, s;
        walk(w, r, theta2, e2, &gx, &gy);
        s = fo->mu * w->bm[r];
        f[2 * w->idx[r]] -= s * gx;
        f[2 * w->idx[r] + 1] -= s * gy;
    }
}

/* The direct sum's potential, pairs and blocks: the tree changes how the
 * force is summed, not the system. */
static void tree_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    swp_mutual.potential(p, fo, x, e);
}

static long tree_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    return swp_mutual.pairs(p, fo, reach);
}

static void tree_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v, swp_blocks *out)
{
    swp_mutual.blocks(p, fo, x, v, out);
}

static void tree_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "G = %g, soft = %g, theta = %g", fo->mu, fo->soft, fo->theta);
}

const swp_force_type swp_tree = {
    .name = "mutual gravity (Barnes-Hut tree)",
    .formula = "f_i = -sum_j G m_i m_j d/(|d|^2 + soft^2)^(3/2), d = x_i - x_j; a cell of side s "
               "at distance d from x_i counts as its mass at its centre of mass when s < theta d",
    .values = tree_values,
    .add = tree_add,
    .potential = tree_potential,
    .term = "mutual gravity potential",
    .term_formula = "- G m_i m_j/√(r² + ε²)",
    .pairs = tree_pairs,
    .blocks = tree_blocks,
    .work_new = tree_work_new,
};
