/* Step traces: column layout, the first rows of a spring under Euler worked
 * by hand, writer and reader round trip (bit for bit), the temporary-file
 * rule, the run rule (every K, until, blow-up), the numdiff comparison, and
 * the reader's errors naming file and line. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stepwise/stepwise.h"
#include "stepwise/sim.h"
#include "grade/check.h"
#include "trace/trace.h"

static char tmpdir[64];

static void make_tmpdir(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/sw_trace_XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(tmpdir));
}

static void remove_tmpdir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    ck_assert_int_eq(system(cmd), 0);
}

static void sim_with(sw_sim *s, const char *scene, const char *method, double dt, const char *set1)
{
    const sw_scene *sc = sw_scene_find(scene);
    ck_assert_ptr_nonnull(sc);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    if (set1)
        ck_assert_msg(sw_scene_set(sc, p, set1, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_sim_init(s, sc, p, sw_integrator_find(method), dt, err, sizeof err) == SW_OK,
                  "%s", err);
}

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Files in tmpdir whose name starts with prefix. */
static int count_prefixed(const char *prefix)
{
    char cmd[256];
    snprintf(cmd, sizeof cmd, "ls -1 '%s' | grep -c '^%s' > '%s/count'", tmpdir, prefix, tmpdir);
    if (system(cmd) == -1)
        return -1;
    char path[128];
    snprintf(path, sizeof path, "%s/count", tmpdir);
    FILE *f = fopen(path, "r");
    int n = -1;
    if (f) {
        if (fscanf(f, "%d", &n) != 1)
            n = -1;
        fclose(f);
    }
    unlink(path);
    return n;
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

/* Record scene/method to path through the writer, as `stepwise record` does. */
static void record(const char *path, const char *scene, const char *method, double dt,
                   const char *set1, sw_trace_spec spec)
{
    sw_sim s;
    sw_trace_writer w;
    char err[SW_ERRLEN];
    sim_with(&s, scene, method, dt, set1);
    ck_assert_msg(sw_trace_open(&w, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_trace_begin(&w, &s, &spec, err, sizeof err) == SW_OK, "%s", err);
    while (!sw_trace_done(&s, &spec)) {
        ck_assert_int_eq(sw_trace_step(&s, &spec, err, sizeof err), SW_OK);
        ck_assert_msg(sw_trace_observe(&w, &s, err, sizeof err) == SW_OK, "%s", err);
    }
    ck_assert_msg(sw_trace_commit(&w, &s, err, sizeof err) == SW_OK, "%s", err);
    sw_sim_free(&s);
}

START_TEST(columns_follow_the_format)
{
    /* spring: one particle, second order, with energy: 2 + 4 + 1 columns. */
    sw_sim s;
    char name[32];
    sim_with(&s, "spring", "euler", 0.02, NULL);
    ck_assert_int_eq(sw_trace_ncols(&s.sys), 7);
    const char *want[] = { "step", "t", "x0", "y0", "vx0", "vy0", "energy" };
    for (int c = 0; c < 7; c++) {
        sw_trace_colname(&s.sys, c, name, sizeof name);
        ck_assert_str_eq(name, want[c]);
    }
    sw_sim_free(&s);
    /* chain of 3: particle i's four values sit together, 2 + 12 + 1 columns. */
    sim_with(&s, "chain", "rk4", 0.01, "n=3");
    ck_assert_int_eq(sw_trace_ncols(&s.sys), 15);
    sw_trace_colname(&s.sys, 2 + 4 * 2 + 3, name, sizeof name);
    ck_assert_str_eq(name, "vy2");
    double row[15];
    sw_trace_row_values(&s, row);
    /* Bead 1 (the middle one, n/2) is plucked sideways by 0.5; spacing rest = 1. */
    ck_assert_double_eq(row[2 + 4 * 1], 2.0);
    ck_assert_double_eq(row[2 + 4 * 1 + 1], 0.5);
    sw_sim_free(&s);
    /* vortex: a first-order flow, positions only, no energy: 2 + 2n. */
    sim_with(&s, "vortex", "rk4", 0.05, "n=5");
    int has_energy = s.sys.scene->energy != NULL;
    ck_assert_int_eq(sw_trace_ncols(&s.sys), 2 + 2 * 5 + has_energy);
    sw_trace_colname(&s.sys, 11, name, sizeof name);
    ck_assert_str_eq(name, "y4");
    sw_sim_free(&s);
}
END_TEST

/* The worked example of docs/trace-format.md. Spring defaults k = 10, m = 1,
 * c = 0.5, rest = 1, stretch = 0.5, dt = 0.02; Euler by hand:
 *   a0 = -(k·0.5)/m = -5          x1 = 1.5,   v1 = 0.02·(-5) = -0.1
 *   a1 = -(k·0.5 + c·(-0.1)) = -4.95   x2 = 1.5 - 0.002 = 1.498,
 *   v2 = -0.1 - 0.099 = -0.199;   E1 = ½·0.01 + ½·10·0.25 = 1.255.
 * Tolerance 4e-16: a couple of roundings of numbers below 2. */
START_TEST(first_spring_rows_by_hand)
{
    sw_sim s;
    sw_trace_spec spec = { .steps = 2, .every = 1 };
    char err[SW_ERRLEN];
    double row[7];
    sim_with(&s, "spring", "euler", 0.02, NULL);
    sw_trace_row_values(&s, row);
    ck_assert_double_eq(row[2], 1.5);
    ck_assert_double_eq_tol(row[6], 1.25, 4e-16);
    ck_assert_int_eq(sw_trace_step(&s, &spec, err, sizeof err), SW_OK);
    sw_trace_row_values(&s, row);
    ck_assert_double_eq(row[0], 1.0);
    ck_assert_double_eq_tol(row[1], 0.02, 4e-16);
    ck_assert_double_eq_tol(row[2], 1.5, 4e-16);
    ck_assert_double_eq_tol(row[4], -0.1, 4e-16);
    ck_assert_double_eq(row[3], 0.0);
    ck_assert_double_eq(row[5], 0.0);
    ck_assert_double_eq_tol(row[6], 1.255, 4e-16);
    ck_assert_int_eq(sw_trace_step(&s, &spec, err, sizeof err), SW_OK);
    sw_trace_row_values(&s, row);
    ck_assert_double_eq_tol(row[2], 1.498, 4e-16);
    ck_assert_double_eq_tol(row[4], -0.199, 4e-16);
    ck_assert(sw_trace_done(&s, &spec));
    sw_sim_free(&s);
}
END_TEST

/* Written with %.17g, read back with strtod: every value round-trips, so a
 * recorded trace equals a fresh run bit for bit. Every 7 of 100 steps:
 * steps 0, 7, ..., 98 (15 rows) and the last, 100. */
START_TEST(write_then_read_bit_for_bit)
{
    make_tmpdir();
    char path[128], err[SW_ERRLEN];
    snprintf(path, sizeof path, "%s/t.csv", tmpdir);
    sw_trace_spec spec = { .steps = 100, .every = 7 };
    record(path, "chain", "rk4", 0.01, "n=4", spec);

    sw_trace_reader r;
    ck_assert_msg(sw_trace_read_open(&r, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_str_eq(r.meta.scene->name, "chain");
    ck_assert_str_eq(r.meta.integrator, "rk4");
    ck_assert_ptr_eq(r.meta.method, sw_integrator_find("rk4"));
    ck_assert_double_eq(r.meta.dt, 0.01);
    ck_assert_int_eq(r.meta.spec.steps, 100);
    ck_assert_int_eq(r.meta.spec.every, 7);
    ck_assert_double_eq(r.meta.p[sw_scene_param_index(r.meta.scene, "n")], 4.0);
    ck_assert_double_eq(r.meta.rtol, SW_RTOL_DEFAULT);
    ck_assert_msg(sw_trace_read_header(&r, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(r.ncols, 2 + 16 + 1);

    sw_sim s;
    sim_with(&s, "chain", "rk4", 0.01, "n=4");
    double got[19], want[19];
    int rows = 0, rc;
    while ((rc = sw_trace_read_row(&r, got, err, sizeof err)) == 1) {
        if (rows > 0)
            do
                ck_assert_int_eq(sw_trace_step(&s, &spec, err, sizeof err), SW_OK);
            while (!sw_trace_due(&s, &spec));
        sw_trace_row_values(&s, want);
        ck_assert_int_eq(memcmp(got, want, sizeof got), 0);
        rows++;
    }
    ck_assert_msg(rc == 0, "%s", err);
    ck_assert_int_eq(rows, 16);
    ck_assert_double_eq(got[0], 100.0);
    sw_trace_read_close(&r);
    sw_sim_free(&s);
    remove_tmpdir();
}
END_TEST

/* Until the trace is committed the real name does not exist; abort leaves
 * nothing; an unwritable place fails without a half-written file. */
START_TEST(temp_file_then_rename)
{
    make_tmpdir();
    char path[128], err[SW_ERRLEN];
    snprintf(path, sizeof path, "%s/t.csv", tmpdir);
    sw_sim s;
    sw_trace_writer w;
    sw_trace_spec spec = { .steps = 10, .every = 1 };
    sim_with(&s, "spring", "euler", 0.02, NULL);
    ck_assert_int_eq(sw_trace_open(&w, path, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_trace_begin(&w, &s, &spec, err, sizeof err), SW_OK);
    ck_assert(!file_exists(path));
    ck_assert_int_eq(count_prefixed("t.csv.tmp."), 1);
    /* Rows are flushed as they are written: the temp file ends in a newline. */
    struct stat st;
    ck_assert_int_eq(stat(w.out.tmp, &st), 0);
    FILE *f = fopen(w.out.tmp, "r");
    ck_assert_ptr_nonnull(f);
    fseek(f, -1, SEEK_END);
    ck_assert_int_eq(fgetc(f), '\n');
    fclose(f);
    sw_trace_abort(&w);
    ck_assert(!file_exists(path));
    ck_assert_int_eq(count_prefixed("t.csv"), 0);

    ck_assert_int_eq(sw_trace_open(&w, path, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_trace_begin(&w, &s, &spec, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_trace_commit(&w, &s, err, sizeof err), SW_OK);
    ck_assert(file_exists(path));
    ck_assert_int_eq(count_prefixed("t.csv.tmp."), 0);

    char bad[160];
    snprintf(bad, sizeof bad, "%s/no/such/dir/t.csv", tmpdir);
    ck_assert_int_eq(sw_trace_open(&w, bad, err, sizeof err), SW_EIO);
    ck_assert_ptr_nonnull(strstr(err, "cannot create"));
    ck_assert_int_eq(sw_trace_open(&w, tmpdir, err, sizeof err), SW_EINVAL);
    sw_sim_free(&s);
    remove_tmpdir();
}
END_TEST

/* --until lands exactly: dt 0.03 to t = 0.1 is three full steps and a
 * shortened fourth of 0.01. */
START_TEST(until_lands_exactly)
{
    sw_sim s;
    sw_trace_spec spec = { .until = 0.1, .every = 1 };
    char err[SW_ERRLEN];
    sim_with(&s, "spring", "rk4", 0.03, NULL);
    ck_assert_int_eq(sw_trace_spec_check(&spec, 0.03, err, sizeof err), SW_OK);
    while (!sw_trace_done(&s, &spec))
        ck_assert_int_eq(sw_trace_step(&s, &spec, err, sizeof err), SW_OK);
    ck_assert_int_eq(s.steps, 4);
    ck_assert_double_eq(s.t, 0.1);
    sw_sim_free(&s);
    /* The limits: 10^7 steps at most, whichever way the run is given. */
    sw_trace_spec big = { .until = 1e6, .every = 1 };
    ck_assert_int_eq(sw_trace_spec_check(&big, 0.01, err, sizeof err), SW_EINVAL);
    big = (sw_trace_spec){ .steps = SW_TRACE_MAX_STEPS + 1, .every = 1 };
    ck_assert_int_eq(sw_trace_spec_check(&big, 0.01, err, sizeof err), SW_EINVAL);
    big = (sw_trace_spec){ .steps = 10, .every = 0 };
    ck_assert_int_eq(sw_trace_spec_check(&big, 0.01, err, sizeof err), SW_EINVAL);
}
END_TEST

/* Undamped Euler with ω·dt = √(1e6)·0.02 = 20 multiplies the amplitude by
 * √(1 + 400) ≈ 20 per step: it runs away within a few steps. The trace ends
 * at that step and says so; the reader accepts the note. */
START_TEST(blowup_ends_the_trace)
{
    make_tmpdir();
    char path[128], err[SW_ERRLEN];
    snprintf(path, sizeof path, "%s/b.csv", tmpdir);
    sw_trace_spec spec = { .steps = 1000, .every = 10 };
    record(path, "spring", "euler", 0.02, "k=1e6", spec);
    sw_sim s;
    sim_with(&s, "spring", "euler", 0.02, "k=1e6");
    ck_assert_int_eq(sw_sim_run_until(&s, 20.0), 1);
    long blow = s.blow_step;
    ck_assert_int_lt(blow, 20);
    sw_sim_free(&s);

    sw_trace_reader r;
    double row[7], last = -1;
    int rc;
    ck_assert_msg(sw_trace_read_open(&r, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_trace_read_header(&r, err, sizeof err) == SW_OK, "%s", err);
    while ((rc = sw_trace_read_row(&r, row, err, sizeof err)) == 1)
        last = row[0];
    ck_assert_msg(rc == 0, "%s", err);
    ck_assert_double_eq(last, (double)blow);
    ck_assert_int_eq(r.meta.diverged, 1);
    sw_trace_read_close(&r);
    remove_tmpdir();
}
END_TEST

START_TEST(value_comparison_rules)
{
    double a, rel, ratio;
    /* Exactly on the boundary passes: e = 1, d = 2^-20 = atol + rtol·1. */
    ck_assert(sw_check_value(1.0, 1.0 + ldexp(1, -20), ldexp(1, -21), ldexp(1, -21), &a, &rel, &ratio));
    ck_assert_double_eq(ratio, 1.0);
    ck_assert(!sw_check_value(1.0, 1.0 + ldexp(1, -19), ldexp(1, -21), ldexp(1, -21), &a, &rel, &ratio));
    ck_assert_double_eq(ratio, 2.0);
    ck_assert_double_eq(rel, ldexp(1, -19));
    /* Equal non-finite values pass; anything else involving one fails. */
    ck_assert(sw_check_value(NAN, NAN, 1e-9, 1e-9, &a, &rel, &ratio));
    ck_assert(sw_check_value(INFINITY, INFINITY, 1e-9, 1e-9, &a, &rel, &ratio));
    ck_assert(!sw_check_value(INFINITY, -INFINITY, 1e-9, 1e-9, &a, &rel, &ratio));
    ck_assert(!sw_check_value(1.0, NAN, 1e-9, 1e-9, &a, &rel, &ratio));
    ck_assert(!sw_check_value(NAN, 1.0, 1e-9, 1e-9, &a, &rel, &ratio));
    ck_assert(isinf(ratio));
    /* Expected zero: only atol applies; the relative error is taken against
     * atol/rtol = 1 (the scale below which atol dominates), so it is 1e-6,
     * not infinite. */
    ck_assert(!sw_check_value(0.0, 1e-6, 1e-9, 1e-9, &a, &rel, &ratio));
    ck_assert_double_eq_tol(rel, 1e-6, 1e-20);
    ck_assert(sw_check_value(1e-3, 1e-3 + 1e-10, 1e-9, 1e-9, &a, &rel, &ratio));
    /* |e| = 1e-3 < 1: still against the scale 1 (1e-3 + 1e-10 is rounded: ulp 2e-19) */
    ck_assert_double_eq_tol(rel, 1e-10, 1e-17);
}
END_TEST

/* Two runs in lockstep: a method against itself passes exactly; rk4 against
 * euler fails at step 1 (x changes under rk4 in the first step, by
 * -k·stretch·dt²/2 ≈ -1e-3, and not under Euler); a run with fewer steps
 * is reported as missing rows. */
START_TEST(compare_runs)
{
    sw_sim a, b;
    sw_trace_spec spec = { .steps = 50, .every = 1 };
    sw_check_result res;
    char err[SW_ERRLEN];
    sim_with(&a, "spring", "euler", 0.02, NULL);
    sim_with(&b, "spring", "euler", 0.02, NULL);
    sw_row_source ea = { .sim = &a, .spec = spec }, eb = { .sim = &b, .spec = spec };
    ck_assert_int_eq(sw_check_compare(&ea, &eb, 7, SW_CHECK_RTOL, SW_CHECK_ATOL, &res, err, sizeof err), SW_OK);
    ck_assert(res.pass);
    ck_assert_int_eq(res.rows_compared, 51);
    ck_assert_int_eq(res.values_compared, 51 * 7);
    ck_assert(!res.have_worst);
    sw_sim_free(&a);
    sw_sim_free(&b);

    sim_with(&a, "spring", "euler", 0.02, NULL);
    sim_with(&b, "spring", "rk4", 0.02, NULL);
    ea = (sw_row_source){ .sim = &a, .spec = spec };
    eb = (sw_row_source){ .sim = &b, .spec = spec };
    ck_assert_int_eq(sw_check_compare(&ea, &eb, 7, SW_CHECK_RTOL, SW_CHECK_ATOL, &res, err, sizeof err), SW_OK);
    ck_assert(!res.pass);
    ck_assert_int_eq(res.first.kind, SW_CHECK_VALUE);
    ck_assert_int_eq(res.first.step, 1);
    ck_assert_int_eq(res.first.column, 2);
    ck_assert_double_eq_tol(res.first.got - res.first.expected, -10 * 0.5 * 0.02 * 0.02 / 2, 1e-5);
    sw_sim_free(&a);
    sw_sim_free(&b);

    sim_with(&a, "spring", "euler", 0.02, NULL);
    sim_with(&b, "spring", "euler", 0.02, NULL);
    sw_trace_spec shorter = { .steps = 30, .every = 1 };
    ea = (sw_row_source){ .sim = &a, .spec = spec };
    eb = (sw_row_source){ .sim = &b, .spec = shorter };
    ck_assert_int_eq(sw_check_compare(&ea, &eb, 7, SW_CHECK_RTOL, SW_CHECK_ATOL, &res, err, sizeof err), SW_OK);
    ck_assert(!res.pass);
    ck_assert_int_eq(res.first.kind, SW_CHECK_MISSING);
    ck_assert_int_eq(res.first.step, 31);
    ck_assert_int_eq(res.rows_got, 31);
    ck_assert_int_eq(res.rows_expected, 51);
    sw_sim_free(&a);
    sw_sim_free(&b);
}
END_TEST

/* Each bad file: SW_EINVAL (or SW_EIO) and a message "PATH:LINE: ...". */
START_TEST(reader_errors_name_file_and_line)
{
    static const char head[] = "# stepwise trace 1\n# scene: spring\n# integrator: euler\n"
                               "# dt: 0.02\n# steps: 2\n";
    static const char header[] = "step,t,x0,y0,vx0,vy0,energy\n";
    static const char row0[] = "0,0,1.5,0,0,0,1.25\n";
    struct { const char *name, *text; int line; const char *needle; } cases[] = {
        { "empty", "", 1, "empty file" },
        { "magic", "# stepwise trace 9\n", 1, "format 9" },
        { "key", "# stepwise trace 1\n# colour: red\n", 2, "unknown metadata key 'colour'" },
        { "scene", "# stepwise trace 1\n# scene: nope\n", 2, "unknown scene 'nope'" },
        { "param", "# stepwise trace 1\n# scene: spring\n# param q: 1\n# integrator: euler\n"
                   "# dt: 0.02\n# steps: 2\nstep\n", 3, "no parameter 'q'" },
        { "missing", "# stepwise trace 1\n# scene: spring\n# dt: 0.02\n# steps: 2\nstep\n", 5,
          "lacks '# integrator" },
        { "header", NULL, 6, "missing column 'energy'" },
        { "cell", NULL, 7, "'x0' holds 'abc'" },
        { "cut", NULL, 7, "does not end with a newline" },
        { "binary", NULL, 7, "binary data" },
    };
    make_tmpdir();
    char path[128], err[SW_ERRLEN], text[512], want[160];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *t = cases[i].text;
        if (!t) {
            const char *name = cases[i].name;
            if (strcmp(name, "header") == 0)
                snprintf(text, sizeof text, "%sstep,t,x0,y0,vx0,vy0\n", head);
            else if (strcmp(name, "cell") == 0)
                snprintf(text, sizeof text, "%s%s0,0,abc,0,0,0,1.25\n", head, header);
            else if (strcmp(name, "cut") == 0)
                snprintf(text, sizeof text, "%s%s0,0,1.5,0,0", head, header);
            else
                snprintf(text, sizeof text, "%s%s0,0,1.5\x01,0,0,0,1.25\n", head, header);
            t = text;
        }
        snprintf(path, sizeof path, "%s/%s.csv", tmpdir, cases[i].name);
        write_file(path, t);
        sw_trace_reader r;
        double row[7];
        int rc = sw_trace_read_open(&r, path, err, sizeof err);
        if (rc == SW_OK) {
            rc = sw_trace_read_header(&r, err, sizeof err);
            while (rc == SW_OK && (rc = sw_trace_read_row(&r, row, err, sizeof err)) == 1)
                rc = SW_OK;
            sw_trace_read_close(&r);
        }
        ck_assert_msg(rc < 0, "%s: accepted", cases[i].name);
        snprintf(want, sizeof want, "%s:%d: ", path, cases[i].line);
        ck_assert_msg(strncmp(err, want, strlen(want)) == 0, "%s: '%s' does not start with '%s'",
                      cases[i].name, err, want);
        ck_assert_msg(strstr(err, cases[i].needle), "%s: '%s' lacks '%s'", cases[i].name, err,
                      cases[i].needle);
    }
    /* And the minimal trace those were cut from is fine. */
    snprintf(text, sizeof text, "%s%s%s", head, header, row0);
    snprintf(path, sizeof path, "%s/good.csv", tmpdir);
    write_file(path, text);
    sw_trace_reader r;
    double row[7];
    ck_assert_msg(sw_trace_read_open(&r, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_trace_read_header(&r, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(sw_trace_read_row(&r, row, err, sizeof err), 1);
    ck_assert_double_eq(row[6], 1.25);
    ck_assert_int_eq(sw_trace_read_row(&r, row, err, sizeof err), 0);
    sw_trace_read_close(&r);
    remove_tmpdir();
}
END_TEST

Suite *make_trace_suite(void);
Suite *make_trace_suite(void)
{
    Suite *s = suite_create("trace");
    TCase *tc = tcase_create("trace");
    tcase_add_test(tc, columns_follow_the_format);
    tcase_add_test(tc, first_spring_rows_by_hand);
    tcase_add_test(tc, write_then_read_bit_for_bit);
    tcase_add_test(tc, temp_file_then_rename);
    tcase_add_test(tc, until_lands_exactly);
    tcase_add_test(tc, blowup_ends_the_trace);
    tcase_add_test(tc, value_comparison_rules);
    tcase_add_test(tc, compare_runs);
    tcase_add_test(tc, reader_errors_name_file_and_line);
    suite_add_tcase(s, tc);
    return s;
}
