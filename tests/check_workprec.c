/* The work-precision plot as a student reads it: on a lesson page the
 * methods the lesson has used, short curves on top of long ones, no series
 * hidden whole, errors above the state's size marked on the edge, and
 * lesson 6's table findable where its text says. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "app/runner.h"
#include "canvas_help.h"
#include "measure/bench.h"
#include "render/workprec.h"
#include "stepwise/stepwise.h"

#define L6 "lessons/06-runge-kutta.lesson"

/* A report by hand: series k has npoints[k] points at 10·2^j evaluations
 * and error err[k]·10^-j. */
static void hand_report(sw_bench_report *r, int n, const int *npoints, const double *err)
{
    memset(r, 0, sizeof *r);
    ck_assert_int_ge(sw_integrator_count(), 9 + n);
    r->scene = sw_scene_find("vortex");
    r->nseries = n;
    for (int i = 0; i < n; i++) {
        sw_bench_series *s = &r->series[i];
        s->method = sw_integrator_at(9 + i); /* markers a, b, c: no axis label has them */
        s->npoints = npoints[i];
        for (int j = 0; j < npoints[i]; j++) {
            s->points[j].evals = 10L << j;
            s->points[j].error = err[i] * pow(10, -j);
        }
    }
}

/* How many cells of the plot rows of g show series i's marker. */
static int cells_of(const sw_bench_report *r, const char *g, int rows, int cols, int i)
{
    int n = 0;
    for (int k = 0; k < rows * cols; k++)
        n += g[k] == sw_bench_marker(r->series[i].method);
    return n;
}

/* A curve of 2 points on a curve of 6: the short one is drawn over the
 * long one where they meet (both of its points show), the long one keeps
 * its other 4, and the pair is named with the short one on top. */
START_TEST(short_curve_on_top)
{
    static const int np[2] = { 6, 2 };
    static const double err[2] = { 1, 1 };
    sw_bench_report *r = malloc(sizeof *r);
    hand_report(r, 2, np, err);
    int rows = 14, cols = 50;
    char *g = malloc((size_t)(rows + 2) * (size_t)cols);
    sw_workprec_overlap ov;
    ck_assert_int_eq(sw_workprec_grid(r, NULL, 0, SW_BENCH_X_EVALS, g, rows, cols, &ov), 1);
    ck_assert_int_eq(cells_of(r, g, rows, cols, 1), 2);
    ck_assert_int_eq(cells_of(r, g, rows, cols, 0), 4);
    ck_assert_int_eq(ov.n, 1);
    ck_assert_int_eq(ov.under[0], 0);
    ck_assert_int_eq(ov.over[0], 1);
    free(g);
    free(r);
}
END_TEST

/* Three series on the same four points: every one keeps at least one
 * marker in sight, and the four cells show one marker each. */
START_TEST(no_series_hidden_whole)
{
    static const int np[3] = { 4, 4, 4 };
    static const double err[3] = { 1, 1, 1 };
    sw_bench_report *r = malloc(sizeof *r);
    hand_report(r, 3, np, err);
    int rows = 12, cols = 40;
    char *g = malloc((size_t)(rows + 2) * (size_t)cols);
    ck_assert_int_eq(sw_workprec_grid(r, NULL, 0, SW_BENCH_X_EVALS, g, rows, cols, NULL), 1);
    int total = 0;
    for (int i = 0; i < 3; i++) {
        int n = cells_of(r, g, rows, cols, i);
        ck_assert_msg(n >= 1, "series %d is hidden whole", i);
        total += n;
    }
    ck_assert_int_eq(total, 4);
    free(g);
    free(r);
}
END_TEST

/* With the state's size 1, a point at error 30 is off the axis (its top is
 * 1e0): a '^' on the top row at its cost's column, not joined to its
 * curve, and counted; the other points keep the axis from 1e-3 to 1e0.
 * Without a size (scale 0) the axis reaches up to it and nothing is
 * clipped. */
START_TEST(off_the_top_is_an_edge_mark)
{
    static const int np[1] = { 4 };
    static const double err[1] = { 1 };
    sw_bench_report *r = malloc(sizeof *r);
    hand_report(r, 1, np, err);
    r->series[0].points[0].error = 30;
    r->scale = 1;
    int rows = 10, cols = 40;
    char *g = malloc((size_t)(rows + 2) * (size_t)cols);
    sw_workprec_overlap ov;
    ck_assert_int_eq(sw_workprec_grid(r, NULL, 0, SW_BENCH_X_EVALS, g, rows, cols, &ov), 1);
    ck_assert_int_eq(ov.clipped, 1);
    ck_assert_int_eq(ov.top, 0);
    ck_assert_msg(memcmp(g, " 1e0|", 5) == 0, "the top row is not 1e0: %.*s", cols, g); /* right-aligned to 1e-3 */
    /* the x axis runs 1e1 .. 1e2 (10 to 80 evaluations): the point at 10 sits
     * on the first plot column, right of the axis' '|' */
    const char *bar = memchr(g, '|', (size_t)cols);
    ck_assert_int_eq(bar[1], '^');
    ck_assert_int_eq(cells_of(r, g, rows, cols, 0), 3);
    r->scale = 0;
    ck_assert_int_eq(sw_workprec_grid(r, NULL, 0, SW_BENCH_X_EVALS, g, rows, cols, &ov), 1);
    ck_assert_int_eq(ov.clipped, 0);
    ck_assert_ptr_null(memchr(g, '^', (size_t)rows * (size_t)cols));
    ck_assert_int_eq(cells_of(r, g, rows, cols, 0), 4);
    free(g);
    free(r);
}
END_TEST

