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
#include "canvas_help.h"
#include "measure/bench.h"
#include "render/screen.h"
#include "stepwise/stepwise.h"

static const int sizes[2][2] = { { 80, 24 }, { 120, 40 } };

/* Compose once and fail with the screen when a text was cut; the text
 * of the screen into *out (NULL: not wanted; the caller frees it). */
static void check_screen_text(sw_frame *f, sw_app *a, const sw_side *side, int cols, int rows, const char *what,
                              char **out)
{
    int clipped;
    char *text = ct_compose(f, a, side, cols, rows, &clipped);
    if (clipped)
        ck_abort_msg("%s at %dx%d: %d text(s) cut:\n%s", what, cols, rows, clipped, text);
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

/* The region view's picture rows (between its title and its legend): no
 * two labels run together ("-12-10"), no mark sits against a label ("*8i"). */
static void assert_labels_apart(const char *text, const char *what, int cols, int rows)
{
    const char *line = strchr(text, '\n');
    for (int row = 1; line && *++line; row++) {
        const char *end = strchr(line, '\n');
        if (!end)
            break;
        if (strstr(line, "dt x eigenvalue") && strstr(line, "dt x eigenvalue") < end)
            break; /* the legend: below the picture */
        for (const char *c = line; c + 1 < end; c++) {
            int digit_minus_digit = c + 2 < end && c[0] >= '0' && c[0] <= '9' && c[1] == '-' && c[2] >= '0' && c[2] <= '9';
            int mark_label = (c[0] == '*' && ((c[1] >= '0' && c[1] <= '9') || (c + 2 < end && c[1] == '-' && c[2] >= '0' && c[2] <= '9'))) ||
                             (((c[0] >= '0' && c[0] <= '9') || c[0] == 'i') && c[1] == '*');
            ck_assert_msg(!digit_minus_digit && !mark_label, "%s at %dx%d, row %d: labels touch:\n%s", what, cols,
                          rows, row, text);
        }
        line = end;
    }
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
        int edges_told = 0;
        for (a->help = 1; a->help > 0 && a->help < 20;) {
            snprintf(what, sizeof what, "%s help page %d", name, a->help);
            int before = a->help;
            char *text;
            check_screen_text(&f, a, NULL, cols, rows, what, &text);
            edges_told |= strstr(text, "past the picture's edge") != NULL;
            free(text);
            if (a->help == 0)
                break;
            ck_assert_int_eq(a->help, before);
            a->help++;
            check_screen(&f, a, NULL, cols, rows, what); /* past the last page it closes */
        }
        ck_assert_int_eq(a->help, 0);
        ck_assert_msg(edges_told, "%s at %dx%d: no help line says what the edge markers (<1.42, v43.1) are", name,
                      cols, rows);
        /* the region view zoomed out: labels never touch one another or a mark */
        sw_app_set_view(a, SW_VIEW_REGION);
        for (double zoom = 1; zoom <= 4; zoom *= 2) {
            double z = a->zoom;
            a->zoom = zoom;
            char *text;
            snprintf(what, sizeof what, "%s region view at zoom %g", name, zoom);
            check_screen_text(&f, a, NULL, cols, rows, what, &text);
            assert_labels_apart(text, what, cols, rows);
            free(text);
            a->zoom = z;
        }
        sw_app_set_view(a, SW_VIEW_SCENE);
        sw_frame_free(&f);
    }
}

/* Every integrator, the 11th and any plugin included, has a key that picks
 * it, and the help screen names each key with its integrator. */
