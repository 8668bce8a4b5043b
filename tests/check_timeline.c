/* Time under the student's control (app/timeline.c, sim/history.c): a stop
 * time the run lands on exactly, and stepping back through the history so
 * that stepping on again repeats the forward run bit for bit. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stepwise/stepwise.h"
#include "app/app.h"
#include "app/runner.h"
#include "engine/stepper.h"
#include "sim/history.h"
#include "alloc_count.h"

#define LESSONS_DIR "lessons"

static void app_on(sw_app *a, const char *scene, const char *method, double dt)
{
    char err[SW_ERRLEN];
    ck_assert_msg(sw_app_init(a, sw_scene_find(scene), NULL, method ? sw_integrator_find(method) : NULL, dt,
                              err, sizeof err) == SW_OK, "%s", err);
}

/* Frames of 1/60 s until the clock pauses (or 20 simulated seconds). */
static void run_frames(sw_app *a)
{
    for (int k = 0; k < 1200 && !a->paused; k++)
        sw_app_advance(a, 1.0 / 60, 1000000);
}

/* The run pauses at t = 2.5 exactly: with dt = 0.01 (250 steps whose sum
 * rounds below 2.5) and with dt = 0.03 (the 84th step cut to 0.01), for an
 * adaptive method, and for every run of compare. */
START_TEST(until_lands_exactly)
{
    static const struct { const char *method; double dt; long steps; } cases[] = {
        { "euler", 0.01, 250 }, { "euler", 0.03, 84 }, { "verlet", 0.02, 125 }, { "rk45", 0.05, -1 },
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        sw_app a;
        app_on(&a, "spring", cases[c].method, cases[c].dt);
        sw_app_set_until(&a, 2.5);
        run_frames(&a);
        ck_assert_msg(a.paused, "%s dt=%g: paused at the stop time", cases[c].method, cases[c].dt);
        ck_assert_msg(a.sims[0].t == 2.5, "%s dt=%g: t = %.17g", cases[c].method, cases[c].dt, a.sims[0].t);
        if (cases[c].steps > 0)
            ck_assert_int_eq(a.sims[0].steps, cases[c].steps);
        ck_assert_ptr_nonnull(strstr(a.message, "t = 2.5"));
        /* space runs on past it; the stop time no longer holds the run */
        sw_app_key(&a, ' ', 0);
        sw_app_advance(&a, 0.1, 1000000);
        ck_assert(a.sims[0].t > 2.5);
        sw_app_free(&a);
    }
    sw_app a;
    app_on(&a, "spring", "euler", 0.03);
    sw_app_set_compare(&a, 1, NULL, NULL);
    sw_app_set_until(&a, 2.5);
    run_frames(&a);
    ck_assert_int_eq(a.nsims, 3);
    for (int i = 0; i < a.nsims; i++)
        ck_assert_msg(a.sims[i].t == 2.5, "sim %d: t = %.17g", i, a.sims[i].t);
    sw_app_free(&a);
}
END_TEST

/* u runs every sim to the stop time at once and pauses; the same states
 * as the clock reaching it frame by frame. */
START_TEST(until_key_runs_there)
{
    sw_app a, b;
    app_on(&a, "spring", "rk4", 0.03);
    app_on(&b, "spring", "rk4", 0.03);
    sw_app_key(&a, 'u', 0);
    ck_assert_ptr_nonnull(strstr(a.message, "no stop time"));
    ck_assert_double_eq(a.sims[0].t, 0);
    sw_app_set_until(&a, 2.5);
    sw_app_set_until(&b, 2.5);
    sw_app_key(&a, 'u', 0);
    run_frames(&b);
    ck_assert(a.paused);
    ck_assert(a.sims[0].t == 2.5);
    ck_assert_int_eq(a.sims[0].steps, b.sims[0].steps);
    ck_assert_int_eq(memcmp(a.sims[0].sys.y, b.sims[0].sys.y, 4 * sizeof(double)), 0);
    ck_assert_int_gt(a.series[0].len, 10); /* the graph was sampled on the way */
    sw_app_key(&a, 'u', 0);
    ck_assert_ptr_nonnull(strstr(a.message, "already"));
    sw_app_free(&a);
    sw_app_free(&b);
}
END_TEST

