/* Implicit solves on particle systems. The force Jacobians are analytic and
 * complete, each from its force kind's descriptor (engine/forces.h):
 * springs (stiffness and the damping term, including how the damping
 * force turns with the spring), linear drag, central attraction, mutual
 * gravity.
 * (I - c·J) z = r reduces to the velocity system
 *     (M - c·Fv - c²·Fx) z_v = M·r_v + c·Fx·r_x,   z_x = r_x + c·z_v,
 * which is banded when particles are numbered along their springs (a chain
 * has bandwidth one particle). It is solved by banded LU with partial
 * pivoting: exact, and correct where a compressed spring makes the matrix
 * indefinite or damping makes it non-symmetric — there conjugate gradients,
 * Baraff and Witkin's choice, break down. On a chain (each particle joined
 * only to its neighbours) the same band is first factored by 2x2 blocks
 * (engine/linalg_block.h: no row leaves its particle, no structural zero
 * is touched), and by the band's LU only where the blocks refuse (a Schur
 * complement that grows: compressed or damped springs at large c·ω).
 * The system reads the forces only
 * through the particle accessors. Invariant: the solve allocates nothing;
 * the band is sized once by sw_particles_solver_prepare. */
#include "engine/particles_solve.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/clones.h"
#include "engine/forces.h"
#include "engine/lanes.h"
#include "engine/linalg.h"
#include "engine/linalg_block.h"
#include "stepwise/base.h"

/* The band's column length on a chain (kl = ku = 3: 2·kl + ku + 1). */
#define CHAIN_LD 10

/* Largest band accepted, in doubles (256 MiB). */
#define BAND_MAX ((size_t)1 << 25)

struct sw_particles_solver {
    double *diag;          /* 8 per particle: Fx (2x2) and Fv (2x2) of per-particle forces */
    /* own: some force may write diag (swp_force_type's pairs_only); while
     * it is 0 and diag_zero, every diag entry is +0, from the last
     * clearing, and the assembly need not clear it again */
    int own, diag_zero;
    int *pa, *pb;          /* the pairs the forces join (engine/forces.h's swp_blocks) */
    double *pblock;        /* 8 per pair: ∂g/∂d and ∂g/∂(dv), d = x_a - x_b */
    long npairs, cap;      /* pairs written by the last assembly; room for */
    int counted;           /* 1 + the forces there were when cap was last checked; 0: never */
    double *band;          /* the velocity system's band, or NULL before prepare */
    int *piv;
    int half_band;         /* in dof: 2·(largest particle distance along a spring) + 1 */
    /* The factorisation in band is of M - c·Fv - c²·Fx at y_at and c_at
     * with the blocks above, while `factored`: a solve at the same y and c
     * reuses it (simplified Newton, Rosenbrock stages). Anything that writes
     * the blocks or the band clears it. y_at (4n) comes with the band, from
     * prepare: systems stepped explicitly carry none of it. */
    double *y_at, c_at;
    int factored, keyed;
    sw_band lu;            /* the band's shape and factors, while factored */
    /* On a chain's band (half_band 3: particles joined only to their
     * neighbours) the block Thomas factors (engine/linalg_block.h), 8 a
     * particle, and whether the factorisation kept is theirs (blocked) or
     * the band's own (where they refused). */
    double *block;
    int blocked;
    /* chain: the pairs are chain_ordered's (with lead and flip), checked
     * at the factorisation; generic: never the chain's own passes nor the
     * zero own blocks' shortcut (tests compare them with the generic ones) */
    int chain, lead, flip, generic;
    long fused;            /* factorisations the fused path kept */
};

int sw_particles_solver_init(sw_particles *p)
{
    p->solver = calloc(1, sizeof *p->solver);
    if (!p->solver)
        return SW_ENOMEM;
    p->solver->diag = calloc((size_t)8 * p->n, sizeof *p->solver->diag);
    p->solver->diag_zero = 1;
    return p->solver->diag ? SW_OK : SW_ENOMEM;
}

