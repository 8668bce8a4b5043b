/* The chain's rk4, fused (issue 41): beads in a line, each joined to the
 * next by a spring, the two ends to fixed anchors (the chain scene), stepped
 * tile by tile with every stage of a tile in a tile-local workspace, so the
 * step reads and writes the state once and keeps no state-long vector: no
 * stage state, no running sum, no derivative, no spring forces. Bead i's
 * stage s needs stage s's state at i - 1 .. i + 1, so a tile of beads
 * [lo, hi) computes stage s on [lo - (4 - s), hi + (4 - s)) from the old
 * state on [lo - 4, hi + 4) (the halo's few beads are computed twice, by
 * both tiles: the same numbers). Every bead's derivative is the generic
 * one's arithmetic (particles_deriv.c: spring forces through the same
 * block_forces, the sum (0 + ±F) ± F, gravity, drag, / m) and the stages
 * are rk4_range's (explicit.c: acc = k1, acc += 2k, y + h/6·(acc + k4)),
 * so the bits are the generic step's (tests/check_memory.c). */
#include "engine/particles_chain.h"

#include <string.h>

#include "engine/particles_model.h"
#include "engine/particles_spring_force.h"
#include "engine/stepper.h"

enum {
    TILE = 128,              /* beads a tile writes */
    HALO = 4,                /* beads read on each side: one per stage */
    SPAN = TILE + 2 * HALO,  /* beads a tile holds */
    PAD = 8,                 /* block_forces writes whole vectors of 4 springs */
};

/* The workspace, in doubles: old state and stage state (x and v each),
 * the running sum (x and v), the accelerations of a stage, the paired springs' forces (slot j at 2(j - s0
 * + 1)), the anchors' forces, and block_forces' differences and squares. */
enum {
    W_YX = 0, W_YV = W_YX + 2 * SPAN, W_TX = W_YV + 2 * SPAN, W_TV = W_TX + 2 * SPAN,
    W_QX = W_TV + 2 * SPAN, W_QV = W_QX + 2 * SPAN, W_KV = W_QV + 2 * SPAN, W_F = W_KV + 2 * SPAN,
    W_FL = W_F + 2 * (SPAN + 1) + PAD, W_FR = W_FL + PAD, W_D = W_FR + PAD,
    W_DV = W_D + 2 * BLOCK + PAD, W_L2 = W_DV + 2 * BLOCK + PAD, W_AD = W_L2 + BLOCK + PAD,
    W_ADV = W_AD + PAD, W_AL2 = W_ADV + PAD, W_SIZE = W_AL2 + PAD
};

size_t swp_chain_work_size(void) { return W_SIZE; }

int swp_chain_layout(const struct sw_particles_model *m, int n)
{
    int an = m->npair;
    return n >= 2 && m->stride && m->a0 == 2 && m->b0 == 0 && m->npair == n - 1 && m->nanchor == 2 &&
           m->a[an] == 0 && m->a[an + 1] == 2 * (n - 1);
}

int swp_chain_shaped(const sw_particles *p)
{
    const struct sw_particles_model *m = p->model;
    return !m->small && m->nextra == 0 && m->uniform && m->tile && swp_chain_layout(m, p->n);
}

#ifndef SW_FIELD_ONLY /* a plugin's host keeps no method, fused or not */

/* The tile being stepped: its span's first bead s0, and its arrays. */
typedef struct tile {
    const sw_particles *p;
    const struct sw_particles_model *m;
    double *w;
    int n, s0;
} tile;

/* Forces of the paired springs [j0, j1) (spring j joins beads j + 1 and j)
 * from the stage state cx, cv (local), into the tile's force row. */
