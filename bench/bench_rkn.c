/* Methods for x'' = f(x) at equal error (issue 27): the Runge-Kutta-Nyström
 * pair rkn and the symplectic composition yoshida4 against dop853, rk45 and
 * verlet on the undamped chain and the orbit (e = 0.5 and 0.9). For each
 * error target and method, the cheapest setting whose largest error over
 * the state at the report time is within the target (fixed steps: fewest
 * steps; adaptive: loosest rtol = atol), found by search as bench_peer.c
 * does; then every method's run timed in paired, interleaved repeats
 * (medians, and the median of each run's time over rkn's in the same
 * round). Also: what evaluating the acceleration through the whole
 * derivative costs rkn (the v half it copies), the bound on what an
 * acceleration-only path could save. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bench_common.h"
#include "stepwise/sim.h"

typedef struct rkn_problem {
    const char *label, *scene, *sets;
    const sw_scene *sc;
    double p[SW_MAX_PARAMS], T;
    int dim;
    double *ref, *y;
    const char *source;
} rkn_problem;

typedef struct rkn_method {
    const char *name;
    const sw_integrator *m;
    int fixed;
    double setting, error, seconds, ratio;
    long evals;
    int ok;
} rkn_method;

/* One run of m to T (setting: steps, or rtol = atol); its error. */
static int run(rkn_problem *pb, const sw_integrator *m, int fixed, double setting, double *error, double *seconds,
               long *evals)
{
    char err[SW_ERRLEN];
    sw_sim s;
    *error = INFINITY;
    if (sw_sim_init(&s, pb->sc, pb->p, m, fixed ? pb->T / setting : pb->T, err, sizeof err) != SW_OK)
        return -1;
    if (!fixed)
        sw_sim_set_tolerances(&s, setting, setting);
    double t0 = now_seconds();
    int blown = sw_sim_run_until(&s, pb->T);
    *seconds = now_seconds() - t0;
    *evals = sw_sim_evals(&s);
    memcpy(pb->y, s.sys.y, (size_t)pb->dim * sizeof *pb->y);
    sw_sim_free(&s);
    if (blown)
        return -1;
    *error = bench_max_diff(pb->dim, pb->y, pb->ref);
    return 0;
}

#define MAX_STEPS (1L << 23)

/* The cheapest setting reaching target: fewest fixed steps (doubling, then
 * bisection to 0.4 %), or the loosest tolerance (quarter decades from 100
 * times the target down, then bisection to 1/32 decade). */
static void search(rkn_problem *pb, rkn_method *c, double target)
{
    double e, sec;
    long ev;
    c->ok = 0;
    if (c->fixed) {
        long lo = 0, hi = 8;
        while (hi <= MAX_STEPS && (run(pb, c->m, 1, (double)hi, &e, &sec, &ev) != 0 || !(e <= target)))
            lo = hi, hi *= 2;
        if (hi > MAX_STEPS)
            return;
        while (hi - lo > 1 && hi - lo > hi / 256) {
            long mid = lo + (hi - lo) / 2;
            if (run(pb, c->m, 1, (double)mid, &e, &sec, &ev) == 0 && e <= target)
                hi = mid;
            else
                lo = mid;
        }
        c->setting = (double)hi;
    } else {
        int k;
        for (k = 0; k <= 40; k++) {
            double tol = 100.0 * target * pow(10.0, -0.25 * k);
            if (tol < 1e-14)
                return;
            if (run(pb, c->m, 0, tol, &e, &sec, &ev) == 0 && e <= target)
                break;
        }
        if (k > 40)
            return;
        double hit = 100.0 * target * pow(10.0, -0.25 * k), miss = hit * pow(10.0, 0.25);
        for (int b = 0; k > 0 && b < 3; b++) {
            double mid = sqrt(hit * miss);
            if (run(pb, c->m, 0, mid, &e, &sec, &ev) == 0 && e <= target)
                hit = mid;
            else
                miss = mid;
        }
        c->setting = hit;
    }
    run(pb, c->m, c->fixed, c->setting, &c->error, &sec, &c->evals);
    c->ok = 1;
}