/* The u key spends at most 4 × a->work_key state evaluations: on the spring
 * (4 components, rk4's 4 evaluations a step: 16 a step) at a work_key of
 * 1e5 that is 25 000 steps, half the way to t = 50 at dt = 0.001; the key
 * says so, and pressed again goes on to the stop time exactly (a third
 * press at most: 50 000 steps of 0.001 add up to a hair under 50, and the
 * step that lands there is one more). */
START_TEST(until_key_keeps_to_its_budget)
{
    sw_app a;
    app_on(&a, "spring", "rk4", 0.001);
    a.work_key = 1e5;
    sw_app_set_until(&a, 50);
    ck_assert_int_eq(sw_app_key(&a, 'u', 0), 1);
    ck_assert(a.paused);
    ck_assert_int_eq(a.sims[0].steps, 25000);
    ck_assert_msg(strstr(a.message, "stopped after many steps short of the stop time t = 50 (u goes on)"), "%s",
                  a.message);
    for (int press = 0; press < 2 && a.sims[0].t != 50; press++)
        ck_assert_int_eq(sw_app_key(&a, 'u', 0), 1);
    ck_assert_msg(a.sims[0].t == 50, "t = %.17g", a.sims[0].t);
    sw_app_free(&a);
}
END_TEST

/* What a state is, for comparing bit for bit: y, t, steps, evaluations. */
typedef struct kept {
    double *y;
    double t;
    long steps, evals;
} kept;

static void keep(kept *k, const sw_sim *s)
{
    size_t n = (size_t)s->sys.ode->dim * sizeof(double);
    k->y = malloc(n);
    ck_assert_ptr_nonnull(k->y);
    memcpy(k->y, s->sys.y, n);
    k->t = s->t;
    k->steps = s->steps;
    k->evals = sw_sim_evals(s);
}

static void same(const kept *k, const sw_sim *s, const char *what, int at)
{
    ck_assert_msg(memcmp(k->y, s->sys.y, (size_t)s->sys.ode->dim * sizeof(double)) == 0,
                  "%s: the state at step %d differs", what, at);
    ck_assert_msg(k->t == s->t && k->steps == s->steps && k->evals == sw_sim_evals(s),
                  "%s at step %d: t %.17g/%.17g steps %ld/%ld evals %ld/%ld", what, at, k->t, s->t, k->steps,
                  s->steps, k->evals, sw_sim_evals(s));
}

/* Forward 300 steps with '.', back 120 with ',' and ';' (every state on
 * the way equal to the forward run's, bit for bit), then forward again:
 * the same states as the first time, bit for bit, for methods that carry
 * memory between steps (Verlet's, yoshida4's, rk45's and rkn's FSAL derivative, the
 * adaptive methods' step proposal; rkn12 under predictive control;
 * dop853-lc's variables, which it goes on in from the state it left),
 * implicit ones, a scene with events located
 * (bounce), one with scene data (fireworks' sparks), and compare's runs. */