START_TEST(every_integrator_has_a_key)
{
    const sw_control *pick = sw_control_of(SW_ACT_PICK_METHOD);
    ck_assert_int_le(sw_integrator_count() + SW_REGISTERED_MAX, SW_PICK_KEY_COUNT);
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_control *c;
        int arg;
        ck_assert_msg(pick->keys[i], "integrator %d has no key", i + 1);
        ck_assert(sw_key_lookup(pick->keys[i], SW_CTX_PLAY, &c, &arg));
        ck_assert_int_eq(c->action, SW_ACT_PICK_METHOD);
        ck_assert_int_eq(arg, i + 1);
    }
    sw_app a;
    sw_frame f;
    char err[SW_ERRLEN];
    int clipped;
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    app_for(&a, sw_scene_find("orbit"), NULL, 0); /* (the last method, rkn, refuses the damped spring) */
    sw_app_apply(&a, SW_ACT_PICK_METHOD, sw_integrator_count());
    ck_assert_str_eq(a.sims[0].method->name, sw_integrator_at(sw_integrator_count() - 1)->name);
    a.help = 1;
    char *text = ct_compose(&f, &a, NULL, 120, 60, &clipped);
    char want[64];
    for (int i = 0; i < sw_integrator_count(); i++) {
        snprintf(want, sizeof want, "%c:%s", pick->keys[i], sw_integrator_at(i)->name);
        ck_assert_msg(strstr(text, want), "the help does not show '%s':\n%s", want, text);
    }
    /* the keys column: every pick key past 0, or a '+' saying some are left to the text */
    char keys[32] = "1-9 0 ";
    size_t k = strlen(keys);
    for (int i = 10; i < sw_integrator_count() && pick->keys[i] && k + 1 < sizeof keys; i++)
        keys[k++] = (char)pick->keys[i];
    keys[k] = '\0';
    ck_assert_msg(strstr(text, keys) || strstr(text, "1-9 0 !@#"), "the help's keys column lacks '%s':\n%s", keys,
                  text);
    ck_assert_msg(strstr(text, keys) || strstr(text, "+ "), "the help's keys column leaves keys out unsaid:\n%s",
                  text);
    free(text);
    sw_frame_free(&f);
    sw_app_free(&a);
}
END_TEST

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
        sw_app_key(&a, ' ', 0); /* (compare restarts the runs paused) */
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
    sw_app_key(&a, ' ', 0); /* (compare restarts the runs paused) */
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
        sw_app_sweep_wait(&a);
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

/* Compose a lesson's screen into scr (the caller frees it). */
static void compose_lesson(sw_frame *f, sw_app *a, sw_runner *r, int cols, int rows, sw_screen *scr)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_screen_init(scr, cols, rows, err, sizeof err), SW_OK);
    sw_frame_compose(f, a, sw_runner_side(r, a, cols), scr);
}

/* Two blank columns between the picture and the lesson's text, on every
 * row above the status block (one reads as a space between words). */
static void assert_pane_apart(sw_frame *f, sw_app *a, sw_runner *r, int cols, int rows, const char *what)
{
    sw_screen scr;
    compose_lesson(f, a, r, cols, rows, &scr);
    const sw_side *side = sw_runner_side(r, a, cols);
    int pic_cols = cols - side->width - 1;
    char *text = malloc((size_t)cols * (size_t)rows * 4 + (size_t)rows + 1);
    sw_screen_to_text(&scr, text, (size_t)cols * (size_t)rows * 4 + (size_t)rows + 1);
    for (int row = 0; row < rows - (a->nsims + 5); row++) /* above the status block, its message at 3 rows */
        for (int c = pic_cols; c < pic_cols + 2; c++)
            ck_assert_msg(scr.cp[(size_t)row * (size_t)cols + (size_t)c] == ' ',
                          "%s at %dx%d: row %d, column %d between the picture and the pane is not blank:\n%s", what,
                          cols, rows, row, c, text);
    free(text);
    sw_screen_free(&scr);
}

/* Down scrolls only when there is more below: a page that fits never
 * shows "(Up: more above)". */
