/* The particle derivative against an independent, straightforward one
 * written here (the lecture's loop: clear the forces, let each force object
 * add its part in the order it was added, return v and f/m), on every
 * particle scene of the catalog, at its start and at scrambled states; and
 * the compiled form's bookkeeping: a spring with a bad index is named, a
 * force added later is seen, a spring of length 0 adds no force. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "engine/particles_chain.h"
#include "engine/particles_deriv.h"
#include "engine/particles_model.h"
#include "engine/spring_line.h"
#include "stepwise/stepwise.h"
#include "stepwise/particles.h"
#include "stepwise/sim.h"

#define MAXN 2048

/* Plain derivative; scale (laid out as dydt) = 0 for dx/dt = v, which is
 * copied, and Σ|each force's part| / m for dv/dt: the size that rounding
 * in a sum of those parts is relative to. */
static void plain_deriv(const sw_particles *p, const double *y, double *dydt, double *scale_all)
{
    int n = p->n, n2 = 2 * n;
    const double *x = y, *v = y + n2;
    double *f = dydt + n2, *scale = scale_all + n2;
    memset(f, 0, (size_t)n2 * sizeof *f);
    memset(scale_all, 0, (size_t)(2 * n2) * sizeof *scale_all);
    for (int k = 0; k < p->nforces; k++) {
        const sw_force *fo = &p->forces[k];
        for (int i = 0; i < n && fo->kind == SW_FORCE_MUTUAL; i++) /* each pair once, both ends */
            for (int j = i + 1; j < n; j++) {
                double dx = x[2 * i] - x[2 * j], dy = x[2 * i + 1] - x[2 * j + 1];
                double q2 = dx * dx + dy * dy + fo->soft * fo->soft;
                double s = fo->mu * p->mass[i] * p->mass[j] / (q2 * sqrt(q2));
                f[2 * i] -= s * dx, f[2 * i + 1] -= s * dy;
                f[2 * j] += s * dx, f[2 * j + 1] += s * dy;
                scale[2 * i] += fabs(s * dx), scale[2 * i + 1] += fabs(s * dy);
                scale[2 * j] += fabs(s * dx), scale[2 * j + 1] += fabs(s * dy);
            }
        for (int i = 0; i < n / 2 && fo->kind == SW_FORCE_HEAT; i++) { /* body i, its slot n/2 + i */
            int s = n / 2 + i;
            double th = v[2 * s], parts[6] = {
                p->mass[i] * fo->gx, -(p->mass[i] * fo->k * v[2 * i]), p->mass[i] * fo->gy,
                p->mass[i] * fo->buoy * th, -(p->mass[i] * fo->k * v[2 * i + 1]), -(p->mass[s] * fo->cool * th),
            };
            static const int to[6] = { 0, 0, 1, 1, 1, 2 }; /* body x, body y, slot x */
            for (int k2 = 0; k2 < 6; k2++) {
                int c = to[k2] < 2 ? 2 * i + to[k2] : 2 * s;
                f[c] += parts[k2];
                scale[c] += fabs(parts[k2]);
            }
        }
        for (int i = 0; i < n && fo->kind != SW_FORCE_SPRINGS && fo->kind != SW_FORCE_MUTUAL &&
                        fo->kind != SW_FORCE_HEAT; i++)
            for (int d = 0; d < 2; d++) {
                double part;
                if (fo->kind == SW_FORCE_GRAVITY) {
                    part = p->mass[i] * (d ? fo->gy : fo->gx);
                } else if (fo->kind == SW_FORCE_DRAG) {
                    part = -(fo->k * v[2 * i + d]);
                } else {
                    double dx = x[2 * i] - fo->cx, dy = x[2 * i + 1] - fo->cy, r2 = dx * dx + dy * dy;
                    part = -fo->mu * p->mass[i] / (r2 * sqrt(r2)) * (d ? dy : dx);
                }
                f[2 * i + d] += part;
                scale[2 * i + d] += fabs(part);
            }
        for (int j = 0; fo->kind == SW_FORCE_SPRINGS && j < fo->nsprings; j++) {
            sw_spring at = swp_spring_at(fo, j); /* (a line's springs are generated) */
            const sw_spring *sp = &at;
            int a = sp->a, b = sp->b;
            double bx = b >= 0 ? x[2 * b] : sp->ax, by = b >= 0 ? x[2 * b + 1] : sp->ay;
            double dx = x[2 * a] - bx, dy = x[2 * a + 1] - by, len2 = dx * dx + dy * dy;
            double len = len2 >= 1e-290 ? sqrt(len2) : hypot(dx, dy); /* tiny: the squares lose digits */
            if (!(len > 0))
                continue;
            double ux = dx / len, uy = dy / len;
            double dvx = v[2 * a] - (b >= 0 ? v[2 * b] : 0.0), dvy = v[2 * a + 1] - (b >= 0 ? v[2 * b + 1] : 0.0);
            double mag = sp->k * (len - sp->rest) + sp->c * (dvx * ux + dvy * uy);
            double fx = -mag * ux, fy = -mag * uy;
            f[2 * a] += fx, f[2 * a + 1] += fy;
            scale[2 * a] += fabs(fx), scale[2 * a + 1] += fabs(fy);
            if (b >= 0) {
                f[2 * b] -= fx, f[2 * b + 1] -= fy;
                scale[2 * b] += fabs(fx), scale[2 * b + 1] += fabs(fy);
            }
        }
    }
    for (int i = 0; i < n2; i++) {
        dydt[i] = v[i];
        f[i] *= p->inv_mass[i / 2];
        scale[i] *= p->inv_mass[i / 2];
    }
}

