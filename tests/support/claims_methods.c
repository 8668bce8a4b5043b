/* Claims: yoshida4's and the Barnes-Hut tree's figures in
 * docs/performance.md and docs/scenes.md (issue 27), recomputed: the
 * tree's force error against the direct sum and its net force, yoshida4's
 * energy error over 1000 orbits and its stability limit. Timings are not
 * claims (they are the machine's); every other figure of those sections is. */
#include "claims.h"

#include <stdint.h>

#define PERF "docs/performance.md"
#define SCENES "docs/scenes.md"

/* ---- Barnes-Hut -------------------------------------------------------- */

/* Accelerations (2n, malloc'd) of n bodies (positions xy, masses m) under
 * softened gravity, G = 1, by the tree at theta (0: the direct sum). */
static double *accelerations(int n, const double *xy, const double *m, double soft, double theta)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, n, 1.0, err, sizeof err), SW_OK);
    for (int i = 0; i < n; i++)
        p.mass[i] = m[i], p.inv_mass[i] = 1.0 / m[i];
    memcpy(p.y, xy, (size_t)2 * n * sizeof *xy);
    sw_force g = { .kind = theta > 0 ? SW_FORCE_TREE : SW_FORCE_MUTUAL, .mu = 1.0, .soft = soft, .theta = theta };
    ck_assert_int_eq(sw_particles_add_force(&p, &g), SW_OK);
    double *dydt = malloc((size_t)4 * n * sizeof *dydt), *a = malloc((size_t)2 * n * sizeof *a);
    ck_assert(dydt && a);
    p.ode.deriv(&p, 0.0, p.y, dydt);
    memcpy(a, dydt + 2 * n, (size_t)2 * n * sizeof *a);
    free(dydt);
    sw_particles_free(&p);
    return a;
}

/* The bodies: 0, the scene's two galaxies of `size` stars each (2size + 2
 * bodies; above 2000 stars at theta 0.5, which the scene needs there);
 * 1, `size` equal bodies uniform in the unit square (the LCG of
 * tests/check_tree.c). Returns n; xy and m malloc'd. */
static int bodies_of(int which, int size, double **xy, double **m)
{
    if (which == 0) {
        sw_sim s;
        char sets[64];
        snprintf(sets, sizeof sets, "n=%d discs=2%s", size, size > 2000 ? " theta=0.5" : "");
        cl_sim_init(&s, "galaxy", sets, "verlet", 0.01);
        int n = s.sys.particles.n;
        *xy = malloc((size_t)2 * n * sizeof **xy), *m = malloc((size_t)n * sizeof **m);
        ck_assert(*xy && *m);
        memcpy(*xy, s.sys.y, (size_t)2 * n * sizeof **xy);
        memcpy(*m, s.sys.particles.mass, (size_t)n * sizeof **m);
        sw_sim_free(&s);
        return n;
    }
    int n = size;
    *xy = malloc((size_t)2 * n * sizeof **xy), *m = malloc((size_t)n * sizeof **m);
    ck_assert(*xy && *m);
    uint64_t z = 12345;
    for (int i = 0; i < 2 * n; i++) {
        z = z * 6364136223846793005ull + 1442695040888963407ull;
        (*xy)[i] = (double)(z >> 11) / 9007199254740992.0;
    }
    for (int i = 0; i < n; i++)
        (*m)[i] = 1.0 / n;
    return n;
}

/* 0: two galaxies of 2000 stars (4002 bodies); 1: a cloud of 4000. */
static int bodies(int which, double **xy, double **m) { return bodies_of(which, which == 0 ? 2000 : 4000, xy, m); }

/* Relative RMS error of the tree's accelerations, or (net = 1) its net
 * force |Σ m a| / Σ |m a|. */
