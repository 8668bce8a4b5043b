/* The implicit solves' kept factorisations and simplified Newton: a solve
 * that reuses the factors gives the numbers a fresh one gives, bit for bit;
 * a change of the state (contents) or of c is never served stale; the
 * dense fallback's kept LU equals Gaussian elimination; and a Newton step
 * that keeps J lands on the solution of the implicit equation, checked
 * against the equation itself and against full Newton on dense matrices. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/particles.h"
#include "engine/linalg.h"
#include "engine/particles_solve.h"
#include "engine/stepper.h"

#define NB 6           /* beads */
#define DIM (4 * NB)

/* A damped chain of NB beads between two anchors, with gravity, plucked
 * and moving: nonlinear springs (rest length), damping, a non-symmetric J. */
static void chain(sw_particles *p)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(p, NB, 1.3, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(p, NB + 1);
    ck_assert_ptr_nonnull(s);
    for (int j = 0; j <= NB; j++)
        s[j] = (sw_spring){ .a = j < NB ? j : NB - 1, .b = j == 0 || j == NB ? -1 : j - 1, .k = 40.0 + j,
                            .c = 0.3, .rest = 0.8, .ax = j == 0 ? 0.0 : NB + 1.0, .ay = 0.0 };
    sw_particles_add_gravity(p, 0.0, -9.81);
    ck_assert_int_eq(sw_particles_finish(p, err, sizeof err), SW_OK);
    for (int i = 0; i < NB; i++) {
        p->y[2 * i] = i + 1.0 + 0.1 * sin(i);
        p->y[2 * i + 1] = 0.4 * cos(1.7 * i);
        p->y[2 * NB + 2 * i] = 0.3 * sin(2.1 * i);
        p->y[2 * NB + 2 * i + 1] = -0.2 * i;
    }
    ck_assert_int_eq(sw_particles_solver_prepare(p, err, sizeof err), SW_OK);
}

static void fill(double *r, double scale)
{
    for (int i = 0; i < DIM; i++)
        r[i] = scale * sin(1.0 + 0.37 * i);
}

/* The solve at (y, c) of r, with the kept factors forgotten first. */
static void fresh_solve(sw_particles *p, const double *y, double c, const double *r, double *z)
{
    sw_particles_solver_touch(p);
    ck_assert_int_eq(sw_particles_solve(p, 0.0, y, c, r, z), SW_OK);
}

/* |(I - c·J) z - r|∞ with J = [[0, I], [M⁻¹Fx, M⁻¹Fv]] from
 * sw_particles_jacobian (dense, formed independently of the band and the
 * blocks; the chain's mass 1.3). */
static double dense_residual(sw_particles *p, const double *y, double c, const double *r, const double *z)
{
    static double fx[DIM / 2 * DIM / 2], fv[DIM / 2 * DIM / 2];
    int n2 = DIM / 2;
    ck_assert_int_eq(sw_particles_jacobian(p, y, fx, fv), SW_OK);
    double worst = 0;
    for (int i = 0; i < n2; i++) {
        double rx = z[i] - c * z[n2 + i] - r[i];
        double acc = z[n2 + i];
        for (int j = 0; j < n2; j++)
            acc -= c * (fx[i * n2 + j] * z[j] + fv[i * n2 + j] * z[n2 + j]) / 1.3;
        worst = fmax(worst, fmax(fabs(rx), fabs(acc - r[n2 + i])));
    }
    return worst;
}

/* A second right-hand side at the same y and c is served from the kept
 * factors: bit for bit what a fresh factorisation gives. The answer also
 * solves (I - c·J) z = r with J from sw_particles_jacobian (dense, formed
 * independently of the band): residual at rounding, 1e-12 of |r| with
 * |c·J| of order 1. */
START_TEST(kept_factors_give_fresh_numbers)
{
    sw_particles p;
    chain(&p);
    double y[DIM], r1[DIM], r2[DIM], z1[DIM], z2[DIM], zf[DIM];
    memcpy(y, p.y, sizeof y);
    fill(r1, 1.0);
    fill(r2, -0.3);
    r2[5] += 1.0;
    double c = 0.05;
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r1, z1), SW_OK);
    double ycopy[DIM]; /* same contents, another address: still the same state */
    memcpy(ycopy, y, sizeof y);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, ycopy, c, r2, z2), SW_OK);
    fresh_solve(&p, y, c, r2, zf);
    ck_assert_mem_eq(z2, zf, sizeof z2);

    ck_assert_double_le(dense_residual(&p, y, c, r2, z2), 1e-12);
    sw_particles_free(&p);
}
END_TEST

