/* Hand-fused baselines for the engine benchmark (compiled, like the engine's
 * hot loops, for AVX2 and for the baseline: engine/clones.h): euler and rk4 steps on the
 * vortex and the undamped chain written as one would by hand for that one
 * problem — no function pointers, no state-sized derivative vectors where a
 * register or a per-particle loop does, the forces of the chain's springs in
 * one vectorisable loop and each bead's sum, inverse mass and update in the
 * next. Each computes exactly the arithmetic of the generic step (the same
 * operations in the same order), so after the same steps the states agree
 * bit for bit; the benchmark checks that rather than assuming it. */
#include <math.h>
#include <string.h>

#include "bench_common.h"
#include "util/num.h"
#include "engine/clones.h"

/* The vortex's start as the scene seeds it (flow_scenes.c), written out
 * here so the baseline's memory holds its state alone: point i on ring
 * i mod rings, at angle 2π·j/per + 0.3·ring. */
void base_vortex_seed(double *y, int n)
{
    int rings = n < 8 ? n : (int)ceil(sqrt(n / 8.0));
    if (rings > 24)
        rings = 24;
    int per = (n + rings - 1) / rings;
    for (int i = 0; i < n; i++) {
        int k = i % rings, j = i / rings;
        double r = (k + 1.0) / rings, a = 2.0 * SW_PI * j / per + 0.3 * k;
        y[2 * i] = r * cos(a);
        y[2 * i + 1] = r * sin(a);
    }
}

/* vortex, x' = ω(-y, x), euler: one fused pass. */
SW_CLONES void base_vortex_euler(double *y, int n, double w, double h, long steps)
{
    for (long s = 0; s < steps; s++)
        for (int i = 0; i < n; i++) {
            double px = y[2 * i], py = y[2 * i + 1];
            y[2 * i] = px + h * (-w * py);
            y[2 * i + 1] = py + h * (w * px);
        }
}

/* vortex, rk4: every stage of one point in registers, one pass per step. */
SW_CLONES void base_vortex_rk4(double *y, int n, double w, double h, long steps)
{
    double a = 0.5 * h, b = h / 6.0;
    for (long s = 0; s < steps; s++)
        for (int i = 0; i < n; i++) {
            double px = y[2 * i], py = y[2 * i + 1];
            double k1x = -w * py, k1y = w * px;
            double tx = px + a * k1x, ty = py + a * k1y;
            double k2x = -w * ty, k2y = w * tx;
            tx = px + a * k2x;
            ty = py + a * k2y;
            double k3x = -w * ty, k3y = w * tx;
            tx = px + h * k3x;
            ty = py + h * k3y;
            double k4x = -w * ty, k4y = w * tx;
            y[2 * i] = px + b * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            y[2 * i + 1] = py + b * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
        }
}

/* The undamped chain as the scene builds it: spring j (0..n) joins bead
 * j - 1 (or the left anchor at the origin) and bead j (or, for j = n, the
 * right anchor at ((n + 1)·rest, 0)); its force on its right end is
 *   F_j = -k(|d| - rest) d/|d|,  d = x_j - x_{j-1},
 * 0 where |d| = 0. Bead i feels F_i - F_{i+1}, summed from +0 as the
 * generic loop does: (0 + F_i) - F_{i+1}. The last spring is stored with
 * d = x_{n-1} - anchor, so the last bead adds it: (0 + F_{n-1}) + F_n. */
static inline __attribute__((always_inline)) void spring_force(double dx, double dy, double k, double rest, double *fx, double *fy)
{
    double l = sqrt(dx * dx + dy * dy), d = l + (l == 0);
    double mag = k * (l - rest);
    *fx = -mag * (dx / d);
    *fy = -mag * (dy / d);
}

/* Inlined into each compiled copy of its callers (engine/clones.h). */
static inline __attribute__((always_inline)) void chain_forces(const bench_chain *ch, const double *restrict x)
{
    int n = ch->n;
    double *restrict fx = ch->f, *restrict fy = ch->f + (n + 1);
    double k = ch->k, rest = ch->rest;
    spring_force(x[0], x[1], k, rest, &fx[0], &fy[0]); /* x_0 - (0, 0) */
    for (int j = 1; j < n; j++)
        spring_force(x[2 * j] - x[2 * j - 2], x[2 * j + 1] - x[2 * j - 1], k, rest, &fx[j], &fy[j]);
    spring_force(x[2 * n - 2] - ch->right_x, x[2 * n - 1], k, rest, &fx[n], &fy[n]);
}