/* A fixed pseudo-random sequence in [-1, 1) (no library generator). */
static double scramble(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 4503599627370496.0 - 1.0;
}

static double y[4 * MAXN], got[4 * MAXN], want[4 * MAXN], scale[4 * MAXN];

/* Scene with settings: compare at the start and at 5 scrambled states
 * (positions moved by up to `spread`, velocities up to 3 in each component,
 * so every damping and drag term is exercised). Tolerance 4ε·scale per
 * component: both sum the same parts; in another order a sum of k parts
 * changes by at most (k - 1)·ε·Σ|parts| (here k ≤ 3). Returns how many
 * components differ in any bit. */
static long compare_scene(const char *name, const char *const *sets, int nsets, double spread)
{
    const sw_scene *sc = sw_scene_find(name);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    for (int i = 0; i < nsets; i++)
        ck_assert_msg(sw_scene_set(sc, p, sets[i], err, sizeof err) == SW_OK, "%s", err);
    sw_system sys;
    ck_assert_msg(sw_system_build(&sys, sc, p, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(sys.kind, SW_SYS_PARTICLES);
    const sw_particles *pa = &sys.particles;
    int dim = sys.ode->dim;
    ck_assert_int_le(dim, 4 * MAXN);
    unsigned long long seed = 12345;
    long differ = 0;
    for (int trial = 0; trial < 6; trial++) {
        memcpy(y, sys.y, (size_t)dim * sizeof *y);
        for (int i = 0; trial > 0 && i < dim; i++)
            y[i] += i < dim / 2 ? spread * scramble(&seed) : 3.0 * scramble(&seed);
        sys.ode->deriv(sys.ode->ctx, 0.0, y, got);
        plain_deriv(pa, y, want, scale);
        for (int i = 0; i < dim; i++) {
            double tol = 4 * DBL_EPSILON * scale[i];
            ck_assert_msg(fabs(got[i] - want[i]) <= tol, "%s trial %d component %d: %.17g vs %.17g (tol %g)", name,
                          trial, i, got[i], want[i], tol);
            differ += memcmp(&got[i], &want[i], sizeof got[i]) != 0;
        }
    }
    sw_system_free(&sys);
    return differ;
}

/* Every particle scene of the catalog at its defaults, and the variants
 * that switch on what the defaults leave off (damping, gravity, drag). The
 * compiled derivative sums in the plain loop's order for all of them, so
 * beyond the tolerance they agree bit for bit (particles_deriv.c says when
 * they would not). */
START_TEST(derivative_matches_plain)
{
    int scenes = 0;
    for (int i = 0; i < sw_scene_count(); i++) {
        const sw_scene *sc = sw_scene_at(i);
        sw_system sys;
        char err[SW_ERRLEN];
        ck_assert_int_eq(sw_system_build(&sys, sc, NULL, err, sizeof err), SW_OK);
        int particles = sys.kind == SW_SYS_PARTICLES, sph = 0;
        for (int k = 0; particles && k < sys.particles.nforces; k++)
            sph |= sys.particles.forces[k].kind == SW_FORCE_SPH;
        sw_system_free(&sys);
        if (!particles || sph) /* water: against its own direct sum in check_water.c */
            continue;
        scenes++;
        ck_assert_int_eq(compare_scene(sc->name, NULL, 0, 0.3), 0);
    }
    ck_assert_int_eq(scenes, 10); /* projectile, bounce, fireworks, spring, stiff-spring, chain, orbit, galaxy,
                                     fire, explosion */
    const char *chain[] = { "n=1000", "c=2.5", "g=9.81" }, *spring[] = { "g=9.81", "c=0" },
               *proj[] = { "drag=0" }, *orbit[] = { "e=0.9" }, *bounce[] = { "drag=0.7" };
    ck_assert_int_eq(compare_scene("chain", chain, 3, 0.4), 0);
    ck_assert_int_eq(compare_scene("chain", chain, 1, 0.4), 0);
    ck_assert_int_eq(compare_scene("spring", spring, 2, 0.5), 0);
    ck_assert_int_eq(compare_scene("projectile", proj, 1, 1.0), 0);
    ck_assert_int_eq(compare_scene("bounce", bounce, 1, 1.0), 0);
    ck_assert_int_eq(compare_scene("orbit", orbit, 1, 0.05), 0);
}
END_TEST

/* Three particles, hand-made: forces added in an order no scene uses
 * (drag, then springs with three per particle, then gravity twice and a
 * central field), so the sums may round differently, but only at the
 * tolerance of compare_scene's argument. */
START_TEST(derivative_any_order)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 3, 2.0, err, sizeof err), SW_OK);
    p.mass[1] = 0.5, p.inv_mass[1] = 2.0;
    ck_assert_int_eq(sw_particles_add_drag(&p, 0.3), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 4);
    s[0] = (sw_spring){ .a = 0, .b = 1, .k = 10, .c = 0.2, .rest = 1 };
    s[1] = (sw_spring){ .a = 1, .b = 2, .k = 7, .c = 0, .rest = 0.5 };
    s[2] = (sw_spring){ .a = 2, .b = 0, .k = 3, .c = 0.1, .rest = 2 };
    s[3] = (sw_spring){ .a = 1, .b = -1, .k = 5, .c = 0.4, .rest = 0.2, .ax = 0.3, .ay = -1 };
    ck_assert_int_eq(sw_particles_add_gravity(&p, 0.1, -9.81), SW_OK);
    ck_assert_int_eq(sw_particles_add_gravity(&p, -0.2, 1.0), SW_OK);
    ck_assert_int_eq(sw_particles_add_central(&p, 0.5, 0.5, 2.0), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    unsigned long long seed = 99;
    for (int trial = 0; trial < 20; trial++) {
        for (int i = 0; i < 12; i++)
            y[i] = 2.0 * scramble(&seed);
        p.ode.deriv(p.ode.ctx, 0.0, y, got);
        plain_deriv(&p, y, want, scale);
        for (int i = 0; i < 12; i++)
            ck_assert_msg(fabs(got[i] - want[i]) <= 4 * 4 * DBL_EPSILON * scale[i], "component %d: %.17g vs %.17g",
                          i, got[i], want[i]); /* up to 6 parts per component here: (6 - 1)ε < 16ε */
    }
    sw_particles_free(&p);
}
END_TEST

