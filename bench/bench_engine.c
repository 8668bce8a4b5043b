/* The engine benchmark: ns per particle-step of every integrator on chain
 * (n = 1000) and vortex (n = 100000) beside hand-fused loops that compute
 * the same step with no abstraction (bench_base.c); frame cost (sim +
 * rasterise) per scene; peak RSS; allocations counted in every step loop;
 * and stepwise against GSL at equal accuracy (bench_peer.c). `make bench` builds
 * it as its own program, linked with -Wl,--wrap=malloc,--wrap=calloc,
 * --wrap=realloc so every call from our code goes through the tests'
 * counter (tests/support/alloc_count.c). */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "engine/stepper.h"
#include "stepwise/sim.h"

/* ---- allocation counting ------------------------------------------------- */

#include "alloc_count.h" /* the tests' counter, linked in by `make bench` */
#include "bench_common.h"

/* Allocation calls so far. */
static long alloc_count(void) { return sw_test_allocations(); }
/* How to re-run this binary as a memory probe. */
static const char *const probe_prefix[] = { "--engine" };
#define NPREFIX ((int)(sizeof probe_prefix / sizeof probe_prefix[0]))

typedef struct bench_opts {
    int repeats;
    int chain_n, vortex_n;
    double target;   /* seconds per timed repeat */
} bench_opts;

/* ---- throughput --------------------------------------------------------- */

typedef struct workload {
    const char *scene;
    int n;
} workload;

static int build_params(const sw_scene *sc, int n, double *p)
{
    char err[SW_ERRLEN], set[32];
    sw_scene_defaults(sc, p);
    snprintf(set, sizeof set, "n=%d", n);
    return sw_scene_set(sc, p, set, err, sizeof err);
}

/* Steps per timed repeat so that one repeat takes about `target` seconds. */
static long calibrate(double seconds_per_step, double target)
{
    double k = target / fmax(seconds_per_step, 1e-9);
    return k < 1 ? 1 : k > 1e7 ? 10000000L : (long)k;
}

/* The step size and steps per timed repeat for sim s: calibrated on a few
 * steps to take about `target` seconds, at dt or a tenth of it (down to
 * 1e-6 of it) until a trial of all the timed steps (sim and stepper loops)
 * stays finite. The sim is
 * reset to its start and *dt set on return. */
static long stable_steps(sw_sim *s, double *dt, double target, int repeats)
{
    char err[SW_ERRLEN];
    double t0 = now_seconds();
    for (int j = 0; j < 3; j++)
        sw_sim_step(s);
    long k = calibrate((now_seconds() - t0) / 3.0, target);
    for (int tries = 0; tries < 6; tries++) {
        sw_sim_reset(s, err, sizeof err);
        sw_sim_set_dt(s, *dt, err, sizeof err);
        for (long j = 0; j < 2 * k * repeats && !s->blown; j++)
            sw_sim_step(s);
        if (!s->blown)
            break;
        *dt *= 0.1;
    }
    sw_sim_reset(s, err, sizeof err);
    sw_sim_set_dt(s, *dt, err, sizeof err);
    return k;
}

/* The chain's baseline description for n beads under p (bench_base.c); its
 * force buffer is allocated (NULL when out of memory; the caller frees it). */
static bench_chain chain_baseline(int n, const double *p)
{
    return (bench_chain){ .n = n, .k = p[1], .rest = p[4], .inv_m = 1.0 / p[2], .right_x = (n + 1) * p[4],
                          .f = malloc((size_t)(2 * n + 2) * sizeof(double)) };
}

/* Run a baseline `steps` steps on a copy of y0; 0 when m has none. */
static int run_baseline(const sw_scene *sc, const double *p, const sw_integrator *m, double *y,
                        int n, double h, long steps, bench_chain *ch, double *work)
{
    int is_rk4 = strcmp(m->name, "rk4") == 0, is_euler = strcmp(m->name, "euler") == 0;
    if (!is_rk4 && !is_euler)
        return 0;
    if (strcmp(sc->name, "chain") == 0 && (p[3] != 0 || p[5] != 0))
        return 0; /* the baseline is the undamped chain without gravity (the defaults) */
    if (strcmp(sc->name, "vortex") == 0) {
        if (is_euler)
            base_vortex_euler(y, n, p[0], h, steps);
        else
            base_vortex_rk4(y, n, p[0], h, steps);
    } else {
        if (is_euler)
            base_chain_euler(ch, y, h, steps);
        else
            base_chain_rk4(ch, y, work, h, steps);
    }
    return 1;
}