/* Never stale: after a solve at y, a solve at y with one component nudged
 * by one ulp, or at another c, or after the forces changed in place
 * (sw_particles_finish), equals a fresh solve there and not the first
 * answer. A cache that compared addresses, or forgot c, fails here. */
START_TEST(changed_state_or_c_refactors)
{
    sw_particles p;
    chain(&p);
    double y[DIM], r[DIM], z0[DIM], z[DIM], zf[DIM];
    char err[SW_ERRLEN];
    memcpy(y, p.y, sizeof y);
    fill(r, 1.0);
    double c = 0.05;
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z0), SW_OK);
    for (int k = 0; k < DIM; k += 5) { /* positions and velocities alike, in place */
        double keep = y[k];
        y[k] = nextafter(y[k], INFINITY);
        ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z), SW_OK);
        fresh_solve(&p, y, c, r, zf);
        ck_assert_mem_eq(z, zf, sizeof z);
        y[k] = keep;
        ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z), SW_OK);
        ck_assert_mem_eq(z, z0, sizeof z);
    }
    /* and the nudged answers are not the first one: a bead moved by 1e-9
     * moves its springs' blocks, so z moves */
    y[2] += 1e-9;
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z), SW_OK);
    ck_assert(memcmp(z, z0, sizeof z) != 0);
    y[2] = p.y[2];

    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z0), SW_OK);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, 2 * c, r, z), SW_OK);
    fresh_solve(&p, y, 2 * c, r, zf);
    ck_assert_mem_eq(z, zf, sizeof z);
    ck_assert(memcmp(z, z0, sizeof z) != 0);

    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z0), SW_OK);
    p.forces[0].springs[2].k *= 3; /* in place, then finish, as the API asks */
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z), SW_OK);
    ck_assert(memcmp(z, z0, sizeof z) != 0);
    fresh_solve(&p, y, c, r, zf);
    ck_assert_mem_eq(z, zf, sizeof z);

    /* the Jacobian queries write the blocks the kept factors were made
     * with: the next solve must not use them as the solve's */
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z0), SW_OK);
    double w[DIM / 2], out[DIM / 2], y2[DIM];
    memcpy(y2, y, sizeof y2);
    y2[0] += 0.5;
    for (int i = 0; i < DIM / 2; i++)
        w[i] = 1.0;
    ck_assert_int_eq(sw_particles_jacobian_apply(&p, y2, 1.0, 0.0, w, out, 1), SW_OK);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r, z), SW_OK);
    ck_assert_mem_eq(z, z0, sizeof z);
    sw_particles_free(&p);
}
END_TEST

/* The solve a caller promises is at the last solve's state
 * (sw_particles_solve_same: Newton's kept J, Rosenbrock's later stages)
 * skips comparing y, and nothing else: its answers are a fresh solve's
 * bit for bit; at another c, after the factors were dropped, or first of
 * all (nothing kept) it factors afresh; and the key it leaves still tells
 * a later ordinary solve at a moved state to factor afresh. */
