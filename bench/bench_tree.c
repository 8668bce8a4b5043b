/* The galaxy at scale (issue 27): the time of one evaluation of softened
 * mutual gravity, Barnes-Hut (force_tree.c) at θ = 0.3, 0.5, 0.7 against
 * the direct sum, on one disc like the galaxy scene's (a core of mass 1,
 * stars of 0.05/n from r = 0.3 to 1 at golden-angle steps, softening
 * 0.01) of n = 1e3, 1e4, 1e5 bodies; the exponent of n fitted to each, the
 * tree's relative RMS force error against the direct sum, and the
 * allocations the timed evaluations made (none). Medians of repeats. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc_count.h"
#include "bench_common.h"
#include "stepwise/stepwise.h"

/* One disc of n bodies under the tree (theta > 0) or the direct sum. */
static int disc(sw_particles *p, int n, double theta)
{
    char err[SW_ERRLEN];
    if (sw_particles_init(p, n, 1.0, err, sizeof err) != SW_OK)
        return -1;
    double golden = 3.141592653589793 * (3.0 - sqrt(5.0));
    p->y[0] = p->y[1] = 0;
    for (int k = 1; k < n; k++) {
        double r = 0.3 + 0.7 * (k - 0.5) / (n - 1), a = k * golden;
        p->mass[k] = 0.05 / (n - 1);
        p->inv_mass[k] = 1.0 / p->mass[k];
        p->y[2 * k] = r * cos(a);
        p->y[2 * k + 1] = r * sin(a);
    }
    sw_force g = { .kind = theta > 0 ? SW_FORCE_TREE : SW_FORCE_MUTUAL, .mu = 1.0, .soft = 0.01, .theta = theta };
    if (sw_particles_add_force(p, &g) != SW_OK || sw_particles_finish(p, err, sizeof err) != SW_OK) {
        sw_particles_free(p);
        return -1;
    }
    return 0;
}

double bench_time_eval(sw_particles *p, double *dydt, int repeats, double least, long *allocs)
{
    double t[MAX_REPEATS];
    p->ode.deriv(p, 0.0, p->y, dydt); /* warm */
    long before = sw_test_allocations();
    for (int r = 0; r < repeats; r++) {
        long k = 0;
        double t0 = now_seconds(), t1;
        do {
            p->ode.deriv(p, 0.0, p->y, dydt);
            k++;
        } while ((t1 = now_seconds()) - t0 < least);
        t[r] = (t1 - t0) / (double)k;
    }
    *allocs = sw_test_allocations() - before;
    return median(t, repeats);
}

double bench_fit(const double *n, const double *t, int m)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int k = 0;
    for (int i = 0; i < m; i++)
        if (t[i] > 0) {
            double x = log(n[i]), y = log(t[i]);
            sx += x, sy += y, sxx += x * x, sxy += x * y, k++;
        }
    return k < 2 ? NAN : (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

void bench_tree(int repeats, int quick)
{
    static const double thetas[] = { 0.3, 0.5, 0.7 };
    double ns[3] = { 1e3, 1e4, 1e5 }, t_tree[3][3] = { { 0 } }, t_direct[3] = { 0 }, err[3][3] = { { 0 } };
    int sizes = quick ? 2 : 3;
    long allocs = 0, a;
    printf("\nBarnes-Hut against the direct sum (one disc, softening 0.01; seconds per evaluation, median of %d)\n",
           repeats);
    printf("  %-8s %-12s %-22s %-22s %-22s\n", "n", "direct", "theta 0.3 (error)", "theta 0.5 (error)",
           "theta 0.7 (error)");
    for (int s = 0; s < sizes; s++) {
        int n = (int)ns[s];
        sw_particles d, t;
        double *ref = malloc((size_t)4 * n * sizeof *ref), *got = malloc((size_t)4 * n * sizeof *got);
        if (!ref || !got || disc(&d, n, 0) != 0) {
            printf("  %-8d out of memory\n", n);
            free(ref), free(got);
            return;
        }
        d.ode.deriv(&d, 0.0, d.y, ref);
        if (n <= 10000) { /* 1e5: 5e9 pairs an evaluation, ~20 s; extrapolated below */
            t_direct[s] = bench_time_eval(&d, got, repeats, quick ? 0.02 : 0.2, &a);
            allocs += a;
        }
        char cells[3][32];
        for (int k = 0; k < 3; k++) {
            if (disc(&t, n, thetas[k]) != 0)
                continue;
            t_tree[k][s] = bench_time_eval(&t, got, repeats, quick ? 0.02 : 0.2, &a);
            allocs += a;
            double num = 0, den = 0;
            for (int i = 2 * n; i < 4 * n; i++)
                num += (got[i] - ref[i]) * (got[i] - ref[i]), den += ref[i] * ref[i];
            err[k][s] = sqrt(num / den);
            snprintf(cells[k], sizeof cells[k], "%.3g s (%.2g)", t_tree[k][s], err[k][s]);
            sw_particles_free(&t);
        }
        char direct[32];
        if (t_direct[s] > 0)
            snprintf(direct, sizeof direct, "%.3g s", t_direct[s]);
        else
            snprintf(direct, sizeof direct, "~%.2g s (n^2)", t_direct[s - 1] * (ns[s] / ns[s - 1]) * (ns[s] / ns[s - 1]));
        printf("  %-8d %-12s %-22s %-22s %-22s\n", n, direct, cells[0], cells[1], cells[2]);
        sw_particles_free(&d);
        free(ref), free(got);
    }
    double nlogn = 1 + log(log(ns[sizes - 1]) / log(ns[0])) / log(ns[sizes - 1] / ns[0]);
    printf("  fitted exponent of n: direct %.2f; tree theta 0.3 %.2f, 0.5 %.2f, 0.7 %.2f (n log n over the same "
           "n: %.2f)\n",
           bench_fit(ns, t_direct, sizes), bench_fit(ns, t_tree[0], sizes), bench_fit(ns, t_tree[1], sizes), bench_fit(ns, t_tree[2], sizes),
           nlogn);
    printf("  allocations during the timed evaluations: %ld\n", allocs);
}

int bench_tree_probe(const char *n_arg, const char *theta_arg, const char *evals_arg)
{
    char *end_n, *end_t, *end_e;
    long n = strtol(n_arg, &end_n, 10), evals = strtol(evals_arg, &end_e, 10);
    double theta = strtod(theta_arg, &end_t);
    if (*end_n || *end_t || *end_e || n < 2 || n > 1000000 || !(theta > 0 && theta <= 1) || evals < 0 || evals > 1000) {
        fprintf(stderr, "stepwise: --tree-probe N THETA EVALS takes N in [2, 1000000], THETA in (0, 1], EVALS in "
                        "[0, 1000]; not '%.20s %.20s %.20s'\n", n_arg, theta_arg, evals_arg);
        return 2;
    }
    sw_particles p;
    if (disc(&p, (int)n, theta) != 0)
        return 1;
    double *dydt = malloc((size_t)4 * n * sizeof *dydt);
    for (int k = 0; dydt && k < evals; k++)
        p.ode.deriv(&p, 0.0, p.y, dydt);
    int bad = !dydt;
    free(dydt);
    sw_particles_free(&p);
    return bad;
}
