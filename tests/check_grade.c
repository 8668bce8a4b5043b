/* Grading: the sandbox's children and limits, plugin names and escaping,
 * shortest round-trip numbers, column tolerances, assignments and their
 * header differences, the explaining checker naming a mistake, and the
 * work budget. */
#include <check.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade/assignment.h"
#include "grade/explain.h"
#include "plugin/plugin.h"
#include "plugin/sandbox.h"
#include "grade/verdict.h"
#include "stepwise/stepwise.h"

static char tmpdir[64];

static void make_tmpdir(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/sw_grade_XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(tmpdir));
}

static void remove_tmpdir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    ck_assert_int_eq(system(cmd), 0);
}

/* ---- the sandbox ------------------------------------------------------------- */

static int child_exits(void *ctx, int in, int out)
{
    (void)ctx, (void)in, (void)out;
    return 3;
}

static int child_crashes(void *ctx, int in, int out)
{
    (void)ctx, (void)in, (void)out;
    raise(SIGSEGV);
    return 0;
}

static int child_loops(void *ctx, int in, int out)
{
    (void)ctx, (void)in, (void)out;
    for (volatile int spin = 1; spin;) {
    }
    return 0;
}

static int child_echoes(void *ctx, int in, int out)
{
    (void)ctx;
    char c;
    while (read(in, &c, 1) == 1)
        sw_sandbox_write(out, &c, 1);
    return 0;
}

#if !defined(__SANITIZE_ADDRESS__) /* used only where the memory limit applies (see below) */
static int child_allocates(void *ctx, int in, int out)
{
    (void)ctx, (void)in, (void)out;
    char *big = malloc((size_t)512 << 20);
    if (!big)
        return 4;
    memset(big, 1, (size_t)512 << 20);
    free(big);
    return 0;
}
#endif

START_TEST(sandbox_says_how_a_child_ended)
{
    sw_child c;
    sw_child_end end;
    char err[SW_ERRLEN], how[120];
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_exits, NULL, NULL, -1, err, sizeof err), SW_OK);
    sw_sandbox_reap(&c, 120.0, &end);
    sw_sandbox_describe(&end, how, sizeof how);
    ck_assert_str_eq(how, "exited with status 3");
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_crashes, NULL, NULL, -1, err, sizeof err), SW_OK);
    sw_sandbox_reap(&c, 120.0, &end);
    sw_sandbox_describe(&end, how, sizeof how);
    ck_assert_str_eq(how, "crashed with SIGSEGV (invalid memory access)");
    ck_assert_int_eq(c.pid, 0);
}
END_TEST

/* A round trip works; a child that never answers is a timeout within the
 * limit (0.2 s, checked with slack for a loaded machine), then killed. */
static int child_answers(void *ctx, int in, int out)
{
    (void)ctx, (void)in;
    return sw_sandbox_write(out, "r", 1) == 0 ? 0 : 3;
}

/* A child whose set-up fails ends before it runs anything of its own
 * (issue 39: child_setup ignored dup2 and the rest). Its output
 * descriptor here is a number the parent has not open, so the dup2 onto
 * its stdout fails: it must end with status 125 and never reach fn,
 * which would answer on the channel. */
START_TEST(sandbox_child_whose_setup_fails_never_runs)
{
    enum { NOT_OPEN = 1000 };
    ck_assert_int_eq(fcntl(NOT_OPEN, F_GETFD), -1);
    sw_child c;
    sw_child_end end;
    char err[256], byte;
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_answers, NULL, NULL, NOT_OPEN, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_sandbox_read(c.from_child, &byte, 1, 30.0), 0); /* the end, no answer */
    sw_sandbox_reap(&c, 30.0, &end);
    ck_assert(end.exited && end.code == 125);
    /* the same child with an open output descriptor answers */
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_answers, NULL, NULL, STDERR_FILENO, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_sandbox_read(c.from_child, &byte, 1, 30.0), 1);
    ck_assert_int_eq(byte, 'r');
    sw_sandbox_reap(&c, 30.0, &end);
    ck_assert(end.exited && end.code == 0);
}
END_TEST

