/* Homeworks (grade/homework.h): parts and what they share, visibility,
 * values drawn per student (SipHash-2-4 against the paper's test vector,
 * every grid value reachable and none outside it, the same student the
 * same values, another secret other ones), the part a trace is for, the
 * student's sheet, and each mistake in a homework file named by line. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade/homework.h"
#include "stepwise/stepwise.h"
#include "util/siphash.h"

static char path[64];

static void write_file(const char *text)
{
    snprintf(path, sizeof path, "/tmp/sw-homework-%d.txt", (int)getpid());
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

static const char course[] =
    "# stepwise assignment 1\n"
    "# title: RK4 on two scenes\n"
    "# kind: plugin\n"
    "# secret: seven blue herons\n"
    "# count: latest\n"
    "# integrator: rk4\n"
    "# dt: 0.005\n"
    "# steps: 200\n"
    "# points x* y*: 4\n"
    "# points order: 1\n"
    "# part chain\n"
    "# scene: chain\n"
    "# param n: 4\n"
    "# param k: 80..120 per student\n"
    "# part gyre\n"
    "# scene: gyre\n"
    "# param n: 9\n"
    "# dt: 0.1\n"
    "# param omega: one of 0.5, 1, 2\n"
    "# visibility: hidden\n"
    "# part spring\n"
    "# scene: spring\n"
    "# visibility: after_due_date\n";

/* The reference test vector of SipHash-2-4 (Aumasson and Bernstein 2012,
 * appendix A): key 00..0f, message 00..0e. */
START_TEST(siphash_vector)
{
    unsigned long long k[2] = { 0x0706050403020100ull, 0x0f0e0d0c0b0a0908ull };
    unsigned char msg[15];
    for (int i = 0; i < 15; i++)
        msg[i] = (unsigned char)i;
    ck_assert(sw_siphash24(k, msg, 15) == 0xa129ca6149be45e5ull);
}
END_TEST