static void throughput(const bench_opts *o)
{
    const workload loads[2] = { { "chain", o->chain_n }, { "vortex", o->vortex_n } };
    printf("throughput: ns per particle-step, median of %d repeats of about %.0f ms each\n"
           "  sim   = sw_sim_step (the UI's path: step, post-step hook, blow-up check)\n"
           "  step  = sw_stepper_step alone (the integrator and the derivative)\n"
           "  base  = hand-fused loop for this one problem, same arithmetic (euler, rk4; bench_base.c)\n"
           "  /eval = step per derivative evaluation; /rk4 = that against rk4's (target for the\n"
           "          adaptive methods: <= 1.2)\n\n",
           o->repeats, o->target * 1e3);
    printf("  %-7s %7s %-18s %8s %9s %9s %9s %8s %8s %6s %6s %5s %6s  %s\n", "scene", "n", "method", "dt",
           "sim", "step", "base", "sim/base", "step/bas", "evals", "/eval", "/rk4", "allocs", "baseline result");
    for (int w = 0; w < 2; w++) {
        double rk4_per_eval = NAN;
        const sw_scene *sc = sw_scene_find(loads[w].scene);
        double p[SW_MAX_PARAMS];
        if (build_params(sc, loads[w].n, p) != SW_OK)
            continue;
        for (int i = 0; i < sw_integrator_count(); i++) {
            const sw_integrator *m = sw_integrator_at(i);
            char err[SW_ERRLEN];
            sw_sim s;
            if (sw_sim_init(&s, sc, p, m, sc->dt, err, sizeof err) != SW_OK)
                continue; /* the method does not apply to this scene */
            /* A fixed step costs the same at any dt, but a sim that blows up
             * stops stepping: use the scene's dt, or a tenth of it as often
             * as needed for the timed steps to stay finite (euler on the
             * undamped chain grows at every dt). */
            double dt = sc->dt;
            long k = stable_steps(&s, &dt, o->target, o->repeats);
            int n = s.sys.n, dim = s.sys.ode->dim;
            double *y0 = malloc((size_t)dim * sizeof *y0), *yb = malloc((size_t)dim * sizeof *yb);
            double *work = malloc((size_t)(5 * dim) * sizeof *work);
            bench_chain ch = chain_baseline(n, p);
            if (!y0 || !yb || !work || !ch.f) {
                free(y0), free(yb), free(work), free(ch.f);
                sw_sim_free(&s);
                printf("  %-7s out of memory\n", sc->name);
                continue;
            }
            memcpy(y0, s.sys.y, (size_t)dim * sizeof *y0);
            /* Interleaved repeats (sim, step, baseline in turn) so that load
             * from other processes falls on all three alike. The step loop
             * carries on from the state the sim loop left. */
            double t0, t = 0, sim_t[MAX_REPEATS], step_t[MAX_REPEATS], base_t[MAX_REPEATS];
            long allocs = 0, evals = 0, steps = 0;
            memcpy(yb, y0, (size_t)dim * sizeof *yb);
            int has_base = run_baseline(sc, p, m, yb, n, dt, 0, &ch, work);
            for (int r = 0; r < o->repeats; r++) {
                long a0 = alloc_count(), e0 = sw_sim_evals(&s), s0 = s.steps;
                t0 = now_seconds();
                for (long j = 0; j < k; j++)
                    sw_sim_step(&s);
                sim_t[r] = (now_seconds() - t0) / ((double)k * n) * 1e9;
                evals += sw_sim_evals(&s) - e0;
                steps += s.steps - s0;
                t0 = now_seconds();
                for (long j = 0; j < k; j++)
                    sw_stepper_step(s.stepper, s.sys.ode, &t, s.sys.y, dt);
                step_t[r] = (now_seconds() - t0) / ((double)k * n) * 1e9;
                allocs += alloc_count() - a0;
                if (has_base) {
                    t0 = now_seconds();
                    run_baseline(sc, p, m, yb, n, dt, k, &ch, work);
                    base_t[r] = (now_seconds() - t0) / ((double)k * n) * 1e9;
                }
            }
            double evals_per_step = (double)evals / (double)(steps > 0 ? steps : 1);
            int blown = s.blown;
            /* The baseline against the generic stepper: the same number of
             * steps from the same state must give the same numbers. */
            char same[64] = "";
            double base = NAN;
            if (has_base) {
                base = median(base_t, o->repeats);
                const long check = 200;
                memcpy(yb, y0, (size_t)dim * sizeof *yb);
                memcpy(s.sys.y, y0, (size_t)dim * sizeof *y0);
                sw_stepper_touch(s.stepper);
                t = 0;
                run_baseline(sc, p, m, yb, n, dt, check, &ch, work);
                for (long j = 0; j < check; j++)
                    sw_stepper_step(s.stepper, s.sys.ode, &t, s.sys.y, dt);
                double diff = 0;
                for (int j = 0; j < dim; j++)
                    diff = fmax(diff, fabs(yb[j] - s.sys.y[j]));
                if (diff == 0)
                    snprintf(same, sizeof same, "bitwise equal after %ld steps", check);
                else
                    snprintf(same, sizeof same, "differs by %.1e after %ld steps", diff, check);
            }
            double sim = median(sim_t, o->repeats), step = median(step_t, o->repeats);
            double per_eval = step / evals_per_step;
            if (strcmp(m->name, "rk4") == 0)
                rk4_per_eval = per_eval;
            char allocs_s[16] = "n/a", base_s[16] = "-", r1[16] = "-", r2[16] = "-", r3[16] = "-";
            if ((m->flags & SW_ADAPTIVE) && !isnan(rk4_per_eval))
                snprintf(r3, sizeof r3, "%.2f", per_eval / rk4_per_eval);
            if (alloc_count() >= 0)
                snprintf(allocs_s, sizeof allocs_s, "%ld", allocs);
            if (!isnan(base)) {
                snprintf(base_s, sizeof base_s, "%.3g", base);
                snprintf(r1, sizeof r1, "%.2f", sim / base);
                snprintf(r2, sizeof r2, "%.2f", step / base);
            }
            printf("  %-7s %7d %-18s %8.3g %9.3g %9.3g %9s %8s %8s %6.2g %6.3g %5s %6s  %s%s\n", sc->name, n,
                   m->name, dt, sim, step, base_s, r1, r2, evals_per_step, per_eval, r3, allocs_s, same,
                   blown ? " (the sim blew up while timed)" : "");
            fflush(stdout);
            free(y0), free(yb), free(work), free(ch.f);
            sw_sim_free(&s);
        }
    }
    printf("\n");
}

