/* Helpers the canvas, picture and screen tests share (tests/support/canvas_help.c). */
#ifndef SW_TEST_CANVAS_HELP_H
#define SW_TEST_CANVAS_HELP_H

#include <stdint.h>

#include "app/runner.h"
#include "render/canvas.h"
#include "render/screen.h"
#include "stepwise/stepwise.h"

/* A cols x rows canvas on the view [xmin, xmax] x [ymin, ymax]. */
void ct_canvas_new(sw_canvas *c, int cols, int rows, double xmin, double xmax, double ymin, double ymax);
/* The canvas as text, in a buffer the next call reuses. */
const char *ct_frame(const sw_canvas *c);
/* Build scene sc's system with its defaults and up to two NAME=VALUE settings (NULL: none). */
void ct_build(sw_system *sys, const sw_scene *sc, const char *set1, const char *set2);
/* Cells of c holding code point cp. */
int ct_count_cp(const sw_canvas *c, uint32_t cp);
/* Frame f of app a (with side pane side, or NULL) composed on a cols x rows
 * screen, as text the caller frees; the number of texts the composer had
 * to cut into *clipped. */
char *ct_compose(sw_frame *f, sw_app *a, const sw_side *side, int cols, int rows, int *clipped);

/* Open lesson file on the page titled title into r and a (XDG_STATE_HOME in
 * a scratch directory, so no progress file is touched). */
void ct_open_page(sw_runner *r, sw_app *a, const char *file, const char *title);

/* A lesson page on screen: the runner, the app and a frame (ct_page_open
 * opens file on the page titled title; ct_page_screen composes it with its
 * pane, as text the caller frees; ct_page_close frees all). */
typedef struct ct_page {
    sw_runner *r;
    sw_app a;
    sw_frame f;
} ct_page;
void ct_page_open(ct_page *p, const char *file, const char *title);
char *ct_page_screen(ct_page *p, int cols, int rows);
void ct_page_close(ct_page *p);

/* fn on every page of every lesson in lessons/, in the course's order, the
 * runner entered on the page (XDG_STATE_HOME in a scratch directory);
 * e[lesson] is the lesson walked, of n. */
struct sw_lesson_entry;
typedef void ct_page_fn(sw_runner *r, sw_app *a, const struct sw_lesson_entry *e, int n, int lesson, int page,
                        void *ctx);
void ct_each_page(ct_page_fn *fn, void *ctx);

#endif