/* Bead i's force: (0 + F_i) ∓ F_{i+1}. */
static inline __attribute__((always_inline)) double bead_force(const double *F, int i, int n)
{
    return i < n - 1 ? (0.0 + F[i]) - F[i + 1] : (0.0 + F[i]) + F[i + 1];
}

SW_CLONES void base_chain_euler(bench_chain *ch, double *y, double h, long steps)
{
    int n = ch->n, n2 = 2 * n;
    double *x = y, *v = y + n2, inv = ch->inv_m;
    const double *fx = ch->f, *fy = ch->f + (n + 1);
    for (long s = 0; s < steps; s++) {
        chain_forces(ch, x);
        for (int i = 0; i < n; i++) {
            double vx = v[2 * i], vy = v[2 * i + 1];
            v[2 * i] = vx + h * (bead_force(fx, i, n) * inv);
            v[2 * i + 1] = vy + h * (bead_force(fy, i, n) * inv);
            x[2 * i] += h * vx;
            x[2 * i + 1] += h * vy;
        }
    }
}

/* One rk4 stage on the chain after the spring forces of state cur: k =
 * (v of cur, f/m), added into the weighted sum (k1 + 2k2 + 2k3 + k4, in that
 * order, as the generic final loop adds) and, but for the last stage, the
 * next stage's state y + a·k into yt (which may be cur: each component is
 * read before it is written, and the forces are already computed). */
static inline __attribute__((always_inline)) void rk4_stage(const bench_chain *ch, const double *cur, const double *y, double *yt, double *sum,
                             double a, double w, int first, int last)
{
    int n = ch->n, n2 = 2 * n;
    const double *fx = ch->f, *fy = ch->f + (n + 1);
    double inv = ch->inv_m;
    for (int i = 0; i < n; i++) {
        double kx0 = cur[n2 + 2 * i], kx1 = cur[n2 + 2 * i + 1];
        double kv0 = bead_force(fx, i, n) * inv, kv1 = bead_force(fy, i, n) * inv;
        if (first) {
            sum[2 * i] = kx0, sum[2 * i + 1] = kx1, sum[n2 + 2 * i] = kv0, sum[n2 + 2 * i + 1] = kv1;
        } else if (!last) {
            sum[2 * i] += w * kx0, sum[2 * i + 1] += w * kx1;
            sum[n2 + 2 * i] += w * kv0, sum[n2 + 2 * i + 1] += w * kv1;
        } else {
            sum[2 * i] += kx0, sum[2 * i + 1] += kx1, sum[n2 + 2 * i] += kv0, sum[n2 + 2 * i + 1] += kv1;
        }
        if (!last) {
            yt[2 * i] = y[2 * i] + a * kx0, yt[2 * i + 1] = y[2 * i + 1] + a * kx1;
            yt[n2 + 2 * i] = y[n2 + 2 * i] + a * kv0, yt[n2 + 2 * i + 1] = y[n2 + 2 * i + 1] + a * kv1;
        }
    }
}

/* rk4 on the chain: per stage the spring forces, then one pass over the
 * beads (rk4_stage). Three state-sized vectors: y, the stage state, the sum. */
SW_CLONES void base_chain_rk4(bench_chain *ch, double *y, double *work, double h, long steps)
{
    int dim = 4 * ch->n;
    double *yt = work, *sum = work + dim, b = h / 6.0;
    for (long s = 0; s < steps; s++) {
        chain_forces(ch, y);
        rk4_stage(ch, y, y, yt, sum, 0.5 * h, 1.0, 1, 0);
        chain_forces(ch, yt);
        rk4_stage(ch, yt, y, yt, sum, 0.5 * h, 2.0, 0, 0);
        chain_forces(ch, yt);
        rk4_stage(ch, yt, y, yt, sum, h, 2.0, 0, 0);
        chain_forces(ch, yt);
        rk4_stage(ch, yt, y, yt, sum, 0.0, 1.0, 0, 1);
        for (int c = 0; c < dim; c++)
            y[c] += b * sum[c];
    }
}

/* The largest |a[i] - b[i]| (a NaN difference always replaces the
 * maximum). */
double bench_max_diff(int n, const double *a, const double *b)
{
    double m = 0;
    for (int i = 0; i < n; i++) {
        double d = fabs(a[i] - b[i]);
        if (!(d <= m))
            m = d;
    }
    return m;
}