/* finish() names a spring whose particle does not exist; the derivative
 * leaves it out rather than reading outside the state. */
START_TEST(finish_names_bad_spring)
{
    sw_particles p;
    char err[SW_ERRLEN] = "";
    ck_assert_int_eq(sw_particles_init(&p, 2, 1.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 2);
    s[0] = (sw_spring){ .a = 0, .b = 1, .k = 1, .rest = 1 };
    s[1] = (sw_spring){ .a = 0, .b = 2, .k = 1, .rest = 1 };
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "spring 1"));
    ck_assert_ptr_nonnull(strstr(err, "0 to 1"));
    p.y[0] = 3.0; /* particle 0 at (3, 0), particle 1 at the origin: stretch 2 */
    p.ode.deriv(p.ode.ctx, 0.0, p.y, got);
    ck_assert_double_eq(got[4], -2.0); /* only spring 0: f = -k (|d| - rest) = -2 along x */
    ck_assert_double_eq(got[6], 2.0);
    sw_particles_free(&p);
}
END_TEST

/* A force added after the derivative was first used is in the next one;
 * a spring of length 0 (direction undefined) adds no force, as before. */
START_TEST(later_force_and_zero_length)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 2, 2.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, 2);
    s[0] = (sw_spring){ .a = 0, .b = 1, .k = 4, .c = 1, .rest = 1 };
    s[1] = (sw_spring){ .a = 1, .b = -1, .k = 4, .c = 1, .rest = 1, .ax = 0.5, .ay = 0.25 };
    p.y[2] = 0.5, p.y[3] = 0.25; /* both particles: particle 0 at the origin, particle 1 on its anchor */
    p.y[0] = 0.5, p.y[1] = 0.25;
    p.y[4] = 1.0, p.y[7] = -1.0;
    p.ode.deriv(p.ode.ctx, 0.0, p.y, got);
    for (int i = 4; i < 8; i++)
        ck_assert_double_eq(got[i], 0.0);
    ck_assert(!signbit(got[4]) && !signbit(got[7]));
    ck_assert_int_eq(sw_particles_add_gravity(&p, 0.0, -10.0), SW_OK);
    p.ode.deriv(p.ode.ctx, 0.0, p.y, got);
    ck_assert_double_eq(got[5], -10.0);
    ck_assert_double_eq(got[7], -10.0);
    ck_assert_double_eq(got[0], 1.0);
    sw_particles_free(&p);
}
END_TEST