START_TEST(rewind_bit_for_bit)
{
    static const struct { const char *scene, *method; double dt; int compare, locate; } cases[] = {
        { "spring", "verlet", 0, 0, 0 }, { "spring", "rk45", 0.5, 0, 0 }, { "orbit", "dop853", 1, 0, 0 },
        { "stiff-spring", "implicit-euler", 0, 0, 0 }, { "bounce", "rk4", 0, 0, 1 },
        { "fireworks", "heun", 0, 0, 0 }, { "spring", "euler", 0, 1, 0 }, { "orbit", "yoshida4", 0, 0, 0 },
        { "chain", "rkn", 0.5, 0, 0 }, { "orbit", "rkn12", 1, 0, 0 }, { "orbit", "dop853-lc", 1, 0, 0 },
    };
    enum { N = 300, BACK = 120 };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        sw_app a;
        char what[80];
        snprintf(what, sizeof what, "%s %s", cases[c].scene, cases[c].method);
        app_on(&a, cases[c].scene, cases[c].method, cases[c].dt); /* rk45, dop853, rkn12: steps below dt */
        if (cases[c].locate)
            sw_app_set_events(&a, SW_EVENTS_LOCATE);
        if (cases[c].compare)
            sw_app_set_compare(&a, 1, NULL, NULL);
        kept (*fwd)[SW_APP_SIMS] = calloc(N + 1, sizeof *fwd);
        ck_assert_ptr_nonnull(fwd);
        for (int i = 0; i < a.nsims; i++)
            keep(&fwd[0][i], &a.sims[i]);
        for (int k = 1; k <= N; k++) {
            sw_app_key(&a, '.', 0);
            for (int i = 0; i < a.nsims; i++)
                keep(&fwd[k][i], &a.sims[i]);
        }
        ck_assert_msg(!a.sims[0].blown, "%s blew up", what);
        for (int k = N - 1; k >= N - 20; k--) { /* one step back at a time */
            sw_app_key(&a, ',', 0);
            for (int i = 0; i < a.nsims; i++)
                same(&fwd[k][i], &a.sims[i], what, k);
        }
        for (int k = N - 20 - SW_APP_BACK_MANY; k >= N - BACK; k -= SW_APP_BACK_MANY) { /* ; goes 50 back */
            sw_app_key(&a, ';', 0);
            for (int i = 0; i < a.nsims; i++)
                same(&fwd[k][i], &a.sims[i], what, k);
        }
        ck_assert(a.paused);
        for (int k = N - BACK + 1; k <= N; k++) {
            sw_app_key(&a, '.', 0);
            for (int i = 0; i < a.nsims; i++)
                same(&fwd[k][i], &a.sims[i], what, k);
        }
        for (int k = 0; k <= N; k++)
            for (int i = 0; i < a.nsims; i++)
                free(fwd[k][i].y);
        free(fwd);
        sw_app_free(&a);
    }
}
END_TEST

/* A snapshot holds the adaptive controller's memory: the step proposal,
 * the last step and the last accepted error (rkn12's predictive control
 * reads it). At a frame's end the last step is mostly cut short, so its
 * error is floored at 0.01 and a rewind through frames seldom sees the
 * last error at all: here it is set to a value a step could leave, kept,
 * changed by stepping on, and must come back. */
START_TEST(snapshot_keeps_controller_memory)
{
    sw_sim s;
    sw_history h;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_sim_init(&s, sw_scene_find("orbit"), NULL, sw_integrator_find("rkn12"), 1.0, err, sizeof err),
                     SW_OK);
    sw_history_init(&h, &s);
    ck_assert_int_gt(h.cap, 0);
    ck_assert_int_eq(sw_sim_step_until(&s, 1.0), 0);
    s.stepper->err_last = 0.37;
    const double t = s.t, h_next = s.stepper->h_next, h_last = s.stepper->h_last;
    sw_history_push(&h, &s);
    for (int k = 2; k <= 5; k++) {
        ck_assert_int_eq(sw_sim_step_until(&s, (double)k), 0);
        sw_history_push(&h, &s);
    }
    ck_assert(s.stepper->err_last != 0.37);
    ck_assert_int_eq(sw_history_back_to(&h, &s, t), 1);
    ck_assert(s.t == t && s.stepper->h_next == h_next && s.stepper->h_last == h_last);
    ck_assert_double_eq(s.stepper->err_last, 0.37);
    sw_history_free(&h);
    sw_sim_free(&s);
}
END_TEST

/* Stepping back through frames of the clock: the graph and the phase path
 * are cut back to the time stepped to; the history starts again at a reset
 * and at a change of dt, and says so. */