static void assert_scroll_stops(sw_frame *f, sw_app *a, sw_runner *r, int cols, int rows, const char *what)
{
    char *text;
    check_screen_text(f, a, sw_runner_side(r, a, cols), cols, rows, what, &text);
    int more = strstr(text, "more below") != NULL || strstr(text, "question below") != NULL ||
               strstr(text, "(question: Down)") != NULL;
    free(text);
    if (more)
        return;
    sw_runner_key(r, a, SW_KEY_DOWN);
    check_screen_text(f, a, sw_runner_side(r, a, cols), cols, rows, what, &text);
    ck_assert_msg(strstr(text, "more above") == NULL, "%s at %dx%d: Down scrolled a pane that fits:\n%s", what, cols,
                  rows, text);
    ck_assert_int_eq(r->scroll, 0);
    free(text);
    a->message[0] = '\0';
}

/* An overlay over the pane claims all of it: no fragment of the page
 * (its header, say) shows beside the box. While a question is open the
 * overlays stay in the picture and the pane shows whole. The parameter
 * panel always stays over the picture: the page's goals beside it say
 * what the values are for (issue 37: it hid them). */
static void assert_overlays_claim_pane(sw_frame *f, sw_app *a, sw_runner *r, int cols, int rows, const char *what)
{
    const sw_side *side = sw_runner_side(r, a, cols);
    char head[24];
    snprintf(head, sizeof head, "%.12s", r->lesson.title);
    for (int ov = 0; ov < 2; ov++) {
        a->help = ov == 0;
        a->panel = ov == 1;
        char *text;
        check_screen_text(f, a, side, cols, rows, what, &text);
        int shown = strstr(text, head) != NULL, want = side->question_open || ov == 1;
        ck_assert_msg(want ? shown : !shown, "%s at %dx%d: with the %s open the page %s:\n%s", what,
                      cols, rows, ov ? "panel" : "help", want ? "is hidden" : "shows beside it", text);
        if (ov == 1 && strstr(text, "Goals:") == NULL)
            for (int i = 0; i < side->nlines; i++)
                ck_assert_msg(strcmp(side->lines[i], "Goals:") != 0, "%s at %dx%d: the panel hides the goals:\n%s",
                              what, cols, rows, text);
        free(text);
    }
    a->help = a->panel = 0;
}

/* Every page of every lesson, with its pane: as it opens, after a second
 * of play, with the hint, with the help screen over the picture. */
/* One page, with its pane: as it opens, after a second of play, with the
 * hint, with the help screen over the picture. */
static void lesson_page(sw_runner *r, sw_app *a, const sw_lesson_entry *e, int n, int lesson, int page, void *ctx)
{
    (void)n;
    (void)ctx;
    char what[300];
    for (int s = 0; s < 2; s++) {
        sw_frame f;
        char ferr[SW_ERRLEN];
        ck_assert_int_eq(sw_frame_init(&f, ferr, sizeof ferr), SW_OK);
        int cols = sizes[s][0], rows = sizes[s][1];
        snprintf(what, sizeof what, "%s page %d", e[lesson].file, page + 1);
        check_screen(&f, a, sw_runner_side(r, a, cols), cols, rows, what);
        assert_pane_apart(&f, a, r, cols, rows, what);
        assert_scroll_stops(&f, a, r, cols, rows, what);
        assert_overlays_claim_pane(&f, a, r, cols, rows, what);
        r->hint = 1;
        check_screen(&f, a, sw_runner_side(r, a, cols), cols, rows, what);
        r->hint = 0;
        /* an open question stays in sight under every overlay */
        const sw_lesson_question *q = &r->lesson.pages[page].question;
        if (q->text && !r->answered[page]) {
            const sw_side *side = sw_runner_side(r, a, cols);
            char want[16];
            snprintf(want, sizeof want, "%c) ", SW_ANSWER_FIRST + q->nanswers - 1);
            for (int ov = 0; ov < 2; ov++) {
                a->help = ov == 0;
                a->panel = ov == 1;
                char *text;
                int scroll = r->scroll;
                r->scroll = 1000; /* the pane's end: the answers */
                check_screen_text(&f, a, side, cols, rows, what, &text);
                r->scroll = scroll;
                ck_assert_msg(strstr(text, want) != NULL, "%s at %dx%d: the %s hides the question's "
                              "answer %s:\n%s", what, cols, rows, ov ? "panel" : "help", want, text);
                free(text);
            }
            a->help = a->panel = 0;
            /* the key line names the question's own letters (A-C for three) */
            char *text, keys[16];
            check_screen_text(&f, a, side, cols, rows, what, &text);
            snprintf(keys, sizeof keys, "A-%c answer", SW_ANSWER_FIRST + q->nanswers - 1);
            const char *k = strstr(text, "A-");
            while (k && strncmp(k + 3, " answer", 7) != 0)
                k = strstr(k + 1, "A-");
            ck_assert_msg(k && strncmp(k, keys, strlen(keys)) == 0, "%s at %dx%d: the key line does not say "
                          "'%s':\n%s", what, cols, rows, keys, text);
            free(text);
        }
        for (int hp = 1; hp < 20; hp++) {
            a->help = hp;
            check_screen(&f, a, sw_runner_side(r, a, cols), cols, rows, what);
            if (a->help == 0)
                break; /* past the last page */
        }
        a->help = 0;
        sw_frame_free(&f);
    }
    int paused = a->paused;
    a->paused = 0;
    sw_app_advance(a, 1.0, 100000);
    a->paused = paused;
    for (int s = 0; s < 2; s++) {
        sw_frame f;
        char ferr[SW_ERRLEN];
        ck_assert_int_eq(sw_frame_init(&f, ferr, sizeof ferr), SW_OK);
        snprintf(what, sizeof what, "%s page %d after a second", e[lesson].file, page + 1);
        check_screen(&f, a, sw_runner_side(r, a, sizes[s][0]), sizes[s][0], sizes[s][1], what);
        sw_frame_free(&f);
    }
}

