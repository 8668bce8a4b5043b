/* Keys that could stall the picture (issue 41: "no key (w, k, c, +, -, ;)
 * stops the picture for more than 100 ms at n = 1e5"). Through the app as
 * the live loop drives it (tui/loop.c, without ncurses): frames of 1/60 s
 * at speed 1 with the loop's step budget (about 10 ms of stepping a frame,
 * from the steps per CPU second measured while warming up), then the key
 * (sw_app_key), then frames until what it started is over. A row is the
 * frame that took longest from the key on, in this thread's CPU time and
 * in wall time (the `w` sweep and a long Δt measurement run on a worker
 * thread: their CPU is not the picture's, but on a busy machine it takes a
 * core), the median of `repeats` runs; the worst of them beside it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/app.h"
#include "bench_common.h"
#include "lesson/controls.h"
#include "render/screen.h"

enum { WARM_FRAMES = 30, AFTER_FRAMES = 120, SWEEP_FRAMES = 6000, MAX_REPEATS_KEYS = 9 };

static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct key_frame {
    double cpu_ms, wall_ms; /* the longest frame from the key on */
    int ok;
} key_frame;

/* One frame as the loop takes it; its CPU and wall milliseconds. */
static void one_frame(sw_app *a, sw_frame *f, sw_screen *scr, long budget, int key, double *cpu_ms, double *wall_ms)
{
    double c0 = thread_cpu(), w0 = now_seconds();
    if (key)
        sw_app_key(a, key, 0);
    sw_app_advance(a, 1.0 / 60, budget);
    sw_frame_push_trails(f, a);
    sw_frame_compose(f, a, NULL, scr);
    *cpu_ms = (thread_cpu() - c0) * 1e3;
    *wall_ms = (now_seconds() - w0) * 1e3;
}

static key_frame key_run(const char *scene, int n, int key, int quick)
{
    key_frame r = { 0, 0, 0 };
    char err[SW_ERRLEN], set[32];
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS];
    sw_app *a = calloc(1, sizeof *a);
    sw_frame f;
    sw_screen scr = { 0 };
    snprintf(set, sizeof set, "n=%d", n);
    if (!a || !sc)
        goto out;
    sw_scene_defaults(sc, p);
    if (sw_scene_set(sc, p, set, err, sizeof err) != SW_OK || sw_app_init(a, sc, p, NULL, 0, err, sizeof err) != SW_OK)
        goto out;
    if (sw_frame_init(&f, err, sizeof err) != SW_OK) {
        sw_app_free(a);
        goto out;
    }
    if (sw_screen_init(&scr, 120, 40, err, sizeof err) != SW_OK) {
        sw_frame_free(&f);
        sw_app_free(a);
        goto out;
    }
    a->paused = 0;
    /* warm up at the loop's budget, measured as the loop measures it */
    long budget = 1, steps0 = a->sims[0].steps;
    double busy = 0, cpu, wall;
    int warm = quick ? 5 : WARM_FRAMES, after = quick ? 10 : AFTER_FRAMES;
    for (int i = 0; i < warm; i++) {
        double c0 = thread_cpu();
        one_frame(a, &f, &scr, budget, 0, &cpu, &wall);
        busy += thread_cpu() - c0;
        double capacity = busy > 0 ? (double)(a->sims[0].steps - steps0) / busy : 0;
        double b = (capacity > 0 ? capacity : 2000) * 0.010 / a->nsims;
        budget = b < 1 ? 1 : b > 1e6 ? 1000000 : (long)b;
    }
    /* the key, then frames until its work is done (the sweep's report or
     * the Δt measurement's figures in) */
    int frames = 0;
    for (; frames < SWEEP_FRAMES; frames++) {
        one_frame(a, &f, &scr, budget, frames == 0 ? key : 0, &cpu, &wall);
        r.cpu_ms = fmax(r.cpu_ms, cpu);
        r.wall_ms = fmax(r.wall_ms, wall);
        if (frames >= after && !a->sweep && !a->dt_job)
            break;
    }
    r.ok = !a->sweep && !a->dt_job;
    if (key == 'w' && r.ok) { /* and the Esc that closes the plot */
        one_frame(a, &f, &scr, budget, SW_KEY_ESC, &cpu, &wall);
        r.cpu_ms = fmax(r.cpu_ms, cpu);
        r.wall_ms = fmax(r.wall_ms, wall);
    }
    sw_app_sweep_wait(a);
    sw_screen_free(&scr);
    sw_frame_free(&f);
    sw_app_free(a);
out:
    free(a);
    return r;
}

void bench_key_gaps(int repeats, int quick)
{
    static const struct { const char *scene; int n; } scenes[] = { { "chain", 100000 }, { "vortex", 100000 } };
    static const int keys[] = { 'w', 'k', 'c', '+', '-', ';' };
    int runs = quick ? 1 : repeats < 1 ? 1 : repeats > MAX_REPEATS_KEYS ? MAX_REPEATS_KEYS : repeats;
    int big = quick ? 1000 : 0;
    printf("keys at n = %s: the longest frame from the key on (w: until the sweep's plot is in, and the\n"
           "Esc that closes it; + and -: until the error's figures are in), the live loop's work without\n"
           "a terminal at its step budget; CPU time of\n"
           "the thread (the picture's) and wall time; median of %d runs, the worst run beside it.\n"
           "Target: <= 100 ms\n\n", quick ? "1e3 (--quick)" : "1e5", runs);
    printf("  %-7s %7s %-4s %9s %9s %9s %9s  %s\n", "scene", "n", "key", "cpu ms", "worst", "wall ms", "worst",
           "<=100ms");
    for (size_t s = 0; s < sizeof scenes / sizeof scenes[0]; s++)
        for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
            double cpu[MAX_REPEATS_KEYS], wall[MAX_REPEATS_KEYS];
            int ok = 1, n = big ? big : scenes[s].n;
            for (int i = 0; i < runs; i++) {
                key_frame r = key_run(scenes[s].scene, n, keys[k], quick);
                cpu[i] = r.cpu_ms;
                wall[i] = r.wall_ms;
                ok &= r.ok;
            }
            double worst_cpu = 0, worst_wall = 0;
            for (int i = 0; i < runs; i++) {
                worst_cpu = fmax(worst_cpu, cpu[i]);
                worst_wall = fmax(worst_wall, wall[i]);
            }
            double mc = median(cpu, runs), mw = median(wall, runs);
            printf("  %-7s %7d %-4c %9.1f %9.1f %9.1f %9.1f  %s%s\n", scenes[s].scene, n, keys[k], mc, worst_cpu,
                   mw, worst_wall, mc <= 100 ? "yes" : "NO", ok ? "" : "  (worker not done)");
            fflush(stdout);
        }
    printf("\n");
}