START_TEST(rewind_follows_and_bounds)
{
    sw_app a;
    app_on(&a, "spring", "euler", 0.01);
    for (int k = 0; k < 60; k++)
        sw_app_advance(&a, 1.0 / 60, 1000000);
    double t = a.sims[0].t;
    int len = a.series[0].len;
    sw_app_key(&a, ';', 0);
    ck_assert(a.sims[0].t < t);
    ck_assert_int_eq(a.sims[0].steps, 50);
    ck_assert_int_lt(a.series[0].len, len);
    ck_assert(a.series[0].t[a.series[0].len - 1] <= a.sims[0].t);
    ck_assert_ptr_nonnull(strstr(a.message, "back to t = 0.5"));
    sw_app_key(&a, '-', 0); /* halve dt: the run starts again at t = 0, nothing earlier */
    ck_assert_int_eq(a.sims[0].steps, 0);
    sw_app_key(&a, ',', 0);
    ck_assert_ptr_nonnull(strstr(a.message, "nothing earlier"));
    ck_assert_int_eq(a.sims[0].steps, 0);
    /* a small system keeps every state: 5000 steps keep the last
     * SW_HISTORY_STATES */
    ck_assert_int_eq(a.hist[0].stride, 1);
    for (int k = 0; k < 5000; k++)
        sw_app_key(&a, '.', 0);
    for (int k = 0; k < 100; k++)
        sw_app_key(&a, ';', 0);
    ck_assert_int_eq(a.sims[0].steps, 5000 - (SW_HISTORY_STATES - 1));
    sw_app_key(&a, ',', 0); /* nothing earlier: the ring's bound, not a reset */
    char says[80];
    snprintf(says, sizeof says, "nothing earlier kept: the last %d states are kept", SW_HISTORY_STATES);
    ck_assert_str_eq(a.message, says);
    sw_app_free(&a);
}
END_TEST

/* A page's @until is its stop time (lesson 7 pages 4 and 5 stop at 2.5);
 * a page without one has none. */
START_TEST(lesson_page_until)
{
    sw_runner r;
    sw_app a;
    char err[SW_ERRLEN];
    ck_assert_msg(sw_runner_start(&r, &a, LESSONS_DIR "/07-implicit.lesson", 4, err, sizeof err) == SW_OK, "%s", err);
    ck_assert(r.lesson.pages[4].until == 2.5);
    ck_assert(a.until == 2.5);
    run_frames(&a);
    ck_assert(a.sims[0].t == 2.5);
    sw_runner_enter(&r, &a, 2); /* the stability region: no stop time */
    ck_assert(a.until == 0);
    sw_runner_free(&r);
    sw_app_free(&a);
}
END_TEST

/* A recording ends at the stop time (a trace cannot describe a step cut
 * in the middle of a run); replayed with the trace's until rule, its last
 * step cut the same way, it reproduces the screen. */
START_TEST(record_to_stop_time)
{
    char dir[] = "/tmp/sw-timeline-XXXXXX", path[64];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/run.trace", dir);
    sw_app a;
    app_on(&a, "spring", "euler", 0.03);
    sw_app_set_until(&a, 2.5);
    sw_app_record_begin(&a, path);
    run_frames(&a);
    ck_assert(a.sims[0].t == 2.5);
    ck_assert_msg(a.recorded, "%s", a.message); /* the stop time ended the recording */
    ck_assert_str_eq(a.record_path, "");
    ck_assert_ptr_nonnull(strstr(a.message, "recorded 84 steps"));
    sw_app_free(&a);
    unlink(path);
    rmdir(dir);
}
END_TEST

/* R names no path: the trace goes to the directory stepwise started in,
 * and the messages say which, by its absolute name, as the recording
 * starts and when it is written (the newcomer's "R wrote into my
 * worktree without saying so"). */
START_TEST(record_says_where)
{
    char dir[] = "/tmp/sw-timeline-XXXXXX", here[512];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    ck_assert_ptr_nonnull(getcwd(here, sizeof here));
    ck_assert_int_eq(chdir(dir), 0);
    char real[512];
    ck_assert_ptr_nonnull(getcwd(real, sizeof real)); /* (the directory's own name, links resolved) */
    sw_app a;
    app_on(&a, "spring", "euler", 0.03);
    sw_app_record_begin(&a, NULL);
    char in[600];
    snprintf(in, sizeof in, " in %s (the directory stepwise started in)", real);
    ck_assert_msg(strstr(a.message, in) != NULL && strstr(a.message, a.record_path) != NULL, "%s", a.message);
    char name[sizeof a.record_path];
    snprintf(name, sizeof name, "%s", a.record_path);
    sw_app_set_until(&a, 0.3);
    run_frames(&a);
    ck_assert_msg(a.recorded && strstr(a.message, in) != NULL, "%s", a.message);
    ck_assert_int_eq(access(name, R_OK), 0);
    sw_app_free(&a);
    unlink(name);
    ck_assert_int_eq(chdir(here), 0);
    rmdir(dir);
}
END_TEST