/* The pairs the forces join, and the widest distance among them. */
static long count_pairs(const sw_particles *p, int *far)
{
    long total = 0;
    *far = 0;
    for (int k = 0; k < p->nforces; k++) {
        int reach;
        total += swp_force_type_of(p->forces[k].kind)->pairs(p, &p->forces[k], &reach);
        *far = reach > *far ? reach : *far;
    }
    return total;
}

/* Room for every pair's blocks: counts them only when forces were added
 * since the last call (a force's pairs are fixed once it is added), and
 * allocates only when they grew (sw_particles_solver_prepare makes the
 * first, before any step). 0 or SW_ENOMEM. */
static int reserve_pairs(sw_particles *p)
{
    struct sw_particles_solver *s = p->solver;
    if (s->counted == p->nforces + 1)
        return SW_OK;
    int far;
    long need = count_pairs(p, &far);
    if (need > SW_PARTICLES_PAIRS_MAX) /* 72 bytes each: 600 MB at most (two galaxies of 2000 fit) */
        return SW_ENOMEM;
    if (need <= s->cap) {
        s->counted = p->nforces + 1;
        return SW_OK;
    }
    int *pa = realloc(s->pa, (size_t)need * sizeof *pa);
    if (pa)
        s->pa = pa;
    int *pb = pa ? realloc(s->pb, (size_t)need * sizeof *pb) : NULL;
    if (pb)
        s->pb = pb;
    double *blk = pb ? realloc(s->pblock, (size_t)need * 8 * sizeof *blk) : NULL;
    if (!blk)
        return SW_ENOMEM;
    s->pblock = blk;
    s->cap = need;
    s->counted = p->nforces + 1;
    return SW_OK;
}

void sw_particles_solver_free(sw_particles *p)
{
    if (p->solver) {
        free(p->solver->diag);
        free(p->solver->pa);
        free(p->solver->pb);
        free(p->solver->pblock);
        free(p->solver->y_at);
        free(p->solver->band);
        free(p->solver->piv);
        free(p->solver->block);
        free(p->solver);
    }
    p->solver = NULL;
}