SW_INLINE void tile_springs(const tile *tl, const double *cx, const double *cv, int j0, int j1, int damped)
{
    double *d = tl->w + W_D, *dv = tl->w + W_DV, *len2 = tl->w + W_L2;
    const double *k = tl->m->shared, *c = k + BLOCK, *rest = k + 2 * BLOCK;
    for (int lo = j0; lo < j1; lo += BLOCK) {
        int len = (j1 - lo < BLOCK ? j1 - lo : BLOCK), b = 2 * (lo - tl->s0);
        for (int t = 0; t < 2 * len; t++)
            d[t] = cx[b + 2 + t] - cx[b + t];
        for (int t = 0; damped && t < 2 * len; t++)
            dv[t] = cv[b + 2 + t] - cv[b + t];
        block_forces(len, k, c, rest, d, dv, tl->w + W_F + b + 2, len2, damped);
    }
}

/* The force of the anchored spring slot j on bead i (local li), into out. */
SW_INLINE void tile_anchor(const tile *tl, const double *cx, const double *cv, int j, int li, double *out,
                           int damped)
{
    const struct sw_particles_model *m = tl->m;
    double *d = tl->w + W_AD, *dv = tl->w + W_ADV;
    d[0] = cx[2 * li] - m->ax[j];
    d[1] = cx[2 * li + 1] - m->ay[j];
    dv[0] = cv[2 * li];
    dv[1] = cv[2 * li + 1];
    block_forces(1, m->shared, m->shared + BLOCK, m->shared + 2 * BLOCK, d, dv, out, tl->w + W_AL2, damped);
}

/* Bead i's acceleration from its two springs' forces fa, fb (signs sa,
 * sb, in the compiled order) at the stage velocity cv: last_range's sum
 * from +0, gravity, drag and 1/m (particles_deriv.c), the same bits. */
SW_INLINE v2d bead_accel(const sw_particles *p, const struct sw_particles_model *m, int i, v2d vi, double sa, v2d fa,
                         double sb, v2d fb, int gravity, int drag)
{
    v2d fi = { 0.0, 0.0 }, g = { m->gx, m->gy };
    fi = (fi + sa * fa) + sb * fb;
    if (gravity)
        fi += p->mass[i] * g;
    if (drag)
        fi -= m->kdrag * vi;
    return fi * p->inv_mass[i];
}

/* The stage update of components [c0, c1) of one half of the state from
 * their k: s = 1: acc = k, next = y + h/2·k; s = 2: acc += 2k, next = y +
 * h/2·k; s = 3: acc += 2k, next = y + h·k; s = 4: out = y + h/6·(acc + k),
 * OR-ing out's runaway bits (rk4_range's arithmetic, explicit.c). next may
 * be k itself (each component is read before it is written). */
SW_INLINE unsigned long long stage_update(int s, int c0, int c1, double h, const double *restrict y0, double *restrict q,
                                          const double *k, double *next, double *restrict out,
                                          unsigned long long add)
{
    double a = s == 3 ? h : 0.5 * h, b = h / 6.0;
    unsigned long long over = 0;
    for (int c = c0; c < c1; c++) {
        double kc = k[c];
        if (s == 1)
            q[c] = kc;
        else if (s < 4)
            q[c] += 2.0 * kc;
        if (s < 4) {
            next[c] = y0[c] + a * kc;
        } else {
            out[c - c0] = y0[c] + b * (q[c] + kc);
            over |= sw_beyond_bits(out[c - c0], add);
        }
    }
    return over;
}

/* Stage s (1..4) of beads [r0, r1) from the stage state (cx, cv) and the
 * springs' forces already computed: the accelerations into the tile's kv
 * row (then the resting contact's hold, as swp_deriv applies it), then
 * the positions' update (k = cv, read before the stage state is
 * overwritten) and the velocities' (k = kv); stage 4 writes the state yg. */
