/* Softened mutual gravity by a Barnes-Hut quadtree, walked by groups: the
 * bodies of a small cell (a group) share one interaction list, in which a
 * cell whose bodies span s (the larger side of their bounding box) and
 * whose centre of mass lies at distance d from the group's bounding box
 * stands as one body of the cell's mass there when s < θ·d, and is opened
 * otherwise; a leaf that is opened gives its bodies. Every body of the
 * group then sums the list, in list order, as the direct sum does:
 *   f_i ≈ -G m_i Σ_list M_c (x_i - X_c)/(|x_i - X_c|² + ε²)^(3/2).
 * Since d is no more than any group body's distance, the criterion holds
 * for each body of the group (a cell taken whole for the group would be for
 * each body). The cells are those of a quadtree on 16-bit Morton keys in
 * the bodies' bounding square, kept only where they split (every inner node
 * has two children or more, so at most 2n - 1 nodes); a range of at most
 * LEAF_MAX bodies, or bodies sharing a cell 2^-16 of the box wide, is a leaf.
 * Invariant: an evaluation allocates nothing — the node pool, the sort
 * buffers and the list are sized when the force is added (tree_work_new) —
 * and is deterministic (a stable radix sort; groups, cells and bodies
 * walked in a fixed order; a full list is summed and emptied at fixed
 * points). The pairs and the Jacobian blocks are the direct sum's
 * (force_mutual.c), so implicit steps see exact softened gravity; the
 * potential is too up to EXACT_BODIES bodies, and above it is summed over
 * the same lists as the force, with a stated error bound (tree_energy).
 * Parameters: mu = G, soft = ε, theta = θ. */
#include "engine/clones.h"
#include "engine/forces.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KEY_BITS 16   /* per axis: the smallest cell is 2^-16 of the box */
#define LEAF_MAX 8    /* a range of at most this many bodies is a leaf */
#define GROUP_MAX 64  /* a cell of at most this many bodies shares one list */
#define BLOCK 4       /* bodies summed side by side (one 4-wide vector) */
#define LIST_MAX 2048 /* interactions gathered before the group sums them */

typedef struct tree_node {
    double mx, my, m; /* centre of mass and mass */
    double size2;     /* the square of the larger side of the bodies' box */
    int lo, hi;       /* its bodies, in sorted order */
    int first, count; /* its children (consecutive nodes); count 0: a leaf */
    int next;         /* the node after its subtree in depth-first order (-1: none) */
} tree_node;

typedef struct tree_box {
    double x0, x1, y0, y1; /* a node's bodies' bounding box (apart: the walk reads only groups') */
} tree_box;

/* What the potential's error bound needs of a node (apart: read only for
 * cells taken whole): its second moment Q = Σ m |x - X|² about its centre
 * of mass X, and b, the farthest its box reaches from X (no body is
 * farther). */
typedef struct tree_moment {
    double q, b;
} tree_moment;

typedef struct tree_work {
    int n, nnodes;
    tree_node *node;    /* 2n - 1 */
    tree_box *box;      /* one per node */
    tree_moment *mom;   /* one per node */
    double *bx, *by, *bm; /* the bodies in key order */
    double *ax, *ay;    /* their sums Σ M (x_r - X)/q³ */
    double *ap;         /* and Σ M/q (the potential's, by the same list) */
    double *px;         /* the positions (2n) the last pass was at, for the potential's cache */
    int have_pot;       /* pot and bound hold for px */
    double pot, bound;  /* Σ_r m_r Σ_list' M/q (self term out), and its error bound (see tree_energy) */
    double group_bound; /* the bound's sum for the group being walked */
    uint32_t *key, *key2;
    int *idx, *idx2;    /* body numbers in key order; the sort's second buffer */
    double lx[LIST_MAX], ly[LIST_MAX], lm[LIST_MAX]; /* a group's list: point masses */
    int len;
    double cd2[LIST_MAX], cb[LIST_MAX], cq[LIST_MAX]; /* the cells the group took whole:
                                   their distance² from its box, reach and second moment (its bound) */
    int ncells;
    int paired;         /* every q² of the pass in [1e-100, 1e100]: sum_block may pair entries */
} tree_work;

static size_t round_up(size_t b) { return (b + 63) & ~(size_t)63; }