int sw_particles_solver_prepare(void *ctx, char *err, size_t errlen)
{
    sw_particles *p = ctx;
    struct sw_particles_solver *s = p->solver;
    int far;
    s->factored = 0;
    long pairs = count_pairs(p, &far);
    if (pairs > SW_PARTICLES_PAIRS_MAX) {
        snprintf(err, errlen, "the implicit solve needs the forces' Jacobian, and here they join %.2g pairs, more "
                 "than the %.2g it may hold", (double)pairs, (double)SW_PARTICLES_PAIRS_MAX);
        return SW_EINVAL;
    }
    if (reserve_pairs(p) != SW_OK) {
        snprintf(err, errlen, "out of memory for the implicit solve's force blocks");
        return SW_ENOMEM;
    }
    int kb = 2 * far + 1, n2 = 2 * p->n;
    size_t len = sw_band_doubles(n2, kb, kb);
    if (len > BAND_MAX) {
        snprintf(err, errlen, "the implicit solve needs the forces to join particles with nearby "
                 "numbers; here they span %d particles, a band of %zu MiB", far,
                 len * sizeof(double) >> 20);
        return SW_EINVAL;
    }
    if (!s->y_at && !(s->y_at = malloc((size_t)4 * p->n * sizeof *s->y_at))) {
        snprintf(err, errlen, "out of memory for the implicit solve (%d particles)", p->n);
        return SW_ENOMEM;
    }
    if (kb == 3 && !s->block && !(s->block = malloc(SW_BLOCK_DOUBLES(p->n) * sizeof *s->block))) {
        snprintf(err, errlen, "out of memory for the implicit solve (%d particles)", p->n);
        return SW_ENOMEM;
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

/* Fill the per-particle and pair blocks at state y, force by force.
 * 0, or SW_ENOMEM when the forces grew and there is no room for them. */
static int assemble(sw_particles *p, const double *y)
{
    struct sw_particles_solver *s = p->solver;
    s->factored = 0;
    if (reserve_pairs(p) != SW_OK)
        return SW_ENOMEM;
    s->own = 0;
    for (int k = 0; k < p->nforces; k++)
        s->own |= !swp_force_type_of(p->forces[k].kind)->pairs_only;
    /* eight doubles a particle, cleared a particle at a time (stores, not
     * one long memset: callgrind counts each byte of a long one), unless
     * no force writes them and they are +0 already */
    if (s->own || !s->diag_zero)
        for (int i = 0; i < p->n; i++)
            memset(s->diag + 8 * i, 0, 8 * sizeof *s->diag);
    s->diag_zero = !s->own;
    swp_blocks out = { s->diag, s->pa, s->pb, s->pblock, 0 };
    for (int k = 0; k < p->nforces; k++)
        swp_force_type_of(p->forces[k].kind)->blocks(p, &p->forces[k], y, y + 2 * p->n, &out);
    s->npairs = out.n;
    return SW_OK;
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
    for (long j = 0; j < s->npairs; j++) {
        const double *kx = s->pblock + 8 * j, *kv = kx + 4;
        /* f_a = g(d, dv), f_b = -g: ±K on the four blocks of (a, b). */
        int ends[2] = { s->pa[j], s->pb[j] };
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

/* The products a·Kx and b·Kv of a 2x2 block pair, by columns: a0 is Kx's
 * first column (xx, yx) times a, a1 its second (xy, yy), b0 and b1 Kv's
 * times b; a factor that is 0 gives no product (with_a = a != 0, with_b =
 * b != 0). */
typedef struct block_cols { v2d a0, a1, b0, b1; } block_cols;

SW_INLINE block_cols block_products(double a, const double *kx, double b, const double *kv, int with_a, int with_b)
{
    block_cols p = { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } };
    if (with_a) {
        v2d c0 = { kx[0], kx[2] }, c1 = { kx[1], kx[3] };
        p.a0 = a * c0;
        p.a1 = a * c1;
    }
    if (with_b) {
        v2d c0 = { kv[0], kv[2] }, c1 = { kv[1], kv[3] };
        p.b0 = b * c0;
        p.b1 = b * c1;
    }
    return p;
}

/* The band += ±(a·Kx) ± (b·Kv) for the 2x2 blocks Kx, Kv at particle rows
 * pi, columns pj, written straight into the factorisation's storage
 * (LAPACK's layout, engine/linalg.h: entry (i, j) at top + i - j + j·ld,
 * so a block's column is two neighbouring doubles), given the products
 * (made once for the four blocks a pair touches) and the sign (1: add,
 * -1: subtract; x - p is x + (-a)·K bit for bit, since (-a)·K = -(a·K)
 * exactly); with own, the particle's own block, its mass m on the
 * diagonal first. A term whose factor is 0 is left out (it would add
 * nothing but could turn an infinite entry into NaN; with_a and with_b
 * constants where the caller fixes them). Each entry gets its terms in
 * the order the blocks come (a particle's own, then the pairs', Kx before
 * Kv), the order the solve has always added them in. */
SW_INLINE void band_blocks(double *top, int ld, int pi, int pj, int own, double m, int sign, const block_cols *p,
                           int with_a, int with_b)
{
    double *e = top + 2 * (pi - pj) + (size_t)2 * (size_t)pj * (size_t)ld; /* (r, c) at e + r - c + c·ld */
    double *e1 = e + ld - 1;                                                 /* column 1: (0, 1), (1, 1) */
    v2d c0, c1;
    memcpy(&c0, e, sizeof c0);
    memcpy(&c1, e1, sizeof c1);
    if (own) { /* a particle's own block, just cleared: its mass first (0 + m) */
        c0[0] = 0.0 + m;
        c1[1] = 0.0 + m;
    }
    if (with_a) {
        c0 = sign > 0 ? c0 + p->a0 : c0 - p->a0;
        c1 = sign > 0 ? c1 + p->a1 : c1 - p->a1;
    }
    if (with_b) {
        c0 = sign > 0 ? c0 + p->b0 : c0 - p->b0;
        c1 = sign > 0 ? c1 + p->b1 : c1 - p->b1;
    }
    memcpy(e, &c0, sizeof c0);
    memcpy(e1, &c1, sizeof c1);
}

/* out += sc·K·w for one block: the product Fx·r_x without forming Fx. */
static inline void apply_block(double *out, int pi, int pj, double sc, const double *blk, const double *w)
{
    double wx = w[2 * pj], wy = w[2 * pj + 1];
    out[2 * pi] += sc * (blk[0] * wx + blk[1] * wy);
    out[2 * pi + 1] += sc * (blk[2] * wx + blk[3] * wy);
}

/* A chain's particle's two band columns zeroed by ten 16-byte stores
 * (straight code: a loop here, or a memset of a known length, becomes
 * `rep stosq`, which callgrind counts a double at a time). */
SW_INLINE void clear_chain_columns(double *col)
{
    const v2d zero = { 0.0, 0.0 };
#define SW_CLEAR2(k) memcpy(col + 2 * (k), &zero, sizeof zero)
    SW_CLEAR2(0); SW_CLEAR2(1); SW_CLEAR2(2); SW_CLEAR2(3); SW_CLEAR2(4);
    SW_CLEAR2(5); SW_CLEAR2(6); SW_CLEAR2(7); SW_CLEAR2(8); SW_CLEAR2(9);
#undef SW_CLEAR2
}
_Static_assert(2 * CHAIN_LD == 20, "clear_chain_columns writes 20 doubles");

/* The velocity system's matrix A = M - c·Fv - c²·Fx from the blocks, into
 * the band (whose shape is set), with_a and with_b as in band_blocks. */
SW_INLINE void fill_velocity_system(const sw_particles *p, double a, double b, const sw_band *band, int with_a,
                                    int with_b, int own)
{
    const struct sw_particles_solver *s = p->solver;
    int ld = band->ld;
    double *top = band->a + band->kl + band->ku; /* the diagonal's row in column 0 */
    for (int i = 0; i < p->n; i++) {
        /* particle i's two columns cleared just before its own entries go
         * in (nothing before wrote there; the pairs come after): the band
         * is cleared column by column while it is in the cache, not in one
         * pass of its own; on a chain's band (ld = 10) by stores, not a
         * call a particle */
        double *col = band->a + (size_t)2 * i * (size_t)ld;
        if (ld == CHAIN_LD)
            clear_chain_columns(col);
        else
            memset(col, 0, (size_t)2 * (size_t)ld * sizeof *col);
        if (own) {
            block_cols pr = block_products(a, s->diag + 8 * i, b, s->diag + 8 * i + 4, with_a, with_b);
            band_blocks(top, ld, i, i, 1, p->mass[i], 1, &pr, with_a, with_b);
        } else { /* m·I: see factor_velocity_system */
            band_blocks(top, ld, i, i, 1, p->mass[i], 1, NULL, 0, 0);
        }
    }
    for (long j = 0; j < s->npairs; j++) {
        const double *kx = s->pblock + 8 * j, *kv = kx + 4;
        /* f_a = g(d, dv), f_b = -g: ±K on the four blocks of (a, b), each
         * product a·K, b·K' made once */
        int ea = s->pa[j], eb = s->pb[j];
        block_cols pr = block_products(a, kx, b, kv, with_a, with_b);
        if (ea >= 0)
            band_blocks(top, ld, ea, ea, 0, 0.0, 1, &pr, with_a, with_b);
        if (ea >= 0 && eb >= 0) {
            band_blocks(top, ld, ea, eb, 0, 0.0, -1, &pr, with_a, with_b);
            band_blocks(top, ld, eb, ea, 0, 0.0, -1, &pr, with_a, with_b);
        }
        if (eb >= 0)
            band_blocks(top, ld, eb, eb, 0, 0.0, 1, &pr, with_a, with_b);
    }
}

/* 1 when the pairs are a chain's in the order the band's fill meets
 * them: at most one anchored spring on particle 0 first, then (i, i + 1)
 * for i = 0, 1, ..., n - 2 (either end first), then at most one anchored
 * spring on particle n - 1; *lead = 1 with the first, *flip = 1 where
 * every (i, i + 1) spring has i + 1 first, 0 where every one has i (not
 * a chain's otherwise). Each particle's own block then gets its terms as
 * fill_velocity_system adds them: its mass, the left spring's, the right
 * spring's. */
static int chain_ordered(const struct sw_particles_solver *s, int n, int *lead, int *flip)
{
    long j = 0, np = s->npairs;
    const int *pa = s->pa, *pb = s->pb;
#define SW_ANCHOR(j, k) (j < np && ((pa[j] == k && pb[j] < 0) || (pa[j] < 0 && pb[j] == k)))
    *lead = SW_ANCHOR(0, 0);
    j = *lead;
    *flip = n > 1 && j < np && pa[j] == 1;
    if (np - j < n - 1)
        return 0;
    for (int i = 0; i + 1 < n; i++, j++)
        if (pa[j] != i + *flip || pb[j] != i + 1 - *flip)
            return 0;
    j += SW_ANCHOR(j, n - 1);
#undef SW_ANCHOR
    return n >= 1 && j == np;
}

/* d += the products of a pair, column by column, a's before b's (the
 * order band_blocks adds them in). */
SW_INLINE void add_products(v2d *d0, v2d *d1, const block_cols *p)
{
    *d0 = *d0 + p->a0;
    *d1 = *d1 + p->a1;
    *d0 = *d0 + p->b0;
    *d1 = *d1 + p->b1;
}

/* A chain's velocity system (chain_ordered, no own blocks, a and b
 * finite and nonzero) filled and factored by blocks in one pass along the
 * chain: each particle's diagonal block made in registers (0 + m on its
 * diagonal, +0 beside, then the springs' products in fill_velocity_system's
 * order), its upper neighbour (i, i + 1), the only entry of that spring's
 * off-diagonal blocks, as (+0 - a·Kx) - b·Kv, which is also the lower
 * block of the row below, and each row factored by sw_block_row as
 * sw_block_factor factors it from the band: the same bits. Only the upper
 * blocks go into the band (the block solve reads them). 0, or -1 where the
 * blocks refuse (then the band holds nothing whole). */
static SW_CLONES int factor_chain(sw_particles *p, double a, double b, const sw_band *band, int lead)
{
    const struct sw_particles_solver *s = p->solver;
    const double *blk = s->pblock;
    double *e = band->a + band->kl + band->ku, *f = s->block; /* row 0's diagonal block and factors */
    const v2d zero = { 0.0, 0.0 };
    v2d l0 = zero, l1 = zero; /* the block left of the row's diagonal (row > 0) */
    block_cols left = { zero, zero, zero, zero };
    const double *mass = p->mass;
    int n = p->n, bad = 0;
    if (lead) {
        left = block_products(a, blk, b, blk + 4, 1, 1);
        blk += 8;
    }
    for (int i = 0; i < n; i++, e += 2 * CHAIN_LD, f += SW_BLOCK_PER) {
        v2d d0 = { 0.0 + mass[i], 0.0 }, d1 = { 0.0, 0.0 + mass[i] };
        if (lead || i > 0)
            add_products(&d0, &d1, &left);
        if (i + 1 < n || blk < s->pblock + 8 * s->npairs) { /* the right spring, or the last anchor */
            left = block_products(a, blk, b, blk + 4, 1, 1);
            blk += 8;
            add_products(&d0, &d1, &left);
        }
        bad |= sw_block_row(f, i > 0 ? f - SW_BLOCK_PER : NULL, d0, d1, l0, l1, l0, l1);
        if (i + 1 < n) {
            l0 = (zero - left.a0) - left.b0;
            l1 = (zero - left.a1) - left.b1;
            store2(e + 2 * CHAIN_LD - 2, l0);
            store2(e + 3 * CHAIN_LD - 3, l1);
        }
    }
    return bad ? -1 : 0;
}

/* A = M - c·Fv - c²·Fx into the band, and its factors: a chain's by
 * blocks where they are safe, else the band's with row interchanges. 0,
 * or -1 when A is singular. a = -c² and b = -c are both nonzero but where
 * c is 0 or c² underflows: that case gets its own copy of the loops. */
static int factor_velocity_system(sw_particles *p, double c, sw_band *band)
{
    struct sw_particles_solver *s = p->solver;
    double a = -c * c, b = -c;
    sw_band_shape(band, 2 * p->n, s->half_band, s->half_band, s->band, s->piv);
    /* Where no force writes a particle's own blocks they are +0, and with
     * a, b finite a·(+0) and b·(+0) are zeros: m + (±0) = m (m > 0) and
     * +0 + (±0) = +0, so the own block is m·I, the same bits, without
     * its products and sums. */
    int own = s->own || !isfinite(a) || !isfinite(b);
    s->chain = s->half_band == 3 && !s->generic && chain_ordered(s, p->n, &s->lead, &s->flip);
    if (a != 0 && b != 0 && !own && s->chain) {
        s->blocked = factor_chain(p, a, b, band, s->lead) == 0;
        if (s->blocked) {
            s->fused++;
            return 0;
        }
        fill_velocity_system(p, a, b, band, 1, 1, 0); /* the blocks refused, as they do from the band */
        return sw_band_factor(band);
    }
    if (a != 0 && b != 0 && own)
        fill_velocity_system(p, a, b, band, 1, 1, 1);
    else if (a != 0 && b != 0)
        fill_velocity_system(p, a, b, band, 1, 1, 0);
    else
        fill_velocity_system(p, a, b, band, a != 0, b != 0, own);
    s->blocked = s->half_band == 3 && sw_block_factor(band, s->block) == 0;
    return s->blocked ? 0 : sw_band_factor(band);
}

/* out = M·v (two components a particle); out may be v itself. */
static SW_CLONES void mass_times(int n, const double *mass, const double *v, double *out)
{
    for (int i = 0; i < n; i++) {
        out[2 * i] = mass[i] * v[2 * i];
        out[2 * i + 1] = mass[i] * v[2 * i + 1];
    }
}

/* out += c·K_i·w_i for each particle's own block K_i (the Fx half of its
 * eight doubles), w and out two components a particle, not aliased. */
static SW_CLONES void own_blocks_times(int n, const double *diag, double c, const double *restrict w,
                                       double *restrict out)
{
    for (int i = 0; i < n; i++) {
        const double *blk = diag + 8 * i;
        double wx = w[2 * i], wy = w[2 * i + 1];
        out[2 * i] += c * (blk[0] * wx + blk[1] * wy);
        out[2 * i + 1] += c * (blk[2] * wx + blk[3] * wy);
    }
}

/* out = M·v + c·K_i·w with each particle's own block K_i = 0 (no force
 * writes them: +0 each, the assembly's): mass_times then
 * own_blocks_times' operations, the zeros constants (0·w is no constant:
 * -0, NaN) and the product c·(0·w_x + 0·w_y), the same in both rows,
 * made once; one pass (out may be v: each read before written). */
static SW_CLONES void mass_times_zero_own(int n, const double *mass, const double *v, double c,
                                         const double *restrict w, double *out)
{
    for (int i = 0; i < n; i++) {
        double own = c * (0.0 * w[2 * i] + 0.0 * w[2 * i + 1]);
        out[2 * i] = mass[i] * v[2 * i] + own;
        out[2 * i + 1] = mass[i] * v[2 * i + 1] + own;
    }
}

/* z = r + c·v over n components (z may be r: each read before written). */
static SW_CLONES void add_scaled(int n, double *z, const double *r, double c, const double *v)
{
#pragma GCC unroll 2
    for (int i = 0; i < n; i++)
        z[i] = r[i] + c * v[i];
}

/* out += c·Fx·r_x for a pair (ea, eb, both particles) with Fx block kx:
 * the four blocks of apply_block, each product K·r_a, K·r_b made once
 * (the same operations, in the same order). */
SW_INLINE void pair_rhs(double *restrict out, const double *kx, int ea, int eb, double c, const double *r)
{
    double kax = kx[0] * r[2 * ea] + kx[1] * r[2 * ea + 1];
    double kay = kx[2] * r[2 * ea] + kx[3] * r[2 * ea + 1];
    double kbx = kx[0] * r[2 * eb] + kx[1] * r[2 * eb + 1];
    double kby = kx[2] * r[2 * eb] + kx[3] * r[2 * eb + 1];
    double ax = out[2 * ea] + c * kax, ay = out[2 * ea + 1] + c * kay;
    out[2 * ea] = ax + -c * kbx;
    out[2 * ea + 1] = ay + -c * kby;
    double bx = out[2 * eb] + -c * kax, by = out[2 * eb + 1] + -c * kay;
    out[2 * eb] = bx + c * kbx;
    out[2 * eb + 1] = by + c * kby;
}

/* The pairs' terms of velocity_rhs on a chain (chain_ordered, flip its
 * springs' first ends): the same terms in the same order, the ends known
 * from the chain's shape rather than read and tested a pair at a time. */
SW_INLINE void chain_pairs_rhs(const struct sw_particles_solver *s, int n, double c, const double *r,
                               double *restrict out, int flip)
{
    const double *kx = s->pblock;
    if (s->lead) {
        apply_block(out, 0, 0, c, kx, r);
        kx += 8;
    }
    for (int i = 0; i + 1 < n; i++, kx += 8)
        pair_rhs(out, kx, i + flip, i + 1 - flip, c, r);
    if (kx < s->pblock + 8 * s->npairs)
        apply_block(out, n - 1, n - 1, c, kx, r);
}

/* out = M r_v + c·Fx r_x, from the blocks (c = 0: M r_v alone), out 2n
 * long; r's velocity half is read only where out is written, so out may be
 * that half itself. Each entry gets its terms in the order it always had:
 * the mass, the particle's own block, then the pairs. (No AVX2 clone: gcc
 * vectorises its copy of the chain's loop two springs at a time, and each
 * 32-byte load then half overlaps the store before it, which the store
 * cannot forward: 49 fewer instructions a particle-step, 8% more time.) */
static void velocity_rhs(const sw_particles *p, double c, const double *r, double *out_v)
{
    const struct sw_particles_solver *s = p->solver;
    int n2 = 2 * p->n;
    if (c != 0 && !s->own && !s->generic) {
        mass_times_zero_own(p->n, p->mass, r + n2, c, r, out_v);
    } else {
        mass_times(p->n, p->mass, r + n2, out_v);
        if (c == 0)
            return;
        own_blocks_times(p->n, s->diag, c, r, out_v);
    }
    if (s->chain && !s->generic) {
        if (s->flip)
            chain_pairs_rhs(s, p->n, c, r, out_v, 1);
        else
            chain_pairs_rhs(s, p->n, c, r, out_v, 0);
        return;
    }
    double *restrict out = out_v; /* only r's position half is read below */
    for (long j = 0; j < s->npairs; j++) {
        const double *kx = s->pblock + 8 * j;
        int ea = s->pa[j], eb = s->pb[j];
        if (ea >= 0 && eb >= 0) {
            pair_rhs(out, kx, ea, eb, c, r);
            continue;
        }
        if (ea >= 0)
            apply_block(out, ea, ea, c, kx, r);
        if (eb >= 0)
            apply_block(out, eb, eb, c, kx, r);
    }
}

/* 1 when y differs from key in any bit (as memcmp: -0 is not +0, a NaN
 * equals its own bits), and key = y either way: the comparison and the
 * copy a new factorisation needs in one pass, not a pass of each. */
static SW_CLONES int key_moved(int len, double *restrict key, const double *restrict y)
{
    uint64_t diff = 0;
    for (int i = 0; i < len; i++) {
        uint64_t was, now;
        memcpy(&was, key + i, sizeof was);
        memcpy(&now, y + i, sizeof now);
        diff |= was ^ now;
        key[i] = y[i];
    }
    return diff != 0;
}

long sw_particles_solver_generic(sw_particles *p, int generic)
{
    p->solver->generic = generic;
    p->solver->factored = 0;
    return p->solver->fused;
}

void sw_particles_solver_touch(sw_particles *p)
{
    if (p->solver)
        p->solver->factored = 0;
}

/* What the caller says of y: nothing (ANY: compared with the key), that
 * it is the last solve's (SAME: the factors serve if c is theirs), or
 * that these factors will be asked for again only with SAME (NEW:
 * factored afresh, no key taken). */
enum { SOLVE_ANY, SOLVE_SAME, SOLVE_NEW };

static int particles_solve(sw_particles *p, const double *y, double c, const double *r, double *z, int mode)
{
    struct sw_particles_solver *s = p->solver;
    if (!s->band)
        return SW_EINVAL; /* not prepared: sw_stepper_init prepares implicit methods */
    int n2 = 2 * p->n;
    /* The factors serve for the same y (contents, not address) and c as
     * theirs, no force added since. The key is compared and taken in one
     * pass; it is y_at's while `keyed` (a NEW factorisation takes none). */
    int fits = s->factored && s->c_at == c && s->counted == p->nforces + 1, reuse;
    if (mode == SOLVE_SAME && fits) {
        reuse = 1;
    } else if (mode == SOLVE_NEW) {
        reuse = 0;
        s->keyed = 0;
    } else {
        reuse = !key_moved(2 * n2, s->y_at, y) && fits && s->keyed;
        s->keyed = 1;
    }
    if (!reuse) {
        if (assemble(p, y) != SW_OK)
            return SW_ENOMEM;
        if (factor_velocity_system(p, c, &s->lu) != 0)
            return SW_EDIVERGED;
        s->c_at = c;
        s->factored = 1;
    }
    /* the velocity system solved where its solution belongs, z's
     * velocity half (z may be r: r's positions are read, never written) */
    double *z_v = z + n2;
    velocity_rhs(p, c, r, z_v);
    if (s->blocked)
        sw_block_solve(&s->lu, s->block, z_v);
    else
        sw_band_solve(&s->lu, z_v);
    add_scaled(n2, z, r, c, z_v);
    p->ode.solver_iters++;
    return SW_OK;
}

int sw_particles_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t; /* the forces do not depend on time */
    return particles_solve(ctx, y, c, r, z, SOLVE_ANY);
}

int sw_particles_solve_same(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t;
    return particles_solve(ctx, y, c, r, z, SOLVE_SAME);
}

int sw_particles_solve_new(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t;
    return particles_solve(ctx, y, c, r, z, SOLVE_NEW);
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

int sw_particles_jacobian(sw_particles *p, const double *y, double *fx, double *fv)
{
    int n2 = 2 * p->n;
    if (assemble(p, y) != SW_OK)
        return SW_ENOMEM;
    memset(fx, 0, (size_t)n2 * n2 * sizeof *fx);
    memset(fv, 0, (size_t)n2 * n2 * sizeof *fv);
    dense_ctx cx = { fx, n2 }, cv = { fv, n2 };
    scatter(p, 1.0, 0.0, dense_sink, &cx);
    scatter(p, 0.0, 1.0, dense_sink, &cv);
    return SW_OK;
}

/* out += s·K·w for one block, as a sink for scatter. */
typedef struct apply_ctx { const double *w; double *out; } apply_ctx;

static void apply_sink(void *ctx, int pi, int pj, double s, const double *blk)
{
    apply_ctx *ac = ctx;
    if (s != 0)
        apply_block(ac->out, pi, pj, s, blk, ac->w);
}

int sw_particles_jacobian_apply(sw_particles *p, const double *y, double a, double b, const double *w,
                                double *out, int assemble_first)
{
    if (assemble_first && assemble(p, y) != SW_OK)
        return SW_ENOMEM;
    memset(out, 0, (size_t)2 * p->n * sizeof *out);
    apply_ctx ac = { w, out };
    scatter(p, a, b, apply_sink, &ac);
    return SW_OK;
}

const double *sw_particles_own_blocks(sw_particles *p, const double *y)
{
    return assemble(p, y) == SW_OK ? p->solver->diag : NULL;
}

double sw_particles_work(const sw_particles *p, double *solve)
{
    int far;
    double dim = 4.0 * p->n, per = (double)count_pairs(p, &far) / p->n, width = (2.0 * far + 1) / 3.0;
    *solve = dim * (width > 1 ? width * width : 1.0);
    return dim * (per > 1 ? per : 1.0);
}

long sw_particles_pair_count(const sw_particles *p)
{
    int far;
    return count_pairs(p, &far);
}

int sw_particles_coupled(const sw_particles *p)
{
    int far;
    return count_pairs(p, &far) > 0;
}