START_TEST(sandbox_watchdog_stops_a_loop)
{
    sw_child c;
    sw_child_end end;
    char err[SW_ERRLEN], byte = 'x';
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_echoes, NULL, NULL, -1, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_sandbox_write(c.to_child, "q", 1), 0);
    ck_assert_int_eq(sw_sandbox_read(c.from_child, &byte, 1, 5.0), 1);
    ck_assert_int_eq(byte, 'q');
    sw_sandbox_kill(&c, &end);
    ck_assert(end.killed);
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_loops, NULL, NULL, -1, err, sizeof err), SW_OK);
    double start = sw_sandbox_now();
    ck_assert_int_eq(sw_sandbox_read(c.from_child, &byte, 1, 0.2), -2);
    double took = sw_sandbox_now() - start;
    /* at least its limit; the upper bound only tells a hang from a busy machine */
    ck_assert_msg(took >= 0.19 && took < 60.0, "the watchdog took %g s for a 0.2 s limit", took);
    sw_sandbox_kill(&c, &end);
    ck_assert(end.killed);
    /* Writing to a dead child is an error, not a SIGPIPE. */
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_exits, NULL, NULL, -1, err, sizeof err), SW_OK);
    sw_child_end e2;
    int fd = dup(c.to_child);
    sw_sandbox_reap(&c, 120.0, &e2);
    int rc = 0;
    for (int i = 0; i < 100 && rc == 0; i++)
        rc = sw_sandbox_write(fd, "x", 1);
    ck_assert_int_eq(rc, -1);
    close(fd);
}
END_TEST

/* CPU time: a loop under a 1 s limit dies of SIGXCPU. The limit is CPU
 * time, which a loaded machine hands out slowly (load 21 on two cores once
 * took it past a 30 s wait): the wall-clock wait only guards a hang. */
START_TEST(sandbox_cpu_limit)
{
    sw_child c;
    sw_child_end end;
    char err[SW_ERRLEN], how[120];
    sw_limits lim = { .cpu_seconds = 1 };
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_loops, NULL, &lim, -1, err, sizeof err), SW_OK);
    sw_sandbox_reap(&c, 300.0, &end);
    sw_sandbox_describe(&end, how, sizeof how);
    ck_assert_msg(end.signal == SIGXCPU || end.signal == SIGKILL, "%s", how);
    ck_assert(!end.killed);
}
END_TEST

START_TEST(sandbox_memory_limit)
{
#if defined(__SANITIZE_ADDRESS__)
    return; /* the memory limit is not applied under AddressSanitizer */
#else
    sw_child c;
    sw_child_end end;
    char err[SW_ERRLEN];
    sw_limits lim = { .memory_bytes = (size_t)128 << 20 };
    ck_assert_int_eq(sw_sandbox_spawn(&c, child_allocates, NULL, &lim, -1, err, sizeof err), SW_OK);
    sw_sandbox_reap(&c, 300.0, &end);
    ck_assert(end.exited);
    ck_assert_int_eq(end.code, 4); /* 512 MiB refused under a 128 MiB limit */
#endif
}
END_TEST

/* ---- names, escaping, numbers --------------------------------------------------- */

START_TEST(plugin_names_and_labels)
{
    char why[SW_ERRLEN];
    ck_assert(sw_plugin_name_ok("my-rk4", why, sizeof why));
    ck_assert(sw_plugin_name_ok("rk4_v2.1+fix", why, sizeof why));
    ck_assert(!sw_plugin_name_ok("", why, sizeof why));
    ck_assert(!sw_plugin_name_ok("a-name-far-longer-than-forty-characters-xx", why, sizeof why));
    ck_assert(!sw_plugin_name_ok("euler ", why, sizeof why));
    ck_assert_ptr_nonnull(strstr(why, "character 6"));
    ck_assert(!sw_plugin_name_ok("two\nlines", why, sizeof why));
    ck_assert(!sw_plugin_name_ok("-flag", why, sizeof why));
    ck_assert(!sw_plugin_name_ok("RK4", why, sizeof why));
    ck_assert_ptr_nonnull(strstr(why, "shadows the built-in method 'rk4'"));
    ck_assert(sw_plugin_label_ok("Runge–Kutta (student)", why, sizeof why)); /* UTF-8 dash */
    ck_assert(!sw_plugin_label_ok("PASS\033[2J", why, sizeof why));
    ck_assert(!sw_plugin_label_ok("trailing ", why, sizeof why));
    ck_assert(!sw_plugin_label_ok("c1 \xc2\x9b control", why, sizeof why));
    ck_assert(!sw_plugin_label_ok("bad \xff byte", why, sizeof why));
}
END_TEST

