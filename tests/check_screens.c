/* Every screen a student can see, composed at 80x24 and 120x40: every
 * scene in every view and overlay, compare overlaid and in lanes, a blown-up
 * run, and every page of every lesson with its pane, hint and help. The
 * composer counts every text it had to cut (sw_screen.clipped: a word or a
 * number cut at its box's edge); this suite asks for none. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/runner.h"
#include "lab/bench.h"
#include "render/screen.h"
#include "stepwise/stepwise.h"

static const int sizes[2][2] = { { 80, 24 }, { 120, 40 } };

/* Compose once and fail with the screen when a text was cut; the text
 * of the screen into *out (NULL: not wanted; the caller frees it). */
static void check_screen_text(sw_frame *f, sw_app *a, const sw_side *side, int cols, int rows, const char *what,
                              char **out)
{
    sw_screen scr;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_screen_init(&scr, cols, rows, err, sizeof err), SW_OK);
    sw_frame_push_trails(f, a);
    sw_frame_compose(f, a, side, &scr);
    size_t cap = (size_t)cols * (size_t)rows * 4 + (size_t)rows + 1;
    char *text = malloc(cap);
    sw_screen_to_text(&scr, text, cap);
    if (scr.clipped)
        ck_abort_msg("%s at %dx%d: %d text(s) cut:\n%s", what, cols, rows, scr.clipped, text);
    sw_screen_free(&scr);
    if (out)
        *out = text;
    else
        free(text);
}

static void check_screen(sw_frame *f, sw_app *a, const sw_side *side, int cols, int rows, const char *what)
{
    check_screen_text(f, a, side, cols, rows, what, NULL);
}

static void app_for(sw_app *a, const sw_scene *sc, const char *method, double dt)
{
    char err[SW_ERRLEN];
    ck_assert_msg(sw_app_init(a, sc, NULL, method ? sw_integrator_find(method) : NULL, dt, err, sizeof err) == SW_OK,
                  "%s", err);
}

/* Each view and overlay of one app, at both sizes. */
static void every_view(sw_app *a, const char *name)
{
    char what[160];
    for (int s = 0; s < 2; s++) {
        sw_frame f;
        char err[SW_ERRLEN];
        ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
        int cols = sizes[s][0], rows = sizes[s][1];
        a->trails = 1;
        for (int v = 0; v < 3; v++) {
            sw_app_set_view(a, (sw_app_view)v);
            for (int braille = 0; braille < 2; braille++) {
                a->braille = braille;
                f.unicode = braille;
                a->graph = 0;
                snprintf(what, sizeof what, "%s view %d braille %d", name, v, braille);
                check_screen(&f, a, NULL, cols, rows, what);
                a->graph = 1;
                snprintf(what, sizeof what, "%s view %d braille %d with the graph", name, v, braille);
                check_screen(&f, a, NULL, cols, rows, what);
            }
        }
        sw_app_set_view(a, SW_VIEW_SCENE);
        a->graph = 0;
        a->panel = 1;
        snprintf(what, sizeof what, "%s parameter panel", name);
        check_screen(&f, a, NULL, cols, rows, what);
        a->panel = 0;
        for (a->help = 1; a->help > 0 && a->help < 20;) {
            snprintf(what, sizeof what, "%s help page %d", name, a->help);
            int before = a->help;
            check_screen(&f, a, NULL, cols, rows, what);
            if (a->help == 0)
                break;
            ck_assert_int_eq(a->help, before);
            a->help++;
            check_screen(&f, a, NULL, cols, rows, what); /* past the last page it closes */
        }
        ck_assert_int_eq(a->help, 0);
        sw_frame_free(&f);
    }
}

START_TEST(every_scene_every_view)
{
    for (int k = 0; k < sw_scene_count(); k++) {
        const sw_scene *sc = sw_scene_at(k);
        sw_app a;
        app_for(&a, sc, NULL, 0);
        sw_app_advance(&a, 0.5, 100000);
        every_view(&a, sc->name);
        /* compare overlaid, then in lanes */
        sw_app_key(&a, 'c', 0);
        sw_app_advance(&a, 0.5, 100000);
        a.lanes = 0;
        every_view(&a, sc->name);
        a.lanes = 1;
        every_view(&a, sc->name);
        sw_app_free(&a);
    }
}
END_TEST

/* Blow-ups: the banner wraps, the lanes say which one, adaptive methods
 * explain why there is no region. */
START_TEST(blowups_and_adaptive)
{
    sw_app a;
    app_for(&a, sw_scene_find("spring"), "euler", 0.3);
    sw_app_key(&a, 'c', 0);
    for (int i = 0; i < 200 && !a.sims[0].blown; i++)
        sw_app_advance(&a, 1.0, 100000);
    ck_assert(a.sims[0].blown);
    a.lanes = 0;
    every_view(&a, "blown spring");
    a.lanes = 1;
    every_view(&a, "blown spring in lanes");
    sw_app_free(&a);
    app_for(&a, sw_scene_find("orbit"), "rk45", 0);
    sw_app_advance(&a, 0.5, 100000);
    every_view(&a, "orbit rk45");
    sw_app_free(&a);
}
END_TEST