START_TEST(parts_share_and_replace)
{
    write_file(course);
    static sw_homework h;
    char err[512];
    ck_assert_msg(sw_homework_read(&h, path, NULL, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(h.nparts, 3);
    ck_assert_str_eq(h.parts[0].name, "chain");
    ck_assert_str_eq(h.parts[1].name, "gyre");
    ck_assert_str_eq(h.parts[0].a.meta.scene->name, "chain");
    ck_assert_str_eq(h.parts[1].a.meta.scene->name, "gyre");
    /* the shared dt, and gyre's own */
    ck_assert(h.parts[0].a.meta.dt == 0.005);
    ck_assert(h.parts[1].a.meta.dt == 0.1);
    ck_assert(h.parts[2].a.meta.dt == 0.005);
    ck_assert_int_eq(h.parts[0].visibility, SW_VIS_VISIBLE);
    ck_assert_int_eq(h.parts[1].visibility, SW_VIS_HIDDEN);
    ck_assert_int_eq(h.parts[2].visibility, SW_VIS_AFTER_DUE_DATE);
    ck_assert_int_eq(sw_homework_hidden_parts(&h), 2);
    ck_assert_int_eq(h.kind, SW_KIND_PLUGIN);
    ck_assert_int_eq(h.rule, SW_COUNT_LATEST);
    ck_assert_str_eq(h.title, "RK4 on two scenes");
    /* a plugin: values 4 and order 1 on each of three parts */
    ck_assert(h.max == 15);
    ck_assert(h.max_of[0] == 12);
    /* the teacher's preview: each range's low end, each list's first */
    ck_assert(h.nvarying == 2);
    ck_assert(sw_homework_varies(&h, 0, "k") && !sw_homework_varies(&h, 0, "omega"));
    ck_assert(sw_homework_varies(&h, 1, "omega") && !sw_homework_varies(&h, 1, "k"));
    ck_assert_str_eq(sw_visibility_name(h.parts[2].visibility), "after_due_date");
    sw_homework_free(&h);
    unlink(path);
}
END_TEST

/* The parameter's value in part p as the assignment reader read it. */
static double param(const sw_homework *h, int p, const char *name)
{
    const sw_scene *sc = h->parts[p].a.meta.scene;
    for (int i = 0; i < sc->nparams; i++)
        if (strcmp(sc->params[i].name, name) == 0)
            return h->parts[p].a.meta.p[i];
    return NAN;
}

START_TEST(values_per_student)
{
    write_file(course);
    static sw_homework h;
    char err[512], who[64];
    ck_assert(sw_homework_read(&h, path, NULL, err, sizeof err) == SW_OK);
    ck_assert(param(&h, 0, "k") == 80 && param(&h, 1, "omega") == 0.5);
    sw_homework_free(&h);
    /* 1000 students: every whole number from 80 to 120 drawn, none else;
     * counts near 1000/41 = 24.4 each (a chi-square over 40 degrees of
     * freedom below 80 fails a fair draw with probability about 2e-4);
     * every list value drawn. */
    int count[41] = { 0 }, omega[3] = { 0 };
    for (int s = 0; s < 1000; s++) {
        snprintf(who, sizeof who, "Student%d@Uni.EDU", s);
        ck_assert(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK);
        double k = param(&h, 0, "k"), w = param(&h, 1, "omega");
        sw_homework_free(&h);
        ck_assert(k >= 80 && k <= 120 && k == floor(k));
        count[(int)k - 80]++;
        ck_assert(w == 0.5 || w == 1 || w == 2);
        omega[w == 0.5 ? 0 : w == 1 ? 1 : 2]++;
    }
    double chi = 0, e = 1000.0 / 41;
    for (int i = 0; i < 41; i++)
        chi += (count[i] - e) * (count[i] - e) / e;
    ck_assert_msg(chi < 80, "chi-square %g", chi);
    ck_assert(omega[0] > 250 && omega[1] > 250 && omega[2] > 250);
    /* the same student, in any case and spacing, the same values */
    double k1, k2;
    ck_assert(sw_homework_read(&h, path, "ada@uni.edu", err, sizeof err) == SW_OK);
    k1 = param(&h, 0, "k");
    sw_homework_free(&h);
    ck_assert(sw_homework_read(&h, path, "  ADA@Uni.edu ", err, sizeof err) == SW_OK);
    k2 = param(&h, 0, "k");
    sw_homework_free(&h);
    ck_assert(k1 == k2);
    /* another secret: other values for most of 100 students (a value kept
     * by chance: 1 in 41 each) */
    char other[sizeof course];
    snprintf(other, sizeof other, "%s", course);
    memcpy(strstr(other, "seven"), "eight", 5);
    int same = 0;
    for (int s = 0; s < 100; s++) {
        snprintf(who, sizeof who, "s%d@u.edu", s);
        write_file(course);
        ck_assert(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK);
        double a = param(&h, 0, "k");
        sw_homework_free(&h);
        write_file(other);
        ck_assert(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK);
        same += a == param(&h, 0, "k");
        sw_homework_free(&h);
    }
    ck_assert_msg(same < 15, "%d of 100 kept their value under another secret", same);
    unlink(path);
}
END_TEST

/* One value says nothing of another (red team 3, F3): the draw once hashed
 * the student and the parameter's name only, so a hidden part's k in
 * 50..90 was always the visible part's (in 80..120) less 30, and a second
 * homework's k in 80..120 under the same secret ten times the first's in
 * 8.0..12.0. Now the part and the range are drawn on too: over 200
 * students the difference (and the ratio) takes many values. (Were they
 * independent, a fixed offset would repeat for about 1 in 41 of them; the
 * 12 allowed here fail a fair draw with probability below 1e-3.) */
START_TEST(values_independent)
{
    static const char two_parts[] =
        "# stepwise assignment 1\n# kind: plugin\n# secret: seven blue herons\n# integrator: rk4\n"
        "# dt: 0.01\n# steps: 10\n# points x* y*: 1\n"
        "# part shown\n# scene: chain\n# param k: 80..120 per student\n"
        "# part hidden\n# scene: chain\n# param k: 50..90 per student\n# visibility: hidden\n";
    static const char tenth[] =
        "# stepwise assignment 1\n# kind: plugin\n# secret: seven blue herons\n# integrator: rk4\n"
        "# dt: 0.01\n# steps: 10\n# points x* y*: 1\n# scene: chain\n# param k: 8.0..12.0 per student\n";
    static const char whole[] =
        "# stepwise assignment 1\n# kind: plugin\n# secret: seven blue herons\n# integrator: rk4\n"
        "# dt: 0.01\n# steps: 10\n# points x* y*: 1\n# scene: chain\n# param k: 80..120 per student\n";
    static sw_homework h;
    char err[512], who[64];
    int offset30 = 0, times10 = 0;
    for (int s = 0; s < 200; s++) {
        snprintf(who, sizeof who, "s%d@u.edu", s);
        write_file(two_parts);
        ck_assert_msg(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK, "%s", err);
        offset30 += param(&h, 0, "k") - param(&h, 1, "k") == 30;
        sw_homework_free(&h);
        write_file(tenth);
        ck_assert_msg(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK, "%s", err);
        double a = param(&h, 0, "k");
        sw_homework_free(&h);
        write_file(whole);
        ck_assert(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK);
        times10 += fabs(param(&h, 0, "k") - 10 * a) < 1e-9;
        sw_homework_free(&h);
    }
    ck_assert_msg(offset30 <= 12, "%d of 200: the hidden k is the shown one less 30", offset30);
    ck_assert_msg(times10 <= 12, "%d of 200: one homework's k is ten times the other's", times10);
    unlink(path);
}
END_TEST

/* A range's grid is the finer of its ends': 0.50..2 in hundredths. */
START_TEST(values_on_the_grid)
{
    write_file("# stepwise assignment 1\n# secret: s\n# scene: spring\n# integrator: rk4\n"
               "# dt: 0.01\n# steps: 10\n# param k: 0.50..2 per student\n");
    static sw_homework h;
    char err[512], who[64];
    int low = 0, high = 0;
    for (int s = 0; s < 2000; s++) {
        snprintf(who, sizeof who, "%d@x", s);
        ck_assert_msg(sw_homework_read(&h, path, who, err, sizeof err) == SW_OK, "%s", err);
        double k = param(&h, 0, "k");
        sw_homework_free(&h);
        double hundredths = k * 100;
        ck_assert(k >= 0.5 && k <= 2);
        ck_assert(fabs(hundredths - nearbyint(hundredths)) < 1e-9);
        low += k == 0.5;
        high += k == 2;
    }
    ck_assert(low > 0 && high > 0); /* both ends reachable (151 values, 2000 draws) */
    unlink(path);
}
END_TEST

static void refused(const char *text, const char *line, const char *words)
{
    write_file(text);
    static sw_homework h;
    char err[512];
    ck_assert_int_eq(sw_homework_read(&h, path, NULL, err, sizeof err), SW_EINVAL);
    sw_homework_free(&h);
    ck_assert_msg(strstr(err, line) && strstr(err, words), "%s", err);
    unlink(path);
}

START_TEST(mistakes_named)
{
    static const struct {
        const char *tail, *line, *words;
    } cases[] = {
        { "# param k: 8..12 per student\n", ":6:", "need '# secret: WORDS'" },
        { "# secret: s\n# param n: 2.5..4 per student\n", ":7:", "whole number in [1, 1e+06]" },
        { "# secret: s\n# param k: 1..2e9 per student\n", ":7:", "LO..HI per student" },
        { "# secret: s\n# param k: 100..100000000 per student\n", ":7:", "outside chain's range" },
        { "# secret: s\n# param k: 8..12\n", ":7:", "LO..HI per student" },
        { "# secret: s\n# param k: one of 5\n", ":7:", "one of A, B" },
        { "# part a\n# kind: trace\n", ":7:", "the homework's, not a part's" },
        { "# part a\n# part a\n", ":7:", "each name once" },
        { "# part a\n# visibility: secret\n", ":7:", "visible, hidden, after_due_date or after_published" },
        { "# count: first\n", ":6:", "best or latest" },
        { "# part a\n# scene: nowhere\n", ":7:", "nowhere" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[1024];
        snprintf(text, sizeof text, "# stepwise assignment 1\n# scene: chain\n# integrator: rk4\n# dt: 0.01\n"
                 "# steps: 10\n%s", cases[i].tail);
        refused(text, cases[i].line, cases[i].words);
    }
}
END_TEST

START_TEST(trace_parts)
{
    write_file(course);
    static sw_homework h;
    char err[512], why[400];
    ck_assert(sw_homework_read(&h, path, NULL, err, sizeof err) == SW_OK);
    sw_trace_meta m;
    memset(&m, 0, sizeof m);
    m.scene = h.parts[1].a.meta.scene; /* a gyre trace */
    ck_assert_int_eq(sw_homework_part_of_trace(&h, "x/Chain.trace", &m, why, sizeof why), 0);
    ck_assert_int_eq(sw_homework_part_of_trace(&h, "hw4-spring.csv", &m, why, sizeof why), 2);
    ck_assert_int_eq(sw_homework_part_of_trace(&h, "mine.trace", &m, why, sizeof why), 1);
    ck_assert_int_eq(sw_homework_part_of_trace(&h, "chained.trace", &m, why, sizeof why), 1);
    m.scene = sw_scene_find("orbit");
    ck_assert_int_eq(sw_homework_part_of_trace(&h, "mine.trace", &m, why, sizeof why), -1);
    ck_assert_ptr_nonnull(strstr(why, "chain.trace: chain, gyre.trace: gyre"));
    sw_homework_free(&h);
    unlink(path);
}
END_TEST

START_TEST(student_sheet)
{
    write_file(course);
    static sw_homework h, back;
    char err[512], sheet[96];
    ck_assert(sw_homework_read(&h, path, "ada@uni.edu", err, sizeof err) == SW_OK);
    snprintf(sheet, sizeof sheet, "%s.sheet", path);
    FILE *f = fopen(sheet, "w");
    ck_assert_int_eq(sw_homework_write_sheet(&h, f, "Ada Lovelace"), SW_OK);
    fclose(f);
    char text[4096];
    f = fopen(sheet, "r");
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    ck_assert_ptr_null(strstr(text, "herons"));   /* no secret */
    ck_assert_ptr_null(strstr(text, "gyre"));     /* a plugin homework's hidden parts left out */
    ck_assert_ptr_null(strstr(text, "per student"));
    ck_assert_ptr_nonnull(strstr(text, "2 more parts are graded"));
    /* it reads back as an assignment with Ada's values */
    ck_assert_msg(sw_homework_read(&back, sheet, NULL, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(back.nparts, 1);
    ck_assert(param(&back, 0, "k") == param(&h, 0, "k"));
    ck_assert_int_eq(back.nvarying, 0);
    sw_homework_free(&back);
    sw_homework_free(&h);
    unlink(sheet);
    unlink(path);
}
END_TEST

Suite *make_homework_suite(void);
Suite *make_homework_suite(void)
{
    Suite *s = suite_create("homework");
    TCase *tc = tcase_create("homework");
    tcase_add_test(tc, siphash_vector);
    tcase_add_test(tc, parts_share_and_replace);
    tcase_add_test(tc, values_per_student);
    tcase_add_test(tc, values_on_the_grid);
    tcase_add_test(tc, values_independent);
    tcase_add_test(tc, mistakes_named);
    tcase_add_test(tc, trace_parts);
    tcase_add_test(tc, student_sheet);
    suite_add_tcase(s, tc);
    return s;
}