static double tree_figure(int which, double theta, int net)
{
    double *xy, *m, soft = which == 0 ? 0.1 : 0.01, r = 0;
    int n = bodies(which, &xy, &m);
    double *t = accelerations(n, xy, m, soft, theta);
    if (net) {
        double px = 0, py = 0, size = 0;
        for (int i = 0; i < n; i++) {
            px += m[i] * t[2 * i], py += m[i] * t[2 * i + 1];
            size += m[i] * hypot(t[2 * i], t[2 * i + 1]);
        }
        r = hypot(px, py) / size;
    } else {
        double *d = accelerations(n, xy, m, soft, 0), num = 0, den = 0;
        for (int i = 0; i < 2 * n; i++)
            num += (t[i] - d[i]) * (t[i] - d[i]), den += d[i] * d[i];
        r = sqrt(num / den);
        free(d);
    }
    free(t), free(xy), free(m);
    return r;
}

static double net_03(void) { return tree_figure(0, 0.3, 1); }
static double net_05(void) { return tree_figure(0, 0.5, 1); }
static double net_07(void) { return tree_figure(0, 0.7, 1); }
static double gal_03(void) { return tree_figure(0, 0.3, 0); }
static double gal_05(void) { return tree_figure(0, 0.5, 0); }
static double gal_07(void) { return tree_figure(0, 0.7, 0); }
static double cloud_03(void) { return tree_figure(1, 0.3, 0); }
static double cloud_05(void) { return tree_figure(1, 0.5, 0); }
static double cloud_07(void) { return tree_figure(1, 0.7, 0); }
static double cloud_least(void) { return fmin(cloud_03() / 0.09, fmin(cloud_05() / 0.25, cloud_07() / 0.49)); }
static double cloud_most(void) { return fmax(cloud_03() / 0.09, fmax(cloud_05() / 0.25, cloud_07() / 0.49)); }
static double tiny_theta(void) { return tree_figure(1, 1e-6, 0); }

/* ---- the tree's energy (issue 41) --------------------------------------- */

/* The tree's potential against the direct sum's on the bodies of
 * bodies_e (0: two galaxies of 2500 stars, 5002 bodies; 1: the cloud of
 * 5000): bound (ratio = 0) or bound over the actual error (ratio = 1). */
static double energy_figure(int which, double theta, int ratio)
{
    sw_particles d, t;
    char err[SW_ERRLEN];
    double *xy, *m, soft = which == 0 ? 0.1 : 0.01;
    int n = bodies_of(which, which == 0 ? 2500 : 5000, &xy, &m);
    sw_particles *both[2] = { &d, &t };
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(sw_particles_init(both[k], n, 1.0, err, sizeof err), SW_OK);
        for (int i = 0; i < n; i++)
            both[k]->mass[i] = m[i], both[k]->inv_mass[i] = 1.0 / m[i];
        memcpy(both[k]->y, xy, (size_t)2 * n * sizeof *xy);
        sw_force g = { .kind = k ? SW_FORCE_TREE : SW_FORCE_MUTUAL, .mu = 1.0, .soft = soft, .theta = theta };
        ck_assert_int_eq(sw_particles_add_force(both[k], &g), SW_OK);
    }
    double off = fabs(sw_particles_energy(&t, t.y) - sw_particles_energy(&d, d.y));
    double bound = sw_particles_energy_error(&t, t.y);
    sw_particles_free(&d), sw_particles_free(&t);
    free(xy), free(m);
    return ratio ? bound / off : bound;
}

/* The bound over the error: its least and largest at θ = 0.3, 0.5, 0.7 on both. */
static double bound_ratio(int largest)
{
    static const double thetas[] = { 0.3, 0.5, 0.7 };
    double r = largest ? 0 : INFINITY;
    for (int w = 0; w < 2; w++)
        for (int k = 0; k < 3; k++) {
            double q = energy_figure(w, thetas[k], 1);
            r = largest ? fmax(r, q) : fmin(r, q);
        }
    return r;
}
static double bound_least(void) { return bound_ratio(0); }
static double bound_most(void) { return bound_ratio(1); }

/* The galaxy at n = 1e5, θ = 0.5 as play builds it: the bound on E over
 * |E| in percent (a side), and the status line's ± at t = 0 (both sides). */