/* A chain whose springs join neighbours in order, which the compiled form
 * reads contiguously (a regular run of beads, two at a time, and the odd
 * one after), with damping, gravity, drag and masses that differ: bit for
 * bit the plain loop's numbers, also where two beads coincide (no force),
 * where they are 1e-160 apart (the squares vanish: hypot), and where a
 * position is NaN (no force from its springs, as in the plain loop). */
START_TEST(regular_chain_matches_plain)
{
    enum { N = 37 };
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, N, 1.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(&p, N + 1);
    ck_assert_ptr_nonnull(s);
    for (int j = 0; j <= N; j++) {
        s[j] = (sw_spring){ .a = j, .b = j - 1, .k = 30.0 + j, .c = 0.25 * (j % 3), .rest = 0.1 };
        if (j == 0)
            s[j].b = -1;
        if (j == N)
            s[j].a = N - 1, s[j].b = -1, s[j].ax = 4.0, s[j].ay = 0.5;
    }
    ck_assert_int_eq(sw_particles_add_gravity(&p, 0.5, -9.81), SW_OK);
    ck_assert_int_eq(sw_particles_add_drag(&p, 0.3), SW_OK);
    unsigned long long seed = 7;
    for (int i = 0; i < N; i++) {
        p.mass[i] = 1.0 + 0.5 * scramble(&seed);
        p.inv_mass[i] = 1.0 / p.mass[i];
    }
    for (int i = 0; i < 4 * N; i++)
        y[i] = (i < 2 * N ? 0.1 * (i / 2) : 0.0) + 0.05 * scramble(&seed);
    y[2 * 6] = y[2 * 5], y[2 * 6 + 1] = y[2 * 5 + 1];                  /* beads 5 and 6 coincide */
    y[2 * 11] = y[2 * 10] + 1e-160, y[2 * 11 + 1] = y[2 * 10 + 1];     /* 10 and 11: 1e-160 apart */
    y[2 * 20] = NAN;                                                   /* bead 20 lost */
    p.ode.deriv(p.ode.ctx, 0.0, y, got);
    plain_deriv(&p, y, want, scale);
    for (int i = 0; i < 4 * N; i++)
        ck_assert_msg(memcmp(&got[i], &want[i], sizeof got[i]) == 0 || (isnan(got[i]) && isnan(want[i])),
                      "component %d: compiled %.17g, plain %.17g", i, got[i], want[i]);
    ck_assert(got[2 * N + 2 * 5] != 0 && got[2 * N + 2 * 10] != 0); /* gravity and drag, at least */
    sw_particles_free(&p);
}
END_TEST