START_TEST(same_state_solve_is_the_solve)
{
    sw_particles p;
    chain(&p);
    double y[DIM], r1[DIM], r2[DIM], z[DIM], zf[DIM];
    memcpy(y, p.y, sizeof y);
    fill(r1, 1.0);
    fill(r2, -0.3);
    double c = 0.05;
    sw_particles_solver_touch(&p); /* nothing kept: the promise must factor */
    ck_assert_int_eq(sw_particles_solve_same(&p, 0.0, y, c, r1, z), SW_OK);
    fresh_solve(&p, y, c, r1, zf);
    ck_assert_mem_eq(z, zf, sizeof z);
    ck_assert_int_eq(sw_particles_solve_same(&p, 0.0, y, c, r2, z), SW_OK);
    fresh_solve(&p, y, c, r2, zf);
    ck_assert_mem_eq(z, zf, sizeof z);
    ck_assert_int_eq(sw_particles_solve_same(&p, 0.0, y, 2 * c, r2, z), SW_OK); /* another c */
    fresh_solve(&p, y, 2 * c, r2, zf);
    ck_assert_mem_eq(z, zf, sizeof z);
    ck_assert(memcmp(z, (double[DIM]){ 0 }, sizeof z) != 0);
    /* the kept key is y's: a moved state through the ordinary solve refactors */
    ck_assert_int_eq(sw_particles_solve_same(&p, 0.0, y, c, r1, z), SW_OK);
    y[3] += 1e-6;
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, c, r1, z), SW_OK);
    fresh_solve(&p, y, c, r1, zf);
    ck_assert_mem_eq(z, zf, sizeof z);
    sw_particles_free(&p);
}
END_TEST

/* A solve that takes no key (sw_particles_solve_new: a step's first
 * solve, asked for again only as the same state's) answers as a fresh
 * solve, serves the same-state solves after it, and leaves no stale key:
 * after an ordinary solve at y1 (the key y1) and a new one at y2, an
 * ordinary solve at y1 again must factor afresh, not take y2's factors
 * for y1's because the key still reads y1. */
START_TEST(new_solve_leaves_no_stale_key)
{
    sw_particles p;
    chain(&p);
    double y1[DIM], y2[DIM], r[DIM], z[DIM], zf1[DIM], zf2[DIM];
    memcpy(y1, p.y, sizeof y1);
    memcpy(y2, p.y, sizeof y2);
    y2[1] += 0.25;
    y2[2 * NB + 3] -= 0.5;
    fill(r, 1.0);
    double c = 0.05;
    fresh_solve(&p, y1, c, r, zf1);
    fresh_solve(&p, y2, c, r, zf2);
    ck_assert(memcmp(zf1, zf2, sizeof zf1) != 0);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y1, c, r, z), SW_OK); /* the key: y1 */
    ck_assert_int_eq(sw_particles_solve_new(&p, 0.0, y2, c, r, z), SW_OK);
    ck_assert_mem_eq(z, zf2, sizeof z);
    ck_assert_int_eq(sw_particles_solve_same(&p, 0.0, y2, c, r, z), SW_OK);
    ck_assert_mem_eq(z, zf2, sizeof z);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y1, c, r, z), SW_OK);
    ck_assert_mem_eq(z, zf1, sizeof z);
    ck_assert_double_le(dense_residual(&p, y1, c, r, z), 1e-12);
    sw_particles_free(&p);
}
END_TEST

/* Where no force writes a particle's own blocks (springs and gravity:
 * pairs_only) the solve takes them as the zeros they are, without their
 * products: the same bits as a system whose own blocks are written but
 * are +0 (drag with k = 0, the products made), at several c, both signs
 * (a backward step) and c = 0. A force added later that does write them
 * (drag, k = 2) is seen: the answer then solves the system with that
 * drag (residual against the dense Jacobian at rounding, 1e-12 of |r| ~ 1
 * as above). */
START_TEST(own_blocks_skipped_where_zero)
{
    sw_particles p, q;
    char err[SW_ERRLEN];
    chain(&p);
    chain(&q);
    ck_assert_int_eq(sw_particles_add_drag(&q, 0.0), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&q, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_solver_prepare(&q, err, sizeof err), SW_OK);
    double y[DIM], r[DIM], zp[DIM], zq[DIM];
    memcpy(y, p.y, sizeof y);
    fill(r, 1.0);
    const double cs[] = { 0.05, 3.0, -0.02, 0.0 };
    for (int k = 0; k < 4; k++) {
        ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, cs[k], r, zp), SW_OK);
        ck_assert_int_eq(sw_particles_solve(&q, 0.0, y, cs[k], r, zq), SW_OK);
        ck_assert_mem_eq(zp, zq, sizeof zp);
    }
    ck_assert_int_eq(sw_particles_add_drag(&p, 2.0), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_particles_solve(&p, 0.0, y, 0.05, r, zp), SW_OK);
    ck_assert_double_le(dense_residual(&p, y, 0.05, r, zp), 1e-12);
    sw_particles_free(&p);
    sw_particles_free(&q);
}
END_TEST

