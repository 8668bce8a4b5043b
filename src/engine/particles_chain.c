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

#include <limits.h>
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

/* ---- the small chain's derivative (issue 41) ----------------------------
 * The generic passes' arithmetic (particles_deriv.c) on a chain of at most
 * SWP_LINE_BEADS beads, fused into one function: the differences in
 * registers, the forces into one small array on the stack, in whole
 * vectors of two springs (a pair) or two beads. Spring
 * slot s is spring s - 1 for 0 < s < n (bead s minus bead s - 1), slot 0
 * the left anchor's, slot n the right anchor's, so that bead i's springs
 * are slots i and i + 1. A spring's force is block_forces' operations in
 * the same order, four springs (two pairs) a vector: it does not depend
 * on the slot. Bead i's sum is the generic last pass's (0 + F_i) - F_{i+1}
 * (its signs: the chain's layout fixes them; bead n - 1 adds its anchor's),
 * then gravity, drag and 1/m. The two terms of a sum commute exactly
 * unless one is NaN, and a NaN's bits may depend on which operand an
 * instruction takes first, which C does not fix: so where any
 * acceleration comes out NaN, as where a length² is below 1e-290 or NaN
 * (the generic passes' hypot), this returns 0 and the generic passes
 * evaluate instead. Otherwise the bits are the generic passes'
 * (tests/check_derivative.c). Vectors are loaded where they were stored
 * whole (the state at multiples of four, as the methods' loops write it;
 * the arrays here as written), and the derivative is written so, as the
 * methods' next loops read it: a load across two stores waits for both. */
typedef long long v4di __attribute__((vector_size(4 * sizeof(long long))));
enum { LINE_PAIRS = 2 * (((SWP_LINE_BEADS + 2) / 2 + 1) / 2) }; /* pairs, whole vectors of two */

#define LOAD4(r, q) memcpy(&(r), (q), sizeof(r))
#define STORE4(q, ...) do { v4d s_ = (__VA_ARGS__); memcpy((q), &s_, sizeof s_); } while (0)
/* (a.hi, b.lo): the two springs or beads across two whole vectors */
#define ACROSS(a, b) __builtin_shufflevector((a), (b), 2, 3, 4, 5)

/* The forces of two pairs of springs from their differences d (and dv),
 * (x, y) per spring, into f; ORs into *flag where a length² is not
 * >= 1e-290: block_forces' arithmetic, lane by lane. */
SW_INLINE void line_forces(const v4d *d, const v4d *dv, double *f, double k, double c, double rest, v4di *flag,
                           int damped)
{
    v4d d0 = d[0], d1 = d[1];
    /* lanes: springs 0, 2, 1, 3 of the four */
    v4d dx = __builtin_shufflevector(d0, d1, 0, 4, 2, 6), dy = __builtin_shufflevector(d0, d1, 1, 5, 3, 7);
    v4d l2 = dx * dx + dy * dy, l, one = { 1.0, 1.0, 1.0, 1.0 }, tiny = one * 1e-290;
    for (int t = 0; t < 4; t++)
        l[t] = sqrt(l2[t]);
    v4di zero_l = l == 0.0; /* q = l == 0 ? 1 : l: l + (l == 0)'s value (l is never -0), one step less */
    v4d q = (v4d)((zero_l & (v4di)one) | (~zero_l & (v4di)l));
    v4d ux = dx / q, uy = dy / q;
    v4d mag = k * (l - rest);
    if (damped) {
        v4d dv0 = dv[0], dv1 = dv[1];
        v4d dvx = __builtin_shufflevector(dv0, dv1, 0, 4, 2, 6),
            dvy = __builtin_shufflevector(dv0, dv1, 1, 5, 3, 7);
        mag += c * (dvx * ux + dvy * uy);
    }
    v4d fx = -mag * ux, fy = -mag * uy;
    *flag |= ~(l2 >= tiny);
    STORE4(f, __builtin_shufflevector(fx, fy, 0, 4, 2, 6));
    STORE4(f + 4, __builtin_shufflevector(fx, fy, 1, 5, 3, 7));
}