/* ---- memory ------------------------------------------------------------- */

/* Peak resident set of this process so far, in KiB (VmHWM), or -1. */
static long peak_rss_kib(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    long kib = -1;
    if (!f)
        return -1;
    char line[256];
    while (fgets(line, sizeof line, f))
        if (strncmp(line, "VmHWM:", 6) == 0) {
            kib = strtol(line + 6, NULL, 10);
            break;
        }
    fclose(f);
    return kib;
}

/* In a fresh process, for counting instructions (bench/instructions.sh runs
 * this under callgrind at two step counts and takes the difference): build
 * SCENE with n particles, then take `steps` steps of METHOD at the scene's
 * dt (euler on the chain at a tenth of it, as timed above) through the
 * generic stepper, or (base) through the hand-fused loop. */
static int count_probe(const char *scene, int n, const char *method, long steps, int base)
{
    const sw_scene *sc = sw_scene_find(scene);
    const sw_integrator *m = sw_integrator_find(method);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_sim s;
    if (!sc || !m || build_params(sc, n, p) != SW_OK || sw_sim_init(&s, sc, p, m, sc->dt, err, sizeof err) != SW_OK)
        return 1;
    double dt = sc->dt * (strcmp(scene, "chain") == 0 && strcmp(method, "euler") == 0 ? 0.1 : 1.0), t = 0;
    int dim = s.sys.ode->dim, ok = 1;
    if (base) {
        double *work = malloc((size_t)(5 * dim) * sizeof *work);
        bench_chain ch = chain_baseline(n, p);
        ok = work && ch.f && run_baseline(sc, p, m, s.sys.y, n, dt, steps, &ch, work);
        free(work), free(ch.f);
    } else {
        for (long j = 0; j < steps; j++)
            sw_stepper_step(s.stepper, s.sys.ode, &t, s.sys.y, dt);
    }
    sw_sim_free(&s);
    return ok ? 0 : 1;
}