/* Every page of every lesson (lesson_page above). */
START_TEST(every_lesson_page)
{
    ct_each_page(lesson_page, NULL);
}
END_TEST

/* A lesson written to show the pane's layout: formulas, bracketed prose,
 * a table, a question and a long title (the real lessons change; these
 * lines are here to stay). */
static const char layout_lesson[] =
    "title: Runge-Kutta: midpoint and RK4, a long title\n"
    "\n"
    "--- Formulas and a table\n"
    "@scene vortex\n"
    "@integrator midpoint\n"
    "@dt 0.1\n"
    "A mass on an undamped spring: f = -k(x - r). Its energy should stay constant; Euler multiplies each mode "
    "by the disc |1 + Δt·λ| <= 1 around -1 where the marks sit.\n"
    "\n"
    "  f = -[ k_spring·(x - r) + k_damp·v ]\n"
    "  x[i+1] = x[i]\n"
    "         + (Δt/6)·(k1 + 2k2 + 2k3 + k4)\n"
    "  (I - Δt·J) δ = Δt·g(guess) - (guess - x[i])\n"
    "\n"
    "  method     Δt       steps  error\n"
    "  rk4        0.05     126    0.0000003\n"
    "@question When does a 4-evaluation step pay?\n"
    "@answer a) Always | No.\n"
    "@answer b) When the motion is smooth | Yes.\n"
    "@correct b\n"
    "@hint Think.\n"
    "\n"
    "--- Three runs in phase space\n"
    "@scene spring\n"
    "@integrator euler\n"
    "@dt 0.02\n"
    "@compare symplectic-euler implicit-euler\n"
    "@view phase\n"
    "Three methods (o, x and +) from the same start.\n";