/* A chain of N beads between two anchors, every spring k = 40, c, rest =
 * 0.1 (uniform unless vary), joining neighbours in order (reverse: a = j - 1,
 * b = j instead of a = j, b = j - 1) or in a shuffled order (shuffle). */
static void layout_chain(sw_particles *p, int N, double c, int reverse, int shuffle, int vary)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(p, N, 1.5, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(p, N + 1);
    ck_assert_ptr_nonnull(s);
    for (int j = 0; j <= N; j++) {
        int jj = shuffle ? (j * 7) % (N + 1) : j; /* 7 and N + 1 coprime: a permutation */
        s[j] = (sw_spring){ .a = reverse ? jj - 1 : jj, .b = reverse ? jj : jj - 1, .k = 40, .c = c, .rest = 0.1 };
        if (jj == 0)
            s[j].a = 0, s[j].b = -1, s[j].ax = -0.1, s[j].ay = 0.05;
        if (jj == N)
            s[j].a = N - 1, s[j].b = -1, s[j].ax = 0.1 * N, s[j].ay = -0.05;
    }
    if (vary)
        s[N / 2].rest = 0.125;
}

/* The compiled form keeps only what its passes read (particles_model.h):
 * k, c, rest once when the springs share them, the neighbours of a regular
 * run found from the stride without writing their lists, ax, ay of the
 * anchored springs alone. Each layout that changes what is kept, at 300
 * beads (past the small path), against the plain loop: bit for bit where a
 * bead sums at most two spring forces before gravity (the orders then
 * agree, particles_deriv.c), and where the middle bead of `mid` has three
 * within 4ε·scale, as compare_scene (k = 3 parts: (k - 1)ε). */