/* The work-precision plot with its notes, on a flow and a spring. */
START_TEST(workprec_overlay)
{
    const char *scenes[] = { "vortex", "spring" };
    for (int k = 0; k < 2; k++) {
        sw_app a;
        app_for(&a, sw_scene_find(scenes[k]), NULL, 0);
        ck_assert_int_eq(sw_app_apply(&a, SW_ACT_WORKPREC, 1), 1);
        ck_assert_ptr_nonnull(a.bench);
        for (int s = 0; s < 2; s++) {
            sw_frame f;
            char err[SW_ERRLEN];
            ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
            check_screen(&f, &a, NULL, sizes[s][0], sizes[s][1], scenes[k]);
            sw_frame_free(&f);
        }
        sw_app_free(&a);
    }
}
END_TEST

/* Every page of every lesson, with its pane: as it opens, after a second
 * of play, with the hint, with the help screen over the picture. */
START_TEST(every_lesson_page)
{
    char state[] = "/tmp/sw-screens-XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(state));
    setenv("XDG_STATE_HOME", state, 1);
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN], what[300];
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    ck_assert_int_ge(n, 10);
    for (int i = 0; i < n; i++) {
        sw_runner *r = malloc(sizeof *r);
        sw_app a;
        ck_assert_msg(sw_runner_start(r, &a, e[i].path, 0, err, sizeof err) == SW_OK, "%s", err);
        for (int p = 0; p < r->lesson.npages; p++) {
            sw_runner_enter(r, &a, p);
            for (int s = 0; s < 2; s++) {
                sw_frame f;
                char ferr[SW_ERRLEN];
                ck_assert_int_eq(sw_frame_init(&f, ferr, sizeof ferr), SW_OK);
                int cols = sizes[s][0], rows = sizes[s][1];
                snprintf(what, sizeof what, "%s page %d", e[i].file, p + 1);
                check_screen(&f, &a, sw_runner_side(r, &a, cols), cols, rows, what);
                r->hint = 1;
                check_screen(&f, &a, sw_runner_side(r, &a, cols), cols, rows, what);
                r->hint = 0;
                /* an open question stays in sight under every overlay */
                const sw_lesson_question *q = &r->lesson.pages[p].question;
                if (q->text && !r->answered[p]) {
                    const sw_side *side = sw_runner_side(r, &a, cols);
                    char want[16];
                    snprintf(want, sizeof want, "%c) ", SW_ANSWER_FIRST + q->nanswers - 1);
                    for (int ov = 0; ov < 2; ov++) {
                        a.help = ov == 0;
                        a.panel = ov == 1;
                        char *text;
                        int scroll = r->scroll;
                        r->scroll = 1000; /* the pane's end: the answers */
                        check_screen_text(&f, &a, side, cols, rows, what, &text);
                        r->scroll = scroll;
                        ck_assert_msg(strstr(text, want) != NULL, "%s at %dx%d: the %s hides the question's "
                                      "answer %s:\n%s", what, cols, rows, ov ? "panel" : "help", want, text);
                        free(text);
                    }
                    a.help = a.panel = 0;
                }
                for (int page = 1; page < 20; page++) {
                    a.help = page;
                    check_screen(&f, &a, sw_runner_side(r, &a, cols), cols, rows, what);
                    if (a.help == 0)
                        break; /* past the last page */
                }
                a.help = 0;
                sw_frame_free(&f);
            }
            int paused = a.paused;
            a.paused = 0;
            sw_app_advance(&a, 1.0, 100000);
            a.paused = paused;
            for (int s = 0; s < 2; s++) {
                sw_frame f;
                char ferr[SW_ERRLEN];
                ck_assert_int_eq(sw_frame_init(&f, ferr, sizeof ferr), SW_OK);
                snprintf(what, sizeof what, "%s page %d after a second", e[i].file, p + 1);
                check_screen(&f, &a, sw_runner_side(r, &a, sizes[s][0]), sizes[s][0], sizes[s][1], what);
                sw_frame_free(&f);
            }
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
END_TEST

/* The check can fail: a text wider than its box counts as cut. */
START_TEST(a_cut_is_counted)
{
    sw_screen scr;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_screen_init(&scr, 80, 24, err, sizeof err), SW_OK);
    sw_screen_text(&scr, 0, 0, 10, 0, "0123456789");
    ck_assert_int_eq(scr.clipped, 0);
    sw_screen_text(&scr, 1, 0, 10, 0, "error 6.00e-05");
    ck_assert_int_eq(scr.clipped, 1);
    sw_screen_text(&scr, 2, 75, 10, 0, "accepted 51");
    ck_assert_int_eq(scr.clipped, 2);
    sw_screen_clear(&scr);
    ck_assert_int_eq(scr.clipped, 0);
    sw_screen_free(&scr);
}
END_TEST

Suite *make_screens_suite(void);
Suite *make_screens_suite(void)
{
    Suite *s = suite_create("screens");
    const struct { const char *name; const TTest *test; } cases[] = {
        { "cut counted", a_cut_is_counted }, { "scenes", every_scene_every_view },
        { "blowups", blowups_and_adaptive }, { "workprec", workprec_overlay }, { "lessons", every_lesson_page },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        TCase *tc = tcase_create(cases[i].name);
        tcase_set_timeout(tc, 300);
        tcase_add_test(tc, cases[i].test);
        suite_add_tcase(s, tc);
    }
    return s;
}