/* Beads i and i + 1's accelerations into out from their slots' forces fl
 * (slots i, i + 1) and fr (i + 1, i + 2); last: bead i + 1 is bead n - 1.
 * ORs into *nan where one is NaN. */
SW_INLINE void line_beads(const sw_particles *p, const double *v, int i, const v4d *flp, const v4d *frp, int last,
                          double *out, v4di *nan, int gravity, int drag)
{
    v4d fl = *flp, fr = *frp; /* (by pointer: a vector argument's ABI differs without AVX) */
    const struct sw_particles_model *m = p->model;
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass;
    v4d zero = { 0.0, 0.0, 0.0, 0.0 }, g = { m->gx, m->gy, m->gx, m->gy };
    if (last) /* its anchor's force adds: - (-F) = + F exactly */
        fr = (v4d)((v4di)fr ^ (v4di){ 0, 0, LLONG_MIN, LLONG_MIN });
    v4d fi = (zero + fl) - fr;
    if (gravity)
        fi += (v4d){ mass[i], mass[i], mass[i + 1], mass[i + 1] } * g;
    if (drag) {
        v4d vi;
        LOAD4(vi, v + 2 * i);
        fi -= m->kdrag * vi;
    }
    fi *= (v4d){ inv[i], inv[i], inv[i + 1], inv[i + 1] };
    *nan |= fi != fi;
    memcpy(out, &fi, sizeof fi);
}

/* Slots 2q and 2q + 1's differences d (and dv): pair 0 holds the left
 * anchor's (x_0 - anchor; dv = v_0 - 0 = v_0) and spring 0's; a whole
 * pair two paired springs; the last one spring n - 2's when n is odd and
 * the right anchor's; past it, padding (lengths, never tiny). */
SW_INLINE void line_pair(const struct sw_particles_model *m, int n, const double *x, const double *v, int q,
                         v4d *d, v4d *dv, int damped)
{
    int n2 = 2 * n, L = m->npair, R = L + 1;
    v4d zero = { 0.0, 0.0, 0.0, 0.0 }, one = { 1.0, 1.0, 1.0, 1.0 }, a, b, va, vb;
    *dv = zero; /* (read only when damped) */
    if (q == 0) {
        LOAD4(a, x);
        *d = a - __builtin_shufflevector(a, (v4d){ m->ax[L], m->ay[L], 0.0, 0.0 }, 4, 5, 0, 1);
        LOAD4(va, v);
        *dv = va - __builtin_shufflevector(va, zero, 4, 5, 0, 1);
    } else if (2 * q + 1 <= n - 1) {
        LOAD4(a, x + 4 * q - 4);
        LOAD4(b, x + 4 * q);
        *d = b - ACROSS(a, b);
        if (damped) {
            LOAD4(va, v + 4 * q - 4);
            LOAD4(vb, v + 4 * q);
            *dv = vb - ACROSS(va, vb);
        }
    } else if (2 * q <= n) {
        v4d xl = { x[n2 - 2], x[n2 - 1], x[n2 - 2], x[n2 - 1] }, vl = { v[n2 - 2], v[n2 - 1], v[n2 - 2], v[n2 - 1] };
        v4d anchor = { m->ax[R], m->ay[R], m->ax[R], m->ay[R] };
        if (n & 1) {
            *d = xl - __builtin_shufflevector((v4d){ x[n2 - 4], x[n2 - 3], 0.0, 0.0 }, anchor, 0, 1, 6, 7);
            *dv = vl - (v4d){ v[n2 - 4], v[n2 - 3], 0.0, 0.0 };
        } else {
            *d = __builtin_shufflevector(xl - anchor, one, 0, 1, 4, 5);
            *dv = __builtin_shufflevector(vl, zero, 0, 1, 4, 5);
        }
    } else {
        *d = one;
        *dv = zero;
    }
}