/* A run that blew up steps back to its last finite state, and on from
 * there blows up at the same step again. */
START_TEST(rewind_from_blow_up)
{
    sw_app a;
    app_on(&a, "spring", "euler", 0.5);
    for (int k = 0; k < 100000 && !a.sims[0].blown; k++)
        sw_app_key(&a, '.', 0);
    ck_assert(a.sims[0].blown);
    long blow_step = a.sims[0].blow_step;
    sw_app_key(&a, ',', 0);
    ck_assert(!a.sims[0].blown);
    ck_assert_int_eq(a.sims[0].steps, blow_step - 1);
    sw_app_key(&a, '.', 0);
    ck_assert(a.sims[0].blown);
    ck_assert_int_eq(a.sims[0].blow_step, blow_step);
    sw_app_free(&a);
}
END_TEST

/* An app on the vortex of n points under method (dt: the scene's). */
static void vortex_on(sw_app *a, int n, const char *method)
{
    char err[SW_ERRLEN], set[32];
    const sw_scene *sc = sw_scene_find("vortex");
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(sc, p);
    snprintf(set, sizeof set, "n=%d", n);
    ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
    ck_assert_msg(sw_app_init(a, sc, p, sw_integrator_find(method), 0, err, sizeof err) == SW_OK, "%s", err);
}

/* A state for comparing bit for bit without keeping it: FNV-1a over y's
 * bytes, with t, steps and evaluations kept whole. */
typedef struct print {
    unsigned long long hash;
    double t;
    long steps, evals;
} print;

static print print_of(const sw_sim *s)
{
    const unsigned char *b = (const unsigned char *)s->sys.y;
    unsigned long long hash = 14695981039346656037ull;
    for (size_t i = 0; i < (size_t)s->sys.ode->dim * sizeof(double); i++)
        hash = (hash ^ b[i]) * 1099511628211ull;
    return (print){ hash, s->t, s->steps, sw_sim_evals(s) };
}

static void same_print(const print *p, const sw_sim *s, const char *what, int at)
{
    print q = print_of(s);
    ck_assert_msg(p->hash == q.hash && p->t == q.t && p->steps == q.steps && p->evals == q.evals,
                  "%s at step %d: t %.17g/%.17g steps %ld/%ld evals %ld/%ld hash %llx/%llx", what, at, p->t, q.t,
                  p->steps, q.steps, p->evals, q.evals, p->hash, q.hash);
}

/* At a size whose snapshots do not fit SW_HISTORY_SPAN times in the budget
 * (the vortex at n = 50000: 8 bytes × 2 × 100000 components a snapshot, 1.6
 * MB, ten of them in 16 MiB) the history keeps a checkpoint every stride-th
 * step, the ring spanning SW_HISTORY_SPAN steps or more. ',' lands on the
 * newest checkpoint behind, ';' on the newest at least 50 steps behind
 * (checkpoints sit at the multiples of the stride: the first is the state
 * the run started from), each equal bit for bit to the forward run's state
 * there, and stepping on repeats the forward run bit for bit: rk4, and
 * rk45, whose FSAL derivative and step proposal a checkpoint carries. */