static void *tree_work_new(int n)
{
    size_t nodes = 2 * (size_t)n, head = round_up(sizeof(tree_work)), node_b = round_up(nodes * sizeof(tree_node)),
           box_b = round_up(nodes * sizeof(tree_box)), mom_b = round_up(nodes * sizeof(tree_moment)),
           dbl_b = round_up((size_t)n * sizeof(double)), key_b = round_up((size_t)n * sizeof(uint32_t)),
           idx_b = round_up((size_t)n * sizeof(int));
    char *block = calloc(1, head + node_b + box_b + mom_b + 8 * dbl_b + 2 * key_b + 2 * idx_b);
    if (!block)
        return NULL;
    tree_work *w = (tree_work *)block;
    char *at = block + head;
    w->n = n;
    w->node = (tree_node *)at, at += node_b;
    w->box = (tree_box *)at, at += box_b;
    w->mom = (tree_moment *)at, at += mom_b;
    w->bx = (double *)at, at += dbl_b;
    w->by = (double *)at, at += dbl_b;
    w->bm = (double *)at, at += dbl_b;
    w->ax = (double *)at, at += dbl_b;
    w->ay = (double *)at, at += dbl_b;
    w->ap = (double *)at, at += dbl_b;
    w->px = (double *)at, at += 2 * dbl_b;
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

/* Fill node k with bodies [lo, hi) and its subtree (children taken from
 * the pool in order). The cell is the one its first and last keys share:
 * depth D = (common leading bits) / 2; its mass, centre of mass and the
 * bounding box of its bodies. */
static void build(tree_work *w, int k, int lo, int hi)
{
    tree_node *nd = &w->node[k];
    uint32_t diff = w->key[lo] ^ w->key[hi - 1];
    int depth = diff ? __builtin_clz(diff) / 2 : KEY_BITS;
    nd->lo = lo, nd->hi = hi;
    nd->count = 0;
    double m = 0, sx = 0, sy = 0, x0 = w->bx[lo], x1 = x0, y0 = w->by[lo], y1 = y0;
    if (hi - lo <= LEAF_MAX || depth == KEY_BITS) {
        for (int r = lo; r < hi; r++) {
            m += w->bm[r];
            sx += w->bm[r] * w->bx[r];
            sy += w->bm[r] * w->by[r];
            x0 = w->bx[r] < x0 ? w->bx[r] : x0, x1 = w->bx[r] > x1 ? w->bx[r] : x1;
            y0 = w->by[r] < y0 ? w->by[r] : y0, y1 = w->by[r] > y1 ? w->by[r] : y1;
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
            build(w, c, start[d], start[d + 1]);
            nd = &w->node[k];
            const tree_node *ch = &w->node[c];
            const tree_box *cb = &w->box[c];
            m += ch->m;
            sx += ch->m * ch->mx;
            sy += ch->m * ch->my;
            x0 = cb->x0 < x0 ? cb->x0 : x0, x1 = cb->x1 > x1 ? cb->x1 : x1;
            y0 = cb->y0 < y0 ? cb->y0 : y0, y1 = cb->y1 > y1 ? cb->y1 : y1;
            c++;
        }
    }
    double size = fmax(x1 - x0, y1 - y0);
    nd->m = m;
    nd->mx = m > 0 ? sx / m : w->bx[lo];
    nd->my = m > 0 ? sy / m : w->by[lo];
    w->box[k] = (tree_box){ x0, x1, y0, y1 };
    nd->size2 = size * size;
    /* Q about the centre of mass: a leaf's from its bodies, an inner
     * node's from its children's (parallel axes: Q_c + M_c |X_c - X|²) */
    double q = 0, X = nd->mx, Y = nd->my;
    if (nd->count == 0)
        for (int r = lo; r < hi; r++)
            q += w->bm[r] * ((w->bx[r] - X) * (w->bx[r] - X) + (w->by[r] - Y) * (w->by[r] - Y));
    else
        for (int c = nd->first; c < nd->first + nd->count; c++) {
            const tree_node *ch = &w->node[c];
            q += w->mom[c].q + ch->m * ((ch->mx - X) * (ch->mx - X) + (ch->my - Y) * (ch->my - Y));
        }
    double bx = fmax(X - x0, x1 - X), by = fmax(Y - y0, y1 - Y);
    w->mom[k] = (tree_moment){ q, sqrt(bx * bx + by * by) };
}

/* The bodies c .. c + cnt - 1 of the group take the list side by side in
 * `block` lanes (4, or 2; a short block padded with its last body, then
 * dropped): for each entry in list order, each body's three sums. The
 * lanes' loop vectorises without reordering any sum, so a body's bits do
 * not depend on the block it is summed in. Where the pass allows it
 * (w->paired) two entries share one division, s = M·b/(a b) and t =
 * M'·a/(a b) with a = q³, b = q'³: one square root and half a division a
 * pair, the divider being what bounds this loop (a few ulps of each term,
 * against one). With ε = 0 a body meets itself at q = 0, and the guarded
 * loop drops that term. */
SW_INLINE void sum_block(const tree_work *w, int c, int cnt, int block, double e2, double *ax, double *ay, double *ap)
{
    double xr[BLOCK], yr[BLOCK], gx[BLOCK], gy[BLOCK], gp[BLOCK];
    for (int i = 0; i < block; i++) {
        int r = c + (i < cnt ? i : cnt - 1);
        xr[i] = w->bx[r], yr[i] = w->by[r], gx[i] = ax[r], gy[i] = ay[r], gp[i] = ap[r];
    }
    if (e2 > 0) {
        int j = 0;
        if (w->paired) /* two entries share one division: 1/a = b·(1/(a b)) */
            for (; j + 1 < w->len; j += 2) {
                double X = w->lx[j], Y = w->ly[j], M = w->lm[j], X1 = w->lx[j + 1], Y1 = w->ly[j + 1], M1 = w->lm[j + 1];
                for (int i = 0; i < block; i++) {
                    double ex = xr[i] - X, ey = yr[i] - Y, q2 = ex * ex + ey * ey + e2, a = q2 * sqrt(q2);
                    double fx = xr[i] - X1, fy = yr[i] - Y1, p2 = fx * fx + fy * fy + e2, b = p2 * sqrt(p2);
                    double inv = 1 / (a * b), s = M * (b * inv), t = M1 * (a * inv);
                    gx[i] += s * ex;
                    gy[i] += s * ey;
                    gp[i] += s * q2;
                    gx[i] += t * fx;
                    gy[i] += t * fy;
                    gp[i] += t * p2;
                }
            }
        for (; j < w->len; j++) {
            double X = w->lx[j], Y = w->ly[j], M = w->lm[j];
            for (int i = 0; i < block; i++) {
                double ex = xr[i] - X, ey = yr[i] - Y, q2 = ex * ex + ey * ey + e2, s = M / (q2 * sqrt(q2));
                gx[i] += s * ex;
                gy[i] += s * ey;
                gp[i] += s * q2; /* M/q, the potential's term, at the cost of a product */
            }
        }
    } else {
        for (int j = 0; j < w->len; j++) {
            double X = w->lx[j], Y = w->ly[j], M = w->lm[j];
            for (int i = 0; i < block; i++) {
                double ex = xr[i] - X, ey = yr[i] - Y, q2 = ex * ex + ey * ey;
                double s = q2 > 0 ? M / (q2 * sqrt(q2)) : 0;
                gx[i] += s * ex;
                gy[i] += s * ey;
                gp[i] += s * q2;
            }
        }
    }
    for (int i = 0; i < cnt; i++)
        ax[c + i] = gx[i], ay[c + i] = gy[i], ap[c + i] = gp[i];
}

/* Add Σ_list M (x_r - X)/q³ to (ax, ay) and Σ_list M/q to ap for the
 * group's bodies [lo, hi), each body's sum in list order: BLOCK bodies at
 * a time, a rest of one or two by two lanes (at most one lane of a group
 * is padding). On x86-64 an AVX2 copy is chosen at load time where the
 * processor has it: 4 lanes, not 2, of the same IEEE operations (no FMA),
 * hence the same bits. */
SW_CLONES
static void sum_list(const tree_work *w, int lo, int hi, double e2, double *ax, double *ay, double *ap)
{
    int c = lo;
    for (; hi - c >= 3; c += BLOCK)
        sum_block(w, c, hi - c < BLOCK ? hi - c : BLOCK, BLOCK, e2, ax, ay, ap);
    if (hi > c)
        sum_block(w, c, hi - c, 2, e2, ax, ay, ap);
}

/* The potential's error bound for the group from the cells it took whole
 * (their distance² d2 from its box, reach b and second moment Q, in list
 * order): Σ Q/((d - b)² + ε²)^(3/2), d - b taken as 0 where it is not
 * positive (see tree_energy). With ε > 0 the terms are computed side by
 * side ((g + |g|)/2 is g or 0 exactly, without a branch) into d2's place,
 * then summed in list order. */
SW_CLONES
static double group_bound(tree_work *w, double e2)
{
    double sum = 0, *restrict term = w->cd2;
    const double *restrict reach = w->cb, *restrict q = w->cq;
    int n = w->ncells;
    if (e2 > 0) {
        for (int i = 0; i < n; i++) {
            double gap = sqrt(term[i]) - reach[i], pos = 0.5 * (gap + fabs(gap)), t = pos * pos + e2;
            term[i] = q[i] / (t * sqrt(t));
        }
        for (int i = 0; i < n; i++)
            sum += term[i];
    } else {
        for (int i = 0; i < n; i++) {
            double gap = sqrt(term[i]) - reach[i], t = gap > 0 ? gap * gap : 0;
            sum += t > 0 ? q[i] / (t * sqrt(t)) : INFINITY;
        }
    }
    return sum;
}

/* Append one point mass to the list, summing and emptying it when full. */
static void list_add(tree_work *w, const tree_node *g, double x, double y, double m, double e2, double *ax, double *ay)
{
    if (w->len == LIST_MAX) {
        sum_list(w, g->lo, g->hi, e2, ax, ay, w->ap);
        w->len = 0;
    }
    w->lx[w->len] = x, w->ly[w->len] = y, w->lm[w->len] = m;
    w->len++;
}

/* The pull on group g's bodies from the tree, added to (ax, ay) as
 * Σ M (x_r - X)/q³ (times -G m_r by the caller). g's own cell and its
 * ancestors are always opened; another cell at distance d from g's box
 * (0 if its centre of mass lies inside) is taken whole when s² < θ² d². */
static void walk(tree_work *w, const tree_node *g, double theta2, double e2, double *ax, double *ay)
{
    const tree_box *gb = &w->box[g - w->node];
    double x0 = gb->x0, x1 = gb->x1, y0 = gb->y0, y1 = gb->y1;
    w->len = 0;
    w->ncells = 0;
    w->group_bound = 0;
    for (int k = 0; k >= 0;) { /* depth first, first child first, without a stack */
        const tree_node *nd = &w->node[k];
        int holds_g = nd->lo <= g->lo && g->hi <= nd->hi;
        double dx = nd->mx < x0 ? x0 - nd->mx : nd->mx > x1 ? nd->mx - x1 : 0.0;
        double dy = nd->my < y0 ? y0 - nd->my : nd->my > y1 ? nd->my - y1 : 0.0;
        if (!holds_g && nd->size2 < theta2 * (dx * dx + dy * dy)) {
            list_add(w, g, nd->mx, nd->my, nd->m, e2, ax, ay);
            /* the potential's error for any body of g from this cell taken
             * whole: at most Q/((d - b)² + ε²)^(3/2) (see tree_energy),
             * summed with the others at the end of the walk */
            if (w->ncells == LIST_MAX) {
                w->group_bound += group_bound(w, e2);
                w->ncells = 0;
            }
            const tree_moment *mo = &w->mom[nd - w->node];
            w->cd2[w->ncells] = dx * dx + dy * dy, w->cb[w->ncells] = mo->b, w->cq[w->ncells] = mo->q;
            w->ncells++;
            k = nd->next;
        } else if (nd->count == 0) {
            for (int j = nd->lo; j < nd->hi; j++)
                list_add(w, g, w->bx[j], w->by[j], w->bm[j], e2, ax, ay);
            k = nd->next;
        } else {
            k = nd->first;
        }
    }
    sum_list(w, g->lo, g->hi, e2, ax, ay, w->ap);
    w->group_bound += group_bound(w, e2);
}

/* One pass of the tree at positions x: every body's Σ M (x_r - X)/q³ in
 * (ax, ay) and Σ M/q in ap (sorted order), and the potential's sum and
 * bound for x, kept with a copy of x (tree_energy). 0, or -1 where the
 * tree cannot be built (a state that is not finite, or no workspace). */
static int tree_pass(const sw_particles *p, const sw_force *fo, const double *x)
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
    if (!finite || !isfinite(side) || !w || w->n != n)
        return -1;
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
    build(w, 0, 0, n);
    w->node[0].next = -1; /* a parent comes before its children in the pool */
    for (int k = 0; k < w->nnodes; k++)
        for (int c = w->node[k].first, end = c + w->node[k].count; c < end; c++)
            w->node[c].next = c + 1 < end ? c + 1 : w->node[k].next;
    double *ax = w->ax, *ay = w->ay;
    for (int r = 0; r < n; r++)
        ax[r] = 0, ay[r] = 0, w->ap[r] = 0;
    double theta2 = fo->theta * fo->theta, e2 = fo->soft * fo->soft, bound = 0;
    /* q² = |x_r - X|² + ε² lies in [ε², 2 side² + ε²] (bodies and centres of
     * mass are in the box): where that is inside [1e-100, 1e100], a = q³ is
     * inside [1e-150, 1e150] and the product of two is a normal number, so
     * sum_block may share a division between two entries */
    w->paired = e2 >= 1e-100 && 2 * side * side + e2 <= 1e100;
    for (int k = 0; k >= 0;) { /* the groups, in tree order */
        const tree_node *nd = &w->node[k];
        if (nd->hi - nd->lo <= GROUP_MAX || nd->count == 0) {
            walk(w, nd, theta2, e2, ax, ay);
            bound += nd->m * w->group_bound;
            k = nd->next;
        } else {
            k = nd->first;
        }
    }
    /* Σ m_r φ_r, each body's own term (M/q at q = ε, as the list summed it) taken out */
    double pot = 0;
    for (int r = 0; r < n; r++) {
        double self = e2 > 0 ? w->bm[r] / (e2 * sqrt(e2)) * e2 : 0;
        pot += w->bm[r] * (w->ap[r] - self);
    }
    w->pot = pot;
    w->bound = bound;
    memcpy(w->px, x, (size_t)2 * n * sizeof *x);
    w->have_pot = 1;
    return 0;
}