/* A chain of nb beads (at most FB) for fused_chain_equals_band: shape 0
 * anchored at both ends (the chain scene's order: left anchor, springs
 * (i + 1, i), right anchor), 1 free (springs (i, i + 1)), 2 the left
 * anchor only; 3 and 4 not in the fused pass's order (the right anchor
 * first; a second spring on beads 0 and 1); 5 as 0 with drag (own blocks:
 * the chain's right-hand side, not its fused factorisation). Masses
 * differ bead to bead. */
#define FB 40
static void chain_shaped(sw_particles *p, int nb, int shape)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(p, nb, 1.3, err, sizeof err), SW_OK);
    sw_spring sp[FB + 2];
    int ns = 0;
    if (shape == 3)
        sp[ns++] = (sw_spring){ .a = nb - 1, .b = -1, .k = 31.0, .c = 0.2, .rest = 0.7, .ax = nb + 1.0 };
    if (shape == 0 || shape == 2 || shape == 3 || shape == 5)
        sp[ns++] = (sw_spring){ .a = 0, .b = -1, .k = 40.0, .c = 0.3, .rest = 0.8 };
    for (int i = 0; i + 1 < nb; i++) {
        sp[ns] = (sw_spring){ .a = shape % 5 == 0 ? i + 1 : i, .b = shape % 5 == 0 ? i : i + 1, .k = 41.0 + i,
                              .c = 0.3 + 0.01 * i, .rest = 0.8 };
        if (shape == 4 && i == 0) {
            sp[ns + 1] = sp[ns];
            ns++;
        }
        ns++;
    }
    if (shape == 0 || shape == 5)
        sp[ns++] = (sw_spring){ .a = nb - 1, .b = -1, .k = 33.0, .c = 0.25, .rest = 0.9, .ax = nb + 1.0 };
    if (ns > 0) { /* none on one free bead */
        sw_spring *s = sw_particles_add_springs(p, ns);
        ck_assert_ptr_nonnull(s);
        memcpy(s, sp, (size_t)ns * sizeof *s);
    }
    sw_particles_add_gravity(p, 0.0, -9.81);
    if (shape == 5)
        ck_assert_int_eq(sw_particles_add_drag(p, 0.7), SW_OK);
    ck_assert_int_eq(sw_particles_finish(p, err, sizeof err), SW_OK);
    for (int i = 0; i < nb; i++)
        p->mass[i] = 1.3 + 0.07 * i;
    ck_assert_int_eq(sw_particles_solver_prepare(p, err, sizeof err), SW_OK);
}

/* The state, kind: 0 plucked and moving, 1 compressed to a tenth and
 * strongly damped (the blocks refuse at large c), 2 beads 1 and 2 on one
 * point (a spring of length 0), 3 huge velocities beside tiny positions,
 * 4 a NaN velocity and an infinite position. */
static void chain_state(double *y, int nb, int kind)
{
    for (int i = 0; i < nb; i++) {
        double *x = y + 2 * i, *v = y + 2 * nb + 2 * i;
        x[0] = (kind == 1 ? 0.1 : 1.0) * (i + 1.0 + 0.1 * sin(i));
        x[1] = 0.4 * cos(1.7 * i);
        v[0] = 0.3 * sin(2.1 * i) * (kind == 1 ? 300.0 : 1.0);
        v[1] = -0.2 * i;
        if (kind == 3) {
            x[0] *= 1e-300;
            x[1] *= 1e-300;
            v[0] = 1e150 * (i % 3 - 1.0);
        }
    }
    if (kind == 2 && nb > 2)
        memcpy(y + 4, y + 2, 2 * sizeof *y);
    if (kind == 4) {
        y[2 * nb + 1] = NAN;
        y[2 * (nb - 1)] = INFINITY;
    }
}

/* A chain's velocity system filled and factored in one pass along the
 * chain gives the bits of the band's fill and factorisation: the
 * solutions (from fresh factors and from kept ones) and the return codes
 * equal to the last bit on chains of several lengths and shapes, in
 * hostile states too, and at c where the fused pass does not apply (c²
 * underflowing to 0, or overflowing). The fused pass is taken wherever it
 * applies and the blocks accept (its count rises), and never on pairs in
 * another order, with own blocks or on one bead (no chain's band). The
 * chain's right-hand side (with own blocks too) and the zero own blocks,
 * left as constants, give the bits of the generic loops. */