/* The hand-fused rk4 of bench_base.c on scene (chain or vortex) with n
 * particles, from the scene's start written out by hand (the chain's beads
 * at (i + 1)·rest, the middle one plucked; the vortex seeded by the scene,
 * then copied): only what that loop needs is allocated. Takes `steps`
 * steps; *ns gets the median ns per particle-step of the last five. The
 * benchmark checks the seeds against the scene's (vortex, n = 1000). */
static int base_probe(const char *scene, int n, long steps, double *ns)
{
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS], h = sc ? sc->dt : 0, times[5];
    if (!sc || build_params(sc, n, p) != SW_OK)
        return 1;
    int chain = strcmp(scene, "chain") == 0, dim = chain ? 4 * n : 2 * n;
    double *y = calloc((size_t)dim, sizeof *y), *work = chain ? malloc((size_t)8 * n * sizeof *work) : NULL;
    bench_chain ch = chain_baseline(chain ? n : 1, p);
    if (!y || (chain && (!work || !ch.f))) {
        free(y), free(work), free(ch.f);
        return 1;
    }
    if (chain) {
        for (int i = 0; i < n; i++)
            y[2 * i] = (i + 1) * p[4];
        y[2 * (n / 2) + 1] = p[6];
    } else {
        base_vortex_seed(y, n);
    }
    for (long j = 0; j < steps; j++) {
        double t0 = now_seconds();
        if (chain)
            base_chain_rk4(&ch, y, work, h, 1);
        else
            base_vortex_rk4(y, n, p[0], h, 1);
        times[j % 5] = (now_seconds() - t0) * 1e9 / n;
    }
    *ns = median(times, steps < 5 ? (int)steps : 5);
    free(y), free(work), free(ch.f);
    return 0;
}

/* In a fresh process: build scene with n particles under `method` ("none":
 * build nothing; "base": the hand-fused rk4 instead), take ten steps, and
 * print the peak RSS in KiB and the median ns per particle-step of the
 * last five on stdout. */
static int memory_probe(const char *scene, const char *method, int n)
{
    sw_sim s;
    int built = 0;
    double ns = 0, times[5];
    if (strcmp(method, "base") == 0) {
        if (base_probe(scene, n, 10, &ns) != 0)
            return 1;
    } else if (strcmp(method, "none") != 0) {
        const sw_scene *sc = sw_scene_find(scene);
        const sw_integrator *m = sw_integrator_find(method);
        double p[SW_MAX_PARAMS];
        char err[SW_ERRLEN];
        if (!sc || !m || build_params(sc, n, p) != SW_OK || sw_sim_init(&s, sc, p, m, sc->dt, err, sizeof err) != SW_OK)
            return 1;
        for (int j = 0; j < 10; j++) {
            double t0 = now_seconds();
            sw_sim_step(&s);
            times[j % 5] = (now_seconds() - t0) * 1e9 / n;
        }
        ns = median(times, 5);
        built = 1;
    }
    printf("%ld %.3f\n", peak_rss_kib(), ns);
    if (built)
        sw_sim_free(&s);
    return 0;
}

/* Peak RSS in KiB of a fresh copy of this program run as a memory probe
 * (and in *ns, when not NULL, its ns per particle-step): the child reads
 * its own VmHWM after exec, so the parent's memory, which a forked child
 * shares until exec, does not count. */
static long probe_rss(const char *scene, const char *method, int n, double *ns)
{
    char count[32];
    snprintf(count, sizeof count, "%d", n);
    const char *args[NPREFIX + 7];
    int k = 0;
    args[k++] = "/proc/self/exe";
    for (int i = 0; i < NPREFIX; i++)
        args[k++] = probe_prefix[i];
    args[k++] = "--memory-probe";
    args[k++] = scene;
    args[k++] = method;
    args[k++] = count;
    args[k] = NULL;
    int fds[2];
    fflush(stdout);
    if (pipe(fds) != 0)
        return -1;
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return -1;
    }
    if (pid == 0) {
        dup2(fds[1], STDOUT_FILENO);
        close(fds[0]);
        close(fds[1]);
        execv("/proc/self/exe", (char *const *)args);
        _exit(127);
    }
    close(fds[1]);
    char buf[128] = "";
    ssize_t got = read(fds[0], buf, sizeof buf - 1);
    close(fds[0]);
    int status;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || got <= 0)
        return -1;
    buf[got] = '\0';
    char *end;
    long kib = strtol(buf, &end, 10);
    if (ns)
        *ns = strtod(end, NULL);
    return kib;
}

