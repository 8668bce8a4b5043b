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
 * the running sum (x and v), the paired springs' forces (slot j at 2(j - s0
 * + 1)), the anchors' forces, and block_forces' differences and squares. */
enum {
    W_YX = 0, W_YV = W_YX + 2 * SPAN, W_TX = W_YV + 2 * SPAN, W_TV = W_TX + 2 * SPAN,
    W_QX = W_TV + 2 * SPAN, W_QV = W_QX + 2 * SPAN, W_F = W_QV + 2 * SPAN,
    W_FL = W_F + 2 * (SPAN + 1) + PAD, W_FR = W_FL + PAD, W_D = W_FR + PAD,
    W_DV = W_D + 2 * BLOCK + PAD, W_L2 = W_DV + 2 * BLOCK + PAD, W_AD = W_L2 + BLOCK + PAD,
    W_ADV = W_AD + PAD, W_AL2 = W_ADV + PAD, W_SIZE = W_AL2 + PAD
};

size_t swp_chain_work_size(void) { return W_SIZE; }

int swp_chain_shaped(const sw_particles *p)
{
    const struct sw_particles_model *m = p->model;
    int n = p->n, an = m->npair;
    return !m->small && m->nextra == 0 && m->uniform && n >= 2 && m->stride && m->a0 == 2 && m->b0 == 0 &&
           m->npair == n - 1 && m->nanchor == 2 && m->a[an] == 0 && m->a[an + 1] == 2 * (n - 1) && m->tile;
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

/* Stage s (1..4) of beads [r0, r1): each bead's k = (v, a) from the stage
 * state (cx, cv) and the forces already computed, then the stage update:
 * s = 1: acc = k, next = y + h/2·k; s = 2: acc += 2k, next = y + h/2·k;
 * s = 3: acc += 2k, next = y + h·k; s = 4: y = y + h/6·(acc + k), into the
 * state (yg), OR-ing the runaway bits. next may be the stage state itself:
 * each bead reads its own before writing it, and no other bead reads it. */
SW_INLINE unsigned long long tile_beads(const tile *tl, const double *cx, const double *cv, int s, int r0, int r1,
                                        double h, double *yg, unsigned long long add, int gravity, int drag)
{
    const sw_particles *p = tl->p;
    const struct sw_particles_model *m = tl->m;
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass;
    const double *f = tl->w + W_F, *fl = tl->w + W_FL, *fr = tl->w + W_FR;
    const double *yx = tl->w + W_YX, *yv = tl->w + W_YV;
    double *tx = tl->w + W_TX, *tv = tl->w + W_TV, *qx = tl->w + W_QX, *qv = tl->w + W_QV;
    double gx = m->gx, gy = m->gy, kd = m->kdrag, a = s == 3 ? h : 0.5 * h, b = h / 6.0;
    int n = tl->n, n2 = 2 * n, hold = p->walls.rest > 0 && (p->walls.sides & SW_WALL_FLOOR);
    double floor = p->walls.ymin;
    unsigned long long over = 0;
    for (int i = r0; i < r1; i++) {
        int li = i - tl->s0, fi = 2 * (li + 1); /* spring i's force; spring i - 1's at fi - 2 */
        /* the bead's two springs in the compiled order, summed from +0 */
        const double *fa = i == 0 ? f + fi : f + fi - 2, *fb = i == 0 ? fl : i == n - 1 ? fr : f + fi;
        double sa = i == 0 ? -1.0 : 1.0, sb = i == 0 || i == n - 1 ? 1.0 : -1.0;
        double vx = cv[2 * li], vy = cv[2 * li + 1];
        double fx = (0.0 + sa * fa[0]) + sb * fb[0], fy = (0.0 + sa * fa[1]) + sb * fb[1];
        if (gravity)
            fx += mass[i] * gx, fy += mass[i] * gy;
        if (drag)
            fx -= kd * vx, fy -= kd * vy;
        double k[4] = { vx, vy, fx * inv[i], fy * inv[i] };
        if (hold && cx[2 * li + 1] == floor && vy == 0 && k[3] < 0) /* resting contact (swp_deriv) */
            k[3] = 0;
        double *q[4] = { qx + 2 * li, qx + 2 * li + 1, qv + 2 * li, qv + 2 * li + 1 };
        double *next[4] = { tx + 2 * li, tx + 2 * li + 1, tv + 2 * li, tv + 2 * li + 1 };
        const double *y0[4] = { yx + 2 * li, yx + 2 * li + 1, yv + 2 * li, yv + 2 * li + 1 };
        double *out[4] = { yg + 2 * i, yg + 2 * i + 1, yg + n2 + 2 * i, yg + n2 + 2 * i + 1 };
        for (int e = 0; e < 4; e++) {
            if (s == 1)
                *q[e] = k[e];
            else if (s < 4)
                *q[e] += 2.0 * k[e];
            if (s < 4) {
                *next[e] = *y0[e] + a * k[e];
            } else {
                *out[e] = *y0[e] + b * (*q[e] + k[e]);
                over |= sw_beyond_bits(*out[e], add);
            }
        }
    }
    return over;
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
        over |= tile_beads(tl, cx, cv, s, r0, r1, h, y, add, gravity, drag);
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