START_TEST(fused_chain_equals_band)
{
    static const int lengths[] = { 1, 2, 3, 7, FB };
    static const double cs[] = { 0.05, 3.0, -0.02, 40.0, 1e-170, 1e200 };
    for (int li = 0; li < 5; li++)
        for (int shape = 0; shape < 6; shape++)
            for (int kind = 0; kind < 5; kind++) {
                int nb = lengths[li], dim = 4 * nb;
                sw_particles p;
                chain_shaped(&p, nb, shape);
                double y[4 * FB], r[4 * FB], r2[4 * FB], zf[4 * FB], zg[4 * FB], wf[4 * FB], wg[4 * FB];
                chain_state(y, nb, kind);
                for (int i = 0; i < dim; i++)
                    r[i] = sin(1.0 + 0.37 * i);
                for (int k = 0; k < 6; k++) {
                    /* the solve from kept factors: of plain numbers, of
                     * zeros (+0 positions, -0 velocities: M·r_v + c·0·r_x
                     * is +0, M·r_v alone -0) or with an infinite position
                     * (0·∞: NaN where K·∞ alone is ∞) */
                    for (int i = 0; i < dim; i++) {
                        int v = (k + kind) % 3;
                        r2[i] = v == 0 ? cos(0.3 + 1.1 * i) : v == 1 ? (i < dim / 2 ? 0.0 : -0.0) : r[i];
                        if (v == 2 && i == nb / 2 * 2)
                            r2[i] = INFINITY;
                    }
                    long before = sw_particles_solver_generic(&p, 0);
                    int ef = sw_particles_solve(&p, 0.0, y, cs[k], r, zf);
                    int ef2 = ef ? ef : sw_particles_solve_same(&p, 0.0, y, cs[k], r2, wf);
                    long fused = sw_particles_solver_generic(&p, 1) - before;
                    int eg = sw_particles_solve(&p, 0.0, y, cs[k], r, zg);
                    int eg2 = eg ? eg : sw_particles_solve_same(&p, 0.0, y, cs[k], r2, wg);
                    ck_assert_int_eq(sw_particles_solver_generic(&p, 0) - before, fused);
                    ck_assert_msg(ef == eg && ef2 == eg2, "%d beads, shape %d, state %d, c %g: %d %d, %d %d", nb,
                                  shape, kind, cs[k], ef, eg, ef2, eg2);
                    ck_assert_msg(ef || (memcmp(zf, zg, (size_t)dim * sizeof *zf) == 0 &&
                                         (ef2 || memcmp(wf, wg, (size_t)dim * sizeof *wf) == 0)),
                                  "%d beads, shape %d, state %d, c %g: not the band's bits", nb, shape, kind,
                                  cs[k]);
                    if (shape >= 3 || k >= 4)
                        ck_assert_int_eq(fused, 0);
                    else if (kind == 0 && k < 3 && nb >= 2) /* one bead: a band of half width 1 */
                        ck_assert_msg(fused == 1, "%d beads, shape %d, c %g: fused %ld", nb, shape, cs[k], fused);
                }
                sw_particles_free(&p);
            }
}
END_TEST

/* sw_dense_factor + sw_dense_lu_solve do the operations of sw_dense_solve in
 * the same order: equal bit for bit, on matrices that need row interchanges
 * (a small leading pivot) at several columns. */
START_TEST(dense_lu_equals_elimination)
{
    enum { N = 7 };
    for (int trial = 0; trial < 4; trial++) {
        double a[N * N], lu[N * N], b[N], x[N];
        int perm[N];
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++)
                a[i * N + j] = sin(1.3 * i + 0.7 * j + trial) + (i == j ? 0.01 * trial : 0.0);
            b[i] = cos(0.9 * i + trial);
        }
        a[0] = 1e-3; /* row 0 must be swapped away */
        memcpy(lu, a, sizeof a);
        memcpy(x, b, sizeof b);
        ck_assert_int_eq(sw_dense_factor(N, lu, perm), 0);
        sw_dense_lu_solve(N, lu, perm, x);
        int swaps = 0;
        for (int i = 0; i < N; i++)
            swaps += perm[i] != i;
        ck_assert_int_ge(swaps, 2);
        ck_assert_int_eq(sw_dense_solve(N, a, b), 0);
        ck_assert_mem_eq(x, b, sizeof x);
    }
}
END_TEST