static void memory(const bench_opts *o)
{
    int n = o->vortex_n;
    long base = probe_rss("vortex", "none", n, NULL);
    printf("peak memory: vortex n = %d, each method in a fresh process (build, 10 steps);\n"
           "the process alone peaks at %.1f MiB; the state is %.2f MiB (2n doubles)\n\n",
           n, base / 1024.0, 2.0 * n * sizeof(double) / 1048576.0);
    printf("  %-18s %12s %12s %14s\n", "method", "peak MiB", "above base", "work vectors");
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (m->flags & SW_NEEDS_SECOND_ORDER)
            continue;
        long kib = probe_rss("vortex", m->name, n, NULL);
        if (kib < 0) {
            printf("  %-18s %12s\n", m->name, "failed");
            continue;
        }
        printf("  %-18s %12.1f %12.1f %14d\n", m->name, kib / 1024.0, (kib - base) / 1024.0,
               m->work_vectors);
    }
    printf("\n");
}

/* A million particles: chain and vortex at n (1e6; --quick 1e5) under rk4,
 * each in a fresh process, against the hand-fused rk4 of bench_base.c in
 * its own: ns per particle-step (median of five steps) and peak RSS above
 * the bare process, and their ratio. */
static void million(int n)
{
    printf("a million particles: n = %d, rk4, 10 steps in a fresh process each; ns per\n"
           "particle-step (median of the last 5) and peak RSS above the bare process, stepwise\n"
           "(sw_sim_step) against the hand-fused loop (bench_base.c); targets: RSS ratio <= 2\n"
           "(issue 26), stepwise's RSS above the bare process <= 3 times the state (issue 41)\n\n", n);
    printf("  %-7s %8s %10s %10s %10s %12s %12s %10s %8s %8s %8s\n", "scene", "n", "state MiB", "sim ns", "base ns",
           "sim MiB", "base MiB", "RSS ratio", "<=2x", "x state", "<=3x");
    /* the baseline's vortex starts where the scene's does, bit for bit */
    const sw_scene *vx = sw_scene_find("vortex");
    double p[SW_MAX_PARAMS], seeds[2000];
    char err[SW_ERRLEN];
    sw_sim s;
    if (build_params(vx, 1000, p) == SW_OK && sw_sim_init(&s, vx, p, sw_integrator_find("rk4"), vx->dt, err,
                                                          sizeof err) == SW_OK) {
        base_vortex_seed(seeds, 1000);
        int same = memcmp(seeds, s.sys.y, sizeof seeds) == 0;
        printf("  (the baseline's vortex seeds %s the scene's)\n", same ? "equal" : "DIFFER FROM");
        sw_sim_free(&s);
    }
    const char *scenes[2] = { "chain", "vortex" };
    for (int k = 0; k < 2; k++) {
        double ns_sim = 0, ns_base = 0;
        long bare = probe_rss(scenes[k], "none", n, NULL);
        long sim = probe_rss(scenes[k], "rk4", n, &ns_sim), fused = probe_rss(scenes[k], "base", n, &ns_base);
        double state = (k == 0 ? 4.0 : 2.0) * n * sizeof(double) / 1048576.0;
        if (bare < 0 || sim < 0 || fused < 0) {
            printf("  %-7s %8d  failed (out of memory, or n above the scene's limit)\n", scenes[k], n);
            continue;
        }
        double above = (sim - bare) / 1024.0, above_base = (fused - bare) / 1024.0;
        printf("  %-7s %8d %10.1f %10.2f %10.2f %12.1f %12.1f %10.2f %8s %8.2f %8s\n", scenes[k], n, state, ns_sim,
               ns_base, above, above_base, above / above_base, above <= 2 * above_base ? "yes" : "NO", above / state,
               above <= 3 * state ? "yes" : "NO");
    }
    printf("\n");
}

/* ---- entry -------------------------------------------------------------- */

static void machine(void)
{
    char model[256] = "unknown CPU";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "model name", 10) == 0) {
                char *colon = strchr(line, ':');
                if (colon) {
                    snprintf(model, sizeof model, "%s", colon + 2);
                    model[strcspn(model, "\n")] = '\0';
                }
                break;
            }
        fclose(f);
    }
#ifdef __VERSION__
    const char *cc = __VERSION__;