START_TEST(escaping_untrusted_text)
{
    char out[64];
    sw_escape("x\033[2J\n\\é", 40, out, sizeof out);
    ck_assert_str_eq(out, "x\\x1b[2J\\x0a\\x5cé");
    sw_escape("abcdefghij", 4, out, sizeof out);
    ck_assert_str_eq(out, "abcd...");
    sw_escape("\xff\xfe", 40, out, sizeof out);
    ck_assert_str_eq(out, "\\xff\\xfe");
}
END_TEST

START_TEST(shortest_round_trip_numbers)
{
    static const struct { double v; const char *s; } cases[] = {
        { 1e-9, "1e-09" }, { 0.02, "0.02" }, { 60, "60" }, { -0.5, "-0.5" },
        { 0.1 + 0.2, "0.30000000000000004" }, { 1.0 / 3, "0.3333333333333333" },
        { INFINITY, "inf" }, { -INFINITY, "-inf" }, { 0, "0" },
    };
    char buf[40];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sw_fmt_shortest(buf, sizeof buf, cases[i].v);
        ck_assert_str_eq(buf, cases[i].s);
        if (isfinite(cases[i].v))
            ck_assert(strtod(buf, NULL) == cases[i].v);
    }
    sw_fmt_shortest(buf, sizeof buf, NAN);
    ck_assert_str_eq(buf, "nan");
}
END_TEST

/* ---- tolerances and assignments --------------------------------------------------- */