/* Paired, interleaved timing: each round runs every method found once, in
 * order; medians of the times and of each time over rkn's (method 0) in
 * its round. */
static void timed(rkn_problem *pb, rkn_method *c, int n, int repeats)
{
    double t[8][MAX_REPEATS], r[8][MAX_REPEATS], e;
    long ev;
    for (int k = 0; k < repeats; k++)
        for (int i = 0; i < n; i++)
            if (c[i].ok)
                run(pb, c[i].m, c[i].fixed, c[i].setting, &e, &t[i][k], &ev);
    for (int i = 0; i < n; i++) {
        if (!c[i].ok)
            continue;
        for (int k = 0; k < repeats; k++)
            r[i][k] = t[i][k] / t[0][k];
        c[i].ratio = c[0].ok ? median(r[i], repeats) : NAN;
        c[i].seconds = median(t[i], repeats);
    }
}

/* The problem: scene, parameters, report time, reference state (the exact
 * solution, or dop853 at 1e-14; the note says how far rkn at 1e-13 is). */
static int problem_init(rkn_problem *pb)
{
    char err[SW_ERRLEN], sets[64];
    sw_system sys;
    pb->sc = sw_scene_find(pb->scene);
    sw_scene_defaults(pb->sc, pb->p);
    snprintf(sets, sizeof sets, "%s", pb->sets);
    for (char *tok = strtok(sets, " "); tok; tok = strtok(NULL, " "))
        if (sw_scene_set(pb->sc, pb->p, tok, err, sizeof err) != SW_OK)
            return -1;
    if (sw_system_build(&sys, pb->sc, pb->p, err, sizeof err) != SW_OK)
        return -1;
    pb->T = pb->sc->duration;
    pb->dim = sys.ode->dim;
    pb->ref = calloc((size_t)pb->dim, sizeof *pb->ref);
    pb->y = calloc((size_t)pb->dim, sizeof *pb->y);
    int exact = pb->sc->exact && pb->sc->exact(&sys, pb->T, pb->ref) == 0;
    sw_system_free(&sys);
    double e, sec;
    long ev;
    if (!exact) {
        pb->source = "dop853 at 1e-14";
        for (int i = 0; i < pb->dim; i++)
            pb->ref[i] = 0;
        if (run(pb, sw_integrator_find("dop853"), 0, 1e-14, &e, &sec, &ev) != 0)
            return -1;
        memcpy(pb->ref, pb->y, (size_t)pb->dim * sizeof *pb->ref);
    } else {
        pb->source = "exact";
    }
    run(pb, sw_integrator_find("rkn"), 0, 1e-13, &e, &sec, &ev);
    printf("  %s (%s): T = %g, state %d, reference %s; rkn at 1e-13 differs from it by %.1e\n", pb->label,
           pb->sets, pb->T, pb->dim, pb->source, e);
    return 0;
}

/* The derivative's cost per call against copying the v half (dim/2
 * doubles): what the generic path costs rkn beyond the accelerations. */