#else
    const char *cc = "unknown compiler";
#endif
    printf("stepwise engine benchmark\nmachine: %s, %ld cpus online; compiler %s%s\n"
           "allocation counting: %s\n\n", model, sysconf(_SC_NPROCESSORS_ONLN), cc,
#ifdef __OPTIMIZE__
           ", optimised",
#else
           ", NOT optimised",
#endif
           alloc_count() < 0 ? "off in this binary (run `make bench`, which links with "
                               "-Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc)"
                             : "on (malloc, calloc, realloc wrapped at link time)");
}

/* One heavy view of bench_frame.c alone, for paired timings and for
 * callgrind (the difference between two SECONDS counts is the frames'
 * cost alone): VIEW is "plain" or a '+'-joined list of compare, lanes,
 * ghost, trails; DT (NULL: the scene's) the step. 0, or 2 when an
 * argument is not allowed. */
static int frame_view(const char *scene, const char *n_text, const char *view, const char *seconds_text,
                      const char *dt_text)
{
    char *n_end, *end, *dt_end = "";
    long n = strtol(n_text, &n_end, 10);
    double seconds = strtod(seconds_text, &end), dt = dt_text ? strtod(dt_text, &dt_end) : 0;
    char base[64];
    snprintf(base, sizeof base, "%.*s", (int)strcspn(scene, ":"), scene);
    if (*n_end || *end || *dt_end || !(seconds > 0 && seconds <= 40) || n < 0 || n > 1000000 ||
        !(dt_text == NULL || (dt >= 1e-9 && dt <= 1)) || !sw_scene_find(base)) {
        fprintf(stderr, "stepwise: --frame-view takes SCENE[:NAME=VALUE] N VIEW SECONDS [DT]: a scene (and one more "
                "parameter), n in [0, 1000000] "
                "(0: the default), seconds in (0, 40] and a step in [1e-9, 1] (none: the scene's)\n");
        return 2;
    }
    int compare = 0, ghost = 0, lanes = 0, trails = 0;
    char words[64];
    snprintf(words, sizeof words, "%s", view);
    for (char *w = strtok(words, "+"); w; w = strtok(NULL, "+")) {
        if (strcmp(w, "compare") == 0)
            compare = 1;
        else if (strcmp(w, "lanes") == 0)
            compare = lanes = 1;
        else if (strcmp(w, "ghost") == 0)
            ghost = 1;
        else if (strcmp(w, "trails") == 0)
            trails = 1;
        else if (strcmp(w, "plain") != 0) {
            fprintf(stderr, "stepwise: --frame-view: unknown view '%.40s'; allowed: plain, or compare, lanes, "
                    "ghost, trails joined by '+'\n", w);
            return 2;
        }
    }
    char name[64], *set = NULL;
    snprintf(name, sizeof name, "%s", scene);
    if ((set = strchr(name, ':')))
        *set++ = '\0'; /* SCENE:NAME=VALUE, one more parameter */
    bench_heavy_one(name, set, (int)n, compare, ghost, lanes, trails, seconds, dt);
    return 0;
}