SW_INLINE unsigned long long tile_beads(const tile *tl, const double *cx, const double *cv, int s, int r0, int r1,
                                        double h, double *yg, unsigned long long add, int gravity, int drag)
{
    const sw_particles *p = tl->p;
    const struct sw_particles_model *m = tl->m;
    const double *f = tl->w + W_F;
    double *kv = tl->w + W_KV;
    int n = tl->n, s0 = tl->s0, i0 = r0 > 1 ? r0 : 1, i1 = r1 < n - 1 ? r1 : n - 1;
    /* bead i's springs: i - 1 (its end a, +) and i (end b, -); spring j's
     * force at f + 2(j - s0 + 1); bead 0: spring 0 (b, -) then its anchor
     * (+); bead n - 1: spring n - 2 (a, +) then its anchor (+) */
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass;
    v4d g = { m->gx, m->gy, m->gx, m->gy }, zero = { 0.0, 0.0, 0.0, 0.0 }, plus = zero + 1.0, minus = zero - 1.0;
    int i = i0;
    for (; i + 2 <= i1; i += 2) { /* two beads at a time: each lane bead_accel's operations */
        int li = i - s0;
        v4d vi, fa, fb;
        memcpy(&vi, cv + 2 * li, sizeof vi);
        memcpy(&fa, f + 2 * li, sizeof fa);
        memcpy(&fb, f + 2 * li + 2, sizeof fb);
        v4d fi = (zero + plus * fa) + minus * fb;
        if (gravity)
            fi += (v4d){ mass[i], mass[i], mass[i + 1], mass[i + 1] } * g;
        if (drag)
            fi -= m->kdrag * vi;
        fi *= (v4d){ inv[i], inv[i], inv[i + 1], inv[i + 1] };
        memcpy(kv + 2 * li, &fi, sizeof fi);
    }
    for (; i < i1; i++) {
        int li = i - s0;
        v2d a = bead_accel(p, m, i, load2(cv + 2 * li), 1.0, load2(f + 2 * li), -1.0, load2(f + 2 * li + 2),
                           gravity, drag);
        store2(kv + 2 * li, a);
    }
    if (r0 == 0)
        store2(kv - 2 * s0, bead_accel(p, m, 0, load2(cv - 2 * s0), -1.0, load2(f + 2 - 2 * s0), 1.0,
                                       load2(tl->w + W_FL), gravity, drag));
    if (r1 == n)
        store2(kv + 2 * (n - 1 - s0), bead_accel(p, m, n - 1, load2(cv + 2 * (n - 1 - s0)), 1.0,
                                                 load2(f + 2 * (n - 1 - s0)), 1.0, load2(tl->w + W_FR), gravity,
                                                 drag));
    if (p->walls.rest > 0 && (p->walls.sides & SW_WALL_FLOOR))
        for (int li = r0 - s0; li < r1 - s0; li++)
            if (cx[2 * li + 1] == p->walls.ymin && cv[2 * li + 1] == 0 && kv[2 * li + 1] < 0)
                kv[2 * li + 1] = 0;
    int c0 = 2 * (r0 - s0), c1 = 2 * (r1 - s0), n2 = 2 * n;
    double *tx = tl->w + W_TX, *tv = tl->w + W_TV;
    return stage_update(s, c0, c1, h, tl->w + W_YX, tl->w + W_QX, cv, tx, yg + 2 * r0, add) |
           stage_update(s, c0, c1, h, tl->w + W_YV, tl->w + W_QV, kv, tv, yg + n2 + 2 * r0, add);
}