/* The band LU as plainly written (each loop as sw_band_factor and
 * sw_band_solve had it before a chain's band got its own paths):
 * elimination with partial pivoting down each column, multipliers by the
 * pivot's reciprocal, then forward and back substitution over the whole
 * band. The library must give these numbers bit for bit. */
static void plain_band_factor(sw_band *b)
{
    int n = b->n, kl = b->kl, kv = b->kl + b->ku, ld = b->ld, ju = 0;
    for (int j = 0; j < n; j++) {
        double *col = b->a + (size_t)j * ld + kv;
        int km = kl < n - 1 - j ? kl : n - 1 - j, jp = 0;
        double best = fabs(col[0]);
        for (int t = 1; t <= km; t++)
            if (fabs(col[t]) > best) {
                best = fabs(col[t]);
                jp = t;
            }
        b->piv[j] = j + jp;
        int top = j + b->ku + jp < n - 1 ? j + b->ku + jp : n - 1;
        ju = ju > top ? ju : top;
        if (jp != 0)
            for (int c = j; c <= ju; c++) {
                double *cc = b->a + (size_t)c * ld + kv + j - c, tmp = cc[jp];
                cc[jp] = cc[0];
                cc[0] = tmp;
            }
        double inv = 1.0 / col[0];
        for (int t = 1; t <= km; t++)
            col[t] *= inv;
        for (int c = j + 1; c <= ju; c++) {
            double *cc = b->a + (size_t)c * ld + kv + j - c, u = cc[0];
            if (u != 0)
                for (int t = 1; t <= km; t++)
                    cc[t] -= col[t] * u;
        }
    }
}

static void plain_band_solve(const sw_band *b, double *x)
{
    int n = b->n, kl = b->kl, kv = b->kl + b->ku, ld = b->ld;
    for (int j = 0; j < n - 1; j++) {
        const double *col = b->a + (size_t)j * ld + kv;
        int lm = kl < n - 1 - j ? kl : n - 1 - j, l = b->piv[j];
        double tmp = x[l];
        x[l] = x[j];
        x[j] = tmp;
        for (int t = 1; t <= lm; t++)
            x[j + t] -= col[t] * x[j];
    }
    for (int j = n - 1; j >= 0; j--) {
        const double *col = b->a + (size_t)j * ld + kv;
        x[j] /= col[0];
        for (int i = j - kv > 0 ? j - kv : 0; i < j; i++)
            x[i] -= col[i - j] * x[j];
    }
}

/* A chain's band (kl = ku = 3) of every size from 1 to 14, diagonally
 * dominant (no row interchange: the written-out paths run to the end) and
 * with small diagonals (interchanges part way: the generic loops take
 * over), and a right-hand side with an infinite entry (the back
 * substitution leaves its written-out path): the library's factors and
 * solution equal the plain loops' bit for bit (NaN where they are NaN). */
