/* Helpers the canvas tests share: a canvas on a view, its frame as text, a
 * built scene with up to two settings, a count of cells holding a code
 * point, and a whole frame composed as text (the picture and screen tests).
 * Every failure is a test failure (ck_assert). */
#include "canvas_help.h"

#include <check.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "lesson/lesson.h"

static char text[4096];

void ct_canvas_new(sw_canvas *c, int cols, int rows, double xmin, double xmax, double ymin,
                       double ymax)
{
    char err[SW_ERRLEN];
    ck_assert_msg(sw_canvas_init(c, cols, rows, err, sizeof err) == SW_OK, "%s", err);
    sw_view v = { xmin, xmax, ymin, ymax };
    ck_assert_msg(sw_canvas_set_view(c, &v, err, sizeof err) == SW_OK, "%s", err);
}

const char *ct_frame(const sw_canvas *c)
{
    size_t n = sw_canvas_to_text(c, text, sizeof text);
    ck_assert_uint_lt(n, sizeof text);
    return text;
}

void ct_build(sw_system *sys, const sw_scene *sc, const char *set1, const char *set2)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    ck_assert_ptr_nonnull(sc);
    sw_scene_defaults(sc, p);
    if (set1)
        ck_assert_msg(sw_scene_set(sc, p, set1, err, sizeof err) == SW_OK, "%s", err);
    if (set2)
        ck_assert_msg(sw_scene_set(sc, p, set2, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_system_build(sys, sc, p, err, sizeof err) == SW_OK, "%s", err);
}

int ct_count_cp(const sw_canvas *c, uint32_t cp)
{
    int n = 0;
    for (int row = 0; row < c->rows; row++)
        for (int col = 0; col < c->cols; col++)
            n += sw_canvas_codepoint(c, col, row) == cp;
    return n;
}

char *ct_compose(sw_frame *f, sw_app *a, const sw_side *side, int cols, int rows, int *clipped)
{
    sw_screen scr;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_screen_init(&scr, cols, rows, err, sizeof err), SW_OK);
    sw_frame_push_trails(f, a);
    sw_frame_compose(f, a, side, &scr);
    size_t cap = (size_t)cols * (size_t)rows * 4 + (size_t)rows + 1;
    char *out = malloc(cap);
    ck_assert_ptr_nonnull(out);
    sw_screen_to_text(&scr, out, cap);
    *clipped = scr.clipped;
    sw_screen_free(&scr);
    return out;
}

void ct_open_page(sw_runner *r, sw_app *a, const char *file, const char *title)
{
    char err[SW_LESSON_ERRLEN];
    sw_lesson lesson;
    setenv("XDG_STATE_HOME", "/tmp/sw-point-pictures-no-state", 1);
    ck_assert_msg(sw_lesson_load(file, &lesson, err, sizeof err) == SW_OK, "%s", err);
    int page = -1;
    for (int i = 0; i < lesson.npages; i++)
        if (strcmp(lesson.pages[i].title, title) == 0)
            page = i;
    sw_lesson_free(&lesson);
    ck_assert_msg(page >= 0, "%s has no page '%s'", file, title);
    ck_assert_msg(sw_runner_start(r, a, file, page, err, sizeof err) == SW_OK, "%s", err);
}

void ct_page_open(ct_page *p, const char *file, const char *title)
{
    char err[SW_ERRLEN];
    p->r = malloc(sizeof *p->r);
    ck_assert_ptr_nonnull(p->r);
    ct_open_page(p->r, &p->a, file, title);
    ck_assert_int_eq(sw_frame_init(&p->f, err, sizeof err), SW_OK);
}

char *ct_page_screen(ct_page *p, int cols, int rows)
{
    int clipped;
    return ct_compose(&p->f, &p->a, sw_runner_side(p->r, &p->a, cols), cols, rows, &clipped);
}

void ct_page_close(ct_page *p)
{
    sw_frame_free(&p->f);
    sw_app_free(&p->a);
    sw_runner_free(p->r);
    free(p->r);
}

void ct_each_page(ct_page_fn *fn, void *ctx)
{
    char state[] = "/tmp/sw-pages-XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(state));
    setenv("XDG_STATE_HOME", state, 1);
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    ck_assert_int_ge(n, 10);
    for (int i = 0; i < n; i++) {
        sw_runner *r = malloc(sizeof *r);
        sw_app a;
        ck_assert_msg(sw_runner_start(r, &a, e[i].path, 0, err, sizeof err) == SW_OK, "%s", err);
        for (int p = 0; p < r->lesson.npages; p++) {
            sw_runner_enter(r, &a, p);
            fn(r, &a, e, n, i, p, ctx);
        }
        sw_app_free(&a);
        sw_runner_free(r);
        free(r);
    }
    sw_lesson_list_free(e, n);
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", state);
    ck_assert_int_eq(system(cmd), 0);
}
