/* Partial credit and the autograder bundle: the "# points" grammar (values,
 * column globs, checks paid twice), scoring a verdict's facts check by
 * check, the same run written another way (until for steps), and the zip
 * writer (CRC-32 against the standard check value, the archive's bytes). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade/assignment.h"
#include "grade/points.h"
#include "stepwise/stepwise.h"
#include "util/zip.h"

/* ---- the grammar ---------------------------------------------------------------- */

START_TEST(points_grammar)
{
    sw_points_set set = { 0 };
    char err[512];
    ck_assert_int_eq(sw_points_parse(&set, "header", "1", 7, "a:7", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_parse(&set, "x* y*", "3", 8, "a:8", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_parse(&set, "energy", "0.5", 9, "a:9", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_parse(&set, "order", "1", 10, "a:10", err, sizeof err), SW_OK);
    ck_assert_int_eq(set.n, 4);
    ck_assert_int_eq(set.items[0].kind, SW_POINTS_HEADER);
    ck_assert_int_eq(set.items[1].kind, SW_POINTS_COLUMNS);
    ck_assert_int_eq(set.items[3].kind, SW_POINTS_ORDER);
    ck_assert(set.items[2].points == 0.5);
    ck_assert(sw_points_has_column(&set.items[1], "x0"));
    ck_assert(sw_points_has_column(&set.items[1], "y12"));
    ck_assert(!sw_points_has_column(&set.items[1], "vx0"));
    ck_assert(!sw_points_has_column(&set.items[2], "energy2"));
    /* Refused, naming the line: a value out of range or not a number, no
     * subject, a check given twice. */
    ck_assert_int_eq(sw_points_parse(&set, "t", "-1", 11, "a:11", err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "a:11"));
    ck_assert_int_eq(sw_points_parse(&set, "t", "1001", 11, "a:11", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_points_parse(&set, "t", "lots", 11, "a:11", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_points_parse(&set, "t", "nan", 11, "a:11", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_points_parse(&set, "", "1", 11, "a:11", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_points_parse(&set, "header", "2", 12, "a:12", err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "line 7"));
    ck_assert_int_eq(set.n, 4);
}
END_TEST

static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    return fclose(f);
}

static const char head[] = "# stepwise assignment 1\n# scene: spring\n# integrator: euler\n"
                           "# dt: 0.01\n# steps: 200\n";

START_TEST(points_in_assignments)
{
    char path[] = "/tmp/sw_points_XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    close(fd);
    static sw_assignment a;
    char err[600], text[1024];
    /* No points lines: header 1 and every column 1. */
    ck_assert_int_eq(write_file(path, head), 0);
    ck_assert_int_eq(sw_assignment_read(&a, path, err, sizeof err), SW_OK);
    ck_assert_int_eq(a.points.n, 2);
    ck_assert_int_eq(a.points.items[0].kind, SW_POINTS_HEADER);
    ck_assert_str_eq(a.points.items[1].what, "*");
    /* Globs resolved against the scene's columns. */
    snprintf(text, sizeof text, "%s# points x* y*: 3\n# points energy: 1\n", head);
    ck_assert_int_eq(write_file(path, text), 0);
    ck_assert_int_eq(sw_assignment_read(&a, path, err, sizeof err), SW_OK);
    ck_assert_int_eq(a.points.n, 2);
    /* A column the scene does not have, and one paid twice. */
    snprintf(text, sizeof text, "%s# points q*: 3\n", head);
    ck_assert_int_eq(write_file(path, text), 0);
    ck_assert_int_eq(sw_assignment_read(&a, path, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, ":6:"));
    ck_assert_ptr_nonnull(strstr(err, "no column 'q*'"));
    snprintf(text, sizeof text, "%s# points x*: 3\n# points x0 y0: 1\n", head);
    ck_assert_int_eq(write_file(path, text), 0);
    ck_assert_int_eq(sw_assignment_read(&a, path, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "paid for twice"));
    unlink(path);
}
END_TEST

/* until T for steps N is the same run for a fixed-step method. */
START_TEST(until_is_steps)
{
    char path[] = "/tmp/sw_points_XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    close(fd);
    static sw_assignment a;
    char err[600];
    ck_assert_int_eq(write_file(path, head), 0);
    ck_assert_int_eq(sw_assignment_read(&a, path, err, sizeof err), SW_OK);
    sw_trace_meta m = a.meta;
    snprintf(m.integrator, sizeof m.integrator, "euler");
    m.spec.steps = 0;
    m.spec.until = 2;
    sw_system sys;
    ck_assert_int_eq(sw_system_build(&sys, a.meta.scene, a.meta.p, err, sizeof err), SW_OK);
    sw_header_diff d[4];
    int comparable;
    ck_assert_int_eq(sw_assignment_diff(&a, &m, &sys, d, 4, &comparable), 0);
    m.spec.until = 2.01; /* 201 steps' worth: another run */
    ck_assert_int_eq(sw_assignment_diff(&a, &m, &sys, d, 4, &comparable), 1);
    ck_assert_str_eq(d[0].what, "run length");
    ck_assert_str_eq(d[0].got, "until 2.01");
    sw_system_free(&sys);
    unlink(path);
}
END_TEST

/* ---- scoring --------------------------------------------------------------------- */

START_TEST(score_by_check)
{
    sw_points_set set = { 0 };
    char err[256];
    ck_assert_int_eq(sw_points_parse(&set, "header", "1", 1, "a", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_parse(&set, "x* y*", "3", 2, "a", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_parse(&set, "energy", "1", 3, "a", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_parse(&set, "order", "2", 4, "a", err, sizeof err), SW_OK);
    sw_system sys;
    const sw_scene *spring = sw_scene_find("spring");
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(spring, p);
    ck_assert_int_eq(sw_system_build(&sys, spring, p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_resolve(&set, &sys, "a", err, sizeof err), SW_OK);
    int ncols = sw_trace_ncols(&sys); /* step, t, x0, y0, vx0, vy0, energy */
    ck_assert_int_eq(ncols, 7);
    long failed[7] = { 0 };
    sw_check_cell first[7];
    memset(first, 0, sizeof first);
    failed[6] = 3; /* energy wrong, positions right */
    first[6] = (sw_check_cell){ .kind = SW_CHECK_VALUE, .step = 4, .t = 0.04, .column = 6,
                                .expected = 1.25, .got = -1.25 };
    sw_score_facts f = { .usable = 1, .ndiffs = 1, .header_words = "dt: yours 0.02",
                         .comparable = 1, .sys = &sys, .col_failed = failed, .col_first = first,
                         .order = NAN, .expected_order = NAN, .stability = NAN,
                         .expected_stability = NAN };
    sw_score s;
    sw_points_score(&set, &f, &s);
    ck_assert_int_eq(s.n, 3); /* a trace: no order */
    ck_assert(s.score == 3 && s.max == 5);
    ck_assert_str_eq(s.checks[0].name, "header");
    ck_assert(s.checks[0].score == 0);
    ck_assert_str_eq(s.checks[0].output, "dt: yours 0.02");
    ck_assert(s.checks[1].score == 3);
    ck_assert_ptr_nonnull(strstr(s.checks[2].output, "3 values of energy"));
    ck_assert_ptr_nonnull(strstr(s.checks[2].output, "step 4"));
    /* A plugin: no header; its order measured. */
    f.is_plugin = 1;
    f.order = 1.02;
    f.expected_order = 1;
    sw_points_score(&set, &f, &s);
    ck_assert_int_eq(s.n, 3);
    ck_assert(s.score == 5 && s.max == 6);
    /* Not measured: the check says so once, in the verdict's words. */
    f.order = NAN;
    f.measure_note = "order not measured: the plugin ran out of its CPU time (SIGXCPU)";
    sw_points_score(&set, &f, &s);
    ck_assert(s.checks[2].score == 0);
    ck_assert_str_eq(s.checks[2].output, f.measure_note);
    f.order = 1.02;
    f.measure_note = NULL;
    /* A plugin that crashed scores nothing, saying why. */
    f.fault = "the plugin crashed with SIGSEGV";
    sw_points_score(&set, &f, &s);
    ck_assert(s.score == 0 && s.max == 6);
    ck_assert_ptr_nonnull(strstr(s.checks[0].output, "SIGSEGV"));
    /* An unusable file: every check at 0 with the reason. */
    sw_score_facts bad = { .usable = 0, .error = "no header row" };
    sw_points_score(&set, &bad, &s);
    ck_assert(s.score == 0 && s.max == 5);
    ck_assert_ptr_nonnull(strstr(s.checks[1].output, "no header row"));
    sw_system_free(&sys);
}
END_TEST

/* Graded closeness: tiers parsed, refused when they do not widen or are
 * not for columns, and scored from each column's largest difference as
 * |got - expected| / (1 + |expected|) (the figures below are set by hand:
 * 4e-7 is within 1e-6 and misses 1e-9 by a factor of 400). */
START_TEST(closeness_tiers)
{
    sw_points_set set = { 0 };
    char err[400];
    ck_assert_int_eq(sw_points_parse(&set, "x* y*", "3 within 1e-9, 2 within 1e-6, 1 within 1e-3", 1, "a:1",
                                     err, sizeof err), SW_OK);
    ck_assert_int_eq(set.items[0].ntiers, 3);
    ck_assert(set.items[0].points == 3 && set.items[0].tier_within[1] == 1e-6);
    sw_points_set bad = { 0 };
    ck_assert_int_eq(sw_points_parse(&bad, "x*", "2 within 1e-6, 3 within 1e-3", 2, "a:2", err, sizeof err),
                     SW_EINVAL); /* points grow */
    ck_assert_ptr_nonnull(strstr(err, "a:2"));
    ck_assert_int_eq(sw_points_parse(&bad, "x*", "3 within 1e-3, 2 within 1e-6", 2, "a:2", err, sizeof err),
                     SW_EINVAL); /* tolerances narrow */
    ck_assert_int_eq(sw_points_parse(&bad, "x*", "3 within 0", 2, "a:2", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_points_parse(&bad, "x*", "3 within 1e-9, 2 within", 2, "a:2", err, sizeof err),
                     SW_EINVAL);
    ck_assert_int_eq(sw_points_parse(&bad, "header", "1 within 1e-9", 2, "a:2", err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "tiers ('within') are for columns"));
    ck_assert_int_eq(bad.n, 0);
    sw_system sys;
    const sw_scene *spring = sw_scene_find("spring");
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(spring, p);
    ck_assert_int_eq(sw_system_build(&sys, spring, p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_points_resolve(&set, &sys, "a", err, sizeof err), SW_OK);
    long failed[7] = { 0, 0, 5, 0, 0, 0, 0 };
    sw_check_cell first[7];
    memset(first, 0, sizeof first);
    double worst[7] = { 0, 0, 4e-7, 1e-12, 0.5, 0, 0 }; /* x0 4e-7, y0 1e-12; vx0 is no part of it */
    sw_score_facts f = { .usable = 1, .comparable = 1, .sys = &sys, .col_failed = failed, .col_first = first,
                         .col_worst = worst, .order = NAN, .expected_order = NAN, .stability = NAN,
                         .expected_stability = NAN };
    sw_score s;
    sw_points_score(&set, &f, &s);
    ck_assert(s.checks[0].score == 2 && s.checks[0].max == 3);
    ck_assert_ptr_nonnull(strstr(s.checks[0].output, "within 1e-06"));
    ck_assert_ptr_nonnull(strstr(s.checks[0].output, "missed by a factor of 400"));
    worst[2] = 0;
    worst[3] = 0;
    sw_points_score(&set, &f, &s);
    ck_assert(s.checks[0].score == 3);
    ck_assert_ptr_nonnull(strstr(s.checks[0].output, "exactly"));
    worst[2] = INFINITY; /* a non-finite value where the reference has a number */
    sw_points_score(&set, &f, &s);
    ck_assert(s.checks[0].score == 0);
    ck_assert_ptr_nonnull(strstr(s.checks[0].output, "beyond every tier"));
    worst[2] = 1e-3; /* on the widest tier's edge: inside */
    sw_points_score(&set, &f, &s);
    ck_assert(s.checks[0].score == 1);
    f.rows_differ = 1; /* rows missing: nothing for the group */
    f.rows_words = "the trace ends at step 10";
    sw_points_score(&set, &f, &s);
    ck_assert(s.checks[0].score == 0);
    sw_system_free(&sys);
}
END_TEST

/* ---- the zip writer ------------------------------------------------------------ */

START_TEST(crc32_check_value)
{
    /* The CRC-32 catalogue's check value for "123456789". */
    ck_assert_uint_eq(sw_crc32(0, "123456789", 9), 0xCBF43926u);
    ck_assert_uint_eq(sw_crc32(0, "", 0), 0);
    /* Piecewise equals at once. */
    ck_assert_uint_eq(sw_crc32(sw_crc32(0, "1234", 4), "56789", 5), 0xCBF43926u);
}
END_TEST

static unsigned get16(const unsigned char *p) { return p[0] | (unsigned)p[1] << 8; }
static unsigned long get32(const unsigned char *p)
{
    return get16(p) | (unsigned long)get16(p + 2) << 16;
}

START_TEST(zip_layout)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    ck_assert_ptr_nonnull(f);
    sw_zip z;
    char err[256];
    sw_zip_begin(&z, f);
    ck_assert_int_eq(sw_zip_add(&z, "run_autograder", "#!/bin/sh\n", 10, 0755, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_zip_add(&z, "a/b.txt", "123456789", 9, 0644, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_zip_add(&z, "../x", "", 0, 0644, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_zip_add(&z, "/etc/x", "", 0, 0644, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_zip_add(&z, "a/../../x", "", 0, 0644, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_zip_end(&z, err, sizeof err), SW_OK);
    fclose(f);
    const unsigned char *b = (const unsigned char *)buf;
    /* Local header 1 at 0: 30 + 14 name + 10 data = 54; local header 2 at 54:
     * 30 + 7 + 9 = 46; the central directory at 100: 46 + 14 and 46 + 7;
     * the end record (22 bytes) at 213. */
    ck_assert_uint_eq(len, 100 + 60 + 53 + 22);
    ck_assert_uint_eq(get32(b), 0x04034b50ul);
    ck_assert_uint_eq(get32(b + 54), 0x04034b50ul);
    ck_assert_uint_eq(get32(b + 54 + 14), 0xCBF43926ul); /* the entry's CRC-32 */
    ck_assert_uint_eq(get32(b + 100), 0x02014b50ul);
    ck_assert_uint_eq(get32(b + 100 + 38) >> 16, 0100755ul); /* a regular file, rwxr-xr-x */
    const unsigned char *end = b + len - 22;
    ck_assert_uint_eq(get32(end), 0x06054b50ul);
    ck_assert_uint_eq(get16(end + 10), 2);       /* entries */
    ck_assert_uint_eq(get32(end + 12), 113);     /* the directory's size */
    ck_assert_uint_eq(get32(end + 16), 100);     /* and where it starts */
    free(buf);
}
END_TEST

Suite *make_points_suite(void);
Suite *make_points_suite(void)
{
    Suite *s = suite_create("points");
    TCase *tc = tcase_create("points");
    tcase_add_test(tc, points_grammar);
    tcase_add_test(tc, points_in_assignments);
    tcase_add_test(tc, until_is_steps);
    tcase_add_test(tc, score_by_check);
    tcase_add_test(tc, closeness_tiers);
    tcase_add_test(tc, crc32_check_value);
    tcase_add_test(tc, zip_layout);
    suite_add_tcase(s, tc);
    return s;
}