START_TEST(band_chain_paths_equal_plain_loops)
{
    enum { NMAX = 14, KL = 3, LD = 3 * KL + 1 };
    int swapped = 0;
    for (int n = 1; n <= NMAX; n++)
        for (int kind = 0; kind < 3; kind++) {
            double a1[LD * NMAX], a2[LD * NMAX], x1[NMAX], x2[NMAX];
            int p1[NMAX], p2[NMAX];
            sw_band b1, b2;
            sw_band_init(&b1, n, KL, KL, a1, p1);
            sw_band_init(&b2, n, KL, KL, a2, p2);
            for (int i = 0; i < n; i++) {
                for (int j = i - KL; j <= i + KL; j++) {
                    if (j < 0 || j >= n)
                        continue;
                    double v = sin(1.7 * i + 0.3 * j + n) + (i == j ? (kind == 1 ? 0.05 : 8.0) : 0.0);
                    sw_band_add(&b1, i, j, v);
                    sw_band_add(&b2, i, j, v);
                }
                x1[i] = x2[i] = cos(0.7 * i + kind);
            }
            if (kind == 2 && n > 5)
                x1[n - 2] = x2[n - 2] = INFINITY;
            ck_assert_int_eq(sw_band_factor(&b1), 0);
            plain_band_factor(&b2);
            ck_assert_mem_eq(a1, a2, sizeof(double) * LD * n);
            ck_assert_mem_eq(p1, p2, sizeof(int) * n);
            for (int i = 0; i < n; i++)
                swapped += kind == 1 && p1[i] != i;
            sw_band_solve(&b1, x1);
            plain_band_solve(&b2, x2);
            for (int i = 0; i < n; i++) {
                if (isnan(x2[i]))
                    ck_assert_msg(isnan(x1[i]), "n = %d, kind %d: x[%d] = %g, not NaN", n, kind, i, x1[i]);
                else
                    ck_assert_msg(memcmp(&x1[i], &x2[i], sizeof x1[i]) == 0, "n = %d, kind %d: x[%d] = %.17g, "
                                  "plain %.17g", n, kind, i, x1[i], x2[i]);
            }
        }
    ck_assert_int_ge(swapped, 5); /* the small diagonals did need interchanges */
}
END_TEST

/* A first-order system with no solve of its own (the dense fallback) whose
 * Jacobian depends on t and y: y0' = -y0³ + sin(t)·y1, y1' = y0 - 2 y1. */
static void cubic_deriv(void *ctx, double t, const double *y, double *dy)
{
    (void)ctx;
    dy[0] = -y[0] * y[0] * y[0] + sin(t) * y[1];
    dy[1] = y[0] - 2 * y[1];
}

static sw_ode cubic(void)
{
    return (sw_ode){ .dim = 2, .order = 1, .deriv = cubic_deriv };
}

/* The dense fallback keeps its factors for the same (t, y, c) and takes
 * them afresh for another t, y or c: each answer equals that of a stepper
 * that has never solved before. */
START_TEST(dense_fallback_keeps_and_drops)
{
    sw_ode ode = cubic();
    sw_stepper s;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("implicit-euler"), &ode, err, sizeof err), SW_OK);
    double y[2] = { 0.8, -0.3 }, r1[2] = { 1.0, 2.0 }, r2[2] = { -0.5, 0.25 }, z[2], zf[2];
    struct { double t, dy0, c; } cases[] = { { 0.3, 0, 0.1 }, { 0.3, 0, 0.1 }, { 0.9, 0, 0.1 },
                                             { 0.9, 1e-3, 0.1 }, { 0.9, 1e-3, 0.2 } };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double yk[2] = { y[0] + cases[k].dy0, y[1] };
        ck_assert_int_eq(sw_ode_solve(&s, &ode, cases[k].t, yk, cases[k].c, k % 2 ? r1 : r2, z), SW_OK);
        sw_stepper fresh;
        sw_ode o2 = cubic();
        ck_assert_int_eq(sw_stepper_init(&fresh, sw_integrator_find("implicit-euler"), &o2, err, sizeof err),
                         SW_OK);
        ck_assert_int_eq(sw_ode_solve(&fresh, &o2, cases[k].t, yk, cases[k].c, k % 2 ? r1 : r2, zf), SW_OK);
        ck_assert_mem_eq(z, zf, sizeof z);
        sw_stepper_free(&fresh);
    }
    /* the repeat of case 0 (case 1) cost no evaluations: the factors were kept */
    long before = ode.evals;
    ck_assert_int_eq(sw_ode_solve(&s, &ode, 0.9, (double[]){ 0.8 + 1e-3, -0.3 }, 0.2, r1, z), SW_OK);
    ck_assert_int_eq(ode.evals, before);
    sw_stepper_free(&s);
}
END_TEST

/* One backward Euler and one implicit-midpoint step of the chain at a large
 * step (h·|λ| ≈ 3, where J changes along the step and simplified Newton
 * needs several iterations): the result satisfies its implicit equation to
 * the tolerance Newton promises (1e-12 of the state's size, with room for
 * the rounding of h·f: 1e-11 absolute on a state of size ~7), and agrees
 * with full Newton on the dense Jacobian, iterated independently here to
 * |δ| < 1e-14, within the same bound. */