START_TEST(rewind_checkpoints_bit_for_bit)
{
    static const struct { const char *method; int compare; } cases[] = { { "rk4", 1 }, { "rk45", 0 } };
    enum { N = 150 };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const char *what = cases[c].method;
        sw_app a;
        vortex_on(&a, 50000, what);
        if (cases[c].compare)
            sw_app_set_compare(&a, 1, NULL, NULL);
        const sw_history *h = &a.hist[0];
        int stride = h->stride;
        ck_assert_msg(stride > 1, "%s: stride %d", what, stride);
        for (int i = 0; i < a.nsims; i++) { /* compared runs keep their checkpoints at the same steps */
            ck_assert_int_eq(a.hist[i].stride, stride);
            ck_assert_int_ge((a.hist[i].cap - 1) * stride, SW_HISTORY_SPAN);
        }
        print (*fwd)[SW_APP_SIMS] = calloc(N + 1, sizeof *fwd);
        ck_assert_ptr_nonnull(fwd);
        for (int i = 0; i < a.nsims; i++)
            fwd[0][i] = print_of(&a.sims[i]);
        for (int k = 1; k <= N; k++) {
            sw_app_key(&a, '.', 0);
            for (int i = 0; i < a.nsims; i++)
                fwd[k][i] = print_of(&a.sims[i]);
        }
        int at = (N - 1) / stride * stride;
        sw_app_key(&a, ',', 0);
        ck_assert_int_eq(a.sims[0].steps, at);
        for (int i = 0; i < a.nsims; i++)
            same_print(&fwd[a.sims[i].steps][i], &a.sims[i], what, at);
        char says[80];
        snprintf(says, sizeof says, "step %d (checkpoints every %d steps here;", at, stride);
        ck_assert_msg(strstr(a.message, says), "%s", a.message);
        int back = (at - SW_APP_BACK_MANY) / stride * stride;
        sw_app_key(&a, ';', 0);
        ck_assert_int_eq(a.sims[0].steps, back);
        for (int i = 0; i < a.nsims; i++)
            same_print(&fwd[a.sims[i].steps][i], &a.sims[i], what, back);
        for (int k = back + 1; k <= N; k++) {
            sw_app_key(&a, '.', 0);
            for (int i = 0; i < a.nsims; i++)
                same_print(&fwd[a.sims[i].steps][i], &a.sims[i], what, k);
        }
        free(fwd);
        sw_app_free(&a);
    }
}
END_TEST

/* The memory a history allocates (counted at malloc, tests/support/
 * alloc_count.c) stays within its budget, and the budget is the larger of
 * SW_HISTORY_BYTES and two snapshots: a snapshot is the state and the
 * scene's data, the FSAL derivative (as long as the state) for a method
 * that keeps one (rk45 does, rk4 not), and under 256 bytes of counters.
 * Small systems keep every state (stride 1: the chain n = 1000 and the
 * vortex n = 1000, 64 kB and 32 kB a state, 255 or more in 16 MiB); larger
 * ones stride, the same for both methods; the vortex at n = 300000 (4.8 MB
 * a state) keeps two under rk45, in a budget beyond 16 MiB. */
START_TEST(rewind_memory_within_budget)
{
    static const struct { const char *scene; int n; const char *method; int fsal, stride1; } cases[] = {
        { "chain", 1000, "rk4", 0, 1 },        { "vortex", 1000, "rk45", 1, 1 },
        { "vortex", 50000, "rk4", 0, 0 },      { "vortex", 50000, "rk45", 1, 0 },
        { "vortex", 300000, "rk4", 0, 0 },     { "vortex", 300000, "rk45", 1, 0 },
    };
    int stride_before = 0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        sw_sim s;
        sw_history h;
        char err[SW_ERRLEN], set[32];
        const sw_scene *sc = sw_scene_find(cases[c].scene);
        double p[SW_MAX_PARAMS];
        sw_scene_defaults(sc, p);
        snprintf(set, sizeof set, "n=%d", cases[c].n);
        ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
        ck_assert_msg(sw_sim_init(&s, sc, p, sw_integrator_find(cases[c].method), sc->dt, err, sizeof err) == SW_OK,
                      "%s", err);
        size_t before = sw_test_allocated_bytes();
        sw_history_init(&h, &s);
        size_t took = sw_test_allocated_bytes() - before;
        double one = ((1.0 + cases[c].fsal) * s.sys.ode->dim + s.sys.nextra) * sizeof(double);
        double most = fmax((double)SW_HISTORY_BYTES, 2 * (one + 256));
        ck_assert_int_gt(h.cap, 1);
        ck_assert_msg(took <= h.budget && h.bytes <= h.budget && (double)h.budget <= most,
                      "%s n=%d %s: allocated %zu (says %zu), budget %zu, at most %.0f", cases[c].scene, cases[c].n,
                      cases[c].method, took, h.bytes, h.budget, most);
        ck_assert_msg((double)took >= h.cap * one, "%s n=%d %s: %zu bytes for %d snapshots", cases[c].scene,
                      cases[c].n, cases[c].method, took, h.cap);
        if (cases[c].stride1) {
            ck_assert_int_eq(h.stride, 1);
            ck_assert_int_ge(h.cap, SW_HISTORY_SPAN);
        } else {
            ck_assert_int_gt(h.stride, 1);
            ck_assert_int_ge((h.cap - 1) * h.stride, SW_HISTORY_SPAN);
            if (cases[c].fsal) /* the same scene under rk4, the case before */
                ck_assert_int_eq(h.stride, stride_before);
            stride_before = h.stride;
        }
        if (cases[c].n == 300000 && cases[c].fsal) {
            ck_assert_int_eq(h.cap, 2);
            ck_assert_int_gt(h.budget, SW_HISTORY_BYTES);
        }
        sw_history_free(&h);
        sw_sim_free(&s);
    }
}
END_TEST