static void start_layout_lesson(sw_runner *r, sw_app *a, char *dir, size_t dirlen)
{
    snprintf(dir, dirlen, "/tmp/sw-layout-XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(dir));
    setenv("XDG_STATE_HOME", dir, 1);
    char path[256], err[SW_LESSON_ERRLEN];
    snprintf(path, sizeof path, "%s/layout.lesson", dir);
    FILE *out = fopen(path, "w");
    ck_assert_ptr_nonnull(out);
    fputs(layout_lesson, out);
    ck_assert_int_eq(fclose(out), 0);
    ck_assert_msg(sw_runner_start(r, a, path, 0, err, sizeof err) == SW_OK, "%s", err);
}

static void end_layout_lesson(sw_runner *r, sw_app *a, const char *dir)
{
    sw_app_free(a);
    sw_runner_free(r);
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    ck_assert_int_eq(system(cmd), 0);
}

/* Formulas break outside brackets and before an operator, never leaving a
 * lone bracket or one operand; bracketed prose stays on one line; a table
 * row shows whole; the header keeps its page marker whole. */
START_TEST(pane_breaks_where_it_reads)
{
    static const char *const never[] = { "]", "- r)", "k4)", "Δt·λ| <= 1", "- x[i])", "f = -k(x", "|1 +",
                                         "2k3 +", "0.0000003" };
    static const char *const whole[] = { "-k(x - r)", "|1 + Δt·λ|", "(k1 + 2k2", "(guess - x[i])" };
    char dir[64];
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    start_layout_lesson(r, &a, dir, sizeof dir);
    for (int cols = 60; cols <= 120; cols += 10) {
        const sw_side *side = sw_runner_side(r, &a, cols);
        char all[8192] = "";
        for (int i = 0; i < side->nlines; i++) {
            char t[SW_RUNNER_COLS];
            const char *l = side->lines[i];
            while (*l == ' ')
                l++;
            snprintf(t, sizeof t, "%s", l);
            for (size_t k = 0; k < sizeof never / sizeof never[0]; k++)
                ck_assert_msg(strcmp(t, never[k]) != 0 || (strcmp(t, "0.0000003") == 0 && cols < 70),
                              "at %d columns a pane line is \"%s\"", cols, t);
            ck_assert_msg(strcmp(t + (strlen(t) > 8 ? strlen(t) - 8 : 0), "f = -k(x") != 0,
                          "at %d columns \"%s\" breaks inside -k(x - r)", cols, t);
            strncat(all, side->lines[i], sizeof all - strlen(all) - 2);
            strcat(all, "\n");
        }
        for (size_t k = 0; k < sizeof whole / sizeof whole[0]; k++)
            ck_assert_msg(strstr(all, whole[k]) || (cols < 70 && k == 2), /* (k1 + ... k4) is wider than 60's pane */ "at %d columns \"%s\" is broken:\n%s", cols, whole[k], all);
        ck_assert_msg(strstr(all, "(1/2)") || strstr(all, "(page 1/2)"), "at %d columns the page marker is "
                      "broken:\n%s", cols, all);
        if (cols >= 80)
            ck_assert_msg(strstr(all, "rk4        0.05     126    0.0000003"), "at %d columns the table row is "
                          "split:\n%s", cols, all);
        for (int rows = 16; rows <= 40; rows += 8) {
            sw_frame f;
            char err[SW_ERRLEN];
            ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
            check_screen(&f, &a, side, cols, rows, "the layout lesson");
            sw_frame_free(&f);
        }
    }
    end_layout_lesson(r, &a, dir);
    free(r);
}
END_TEST

/* w in a lesson, with the question open: the plot fits the picture (no
 * "needs" message, nothing cut, the answers in sight), and its last row
 * says what w does next, which is what it does. */
START_TEST(workprec_cycle_in_a_lesson)
{
    char dir[64];
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    start_layout_lesson(r, &a, dir, sizeof dir);
    for (int s = 0; s < 2; s++) {
        int cols = sizes[s][0], rows = sizes[s][1];
        sw_frame f;
        char err[SW_ERRLEN];
        ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
        static const char *const next[] = { "against", "w closes" };
        for (int k = 0; k < 2; k++) {
            ck_assert_int_eq(sw_app_key(&a, 'w', 1), 1);
            sw_app_sweep_wait(&a);
            ck_assert_int_eq(a.workprec, k + 1);
            char *text;
            check_screen_text(&f, &a, sw_runner_side(r, &a, cols), cols, rows, "w in a lesson", &text);
            /* a question folded under the text opens once the text is read (Down) */
            for (int down = 0; down < 8 && !strstr(text, "B) When") && strstr(text, "question"); down++) {
                free(text);
                sw_runner_key(r, &a, SW_KEY_DOWN);
                check_screen_text(&f, &a, sw_runner_side(r, &a, cols), cols, rows, "w in a lesson", &text);
            }
            ck_assert_msg(strstr(text, "the plot needs") == NULL && strstr(text, "1e") != NULL,
                          "at %dx%d the plot does not fit:\n%s", cols, rows, text);
            ck_assert_msg(strstr(text, "B) When"), "at %dx%d the plot hides the question:\n%s", cols, rows, text);
            char want[32];
            snprintf(want, sizeof want, k == 0 ? "w: " : "w closes");
            ck_assert_msg(strstr(text, want) && strstr(text, next[k]), "at %dx%d the plot does not say what w "
                          "does next (%s):\n%s", cols, rows, next[k], text);
            free(text);
        }
        ck_assert_int_eq(sw_app_key(&a, 'w', 1), 1);
        ck_assert_int_eq(a.workprec, 0);
        sw_frame_free(&f);
    }
    end_layout_lesson(r, &a, dir);
    free(r);
}
END_TEST

/* The phase view's legend names every run drawn (brief names, a second
 * row), and the graph never squashes the scene below SCENE_MIN_ROWS. */
START_TEST(legend_and_graph_room)
{
    char dir[64];
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    start_layout_lesson(r, &a, dir, sizeof dir);
    sw_runner_enter(r, &a, 1);
    ck_assert_int_eq(a.nsims, 3);
    sw_app_advance(&a, 0.5, 100000);
    for (int s = 0; s < 2; s++) {
        int cols = sizes[s][0], rows = sizes[s][1];
        sw_frame f;
        char err[SW_ERRLEN];
        ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
        char *text;
        check_screen_text(&f, &a, sw_runner_side(r, &a, cols), cols, rows, "phase legend", &text);
        static const char *const entries[] = { "o. euler", "x symp", "+ impl" }; /* (o: now, .: its path) */
        for (int k = 0; k < 3; k++)
            ck_assert_msg(strstr(text, entries[k]), "at %dx%d the legend drops %s:\n%s", cols, rows, entries[k], text);
        free(text);
        /* the graph with three runs, lanes on and off, and a message of three rows */
        sw_app_set_view(&a, SW_VIEW_SCENE);
        a.graph = 1;
        snprintf(a.message, sizeof a.message, "%s", "a long message that takes three rows of the status block at "
                 "eighty columns, so the picture has fewer rows than usual to share with the graph below it, "
                 "and more words still to fill the third row");
        for (a.lanes = 0; a.lanes < 2; a.lanes++) {
            check_screen_text(&f, &a, sw_runner_side(r, &a, cols), cols, rows, "graph room", &text);
            const char *g = strstr(text, "energy drift");
            int row = 0;
            for (const char *c = text; g && c < g; c++)
                row += *c == '\n';
            ck_assert_msg(!g || row >= 10, "at %dx%d the graph leaves the scene %d rows:\n%s", cols, rows, row, text);
            ck_assert_msg(g || strstr(text, "graph"), "at %dx%d the graph is gone without a word:\n%s", cols, rows,
                          text);
            free(text);
        }
        a.graph = 0;
        a.lanes = 0;
        a.message[0] = '\0';
        sw_app_set_view(&a, SW_VIEW_PHASE);
        sw_frame_free(&f);
    }
    end_layout_lesson(r, &a, dir);
    free(r);
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
        { "pane breaks", pane_breaks_where_it_reads }, { "workprec in a lesson", workprec_cycle_in_a_lesson },
        { "legend and graph", legend_and_graph_room }, { "pick keys", every_integrator_has_a_key },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        TCase *tc = tcase_create(cases[i].name);
        tcase_set_timeout(tc, 300);
        tcase_add_test(tc, cases[i].test);
        suite_add_tcase(s, tc);
    }
    return s;
}