START_TEST(simplified_newton_reaches_the_solution)
{
    const char *methods[2] = { "implicit-euler", "implicit-midpoint" };
    for (int mi = 0; mi < 2; mi++) {
        double theta = mi == 0 ? 1.0 : 0.5, h = 0.4;
        sw_particles p, q;
        sw_stepper s;
        char err[SW_ERRLEN];
        chain(&p);
        chain(&q);
        ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(methods[mi]), &p.ode, err, sizeof err), SW_OK);
        double y0[DIM], t = 0;
        memcpy(y0, p.y, sizeof y0);
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, h), SW_OK);

        /* the implicit equation: y1 = y0 + h f(y0 + θ(y1 - y0)) */
        double ym[DIM], f[DIM], size = 0, worst = 0;
        for (int i = 0; i < DIM; i++) {
            ym[i] = y0[i] + theta * (p.y[i] - y0[i]);
            size = fmax(size, fabs(p.y[i]));
        }
        q.ode.deriv(&q, theta * h, ym, f);
        for (int i = 0; i < DIM; i++)
            worst = fmax(worst, fabs(p.y[i] - y0[i] - h * f[i]));
        ck_assert_double_le(worst, 1e-11);

        /* full Newton on G(Δ) = Δ - h f(y0 + θΔ), dense J from the blocks */
        static double fx[(DIM / 2) * (DIM / 2)], fv[(DIM / 2) * (DIM / 2)], a[DIM * DIM];
        double d[DIM] = { 0 }, g[DIM];
        int n2 = DIM / 2;
        for (int it = 0; it < 50; it++) {
            for (int i = 0; i < DIM; i++)
                ym[i] = y0[i] + theta * d[i];
            q.ode.deriv(&q, theta * h, ym, f);
            ck_assert_int_eq(sw_particles_jacobian(&q, ym, fx, fv), SW_OK);
            memset(a, 0, sizeof a);
            for (int i = 0; i < DIM; i++) {
                a[i * DIM + i] = 1.0;
                g[i] = h * f[i] - d[i];
            }
            for (int i = 0; i < n2; i++) {
                a[i * DIM + n2 + i] -= theta * h;
                for (int j = 0; j < n2; j++) {
                    a[(n2 + i) * DIM + j] -= theta * h * fx[i * n2 + j] / 1.3;
                    a[(n2 + i) * DIM + n2 + j] -= theta * h * fv[i * n2 + j] / 1.3;
                }
            }
            ck_assert_int_eq(sw_dense_solve(DIM, a, g), 0);
            double step = 0;
            for (int i = 0; i < DIM; i++) {
                d[i] += g[i];
                step = fmax(step, fabs(g[i]));
            }
            if (step < 1e-14)
                break;
        }
        double diff = 0;
        for (int i = 0; i < DIM; i++)
            diff = fmax(diff, fabs(p.y[i] - (y0[i] + d[i])));
        ck_assert_double_le(diff, 1e-12 * size);
        ck_assert_int_gt(s.newton_iters, 2); /* the kept J was used and iterated on */
        sw_stepper_free(&s);
        sw_particles_free(&p);
        sw_particles_free(&q);
    }
}
END_TEST

Suite *make_solve_suite(void);
Suite *make_solve_suite(void)
{
    Suite *s = suite_create("solve");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, kept_factors_give_fresh_numbers);
    tcase_add_test(tc, changed_state_or_c_refactors);
    tcase_add_test(tc, same_state_solve_is_the_solve);
    tcase_add_test(tc, own_blocks_skipped_where_zero);
    tcase_add_test(tc, fused_chain_equals_band);
    tcase_add_test(tc, new_solve_leaves_no_stale_key);
    tcase_add_test(tc, dense_lu_equals_elimination);
    tcase_add_test(tc, band_chain_paths_equal_plain_loops);
    tcase_add_test(tc, dense_fallback_keeps_and_drops);
    tcase_add_test(tc, simplified_newton_reaches_the_solution);
    suite_add_tcase(s, tc);
    return s;
}