/* sw_history_keeps_cache names every built-in method whose steps keep an
 * FSAL derivative (a snapshot without it would not step on bit for bit):
 * each method takes three steps of the spring, or of the orbit (one body
 * alone: dop853-lc), and a cache it keeps must be one the history keeps. */
START_TEST(history_knows_fsal_methods)
{
    static const char *const scenes[] = { "spring", "orbit" };
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        int stepped = 0;
        for (size_t c = 0; c < sizeof scenes / sizeof scenes[0] && !stepped; c++) {
            sw_sim s;
            char err[SW_ERRLEN];
            const sw_scene *sc = sw_scene_find(scenes[c]);
            if (sw_sim_init(&s, sc, NULL, m, sc->dt, err, sizeof err) != SW_OK)
                continue;
            for (int j = 1; j <= 3; j++)
                ck_assert_int_eq(sw_sim_step_until(&s, j * sc->dt), 0);
            ck_assert_msg(!s.stepper->have_cache || sw_history_keeps_cache(m), "%s keeps a cache", m->name);
            sw_sim_free(&s);
            stepped = 1;
        }
        ck_assert_msg(stepped, "%s stepped neither scene", m->name);
    }
}
END_TEST

/* The vortex at n = 300000 under rk45 keeps two checkpoints
 * SW_HISTORY_SPAN or more steps apart: past two strides, ';' goes back to the older one's time
 * and no further ("nothing earlier kept", the run stays). */
START_TEST(rewind_two_checkpoints)
{
    sw_app a;
    vortex_on(&a, 300000, "rk45");
    int stride = a.hist[0].stride;
    ck_assert_int_eq(a.hist[0].cap, 2);
    ck_assert_int_ge(stride, SW_HISTORY_SPAN);
    for (int k = 0; k < 2 * stride + 2; k++)
        sw_app_key(&a, '.', 0);
    sw_app_key(&a, ';', 0);
    ck_assert_int_eq(a.sims[0].steps, stride);
    ck_assert_msg(strstr(a.message, "; 0 earlier)"), "%s", a.message); /* the one at 2·stride was dropped */
    sw_app_key(&a, ',', 0);
    char says[80]; /* why, in one line of the 80-column screen */
    snprintf(says, sizeof says, "nothing earlier kept: 2 checkpoints, %d steps apart, at this size", stride);
    ck_assert_str_eq(a.message, says);
    ck_assert_int_lt(strlen(a.message), 80);
    ck_assert_int_eq(a.sims[0].steps, stride);
    sw_app_free(&a);
}
END_TEST

Suite *make_timeline_suite(void);
Suite *make_timeline_suite(void)
{
    Suite *s = suite_create("timeline");
    TCase *tc = tcase_create("timeline");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, until_lands_exactly);
    tcase_add_test(tc, until_key_runs_there);
    tcase_add_test(tc, until_key_keeps_to_its_budget);
    tcase_add_test(tc, rewind_bit_for_bit);
    tcase_add_test(tc, snapshot_keeps_controller_memory);
    tcase_add_test(tc, rewind_follows_and_bounds);
    tcase_add_test(tc, lesson_page_until);
    tcase_add_test(tc, record_to_stop_time);
    tcase_add_test(tc, record_says_where);
    tcase_add_test(tc, rewind_from_blow_up);
    tcase_add_test(tc, rewind_checkpoints_bit_for_bit);
    tcase_add_test(tc, rewind_memory_within_budget);
    tcase_add_test(tc, history_knows_fsal_methods);
    tcase_add_test(tc, rewind_two_checkpoints);
    suite_add_tcase(s, tc);
    return s;
}