static int bench_engine_main(int argc, char **argv)
{
    bench_opts o = { .repeats = 5, .chain_n = 1000, .vortex_n = 100000, .target = 0.03 };
    bench_peer_opts peer = { .repeats = 7, .chain_n = 100, .vortex_n = 1000 };
    int sections = ~0, quick = 0; /* 1 throughput, 2 frame cost, 4 memory, 8 peer, 16 tree,
                                     32 rkn, 64 stiff, 128 heavy views, 256 implicit, 512 keys */
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--engine") == 0)
            continue;
        if (strcmp(argv[i], "--memory-probe") == 0 && i + 3 < argc)
            return memory_probe(argv[i + 1], argv[i + 2], atoi(argv[i + 3]));
        if (strcmp(argv[i], "--count-probe") == 0 && i + 5 < argc)
            return count_probe(argv[i + 1], atoi(argv[i + 2]), argv[i + 3], atol(argv[i + 4]),
                               strcmp(argv[i + 5], "base") == 0);
        if (strcmp(argv[i], "--tree-probe") == 0 && i + 3 < argc)
            return bench_tree_probe(argv[i + 1], argv[i + 2], argv[i + 3]);
        if (strcmp(argv[i], "--lc-probe") == 0 && i + 3 < argc)
            return bench_lc_probe(argv[i + 1], atof(argv[i + 2]), atol(argv[i + 3]));
        if (strcmp(argv[i], "--deriv-probe") == 0 && i + 4 < argc)
            return bench_deriv_probe(argv[i + 1], argv[i + 2], atol(argv[i + 3]), strcmp(argv[i + 4], "generic") == 0);
        if (strcmp(argv[i], "--frame-view") == 0 && i + 4 < argc)
            return frame_view(argv[i + 1], argv[i + 2], argv[i + 3], argv[i + 4],
                              i + 5 < argc && argv[i + 5][0] != '-' ? argv[i + 5] : NULL);
        if (strcmp(argv[i], "--quick") == 0) {
            o.repeats = 3;
            o.chain_n = 100;
            o.vortex_n = 10000;
            o.target = 0.003;
            peer = (bench_peer_opts){ .repeats = 3, .chain_n = 20, .vortex_n = 100, .quick = 1 };
            quick = 1;
        } else if (strcmp(argv[i], "--peer") == 0) {
            sections = 8;
        } else if (strcmp(argv[i], "--peer-stiff") == 0) {
            sections = 8;
            peer.stiff = 1;
        } else if (strcmp(argv[i], "--tree") == 0) {
            sections = 16;
        } else if (strcmp(argv[i], "--implicit") == 0) {
            sections = 256;
        } else if (strcmp(argv[i], "--rkn") == 0) {
            sections = 32;
        } else if (strcmp(argv[i], "--stiff") == 0) {
            sections = 64;
        } else if (strcmp(argv[i], "--frames") == 0) {
            sections = 128;
        } else if (strcmp(argv[i], "--memory") == 0) {
            sections = 4;
        } else if (strcmp(argv[i], "--keys") == 0) {
            sections = 512;
        } else if (strcmp(argv[i], "--no-peer") == 0) {
            sections &= ~8;
        } else if ((strcmp(argv[i], "--peer-chain") == 0 || strcmp(argv[i], "--peer-vortex") == 0) && i + 1 < argc) {
            char *end;
            long n = strtol(argv[i + 1], &end, 10);
            if (*end || n < 1 || n > 100000) {
                fprintf(stderr, "stepwise: %s '%.40s' is not allowed: it takes a whole number in [1, 100000]\n",
                        argv[i], argv[i + 1]);
                return 2;
            }
            *(argv[i][7] == 'c' ? &peer.chain_n : &peer.vortex_n) = (int)n;
            i++;
        } else if (strcmp(argv[i], "--peer-only") == 0 && i + 1 < argc) {
            peer.only = argv[++i];
        } else if (strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
            char *end;
            long r = strtol(argv[++i], &end, 10);
            if (*end || r < 1 || r > MAX_REPEATS) {
                fprintf(stderr, "stepwise: --repeats '%.40s' is not allowed: it takes a whole number "
                        "in [1, %d]\n", argv[i], MAX_REPEATS);
                return 2;
            }
            o.repeats = (int)r;
            peer.repeats = r < 5 ? 5 : (int)r;
        } else {
            fprintf(stderr, "stepwise: bench --engine: unknown option '%.40s'; options: --quick, "
                    "--repeats N, --peer, --peer-stiff, --no-peer, --tree, --rkn, --stiff, --frames, --keys, --memory, --implicit, "
                    "--peer-chain N, --peer-vortex N, --peer-only SCENE, --frame-view SCENE[:NAME=VALUE] N VIEW SECONDS [DT]\n",
                    argv[i]);
            return 2;
        }
    }
    machine();
    if (sections & 1)
        throughput(&o);
    if (sections & 256)
        bench_implicit(o.repeats, o.chain_n, o.target);
    if (sections & 2)
        bench_frame_cost(o.vortex_n, o.target);
    if (sections & 128)
        bench_heavy_views(quick);
    if (sections & 512)
        bench_key_gaps(o.repeats, quick);
    if (sections & 4) {
        memory(&o);
        million(quick ? 100000 : 1000000);
    }
    if (sections & 16) {
        bench_tree(o.repeats, quick);
        bench_water(o.repeats, quick);
    }
    if (sections & 8)
        bench_peer(&peer);
    if (sections & 32)
        bench_rkn(o.repeats, quick);
    if (sections & 64)
        bench_stiff(o.repeats, quick);
    return 0;
}

int main(int argc, char **argv) { return bench_engine_main(argc, argv); }