SW_INLINE int line_eval(const sw_particles *p, const double *restrict y, double *restrict dydt, int gravity,
                        int drag, int damped)
{
    const struct sw_particles_model *m = p->model;
    int n = p->n, n2 = 2 * n, pairs = (n + 2) / 2;
    const double *x = y, *v = y + n2;
    double *a = dydt + n2;
    _Alignas(32) double f[4 * LINE_PAIRS];
    /* the forces, two pairs a vector, from differences in registers */
    v4di flag = { 0, 0, 0, 0 };
    for (int k = 0; k < pairs; k += 2) {
        v4d d[2], dv[2];
        line_pair(m, n, x, v, k, &d[0], &dv[0], damped);
        line_pair(m, n, x, v, k + 1, &d[1], &dv[1], damped);
        line_forces(d, dv, f + 4 * k, m->k0, m->c0, m->rest0, &flag, damped);
    }
    if (flag[0] | flag[1] | flag[2] | flag[3])
        return 0;
    /* dx/dt = v, whole vectors; then the beads two a vector, placed so that
     * their vector is a whole one of dydt (bead 0 alone when n is odd) */
    v4d lo, hi;
    int u = 0;
    for (; u + 4 <= n2; u += 4) {
        LOAD4(lo, v + u);
        memcpy(dydt + u, &lo, sizeof lo);
    }
    if (u < n2)
        store2(dydt + u, load2(v + u));
    v4di nan = { 0, 0, 0, 0 };
    if (n & 1) {
        _Alignas(32) double b0[4]; /* lanes 2, 3: bead 1 (unused); bead 0 alone, its lanes 0, 1 */
        LOAD4(lo, f);
        LOAD4(hi, f + 4);
        v4d first = ACROSS(lo, hi);
        line_beads(p, v, 0, &lo, &first, 0, b0, &nan, gravity, drag);
        store2(a, load2(b0));
        for (int i = 1; i < n; i += 2) {
            LOAD4(lo, f + 2 * i - 2);
            LOAD4(hi, f + 2 * i + 2);
            v4d across = ACROSS(lo, hi);
            line_beads(p, v, i, &across, &hi, i + 2 == n, a + 2 * i, &nan, gravity, drag);
        }
    } else {
        for (int i = 0; i < n; i += 2) {
            LOAD4(lo, f + 2 * i);
            LOAD4(hi, f + 2 * i + 4);
            v4d across = ACROSS(lo, hi);
            line_beads(p, v, i, &lo, &across, i + 2 == n, a + 2 * i, &nan, gravity, drag);
        }
    }
    return !(nan[0] | nan[1] | nan[2] | nan[3]);
}

/* One function per combination: gravity (G), drag (K), damped (D). */
#define LINE(G, K, D)                                                                                   \
    SW_CLONES SW_ONE_PASS static int line_##G##K##D(const sw_particles *p, const double *y, double *dydt) \
    {                                                                                                   \
        return line_eval(p, y, dydt, G, K, D);                                                          \
    }
LINE(0, 0, 0) LINE(0, 0, 1) LINE(0, 1, 0) LINE(0, 1, 1) LINE(1, 0, 0) LINE(1, 0, 1) LINE(1, 1, 0) LINE(1, 1, 1)
static swp_line_fn *const line_table[8] = { line_000, line_001, line_010, line_011,
                                            line_100, line_101, line_110, line_111 };

swp_line_fn *swp_line_pick(const sw_particles *p)
{
    const struct sw_particles_model *m = p->model;
    if (m->small || m->nextra > 0 || !m->uniform || p->n > SWP_LINE_BEADS || !swp_chain_layout(m, p->n))
        return NULL;
    return line_table[m->gravity * 4 + m->drag * 2 + m->damped];
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