START_TEST(compact_layouts_match_plain)
{
    enum { N = 300 };
    /* c, reverse, shuffle, vary, then: 1 central field, 2 gravity and drag, 3 a third spring at bead N/2;
     * and what the compiled form should keep: k, c, rest once (uniform), the run's lists unwritten */
    static const int cases[][7] = { { 0, 0, 0, 0, 0, 1, 1 }, { 1, 0, 0, 0, 2, 1, 1 }, { 1, 1, 0, 0, 2, 1, 1 },
                                    { 0, 1, 0, 0, 1, 1, 0 }, { 1, 0, 1, 0, 2, 1, 0 }, { 1, 0, 0, 1, 2, 0, 1 },
                                    { 0, 1, 1, 1, 0, 0, 0 }, { 1, 0, 0, 0, 3, 1, 0 } };
    unsigned long long seed = 2026;
    for (size_t q = 0; q < sizeof cases / sizeof cases[0]; q++) {
        const int *cs = cases[q];
        sw_particles p;
        char err[SW_ERRLEN];
        layout_chain(&p, N, cs[0] ? 0.75 : 0.0, cs[1], cs[2], cs[3]);
        if (cs[4] == 1)
            ck_assert_int_eq(sw_particles_add_central(&p, 3.0, -2.0, 5.0), SW_OK);
        if (cs[4] == 2) {
            ck_assert_int_eq(sw_particles_add_gravity(&p, 0.0, -9.81), SW_OK);
            ck_assert_int_eq(sw_particles_add_drag(&p, 0.2), SW_OK);
        }
        if (cs[4] == 3) {
            sw_spring *extra = sw_particles_add_springs(&p, 1);
            ck_assert_ptr_nonnull(extra);
            *extra = (sw_spring){ .a = N / 2, .b = -1, .k = 40, .c = 0.75, .rest = 0.1, .ax = 15, .ay = 2 };
        }
        ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
        ck_assert(!swp_deriv_is_small(&p));
        ck_assert_int_eq(p.model->uniform, cs[5]);
        ck_assert_int_eq(p.model->skip_run, cs[6]);
        if (!cs[2] && cs[4] != 3) /* in order: every bead a run but the ends (each has an anchor) */
            ck_assert_int_eq(p.model->run_hi - p.model->run_lo, N - 2);
        for (int trial = 0; trial < 4; trial++) {
            for (int i = 0; i < 4 * N; i++)
                y[i] = (i < 2 * N ? 0.1 * (i / 2 + 1) * (i % 2 == 0) : 0.0) + 0.03 * scramble(&seed);
            if (trial == 3)
                y[2 * 41] = y[2 * 40], y[2 * 41 + 1] = y[2 * 40 + 1]; /* two beads coincide: no force */
            p.ode.deriv(p.ode.ctx, 0.0, y, got);
            plain_deriv(&p, y, want, scale);
            for (int i = 0; i < 4 * N; i++) {
                int third = cs[4] == 3 && i >= 2 * N && (i - 2 * N) / 2 == N / 2;
                if (third)
                    ck_assert_msg(fabs(got[i] - want[i]) <= 4 * DBL_EPSILON * scale[i], "case %zu component %d", q, i);
                else
                    ck_assert_msg(memcmp(&got[i], &want[i], sizeof got[i]) == 0,
                                  "case %zu trial %d component %d: compiled %.17g, plain %.17g", q, trial, i, got[i],
                                  want[i]);
            }
        }
        sw_particles_free(&p);
    }
}
END_TEST

/* Whether swp_deriv (the small path where compiling picked one) and the
 * generic passes give the same bits at y; counts the systems that took the
 * small path in *small. */
static long small_vs_generic(sw_particles *p, const double *ys, int *small)
{
    int dim = 4 * p->n;
    p->ode.deriv(p->ode.ctx, 0.0, ys, got);
    swp_deriv_generic(p, 0.0, ys, want);
    *small += swp_deriv_is_small(p);
    long differ = 0;
    for (int i = 0; i < dim; i++)
        differ += memcmp(&got[i], &want[i], sizeof got[i]) != 0;
    return differ;
}

/* The small-system path against the generic one, bit for bit: the
 * small path must be an exact copy of the generic arithmetic, so no
 * tolerance. Every particle scene of the catalog at its defaults and with
 * damping, gravity and drag switched on, at its start and at 20 random
 * states each; then one particle with every combination of the kinds the
 * small path models (springs, damped or not, anchored, a central field,
 * gravity, drag), at random states and at the edge cases: the particle on
 * the anchor (|d| = 0), 1e-160 from it (|d|² underflows: hypot), on the
 * centre, and a NaN position. */
