/* Implicit steps against rk4 (issues 26, 41): ns per particle-step of the
 * three Newton and linearly implicit methods, of rodas4 (one accepted
 * step of at most dt a call) and of rk4 on the chain, timed in
 * turn within each repeat so that load from other processes falls on all
 * alike; the ratio to rk4 is taken per repeat (paired), and its median and
 * range are printed with the solves and Newton iterations per step. The
 * targets (docs/performance.md) are in instructions (bench/instructions.sh). */
#include <math.h>
#include <stdio.h>

#include "bench_common.h"
#include "engine/stepper.h"
#include "stepwise/sim.h"

enum { NM = 5 };

void bench_implicit(int repeats, int chain_n, double target)
{
    const char *names[NM] = { "rk4", "implicit-euler", "implicit-midpoint", "linear-implicit-euler", "rodas4" };
    const sw_scene *sc = sw_scene_find("chain");
    double p[SW_MAX_PARAMS], ns[NM][MAX_REPEATS], ratio[NM][MAX_REPEATS], t[NM] = { 0 };
    long k[NM], solves0[NM], iters0[NM];
    sw_sim s[NM];
    char err[SW_ERRLEN], set[32];
    sw_scene_defaults(sc, p);
    snprintf(set, sizeof set, "n=%d", chain_n);
    if (repeats > MAX_REPEATS || sw_scene_set(sc, p, set, err, sizeof err) != SW_OK)
        return;
    for (int i = 0; i < NM; i++) {
        if (sw_sim_init(&s[i], sc, p, sw_integrator_find(names[i]), sc->dt, err, sizeof err) != SW_OK) {
            printf("implicit steps: %s\n", err);
            while (i-- > 0)
                sw_sim_free(&s[i]);
            return;
        }
        /* steps per repeat for about `target` seconds, from three steps */
        double t0 = now_seconds();
        for (int j = 0; j < 3; j++)
            sw_stepper_step(s[i].stepper, s[i].sys.ode, &t[i], s[i].sys.y, sc->dt);
        double per = fmax((now_seconds() - t0) / 3, 1e-9), want = target / per;
        k[i] = want < 1 ? 1 : want > 1e7 ? 10000000L : (long)want;
        solves0[i] = s[i].sys.ode->solves;
        iters0[i] = s[i].stepper->newton_iters;
    }
    for (int r = 0; r < repeats; r++)
        for (int i = 0; i < NM; i++) {
            double t0 = thread_seconds(); /* this thread's CPU: other programs' turns left out */
            for (long j = 0; j < k[i]; j++)
                sw_stepper_step(s[i].stepper, s[i].sys.ode, &t[i], s[i].sys.y, sc->dt);
            ns[i][r] = (thread_seconds() - t0) / ((double)k[i] * chain_n) * 1e9;
            ratio[i][r] = ns[i][r] / ns[0][r];
        }
    printf("implicit steps: chain n = %d, dt = %g, thread-CPU ns per particle-step (sw_stepper_step), median\n"
           "  of %d repeats; x rk4 = the paired ratio to rk4 timed in the same repeat, median\n"
           "  [min, max]; solves and Newton iterations per step\n\n", chain_n, sc->dt,
           repeats);
    printf("  %-22s %9s %8s %17s %7s %7s\n", "method", "ns", "x rk4", "range", "solves", "newton");
    for (int i = 0; i < NM; i++) {
        double lo = ratio[i][0], hi = ratio[i][0], steps = (double)k[i] * repeats;
        for (int r = 1; r < repeats; r++)
            lo = fmin(lo, ratio[i][r]), hi = fmax(hi, ratio[i][r]);
        printf("  %-22s %9.3g %8.2f     [%5.2f, %5.2f] %7.2f %7.2f\n", names[i], median(ns[i], repeats),
               median(ratio[i], repeats), lo, hi, (double)(s[i].sys.ode->solves - solves0[i]) / steps,
               (double)(s[i].stepper->newton_iters - iters0[i]) / steps);
        sw_sim_free(&s[i]);
    }
    printf("\n");
}