START_TEST(column_tolerances)
{
    sw_coltols t;
    memset(&t, 0, sizeof t);
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_coltol_parse(&t, "energy=1e-6", 0, "--tol", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_coltol_parse(&t, "x0=1e-9,1e-12", 0, "--tol", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_coltol_parse(&t, "v*", 1, "--ignore", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_coltol_parse(&t, "step", 1, "--ignore", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_coltol_parse(&t, "energy=abc", 0, "--tol", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_coltol_parse(&t, "energy=0,0", 0, "--tol", err, sizeof err), SW_EINVAL);
    sw_system sys;
    ck_assert_int_eq(sw_system_build(&sys, sw_scene_find("spring"), NULL, err, sizeof err), SW_OK);
    double r[7], a[7];
    unsigned char ign[7];
    ck_assert_msg(sw_coltol_resolve(&t, &sys, 1e-9, 1e-9, r, a, ign, err, sizeof err) == SW_OK, "%s", err);
    /* columns: step t x0 y0 vx0 vy0 energy */
    ck_assert(r[6] == 1e-6 && a[6] == 1e-6);
    ck_assert(r[2] == 1e-9 && a[2] == 1e-12);
    ck_assert(r[3] == 1e-9 && !ign[3]);
    ck_assert(ign[4] && ign[5] && !ign[2]);
    ck_assert_int_eq(sw_coltol_parse(&t, "x7=1", 0, "--tol", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_coltol_resolve(&t, &sys, 1e-9, 1e-9, r, a, ign, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "no column 'x7'"));
    sw_system_free(&sys);
}
END_TEST

static void write_file(const char *name, const char *text, char *path, size_t len)
{
    snprintf(path, len, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

START_TEST(assignment_and_header_differences)
{
    make_tmpdir();
    char path[128], err[SW_ERRLEN + 4096];
    write_file("a.txt", "\xef\xbb\xbf# stepwise assignment 1  \n# title: week 3\n# scene: spring\n"
               "# param g: 9.81\n# integrator: rk4, midpoint\n# dt: 0.01\n# steps: 100\n"
               "# tolerance: 1e-8\n# tolerance energy: 1e-6\n# ignore: vy0\n", path, sizeof path);
    static sw_assignment a;
    ck_assert_msg(sw_assignment_read(&a, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(a.nmethods, 2);
    ck_assert_str_eq(a.methods[1]->name, "midpoint");
    ck_assert(a.rtol == 1e-8 && a.atol == 1e-8);
    ck_assert_int_eq(a.coltols.n, 2);
    ck_assert_str_eq(a.title, "week 3");
    /* A trace with k = 12, euler and dt 0.02 differs in three places, in header order. */
    write_file("t.trace", "# stepwise trace 1\n# student: Ada\n# note: late\n# scene: spring\n"
               "# param k: 12\n# param g: 9.81\n# integrator: euler\n# dt: 0.02\n# steps: 100\n"
               "step,t,x0,y0,vx0,vy0,energy\n", path, sizeof path);
    sw_trace_reader r;
    ck_assert_msg(sw_trace_read_open(&r, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_str_eq(r.meta.student, "Ada");
    ck_assert_str_eq(r.meta.notes, "late");
    sw_header_diff d[8];
    int comparable;
    int n = sw_assignment_diff(&a, &r.meta, &r.sys, d, 8, &comparable);
    ck_assert_int_eq(n, 3);
    ck_assert(comparable);
    ck_assert_str_eq(d[0].what, "param k");
    ck_assert_str_eq(d[0].got, "12");
    ck_assert_str_eq(d[0].want, "10");
    ck_assert_int_eq(d[0].line, 5);
    ck_assert_str_eq(d[1].what, "integrator");
    ck_assert_str_eq(d[1].want, "any of rk4, midpoint");
    ck_assert_str_eq(d[2].what, "dt");
    ck_assert_int_eq(d[2].line, 8);
    sw_trace_read_close(&r);
    /* An unknown key of an assignment is named with the keys allowed. */
    write_file("b.txt", "# stepwise assignment 1\n# scene: spring\n# colour: red\n", path, sizeof path);
    ck_assert_int_eq(sw_assignment_read(&a, path, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "b.txt:3: unknown metadata key 'colour'"));
    remove_tmpdir();
}
END_TEST

/* ---- the explaining checker --------------------------------------------------------- */

/* Record scene under method (dt) into tmpdir/name, declared as `label`. */
static void record(const char *name, const char *scene, const char *set, const char *method,
                   double dt, long steps, const char *label, char *path, size_t len)
{
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    if (set)
        ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
    sw_sim s;
    ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find(method), dt, err, sizeof err), SW_OK);
    snprintf(path, len, "%s/%s", tmpdir, name);
    sw_trace_writer w;
    sw_trace_spec spec = { .steps = steps, .every = 1 };
    ck_assert_int_eq(sw_trace_open(&w, path, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_trace_begin(&w, &s, &spec, err, sizeof err), SW_OK);
    while (!sw_trace_done(&s, &spec)) {
        ck_assert_int_eq(sw_trace_step(&s, &spec, err, sizeof err), SW_OK);
        ck_assert_int_eq(sw_trace_observe(&w, &s, err, sizeof err), SW_OK);
    }
    ck_assert_int_eq(sw_trace_commit(&w, &s, err, sizeof err), SW_OK);
    sw_sim_free(&s);
    if (strcmp(label, method) != 0) {
        char cmd[512];
        snprintf(cmd, sizeof cmd, "sed -i 's/^# integrator: .*/# integrator: %s/' '%s'", label, path);
        ck_assert_int_eq(system(cmd), 0);
    }
}

static void want_run(sw_run_desc *d, const char *scene, const char *set, const char *method,
                     double dt, long steps)
{
    memset(d, 0, sizeof *d);
    d->scene = sw_scene_find(scene);
    sw_scene_defaults(d->scene, d->p);
    char err[SW_ERRLEN];
    if (set)
        ck_assert_int_eq(sw_scene_set(d->scene, d->p, set, err, sizeof err), SW_OK);
    d->method = sw_integrator_find(method);
    d->dt = dt;
    d->spec = (sw_trace_spec){ .steps = steps, .every = 1 };
    d->rtol = SW_RTOL_DEFAULT;
    d->atol = SW_ATOL_DEFAULT;
}

START_TEST(explain_names_the_mistake)
{
    make_tmpdir();
    char path[128], err[SW_ERRLEN];
    sw_check_tol tol = { .rtol = SW_CHECK_RTOL, .atol = SW_CHECK_ATOL };
    sw_run_desc want;
    sw_explanation ex;
    /* v-then-x Euler under the name euler: symplectic Euler, exactly. */
    record("vx.trace", "spring", "g=9.81", "symplectic-euler", 0.01, 60, "euler", path, sizeof path);
    want_run(&want, "spring", "g=9.81", "euler", 0.01, 60);
    ck_assert_int_eq(sw_explain(path, &want, &tol, &ex, err, sizeof err), 1);
    ck_assert_str_eq(ex.kind, "method");
    ck_assert_msg(strstr(ex.message, "did you update v before x?"), "%s", ex.message);
    ck_assert(ex.agreement == 0);
    /* dt halved: 120 steps of 0.005 against 120 of 0.01. */
    record("dt.trace", "chain", NULL, "rk4", 0.005, 120, "rk4", path, sizeof path);
    want_run(&want, "chain", NULL, "rk4", 0.01, 120);
    ck_assert_int_eq(sw_explain(path, &want, &tol, &ex, err, sizeof err), 1);
    ck_assert_str_eq(ex.kind, "dt");
    ck_assert_msg(strstr(ex.message, "dt = 0.005, half the assignment's 0.01"), "%s", ex.message);
    /* Another parameter value: the trace's own k. */
    record("k.trace", "chain", "k=50", "verlet", 0.01, 80, "verlet", path, sizeof path);
    want_run(&want, "chain", NULL, "verlet", 0.01, 80);
    ck_assert_int_eq(sw_explain(path, &want, &tol, &ex, err, sizeof err), 1);
    ck_assert_str_eq(ex.kind, "parameter");
    ck_assert_msg(strstr(ex.message, "k = 50 (the assignment has k = 100)"), "%s", ex.message);
    /* A correct trace has nothing to explain. */
    record("ok.trace", "chain", NULL, "verlet", 0.01, 80, "verlet", path, sizeof path);
    ck_assert_int_eq(sw_explain(path, &want, &tol, &ex, err, sizeof err), 0);
    remove_tmpdir();
}
END_TEST

START_TEST(budget_refuses_unbounded_work)
{
    char err[SW_ERRLEN];
    double work;
    const sw_scene *vortex = sw_scene_find("vortex");
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(vortex, p);
    p[1] = 200000;
    sw_trace_spec spec = { .steps = 10000000, .every = 1 };
    ck_assert_int_eq(sw_check_budget(vortex, p, sw_integrator_find("euler"), 1e-9, &spec, &work,
                                     err, sizeof err), SW_EINVAL);
    ck_assert(work == 1e7 * 400000);
    ck_assert_ptr_nonnull(strstr(err, "above the budget of 2e+10"));
    spec.steps = 1000;
    ck_assert_int_eq(sw_check_budget(vortex, p, sw_integrator_find("euler"), 1e-9, &spec, &work,
                                     err, sizeof err), SW_OK);
    /* until/dt: refused before the run, not after 10^7 steps */
    sw_trace_spec until = { .until = 0.01, .every = 1 };
    ck_assert_int_eq(sw_trace_spec_check(&until, 1e-9, err, sizeof err), SW_EINVAL);
    until.until = 0.0099;
    ck_assert_int_eq(sw_trace_spec_check(&until, 1e-9, err, sizeof err), SW_OK);
}
END_TEST

Suite *make_grade_suite(void);
Suite *make_grade_suite(void)
{
    Suite *s = suite_create("grade");
    TCase *tc = tcase_create("sandbox");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, sandbox_says_how_a_child_ended);
    tcase_add_test(tc, sandbox_child_whose_setup_fails_never_runs);
    tcase_add_test(tc, sandbox_watchdog_stops_a_loop);
    tcase_add_test(tc, sandbox_cpu_limit);
    tcase_add_test(tc, sandbox_memory_limit);
    suite_add_tcase(s, tc);
    tc = tcase_create("grading");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, plugin_names_and_labels);
    tcase_add_test(tc, escaping_untrusted_text);
    tcase_add_test(tc, shortest_round_trip_numbers);
    tcase_add_test(tc, column_tolerances);
    tcase_add_test(tc, assignment_and_header_differences);
    tcase_add_test(tc, explain_names_the_mistake);
    tcase_add_test(tc, budget_refuses_unbounded_work);
    suite_add_tcase(s, tc);
    return s;
}