static int tree_exact(const sw_particles *p);

static void tree_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    if (tree_pass(p, fo, x) != 0) { /* a blown-up state: the direct sum gives its NaNs, */
        if (tree_exact(p) || !fo->work)
            swp_mutual.add(p, fo, x, v, f);
        else /* or, past its reach (5e9 pairs at n = 1e5, some 17 s), NaN everywhere */
            for (int i = 0; i < 2 * p->n; i++)
                f[i] += NAN;
        return;
    }
    const tree_work *w = fo->work;
    for (int r = 0; r < p->n; r++) {
        double s = fo->mu * w->bm[r];
        f[2 * w->idx[r]] -= s * w->ax[r];
        f[2 * w->idx[r] + 1] -= s * w->ay[r];
    }
}

/* Up to EXACT_BODIES bodies (every galaxy the scene built before n could
 * reach 1e5, so their energies keep their bits) the potential is the
 * direct sum's, n²/2 pairs; above, the tree's, from the lists of the last
 * pass at these positions (a step of verlet ends with one) or a new pass:
 *   V ≈ -½ G Σ_r m_r Σ_list' M/√(|x_r - X|² + ε²),
 * every pair once from each end, each body's own term out. A cell of mass
 * M, second moment Q about its centre of mass X and every body within b of
 * X, taken whole for a body at distance d ≥ b from X, errs in Σ m_j/q_j by
 * at most Q/((d - b)² + ε²)^(3/2): the first-order terms of the Taylor
 * series about X cancel (X is the centre of mass), and the Hessian of
 * 1/√(r² + ε²) has norm at most 2/(r² + ε²)^(3/2), r ≥ d - b on the way
 * (d is at least the distance to the group's box, so one bound serves the
 * group). Hence |V - V_exact| ≤ ½ G Σ_groups M_g Σ_cells Q/((d - b)² +
 * ε²)^(3/2), in exact arithmetic; rounding adds some 1e-16 of Σ|terms|. */