/* One tile [lo, hi) of the step, its span's old state already in place. */
SW_INLINE unsigned long long tile_step(tile *tl, int lo, int hi, double h, double *y, unsigned long long add,
                                       int gravity, int drag, int damped)
{
    const struct sw_particles_model *m = tl->m;
    int n = tl->n;
    unsigned long long over = 0;
    for (int s = 1; s <= 4; s++) {
        const double *cx = tl->w + (s == 1 ? W_YX : W_TX), *cv = tl->w + (s == 1 ? W_YV : W_TV);
        int r0 = lo - (4 - s) > 0 ? lo - (4 - s) : 0, r1 = hi + (4 - s) < n ? hi + (4 - s) : n;
        tile_springs(tl, cx, cv, r0 > 0 ? r0 - 1 : 0, r1 < n - 1 ? r1 : n - 1, damped);
        if (r0 == 0)
            tile_anchor(tl, cx, cv, m->npair, 0 - tl->s0, tl->w + W_FL, damped);
        if (r1 == n)
            tile_anchor(tl, cx, cv, m->npair + 1, n - 1 - tl->s0, tl->w + W_FR, damped);
        if (s == 1) /* (a constant stage each: its update loop without branches) */
            over |= tile_beads(tl, cx, cv, 1, r0, r1, h, y, add, gravity, drag);
        else if (s == 2)
            over |= tile_beads(tl, cx, cv, 2, r0, r1, h, y, add, gravity, drag);
        else if (s == 3)
            over |= tile_beads(tl, cx, cv, 3, r0, r1, h, y, add, gravity, drag);
        else
            over |= tile_beads(tl, cx, cv, 4, r0, r1, h, y, add, gravity, drag);
    }
    return over;
}

/* The whole step, tile by tile: a tile's span takes the beads it shares
 * with the last tile's from that tile's copy (the state there is already
 * the new one), the rest from the state. */
SW_INLINE unsigned chain_step(const sw_particles *p, double *y, double h, unsigned elim, int gravity, int drag,
                              int damped)
{
    tile tl = { .p = p, .m = p->model, .w = p->model->tile, .n = p->n, .s0 = 0 };
    int n = p->n, n2 = 2 * n;
    double *yx = tl.w + W_YX, *yv = tl.w + W_YV;
    unsigned long long over = 0, add = sw_beyond_add(elim);
    for (int lo = 0; lo < n; lo += TILE) {
        int hi = lo + TILE < n ? lo + TILE : n, s0 = lo - HALO > 0 ? lo - HALO : 0;
        int s1 = hi + HALO < n ? hi + HALO : n, kept = lo - s0;
        memmove(yx, yx + 2 * (s0 - tl.s0), 2 * (size_t)kept * sizeof *yx);
        memmove(yv, yv + 2 * (s0 - tl.s0), 2 * (size_t)kept * sizeof *yv);
        memcpy(yx + 2 * kept, y + 2 * lo, 2 * (size_t)(s1 - lo) * sizeof *yx);
        memcpy(yv + 2 * kept, y + n2 + 2 * lo, 2 * (size_t)(s1 - lo) * sizeof *yv);
        tl.s0 = s0;
        /* ask for the next tile's state now, so that it arrives while this
         * one computes (a hint: no effect on the numbers) */
        for (int i = s1; i < s1 + TILE && i < n; i += 4) {
            __builtin_prefetch(y + 2 * i);
            __builtin_prefetch(y + n2 + 2 * i);
            __builtin_prefetch(p->inv_mass + i);
        }
        over |= tile_step(&tl, lo, hi, h, y, add, gravity, drag, damped);
    }
    return sw_beyond_any(over);
}

SW_CLONES unsigned swp_chain_rk4(void *ctx, double t, double *y, double h, unsigned elim)
{
    const sw_particles *p = ctx;
    const struct sw_particles_model *m = p->model;
    (void)t; /* the chain's forces do not depend on time */
    switch (m->gravity | m->drag << 1 | m->damped << 2) {
    case 0: return chain_step(p, y, h, elim, 0, 0, 0);
    case 1: return chain_step(p, y, h, elim, 1, 0, 0);
    case 2: return chain_step(p, y, h, elim, 0, 1, 0);
    case 3: return chain_step(p, y, h, elim, 1, 1, 0);
    case 4: return chain_step(p, y, h, elim, 0, 0, 1);
    case 5: return chain_step(p, y, h, elim, 1, 0, 1);
    case 6: return chain_step(p, y, h, elim, 0, 1, 1);
    default: return chain_step(p, y, h, elim, 1, 1, 1);
    }
}

#endif