/* Lesson 6's pages name midpoint (@integrator), euler and rk4 (@compare)
 * on page 1: from there on the plot's methods are those three; a page of
 * lesson 1 (euler alone) has one. */
START_TEST(lesson_pages_name_their_methods)
{
    static const char *const want[] = { "midpoint", "euler", "rk4" };
    ct_page pg;
    ct_page_open(&pg, L6, "Error against cost");
    ck_assert_int_eq(pg.a.wp_nonly, 3);
    for (int k = 0; k < 3; k++)
        ck_assert_str_eq(pg.a.wp_only[k]->name, want[k]);
    ct_page_close(&pg);
    ct_page_open(&pg, "lessons/02-euler.lesson", "One straight step");
    ck_assert_int_ge(pg.a.wp_nonly, 1);
    ck_assert_str_eq(pg.a.wp_only[0]->name, "euler");
    ct_page_close(&pg);
}
END_TEST

/* The row of text that starts with prefix after skipping blanks, or -1. */
static int row_starting(char **lines, int n, const char *prefix)
{
    for (int i = 0; i < n; i++) {
        const char *s = lines[i];
        while (*s == ' ')
            s++;
        if (strncmp(s, prefix, strlen(prefix)) == 0)
            return i;
    }
    return -1;
}

/* Lesson 6, "Error against cost", at 80x24 with w: the legend names
 * euler, midpoint and rk4 and no method the lesson has not used; the
 * plot has no '&'; each of the three methods has a marker in a plot row
 * between the x axis' 1e2 and 1e3 labels, where the page says the
 * table's runs (503 and 504 evaluations) are. */
START_TEST(lesson6_plot_shows_the_table)
{
    ct_page pg;
    ct_page_open(&pg, L6, "Error against cost");
    ck_assert_int_eq(sw_app_key(&pg.a, 'w', 1), 1);
    sw_app_sweep_wait(&pg.a);
    ck_assert_ptr_nonnull(pg.a.bench);
    char *text = ct_page_screen(&pg, 80, 24);
    char *lines[24];
    int n = 0;
    for (char *s = strtok(text, "\n"); s && n < 24; s = strtok(NULL, "\n"))
        lines[n++] = s;
    static const char *const used[] = { "euler", "midpoint", "rk4" };
    static const char *const others[] = { "heun", "rk45", "dop853", "rodas4", "implicit-midpoint", "verlet" };
    char want[64];
    int legend = -1;
    for (int k = 0; k < 3; k++) {
        snprintf(want, sizeof want, "%c=%s ", sw_bench_marker(sw_integrator_find(used[k])), used[k]);
        for (int i = 0; i < n; i++)
            if (strstr(lines[i], want))
                legend = i;
        ck_assert_msg(legend >= 0, "the legend has no '%s'", want);
    }
    for (size_t k = 0; k < sizeof others / sizeof others[0]; k++) {
        snprintf(want, sizeof want, "=%s ", others[k]);
        for (int i = 0; i < n; i++)
            ck_assert_msg(!strstr(lines[i], want), "the lesson's plot shows %s, not met yet", others[k]);
    }
    int axis = -1;
    for (int i = 0; i < n && axis < 0; i++)
        if (strstr(lines[i], "++-"))
            axis = i;
    ck_assert_msg(axis > 0 && axis + 1 < n, "no x axis");
    const char *l2 = strstr(lines[axis + 1], "1e2"), *l3 = strstr(lines[axis + 1], "1e3");
    ck_assert_msg(l2 && l3, "the x axis has no 1e2 and 1e3 labels: %s", lines[axis + 1]);
    /* the plot is plain ASCII from the left edge: a byte is a column; the
     * labels are centred on their ticks (one column right of the '1') */
    int c2 = (int)(l2 - lines[axis + 1]) + 1, c3 = (int)(l3 - lines[axis + 1]) + 1;
    for (int k = 0; k < 3; k++) {
        char mark = sw_bench_marker(sw_integrator_find(used[k]));
        int found = 0;
        for (int i = row_starting(lines, n, "error vs") + 1; i < axis; i++) {
            for (int c = 0; c <= c3 + 2 && c < (int)strlen(lines[i]); c++) {
                ck_assert_msg(lines[i][c] != '&', "a cell shows '&':\n%s", text);
                found |= c >= c2 && lines[i][c] == mark;
            }
        }
        ck_assert_msg(found, "%s (%c) has no point between 1e2 and 1e3:\n%s", used[k], mark, text);
    }
    free(text);
    ct_page_close(&pg);
}
END_TEST

Suite *make_workprec_suite(void);
Suite *make_workprec_suite(void)
{
    Suite *s = suite_create("workprec");
    TCase *tc = tcase_create("plot");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, short_curve_on_top);
    tcase_add_test(tc, no_series_hidden_whole);
    tcase_add_test(tc, off_the_top_is_an_edge_mark);
    tcase_add_test(tc, lesson_pages_name_their_methods);
    tcase_add_test(tc, lesson6_plot_shows_the_table);
    suite_add_tcase(s, tc);
    return s;
}