START_TEST(small_path_matches_generic)
{
    char err[SW_ERRLEN];
    unsigned long long seed = 4242;
    int small = 0, systems = 0;
    const char *sets[][3] = { { NULL }, { "e=0.9" }, { "c=0.7", "g=9.81" }, { "drag=0.4" }, { "n=3", "c=1" } };
    for (int i = 0; i < sw_scene_count(); i++)
        for (size_t v = 0; v < sizeof sets / sizeof sets[0]; v++) {
            const sw_scene *sc = sw_scene_at(i);
            double par[SW_MAX_PARAMS];
            sw_scene_defaults(sc, par);
            int ok = 1;
            for (int k = 0; k < 3 && sets[v][k]; k++)
                ok &= sw_scene_set(sc, par, sets[v][k], err, sizeof err) == SW_OK;
            sw_system sys;
            if (!ok || sw_system_build(&sys, sc, par, err, sizeof err) != SW_OK)
                continue;
            if (sys.kind == SW_SYS_PARTICLES && sys.ode->dim <= 4 * MAXN) {
                sw_particles *p = &sys.particles;
                int dim = sys.ode->dim;
                systems++;
                for (int trial = 0; trial < 21; trial++) {
                    memcpy(y, sys.y, (size_t)dim * sizeof *y);
                    for (int j = 0; trial > 0 && j < dim; j++)
                        y[j] += 2.0 * scramble(&seed);
                    ck_assert_msg(small_vs_generic(p, y, &small) == 0, "%s variant %zu trial %d", sc->name, v, trial);
                }
            }
            sw_system_free(&sys);
        }
    ck_assert_int_ge(systems, 8 * 2);
    ck_assert_int_gt(small, 0);
    for (int kinds = 0; kinds < 64; kinds++) {
        sw_particles p;
        ck_assert_int_eq(sw_particles_init(&p, 1, 1.5, err, sizeof err), SW_OK);
        if (kinds & 1) {
            sw_spring *sp = sw_particles_add_springs(&p, 1);
            *sp = (sw_spring){ .a = 0, .b = -1, .k = 40, .c = kinds & 2 ? 0.6 : 0.0, .rest = 0.8, .ax = 0.25,
                               .ay = -0.5 };
        }
        if (kinds & 4)
            ck_assert_int_eq(sw_particles_add_central(&p, -0.1, 0.2, 1.7), SW_OK);
        if (kinds & 8)
            ck_assert_int_eq(sw_particles_add_gravity(&p, 0.3, -9.81), SW_OK);
        if (kinds & 16)
            ck_assert_int_eq(sw_particles_add_drag(&p, 0.35), SW_OK);
        if (kinds & 32)
            ck_assert_int_eq(sw_particles_add_gravity(&p, 0.0, 1.0), SW_OK);
        ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
        /* a gravity after another or after drag is a pass of its own, which
         * the small path does not model (a first one before drag is fused) */
        ck_assert_int_eq(swp_deriv_is_small(&p), !((kinds & 32) && (kinds & (8 | 16))));
        double edge[][2] = { { 0.25, -0.5 }, { 0.25 + 1e-160, -0.5 }, { -0.1, 0.2 }, { NAN, 0.5 } };
        for (int trial = 0; trial < 24; trial++) {
            for (int j = 0; j < 4; j++)
                y[j] = 2.0 * scramble(&seed);
            if (trial >= 20)
                y[0] = edge[trial - 20][0], y[1] = edge[trial - 20][1];
            int unused = 0;
            ck_assert_msg(small_vs_generic(&p, y, &unused) == 0, "kinds %d trial %d", kinds, trial);
        }
        sw_particles_free(&p);
    }
}
END_TEST

