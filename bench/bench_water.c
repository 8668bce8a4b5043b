/* Water at scale (issue 40): the time of one evaluation of the water
 * scene's derivative (SPH, engine/force_sph.c: density and forces over
 * neighbours found in a cell list) at its dam break of n = 1e3, 1e4, 1e5
 * particles, the exponent of n fitted (1 for a cell list; 2 for all
 * pairs), and the allocations the timed evaluations made (none). */
#include <stdio.h>
#include <stdlib.h>

#include "alloc_count.h"
#include "bench_common.h"
#include "stepwise/stepwise.h"

void bench_water(int repeats, int quick)
{
    double ns[3] = { 1e3, 1e4, 1e5 }, t[3] = { 0 };
    int sizes = quick ? 2 : 3;
    long allocs = 0, a;
    const sw_scene *sc = sw_scene_find("water");
    printf("\nwater: one SPH evaluation, neighbours from a cell list (seconds, median of %d)\n", repeats);
    for (int s = 0; s < sizes; s++) {
        double p[SW_MAX_PARAMS];
        char err[SW_ERRLEN];
        sw_system sys;
        sw_scene_defaults(sc, p);
        p[sw_scene_param_index(sc, "n")] = ns[s];
        if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK) {
            printf("  n = %.0f: %s\n", ns[s], err);
            return;
        }
        double *dydt = malloc((size_t)sys.ode->dim * sizeof *dydt);
        if (!dydt) {
            sw_system_free(&sys);
            return;
        }
        t[s] = bench_time_eval(&sys.particles, dydt, repeats, quick ? 0.02 : 0.2, &a);
        allocs += a;
        ns[s] = sys.n; /* the lattice's own count */
        printf("  n = %-7d %.3g s (%.3g us a particle)\n", sys.n, t[s], 1e6 * t[s] / sys.n);
        free(dydt);
        sw_system_free(&sys);
    }
    printf("  fitted exponent of n: %.2f (a cell list: 1; every pair: 2)\n", bench_fit(ns, t, sizes));
    printf("  allocations during the timed evaluations: %ld\n", allocs);
}