static double big_bound_pct(void)
{
    sw_sim s;
    cl_sim_init(&s, "galaxy", "n=100000 theta=0.5", "verlet", 0.01);
    double pct = 100 * sw_sim_energy_error(&s) / fabs(sw_sim_energy(&s));
    sw_sim_free(&s);
    return pct;
}
static double big_drift_bound(void)
{
    sw_sim s;
    cl_sim_init(&s, "galaxy", "n=100000 theta=0.5", "verlet", 0.01);
    double pct = sw_sim_energy_drift_error(&s);
    sw_sim_free(&s);
    return pct;
}

/* The reference's cost per simulated second at n = 1e5 (estimated, no pilot). */
static double big_reference_cost(void)
{
    sw_truth tr;
    char err[SW_ERRLEN];
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = sw_scene_find("galaxy");
    sw_scene_defaults(sc, p);
    ck_assert_int_eq(sw_scene_set(sc, p, "n=100000", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_scene_set(sc, p, "theta=0.5", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_truth_init(&tr, sc, p, err, sizeof err), SW_OK);
    double cost = sw_truth_reference_cost(&tr, sc->duration) / sc->duration;
    sw_truth_free(&tr);
    return cost;
}

/* Verlet's largest |E/E0 - 1| over ten rim orbits at the defaults (n = 100),
 * sampled every 0.5 (tests/check_galaxy.c's galaxy_conservation). */
static double verlet_galaxy_energy(void)
{
    sw_sim s;
    cl_sim_init(&s, "galaxy", NULL, "verlet", 0.01);
    double e0 = sw_sim_energy(&s), worst = 0, half = 5 * TWO_PI;
    for (int w = 0; w < 2; w++) /* two windows of five orbits, as that test samples them */
        for (double t = w * half + 0.5; t <= (w + 1) * half + 1e-9; t += 0.5) {
            sw_sim_run_until(&s, t);
            worst = fmax(worst, fabs(sw_sim_energy(&s) / e0 - 1));
        }
    sw_sim_free(&s);
    return worst;
}

/* ---- yoshida4 ---------------------------------------------------------- */

/* Largest |E/E0 - 1| on the orbit at dt 0.05 over periods [from, to). */
static double orbit_energy(const char *m, double from, double to)
{
    sw_sim s;
    double T = TWO_PI, worst = 0;
    cl_sim_init(&s, "orbit", NULL, m, 0.05);
    double e0 = sw_sim_energy(&s);
    while (s.t < to * T) {
        sw_sim_step(&s);
        if (s.t > from * T && s.t <= to * T)
            worst = fmax(worst, fabs(sw_sim_energy(&s) / e0 - 1));
    }
    sw_sim_free(&s);
    return worst;
}

static double y_last(void) { return orbit_energy("yoshida4", 990, 1000); }
static double y_first(void) { return orbit_energy("yoshida4", 0, 10); }
static double rk4_first(void) { return orbit_energy("rk4", 0, 10); }
static double rk4_last(void) { return orbit_energy("rk4", 990, 1000); }
static double y_wdt(void) { return cl_limit0("spring", "k=1 c=0", "yoshida4"); }
static double y_measured(void) { return cl_stability("spring", "k=1 c=0", "yoshida4").dt; }

const claim sw_claims_m[] = {
    { SCENES, "(the net force is {4.8e-4}, 1.2e-3 and 8.6e-4 of Σ|m a|", net_03, ROUNDED, 0, "θ = 0.3 on the two galaxies, to the text's digits", NULL },
    { SCENES, "(the net force is 4.8e-4, {1.2e-3} and 8.6e-4 of Σ|m a|", net_05, ROUNDED, 0, "θ = 0.5 on the two galaxies", NULL },
    { SCENES, "(the net force is 4.8e-4, 1.2e-3 and {8.6e-4} of Σ|m a|", net_07, ROUNDED, 0, "θ = 0.7 on the two galaxies", NULL },
    { PERF, "(the scene at discs = 2, softening 0.1) {3.9e-5}, 1.1e-4 and 2.7e-4", gal_03, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "(the scene at discs = 2, softening 0.1) 3.9e-5, {1.1e-4} and 2.7e-4", gal_05, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "(the scene at discs = 2, softening 0.1) 3.9e-5, 1.1e-4 and {2.7e-4}", gal_07, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "cloud of 4000 equal bodies (softening 0.01), {0.0037}, 0.011 and 0.026", cloud_03, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "cloud of 4000 equal bodies (softening 0.01), 0.0037, {0.011} and 0.026", cloud_05, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "cloud of 4000 equal bodies (softening 0.01), 0.0037, 0.011 and {0.026}", cloud_07, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "({0.04}–0.05·θ²: the cells'", cloud_least, ROUNDED, 0, "the least error over θ², to the text's digits", NULL },
    { PERF, "(0.04–{0.05}·θ²: the cells'", cloud_most, ROUNDED, 0, "the largest error over θ²", NULL },
    { PERF, "the tree is the direct sum to {1e-12}", tiny_theta, ATMOST, 0, "θ = 1e-6 on the cloud", NULL },
    { SCENES, "over the scale: `energy ≈-0.0113% ±10%`. The bound is {10} to 63 times the", bound_least, ROUNDED, 0, "the least bound/error at θ = 0.3-0.7 on 5002 and 5000 bodies", NULL },
    { SCENES, "over the scale: `energy ≈-0.0113% ±10%`. The bound is 10 to {63} times the", bound_most, ROUNDED, 0, "the largest", NULL },
    { SCENES, "θ = 0.5 it is some {5} % of |E| a side", big_bound_pct, ROUNDED, 0, "the bound over |E| at t = 0, n = 1e5", NULL },
    { SCENES, "error ({5.2e-5} of it over ten orbits at n = 100)", verlet_galaxy_energy, ROUNDED, 0, R_ROUND, NULL },
    { SCENES, "ghost: a reference run would cost some {1e13} state evaluations a", big_reference_cost, MAGNITUDE, 0.5, "the estimate at n = 1e5, to its order of magnitude", NULL },
    { PERF, "the bound on the drift: ±{10} % at n = 1e5, θ = 0.5, at t = 0 already", big_drift_bound, ROUNDED, 0, "the status line's ± at t = 0", NULL },
    { PERF, "({5} % of |E| for E and for E(0))", big_bound_pct, ROUNDED, 0, "the bound over |E| at t = 0, n = 1e5", NULL },
    { PERF, "\"no ghost: a reference run for these parameters would cost {2.4e+13}", big_reference_cost, ROUNDED, 0, "the message's figure", NULL },
    { PERF, "over the last 10 of 1000 periods equals that over the first 10 ({1.28e-4} relative)", y_last, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "over the last 10 of 1000 periods equals that over the first 10 ({1.28e-4} relative)", y_first, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "where rk4's grows from {9.7e-5} to 9.5e-3", rk4_first, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "where rk4's grows from 9.7e-5 to {9.5e-3}", rk4_last, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "and its stable ω·h is {1.573} against", y_wdt, ROUNDED, 0, "the theory's limit", NULL },
    { PERF, "against Verlet's {2} and rk4's 2.83", cl_verlet_wdt, ABS, 1e-6, "Verlet's limit in theory", NULL },
    { PERF, "against Verlet's 2 and rk4's {2.83}", cl_rk4_wdt, ROUNDED, 0, "rk4's limit in theory", NULL },
    { PERF, "| yoshida4 | {1.5643} | 1.564 | 1.573 (root of tr M = 2", y_measured, ROUNDED, 0, "the measured limit at ω = 1", NULL },
    { PERF, "| yoshida4 | 1.5643 | {1.564} | 1.573 (root of tr M = 2", y_measured, ROUNDED, 0, "ω·dt with ω = 1", NULL },
    { PERF, "| yoshida4 | 1.5643 | 1.564 | {1.573} (root of tr M = 2", y_wdt, ROUNDED, 0, "the theory's limit", NULL },
};
const size_t sw_claims_m_n = sizeof sw_claims_m / sizeof sw_claims_m[0];
