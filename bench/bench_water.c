/* Water at scale (issue 40): the time of one evaluation of the water
 * scene's derivative (SPH, engine/force_sph.c: density and forces over
 * neighbours from a Verlet list built from a cell list) at its dam break
 * of n = 1e3, 1e4, 1e5 particles, twice: with the list kept (as between
 * builds) and built at every evaluation (skin 0: the cell list walked each
 * time); the exponent of n fitted for each (1 for a cell list; 2 for all
 * pairs), and the allocations the timed evaluations made (none). */
#include <stdio.h>
#include <stdlib.h>

#include "alloc_count.h"
#include "bench_common.h"
#include "engine/forces.h"
#include "stepwise/stepwise.h"

static const sw_force *sph_of(const sw_system *sys)
{
    for (int i = 0; i < sys->particles.nforces; i++)
        if (sys->particles.forces[i].kind == SW_FORCE_SPH)
            return &sys->particles.forces[i];
    return NULL;
}

void bench_water(int repeats, int quick)
{
    double ns[3] = { 1e3, 1e4, 1e5 }, t[2][3] = { { 0 } };
    int sizes = quick ? 2 : 3;
    long allocs = 0, a;
    const sw_scene *sc = sw_scene_find("water");
    printf("\nwater: one SPH evaluation, neighbours from a cell list (seconds, median of %d):\n"
           "the Verlet list kept, and built at every evaluation\n", repeats);
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
        t[0][s] = bench_time_eval(&sys.particles, dydt, repeats, quick ? 0.02 : 0.2, &a);
        allocs += a;
        swp_sph_set_skin(sph_of(&sys), 0); /* every evaluation builds */
        t[1][s] = bench_time_eval(&sys.particles, dydt, repeats, quick ? 0.02 : 0.2, &a);
        allocs += a;
        ns[s] = sys.n; /* the lattice's own count */
        printf("  n = %-7d kept %.3g s (%.3g us a particle), built %.3g s (%.3g us a particle)\n", sys.n, t[0][s],
               1e6 * t[0][s] / sys.n, t[1][s], 1e6 * t[1][s] / sys.n);
        free(dydt);
        sw_system_free(&sys);
    }
    printf("  fitted exponent of n: %.2f (a cell list: 1; every pair: 2), the list kept\n", bench_fit(ns, t[0], sizes));
    printf("  fitted exponent of n: %.2f (a cell list: 1; every pair: 2), built every evaluation\n",
           bench_fit(ns, t[1], sizes));
    printf("  allocations during the timed evaluations: %ld\n", allocs);
}