#define EXACT_BODIES 4002

static int tree_exact(const sw_particles *p) { return p->n <= EXACT_BODIES; }

/* The pass for x is there (one is made if not): 0, or -1 (see tree_pass). */
static int tree_energy(const sw_particles *p, const sw_force *fo, const double *x)
{
    const tree_work *w = fo->work;
    if (w && w->have_pot && w->n == p->n && memcmp(w->px, x, (size_t)2 * p->n * sizeof *x) == 0)
        return 0;
    return tree_pass(p, fo, x);
}

static void tree_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    if (tree_exact(p))
        swp_mutual.potential(p, fo, x, e);
    else if (tree_energy(p, fo, x) != 0)
        *e += NAN; /* a state that is not finite has no energy (the direct sum would take seconds to say so) */
    else
        *e -= 0.5 * fo->mu * ((const tree_work *)fo->work)->pot;
}

static double tree_potential_error(const sw_particles *p, const sw_force *fo, const double *x)
{
    if (tree_exact(p))
        return 0;
    return tree_energy(p, fo, x) == 0 ? 0.5 * fo->mu * ((const tree_work *)fo->work)->bound : NAN;
}

/* The direct sum's pairs and blocks: the Jacobian an implicit step uses
 * is exact softened gravity's. */
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
    .potential_error = tree_potential_error,
    .term = "mutual gravity potential",
    .term_formula = "- G m_i m_j/√(r² + ε²)",
    .pairs = tree_pairs,
    .blocks = tree_blocks,
    .work_new = tree_work_new,
};