static void copy_share(const char *scene, const char *sets)
{
    char err[SW_ERRLEN];
    sw_system sys;
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = sw_scene_find(scene);
    sw_scene_defaults(sc, p);
    if (sets && sw_scene_set(sc, p, sets, err, sizeof err) != SW_OK)
        return;
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK)
        return;
    int dim = sys.ode->dim, half = dim / 2;
    double *out = calloc((size_t)dim, sizeof *out), deriv = INFINITY, copy = INFINITY;
    long calls = 1 + 400000 / dim;
    for (int r = 0; r < 5; r++) {
        double t0 = now_seconds();
        for (long i = 0; i < calls; i++)
            sys.ode->deriv(sys.ode->ctx, 0.0, sys.y, out);
        deriv = fmin(deriv, (now_seconds() - t0) / (double)calls);
        t0 = now_seconds();
        for (long i = 0; i < calls; i++) {
            memcpy(out, sys.y + half, (size_t)half * sizeof *out);
            __asm__ volatile("" : : "r"(out) : "memory"); /* keep the copy */
        }
        copy = fmin(copy, (now_seconds() - t0) / (double)calls);
    }
    printf("  | %s %s | %d | %.3g | %.3g | %.1f %% |\n", scene, sets ? sets : "", dim, deriv * 1e9, copy * 1e9,
           100 * copy / deriv);
    free(out);
    sw_system_free(&sys);
}

void bench_rkn(int repeats, int quick)
{
    static rkn_problem probs[] = {
        { .label = "chain", .scene = "chain", .sets = "c=0" },
        { .label = "orbit", .scene = "orbit", .sets = "e=0.5" },
        { .label = "orbit", .scene = "orbit", .sets = "e=0.9" },
    };
    const char *names[] = { "rkn", "rkn12", "dop853", "rk45", "yoshida4", "verlet" };
    const double targets[] = { 1e-3, 1e-6, 1e-9 };
    int nt = quick ? 1 : 3, nm = (int)(sizeof names / sizeof names[0]);
    if (repeats < 5)
        repeats = 5;
    printf("x'' = f(x) at equal error (issue 27): error = largest |y - y_ref| over the state at the report\n"
           "time T; each method's cheapest setting (fixed: fewest steps; adaptive: loosest rtol = atol, to\n"
           "1/32 decade); %d paired, interleaved rounds; time: median us; ratio: median of time / rkn's\n", repeats);
    printf("  | problem | error | method | setting | evals | time us | time / rkn |\n"
           "  | --- | --- | --- | --- | --- | --- | --- |\n");
    for (size_t q = 0; q < sizeof probs / sizeof probs[0]; q++) {
        rkn_problem *pb = &probs[q];
        if (problem_init(pb) != 0) {
            printf("  %s: could not be built\n", pb->label);
            continue;
        }
        for (int e = 0; e < nt; e++) {
            rkn_method c[sizeof names / sizeof names[0]];
            for (int i = 0; i < nm; i++) {
                const sw_integrator *m = sw_integrator_find(names[i]);
                c[i] = (rkn_method){ .name = names[i], .m = m, .fixed = m && !(m->flags & SW_ADAPTIVE) };
                if (m)
                    search(pb, &c[i], targets[e]);
            }
            timed(pb, c, nm, repeats);
            for (int i = 0; i < nm; i++) {
                char setting[32];
                if (!c[i].ok) {
                    printf("  | %s %s | %.0e | %s | not reached (%ld steps) | | | |\n", pb->label, pb->sets,
                           targets[e], c[i].name, MAX_STEPS);
                    continue;
                }
                snprintf(setting, sizeof setting, c[i].fixed ? "%.0f steps" : "tol %.2g", c[i].setting);
                printf("  | %s %s | %.0e | %s | %s | %ld | %.0f | %.2f |\n", pb->label, pb->sets, targets[e],
                       c[i].name, setting, c[i].evals, c[i].seconds * 1e6, c[i].ratio);
            }
            fflush(stdout);
        }
        free(pb->ref);
        free(pb->y);
    }
    printf("\n  rkn evaluates a(x) through the whole derivative [v | a]: the v half is a copy the\n"
           "  acceleration does not need. Its cost against one evaluation (least of 5 batches):\n"
           "  | system | state | derivative ns | copy of v ns | share |\n  | --- | --- | --- | --- | --- |\n");
    copy_share("orbit", NULL);
    copy_share("chain", "c=0");
    copy_share("chain", "n=1000");
    copy_share("galaxy", NULL);
    printf("\n");
}