/* The small chain's fused derivative (particles_chain.c) against the
 * generic passes, bit for bit (memcmp: a NaN's bits too), on chains of 2
 * to 16 beads and up to its limit (odd and even), damped or not, with
 * gravity (sideways too) and drag or not,
 * unequal masses, at random states and at the edges: two beads coincident
 * and 1e-160 apart (the fused path hands these to the generic passes, with
 * their hypot), a bead blown up to infinity (inf and NaN forces through
 * the fused path), a NaN position. The fused path itself must finish
 * most of the evaluations, and the chain keeps its fused rk4. */
START_TEST(line_path_matches_generic)
{
    static const int sizes[] = { 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 33, 100, 127, SWP_LINE_BEADS };
    unsigned long long seed = 99;
    int fast = 0, evals = 0;
    for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
        for (int kinds = 0, n = sizes[z]; kinds < 8; kinds++) {
            sw_particles p;
            char err[SW_ERRLEN];
            layout_chain(&p, n, kinds & 1 ? 0.75 : 0.0, 0, 0, 0);
            if (kinds & 2)
                ck_assert_int_eq(sw_particles_add_gravity(&p, n % 2 ? 0.0 : 0.3, -9.81), SW_OK);
            if (kinds & 4)
                ck_assert_int_eq(sw_particles_add_drag(&p, 0.2), SW_OK);
            ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
            for (int i = 0; i < n; i++) {
                p.mass[i] = 1.0 + 0.5 * scramble(&seed);
                p.inv_mass[i] = 1.0 / p.mass[i];
            }
            ck_assert(!swp_deriv_is_small(&p));
            ck_assert(p.model->line != NULL);
            ck_assert_int_eq(p.model->chain, 1);
            for (int trial = 0; trial < 14; trial++) {
                for (int i = 0; i < 4 * n; i++)
                    y[i] = (i < 2 * n ? 0.1 * (i / 2) * (i % 2 == 0) : 0.0) + 0.05 * scramble(&seed);
                int b = trial % n;
                if (trial == 10)
                    y[2 * b] = y[2 * (n - 1 - b)], y[2 * b + 1] = y[2 * (n - 1 - b) + 1];
                if (trial == 11)
                    y[2 * b] = y[2 * ((b + 1) % n)] + 1e-160, y[2 * b + 1] = y[2 * ((b + 1) % n) + 1];
                if (trial == 12)
                    y[2 * b + trial % 2] = INFINITY, y[2 * n + 2 * b] = -INFINITY;
                if (trial == 13)
                    y[2 * b + 1] = NAN;
                p.ode.deriv(p.ode.ctx, 0.0, y, got);
                swp_deriv_generic(&p, 0.0, y, want);
                for (int i = 0; i < 4 * n; i++)
                    ck_assert_msg(memcmp(&got[i], &want[i], sizeof got[i]) == 0,
                                  "n %d kinds %d trial %d component %d: fused %.17g, generic %.17g", n, kinds, trial,
                                  i, got[i], want[i]);
                fast += p.model->line(&p, y, got);
                evals++;
            }
            sw_particles_free(&p);
        }
    ck_assert_int_ge(fast, evals * 11 / 14);
    sw_particles p; /* one bead more: the generic passes */
    char err[SW_ERRLEN];
    layout_chain(&p, SWP_LINE_BEADS + 1, 0.75, 0, 0, 0);
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    ck_assert(p.model->line == NULL);
    sw_particles_free(&p);
}
END_TEST

Suite *make_derivative_suite(void);
Suite *make_derivative_suite(void)
{
    Suite *s = suite_create("derivative");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, derivative_matches_plain);
    tcase_add_test(tc, derivative_any_order);
    tcase_add_test(tc, finish_names_bad_spring);
    tcase_add_test(tc, later_force_and_zero_length);
    tcase_add_test(tc, regular_chain_matches_plain);
    tcase_add_test(tc, compact_layouts_match_plain);
    tcase_add_test(tc, small_path_matches_generic);
    tcase_add_test(tc, line_path_matches_generic);
    suite_add_tcase(s, tc);
    return s;
}
