/* The frame composer: where the picture (scene, lanes, phase or region
 * view), the graph, the lesson pane, the status block and the overlays go.
 * Invariant: every text is fitted (brief forms, then the least important
 * fields dropped) or wrapped to the cells it gets, so nothing is cut in a
 * word or a number at any size from SW_MIN_COLS × SW_MIN_ROWS up; while a
 * lesson's question is open, overlays stay inside the picture, so they
 * never hide it. */
#include "render/screen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/decor.h"
#include "render/gap.h"
#include "render/legend.h"
#include "render/side.h"
#include "render/stages.h"
#include "render/text.h"
#include "stepwise/stepwise.h"

/* Rows the scene keeps before a graph gets any, and the fewest a graph is drawn in. */
#define SCENE_MIN_ROWS 10
#define GRAPH_MIN_ROWS 5

static const uint32_t sim_glyph[SW_APP_SIMS] = { SW_GLYPH_MAIN, SW_GLYPH_COMPARE1, SW_GLYPH_COMPARE2 };
static const int sim_style[SW_APP_SIMS] = { SW_STYLE_MAIN, SW_STYLE_COMPARE1, SW_STYLE_COMPARE2 };

static void fit_line(sw_screen *scr, int row, int col, int width, int style, const sw_field *f, int n)
{
    char line[SW_TEXT_LINE];
    if (sw_text_fit(line, sizeof line, width, f, n, "  ") > 0)
        sw_screen_text(scr, row, col, width, style, line);
}

static sw_field *field(sw_field *f, int *n, int prio, const char *full, const char *brief)
{
    sw_field *x = &f[(*n)++];
    /* the texts here are built to fit a field (paths are cut to 90 bytes first) */
    size_t lf = strlen(full), lb = brief ? strlen(brief) : 0;
    lf = lf < sizeof x->full ? lf : sizeof x->full - 1;
    lb = lb < sizeof x->brief ? lb : sizeof x->brief - 1;
    memcpy(x->full, full, lf);
    x->full[lf] = '\0';
    if (lb)
        memcpy(x->brief, brief, lb);
    x->brief[lb] = '\0';
    x->prio = prio;
    return x;
}

/* ---- the camera and the scene ------------------------------------------------- */

/* The scene's natural view (or a page's @view box) times the zoom; when
 * following, grown (never shrunk) to hold the main run's particles. */
static void camera(sw_frame *f, sw_app *a)
{
    const sw_sim *main = &a->sims[0];
    sw_view base = sw_view_zoom(a->have_box ? a->box : a->scene->view(&main->sys), a->zoom);
    if (f->view_scene != a->scene || memcmp(f->view_p, a->p, sizeof f->view_p) != 0 || f->view_zoom != a->zoom ||
        f->view_follow != a->follow || !a->follow || main->t == 0) {
        f->view = base;
        f->view_scene = a->scene;
        memcpy(f->view_p, a->p, sizeof f->view_p);
        f->view_zoom = a->zoom;
        f->view_follow = a->follow;
    }
    if (a->follow && !main->blown)
        sw_view_follow(&f->view, main->sys.y, main->sys.n, 0.25);
}

/* Which particles of sim s are alive (NULL: all). */
static const unsigned char *alive(sw_frame *f, const sw_sim *s)
{
    if (!s->sys.scene || !s->sys.scene->alive)
        return NULL;
    if (s->sys.n > f->keep_cap) {
        unsigned char *k = realloc(f->keep, (size_t)s->sys.n);
        if (!k)
            return NULL;
        f->keep = k;
        f->keep_cap = s->sys.n;
    }
    for (int i = 0; i < s->sys.n; i++)
        f->keep[i] = (unsigned char)sw_sim_alive(s, i);
    return f->keep;
}

/* Whether sw_canvas_offscreen would draw any arrow for these points
 * (kept, finite, outside the visible rectangle, by its tests): most frames
 * have none, so the test for "inside" comes first and alone. */
static int any_outside(const sw_canvas *c, const double *xy, int n, const unsigned char *keep)
{
    sw_view vis = sw_canvas_visible(c);
    for (int i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        if (x >= vis.xmin && x < vis.xmax && y > vis.ymin && y <= vis.ymax)
            continue;
        if ((!keep || keep[i]) && isfinite(x) && isfinite(y))
            return 1;
    }
    return 0;
}

/* Sims first..last (overlaid) on canvas c, sized cols × rows. */
static void draw_sims(sw_frame *f, sw_app *a, sw_canvas *c, int cols, int rows, int first, int last)
{
    char err[SW_ERRLEN];
    if (c->cols != cols || c->rows != rows)
        sw_canvas_resize(c, cols, rows, err, sizeof err);
    sw_canvas_set_mode(c, a->braille ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII);
    sw_canvas_set_view(c, &f->view, err, sizeof err);
    sw_canvas_clear(c);
    const sw_sim *main = &a->sims[0];
    sw_canvas_draw_decor(c, &main->sys, main->t, f->unicode);
    if (a->trails && f->have_trails)
        for (int i = last; i >= first; i--)
            sw_canvas_draw_trails(c, &f->trails[i], SW_STYLE_TRAIL);
    const double *g = a->ghost ? sw_app_ghost(a) : NULL;
    if (g)
        sw_canvas_draw_system(c, &main->sys, g, main->t, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    for (int i = last; i >= first; i--)
        sw_canvas_draw_system(c, &a->sims[i].sys, a->sims[i].sys.y, a->sims[i].t, sim_glyph[i], sim_style[i]);
    /* where runs share a cell with the main one (or the main with its ghost): '&' */
    for (int i = first + 1; i <= last && first == 0; i++)
        sw_canvas_draw_gap(c, &main->sys, main->sys.y, a->sims[i].sys.y, main->t, NULL, SW_STYLE_MAIN);
    if (g && !main->blown)
        sw_canvas_draw_gap(c, &main->sys, main->sys.y, g, main->t, "ghost", SW_STYLE_GHOST);
    /* particles that left the view: an arrow at the edge (the main run's with its distance) */
    for (int i = last; i >= first; i--) {
        const sw_sim *s = &a->sims[i];
        const unsigned char *keep = alive(f, s);
        if (any_outside(c, s->sys.y, s->sys.n, keep))
            sw_canvas_offscreen(c, s->sys.y, s->sys.n, keep, sim_style[i], i == first);
    }
}

/* A blown-up run's banner on the picture's top row: its picture stays frozen
 * where it blew up, the others go on. */
static void blown_banner(sw_screen *scr, const sw_sim *s, int row, int col, int width, int rows)
{
    char line[3][SW_TEXT_LINE], wrapped[4][SW_TEXT_LINE];
    int max = rows > 3 ? 3 : rows;
    /* the whole story where it fits, else shorter: the reason is on the status line too */
    snprintf(line[0], sizeof line[0], "BLOWN UP at step %ld, t = %.4g: %s. Press r to reset.", s->blow_step,
             s->blow_time, s->blow_reason);
    snprintf(line[1], sizeof line[1], "BLOWN UP at step %ld, t = %.4g. Press r to reset.", s->blow_step, s->blow_time);
    snprintf(line[2], sizeof line[2], "BLOWN UP (r resets)");
    int k = 0;
    while (k < 2 && sw_text_wrap(line[k], width, wrapped, 4) > max)
        k++;
    if (sw_text_wrap(line[k], width, wrapped, 4) <= max)
        sw_screen_wrapped(scr, row, col, width, max, SW_STYLE_BAD, line[k]);
}

/* Compare side by side: one lane per method, each with its own title line
 * (method, energy, error) and picture, stacked or in columns, whichever
 * gives the scene the larger scale. */
/* The smallest lane that reads: a picture this wide side by side, or this
 * tall stacked (its status line above it). */
#define LANE_MIN_COLS 20
#define LANE_MIN_ROWS 5

/* Whether a->nsims lanes in rows x cols are each at least that big, side
 * by side or stacked. */
static int lanes_readable(const sw_app *a, int rows, int cols)
{
    int n = a->nsims;
    return (cols - (n - 1)) / n >= LANE_MIN_COLS || rows / n >= LANE_MIN_ROWS;
}

static void draw_lanes(sw_frame *f, sw_app *a, sw_screen *scr, int row0, int col0, int rows, int cols)
{
    int n = a->nsims;
    /* a row under the lanes for the legend of the first one's picture */
    int legend = rows > n * LANE_MIN_ROWS;
    rows -= legend;
    sw_view v = f->view;
    double vx = v.xmax - v.xmin, vy = v.ymax - v.ymin;
    int stack_h = rows / n, col_w = (cols - (n - 1)) / n;
    double s_stack = fmax(vx / cols, vy / (2.0 * (stack_h - 1)));
    double s_cols = fmax(vx / col_w, vy / (2.0 * (rows - 1)));
    int stacked = s_stack <= s_cols;
    /* the finer scale, unless its lanes are too small to read and the other's are not */
    if (!stacked && col_w < LANE_MIN_COLS && stack_h >= LANE_MIN_ROWS)
        stacked = 1;
    else if (stacked && stack_h < LANE_MIN_ROWS && col_w >= LANE_MIN_COLS)
        stacked = 0;
    for (int i = 0; i < n; i++) {
        int r = stacked ? row0 + i * stack_h : row0, c = stacked ? col0 : col0 + i * (col_w + 1);
        int h = stacked ? (i == n - 1 ? rows - i * stack_h : stack_h) : rows, w = stacked ? cols : col_w;
        if (h < 2 || w < 8)
            continue;
        sw_field fl[SW_STATUS_FIELDS + 1];
        int nf = 0;
        char glyph[2] = { (char)sim_glyph[i], '\0' };
        field(fl, &nf, 11, glyph, NULL);
        sw_field st[SW_STATUS_FIELDS];
        int ns = sw_app_status_fields(a, i, st, SW_STATUS_FIELDS);
        /* the lane's own numbers; the shared ones (scene, dt, t) are on the status line */
        for (int k = 0; k < ns; k++)
            if (strcmp(st[k].full, a->scene->name) != 0 && strncmp(st[k].full, "dt=", 3) != 0 &&
                strncmp(st[k].full, "t=", 2) != 0)
                fl[nf++] = st[k];
        char line[SW_TEXT_LINE];
        if (sw_text_fit(line, sizeof line, w, fl, nf, " ") > 0)
            sw_screen_text(scr, r, c, w, a->sims[i].blown ? SW_STYLE_BAD : sim_style[i], line);
        sw_canvas *cv = i == 0 ? &f->canvas : &f->lanes[i - 1];
        if (!cv->cols) {
            char err[SW_ERRLEN];
            if (sw_canvas_init(cv, w, h - 1, err, sizeof err) != SW_OK)
                continue;
        }
        draw_sims(f, a, cv, w, h - 1, i, i);
        sw_screen_blit(scr, cv, r + 1, c);
        if (a->sims[i].blown)
            blown_banner(scr, &a->sims[i], r + 1, c, w, h - 1);
        if (!stacked && i < n - 1)
            for (int k = 0; k < rows; k++)
                sw_screen_text(scr, row0 + k, c + w, 1, SW_STYLE_DIM, "|");
    }
    if (legend && f->canvas.cols) {
        sw_field fl[16];
        const sw_canvas *cv[SW_APP_SIMS] = { &f->canvas, &f->lanes[0], &f->lanes[1] };
        int nf = sw_scene_legend(cv, n, a, fl, 16);
        fit_line(scr, row0 + rows, col0, cols, SW_STYLE_DIM, fl, nf);
    }
}

/* ---- the phase and region views ------------------------------------------------ */

/* The rows (1 or 2) a legend needs so that none of its nmust first
 * entries (the truth, each run drawn) is dropped while brief forms or a
 * second row can keep it. */
static int legend_rows(const sw_field *must, int nmust, int width)
{
    char lines[1][SW_TEXT_LINE];
    int dropped = 0;
    sw_text_fit_rows(lines, 1, width, must, nmust, "  ", &dropped);
    return dropped ? 2 : 1;
}

/* The scene drawn on f->canvas (rows × cols) onto the screen, with its
 * legend on its last row or two (two where one would drop a part and the
 * picture has rows to spare): over the picture's own foot where the
 * legend's cells there are blank (most pictures: the picture keeps its
 * scale), else under a picture drawn that much shorter. */
static void scene_with_legend(sw_frame *f, sw_app *a, sw_screen *scr, int rows, int cols)
{
    const sw_canvas *cv[1] = { &f->canvas };
    sw_field fl[16];
    char lines[2][SW_TEXT_LINE];
    int n = rows > SCENE_MIN_ROWS / 2 ? sw_scene_legend(cv, 1, a, fl, 16) : 0;
    int lr = n == 0 ? 0 : rows > SCENE_MIN_ROWS && legend_rows(fl, n, cols) == 2 ? 2 : 1;
    int used = lr ? sw_text_fit_rows(lines, lr, cols, fl, n, "  ", NULL) : 0;
    int blank = 1;
    for (int i = 0; i < used; i++)
        for (int k = 0; k < sw_text_cells(lines[i]) && blank; k++)
            blank = sw_canvas_codepoint(&f->canvas, k, rows - used + i) == ' ';
    if (!blank) {
        draw_sims(f, a, &f->canvas, cols, rows - used, 0, a->nsims - 1);
        n = sw_scene_legend(cv, 1, a, fl, 16);
        used = sw_text_fit_rows(lines, used, cols, fl, n, "  ", NULL);
    }
    sw_screen_blit(scr, &f->canvas, 0, 0);
    for (int i = 0; i < used; i++)
        sw_screen_text(scr, rows - used + i, 0, cols, SW_STYLE_DIM, lines[i]);
}

static void draw_phase(sw_frame *f, sw_app *a, sw_screen *scr, int row0, int col0, int rows, int cols)
{
    char err[SW_ERRLEN], buf[SW_TEXT_LINE], brief[SW_TEXT_LINE];
    const char *q, *qu, *v, *vu;
    sw_phase_names(a->phase_coord, &q, &qu, &v, &vu);
    sw_field fl[12];
    int n = 0;
    /* which axis is which in words: the coordinate across, its rate up */
    snprintf(buf, sizeof buf, "phase: %s (%s) across, %s (%s) up", q, qu, v, vu);
    snprintf(brief, sizeof brief, "%s across, %s up", q, v);
    field(fl, &n, 10, buf, brief);
    snprintf(buf, sizeof buf, "of particle %d", a->phase_particle + 1);
    snprintf(brief, sizeof brief, "particle %d", a->phase_particle + 1);
    field(fl, &n, 6, buf, brief);
    if (rows < 6)
        return;
    /* the legend: what is drawn first (the truth, each run) */
    sw_field lg[12];
    int nl = 0;
    int exact = a->have_truth && a->truth.source == SW_TRUTH_EXACT;
    int reference = a->truth.source == SW_TRUTH_REFERENCE;
    field(lg, &nl, 9, exact ? "' exact solution" : reference ? "' reference run" : "no truth",
          exact ? "' exact" : reference ? "' reference" : NULL);
    int ascii = !a->braille; /* (in Braille the paths are dots, said by no glyph) */
    for (int i = 0; i < a->nsims; i++) {
        char name[64], mark[8];
        /* the glyphs drawn: the present point, and its path when that differs ("o. euler") */
        uint32_t path = sw_phase_path_glyph(i);
        snprintf(mark, sizeof mark, "%c%s", (char)sim_glyph[i], ascii && path != sim_glyph[i] ? "." : "");
        snprintf(buf, sizeof buf, "%s %s%s", mark, a->sims[i].method->name, a->sims[i].blown ? " (blew up)" : "");
        sw_text_brief_name(a->sims[i].method->name, name, sizeof name);
        snprintf(brief, sizeof brief, "%s %s%s", mark, name[0] ? name : a->sims[i].method->name,
                 a->sims[i].blown ? " (blown)" : "");
        field(lg, &nl, 12 - i, buf, brief);
    }
    /* the keys in words, on a second row when the first has no room */
    field(lg, &nl, 2, "V coordinate  < > particle", "V: axis  < >: particle");
    int nmust = nl, lrows = legend_rows(lg, nmust, cols);
    sw_canvas *c = &f->canvas;
    int crows = rows - 1 - lrows;
    if (c->cols != cols || c->rows != crows)
        sw_canvas_resize(c, cols, crows, err, sizeof err);
    sw_canvas_set_mode(c, a->braille ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII);
    int left = sw_phase_draw(&f->phase, c, a, f->unicode);
    double q0, q1, v0, v1;
    sw_phase_range(&f->phase, a, &q0, &q1, &v0, &v1);
    if (f->phase.have_range) {
        snprintf(buf, sizeof buf, "%s %.3g..%.3g, %s %.3g..%.3g", q, q0, q1, v, v0, v1);
        field(fl, &n, 3, buf, NULL);
    }
    fit_line(scr, row0, col0, cols, SW_STYLE_TITLE, fl, n);
    sw_screen_blit(scr, c, row0 + 1, col0);
    if (left) {
        snprintf(buf, sizeof buf, "%d left the frame (z: zoom out)", left);
        field(lg, &nl, 7, buf, "z: zoom out");
    }
    char lines[2][SW_TEXT_LINE];
    int used = sw_text_fit_rows(lines, lrows, cols, lg, nl, "  ", NULL);
    for (int i = 0; i < used; i++)
        sw_screen_text(scr, row0 + rows - lrows + i, col0, cols, SW_STYLE_DIM, lines[i]);
}

static void draw_region(sw_frame *f, sw_app *a, sw_screen *scr, int row0, int col0, int rows, int cols)
{
    char err[SW_ERRLEN], buf[SW_TEXT_LINE], why[SW_ERRLEN];
    const sw_integrator *m = a->sims[0].method;
    if (rows < 8)
        return;
    sw_field fl[12];
    int n = 0;
    char brief[SW_TEXT_LINE];
    snprintf(buf, sizeof buf, "stability region of %s", m->name);
    snprintf(brief, sizeof brief, "region of %s", m->name);
    field(fl, &n, 10, buf, brief);
    /* the marks' legend in the title's row, so the picture keeps its rows */
    if (a->have_spec && a->spec.n > 0) {
        snprintf(buf, sizeof buf, "* dt x eigenvalue of %s (%d mode%s%s)", a->scene->name, a->spec.n,
                 a->spec.n == 1 ? "" : "s", a->spec.complete ? "" : ", the stiffest");
        field(fl, &n, 9, buf, "* dt x eigenvalue");
        snprintf(buf, sizeof buf, "dt=%g", a->dt);
        field(fl, &n, 8, buf, NULL);
    }
    field(fl, &n, 9, "(shaded: growth per step <= 1; its edge a line)", "(shaded: stable)");
    /* the title and the marks' legend on two rows where one drops either */
    char lines[2][SW_TEXT_LINE];
    int trows = legend_rows(fl, n, cols);
    int used = sw_text_fit_rows(lines, trows, cols, fl, n, "  ", NULL);
    for (int i = 0; i < used; i++)
        sw_screen_text(scr, row0 + i, col0, cols, SW_STYLE_TITLE, lines[i]);
    row0 += trows - 1;
    rows -= trows - 1;
    /* under the picture: the real axis's numbers, the worst mark against
     * its edge along its ray, and the legend */
    int crows = rows - 4;
    sw_canvas *c = &f->canvas;
    if (c->cols != cols || c->rows != crows)
        sw_canvas_resize(c, cols, crows, err, sizeof err);
    /* Braille where the terminal shows it, or when asked for */
    sw_canvas_set_mode(c, f->unicode || a->braille ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII);
    double worst;
    int outside, shown;
    if (sw_region_draw(&f->region, c, a, &worst, &outside, &shown, why, sizeof why) != 0) {
        sw_screen_wrapped(scr, row0 + 2, col0 + 1, cols - 2, rows - 4, SW_STYLE_TEXT, why);
        return;
    }
    sw_screen_blit(scr, c, row0 + 1, col0);
    sw_screen_text(scr, row0 + 1 + crows, col0, cols, SW_STYLE_DIM, f->region.ticks);
    if (f->region.gauge[0])
        sw_screen_text(scr, row0 + 2 + crows, col0, cols, f->region.ratio_grows ? SW_STYLE_WARN : SW_STYLE_STATUS,
                       f->region.gauge);
    n = 0;
    if (why[0]) {
        sw_screen_wrapped(scr, row0 + rows - 2, col0, cols, 2, SW_STYLE_DIM, why);
        return;
    }
    if (f->region.progress < 1) {
        snprintf(buf, sizeof buf, "shading %s's region: %.0f%% (each point steps the sandboxed plugin)", m->name,
                 100 * f->region.progress);
        field(fl, &n, 11, buf, NULL);
    }
    if (outside) {
        snprintf(buf, sizeof buf, "X %d outside: they grow", outside);
        field(fl, &n, 10, buf, "X grows");
    } else
        field(fl, &n, 10, "all inside: no mode grows", "all inside");
    /* the scale chosen for the page: it stays while dt changes */
    snprintf(buf, sizeof buf, "scale +-%.2g, fixed (z zooms)", f->region.fit_half * a->zoom);
    snprintf(brief, sizeof brief, "%s+-%.2g fixed", f->region.beyond > 0 ? "" : "scale ", f->region.fit_half * a->zoom);
    field(fl, &n, 8, buf, brief);
    if (f->region.beyond > 0) {
        snprintf(buf, sizeof buf, "< > ^ v: marks past the edge, to %.3g", f->region.beyond);
        snprintf(brief, sizeof brief, "<>^v past edge: %.3g", f->region.beyond);
        field(fl, &n, 9, buf, brief); /* (before the scale, which the numbers under the picture show too) */
    }
    field(fl, &n, 6, "+/- move the marks", "+/- dt");
    snprintf(buf, sizeof buf, "worst x%.6f/step", worst);
    field(fl, &n, 5, buf, NULL);
    if (a->spec.growing) {
        snprintf(buf, sizeof buf, "(%d growing by the physics, not shown)", a->spec.growing);
        field(fl, &n, 2, buf, NULL);
    }
    fit_line(scr, row0 + rows - 1, col0, cols, outside ? SW_STYLE_WARN : SW_STYLE_STATUS, fl, n);
}

/* ---- the status block ------------------------------------------------------------- */

/* The stability meter's line (app/status.c words it, so the labels and
 * the word beside the growth are unit-tested there). */
static int meter_fields(sw_app *a, sw_field *f, int *style)
{
    int warn, n = sw_app_meter_fields(a, f, 8, &warn);
    *style = warn ? SW_STYLE_WARN : SW_STYLE_STATUS;
    return n;
}

static void key_fields(const sw_app *a, const sw_side *side, sw_field *f, int *n)
{
    if (side) {
        if (side->notice)
            field(f, n, 12, side->notice, NULL);
        if (side->question_open) {
            char keys[16]; /* the question's own letters: A-C for three answers */
            snprintf(keys, sizeof keys, "A-%c answer", 'A' + (side->question_open > 1 ? side->question_open - 1 : 1));
            field(f, n, 11, keys, NULL);
        }
        if (!side->notice)
            field(f, n, 9, "n next page", "n next");
        field(f, n, 8, "h hint", NULL);
    }
    field(f, n, side ? 4 : 9, "i method", NULL);
    field(f, n, side ? 4 : 9, "+/- dt", NULL);
    field(f, n, side ? 3 : 8, "space pause", NULL);
    field(f, n, side ? 3 : 7, "r reset", NULL);
    field(f, n, 6, a->compare ? "l lanes" : "c compare", NULL);
    field(f, n, 6, "g ghost", NULL);
    field(f, n, 5, a->view == SW_VIEW_PHASE ? "v scene" : "v phase", NULL);
    field(f, n, 5, a->view == SW_VIEW_REGION ? "s scene" : "s region", NULL);
    field(f, n, 2, "z/Z zoom", NULL);
    field(f, n, 10, "? help", NULL);
    field(f, n, 10, "q quit", NULL);
}

#define MSG_ROWS 4 /* the message's most lines under the meter */

/* The status block's lines (full width), bottom of the screen; returns its rows. */
static int status_block(sw_app *a, const sw_side *side, sw_screen *scr, int dry)
{
    /* a message as long as a Δt change's report after a restart takes four
     * lines at 80 columns: all of it is shown (the picture gives a row) */
    char msg[MSG_ROWS][SW_TEXT_LINE];
    int nmsg = a->message[0] ? sw_text_wrap(a->message, scr->cols, msg, MSG_ROWS) : 0;
    if (nmsg > MSG_ROWS)
        nmsg = MSG_ROWS;
    int nstat = a->compare && a->lanes && a->view == SW_VIEW_SCENE ? 1 : a->nsims;
    int rows = nstat + 1 + (nmsg ? nmsg : 1) + 1;
    if (dry)
        return rows;
    int row = scr->rows - rows;
    sw_field f[24];
    for (int i = 0; i < nstat; i++) {
        int n = sw_app_status_fields(a, i, f, SW_STATUS_FIELDS);
        char glyph[4] = { (char)sim_glyph[i], ' ', '\0' };
        sw_screen_text(scr, row, 0, 2, sim_style[i], glyph);
        if (i > 0) {
            memmove(f + 1, f, (size_t)n * sizeof *f);
            field(f, &(int){ 0 }, 11, "vs", NULL);
            n++;
        }
        fit_line(scr, row++, 2, scr->cols - 2, a->sims[i].blown ? SW_STYLE_BAD : SW_STYLE_STATUS, f, n);
    }
    int st, n = meter_fields(a, f, &st);
    /* the run's state: PAUSED said whenever it is (every restart leaves
     * it so: app.c, restart_run); "running" only where it costs the meter
     * nothing */
    if (a->paused)
        field(f, &n, 10, "PAUSED", NULL);
    else if (a->slowmo > 1.05) {
        char b[48], s[24];
        snprintf(b, sizeof b, "slow motion x%.1f", a->slowmo);
        snprintf(s, sizeof s, "slow x%.1f", a->slowmo);
        field(f, &n, 7, b, s);
    } else if (!a->sims[0].blown)
        field(f, &n, 1, "running", NULL);
    if (a->speed != 1) {
        char b[48];
        snprintf(b, sizeof b, "speed x%g", a->speed);
        field(f, &n, 6, b, NULL);
    }
    if (a->record_path[0]) {
        char b[300];
        snprintf(b, sizeof b, "REC %.90s", a->record_path);
        field(f, &n, 5, b, "REC");
    }
    fit_line(scr, row++, 0, scr->cols, st, f, n);
    for (int i = 0; i < nmsg; i++)
        sw_screen_text(scr, row++, 0, scr->cols, SW_STYLE_TEXT, msg[i]);
    if (!nmsg)
        row++;
    n = 0;
    key_fields(a, side, f, &n);
    fit_line(scr, row, 0, scr->cols, side && side->notice ? SW_STYLE_OK : SW_STYLE_DIM, f, n);
    return rows;
}

/* ---- the frame ---------------------------------------------------------------------- */

void sw_frame_compose(sw_frame *f, sw_app *a, const sw_side *side, sw_screen *scr)
{
    sw_screen_clear(scr);
    if (scr->cols < SW_MIN_COLS || scr->rows < SW_MIN_ROWS) {
        char m[160];
        snprintf(m, sizeof m, "terminal too small: %dx%d, stepwise needs %dx%d. Enlarge the window, or press q to "
                 "quit.", scr->cols, scr->rows, SW_MIN_COLS, SW_MIN_ROWS);
        sw_screen_wrapped(scr, 0, 0, scr->cols, scr->rows, SW_STYLE_BAD, m);
        return;
    }
    int bottom = status_block(a, side, scr, 1);
    int pic_rows = scr->rows - bottom, pic_cols = scr->cols, side_w = 0;
    if (side && side->nlines > 0 && side->full) {
        /* the reading mode: the text over the whole width, no picture */
        sw_side_draw(side, scr, 0, 1, pic_rows, scr->cols - 2);
        status_block(a, side, scr, 0);
        if (a->help)
            sw_draw_help(a, scr, 0, 0, pic_rows, scr->cols, 1);
        return;
    }
    if (side && side->nlines > 0) {
        side_w = side->width > 0 ? side->width : scr->cols / 2;
        if (scr->cols - side_w - 1 < 30)
            side_w = scr->cols - 31;
        pic_cols = scr->cols - side_w - 1;
    }
    /* The scene keeps SCENE_MIN_ROWS (or all it has); the graph takes up to
     * 8 rows of the rest, and is left out, with a note, when that leaves it
     * fewer than GRAPH_MIN_ROWS. */
    int graph_h = 0, graph_squeezed = 0;
    if (a->graph) {
        graph_h = pic_rows >= 20 ? 8 : pic_rows / 3;
        if (pic_rows - graph_h < SCENE_MIN_ROWS)
            graph_h = pic_rows - SCENE_MIN_ROWS;
        if (graph_h < GRAPH_MIN_ROWS) {
            graph_h = 0;
            graph_squeezed = 1;
        }
    }
    int view_rows = pic_rows - graph_h;
    camera(f, a);
    if (a->stages_open && a->view == SW_VIEW_SCENE)
        sw_draw_stages(f, a, scr, 0, 0, view_rows, pic_cols);
    else if (a->view == SW_VIEW_PHASE)
        draw_phase(f, a, scr, 0, 0, view_rows, pic_cols);
    else if (a->view == SW_VIEW_REGION)
        draw_region(f, a, scr, 0, 0, view_rows, pic_cols);
    else if (a->compare && a->lanes && a->nsims > 1 && lanes_readable(a, view_rows, pic_cols))
        draw_lanes(f, a, scr, 0, 0, view_rows, pic_cols);
    else {
        /* the scene, and at its foot what each glyph drawn is (render/legend.c) */
        draw_sims(f, a, &f->canvas, pic_cols, view_rows, 0, a->nsims - 1);
        scene_with_legend(f, a, scr, view_rows, pic_cols);
        if (a->sims[0].blown)
            blown_banner(scr, &a->sims[0], 0, 0, pic_cols, view_rows);
    }
    if (a->view == SW_VIEW_SCENE && !a->stages_open && a->compare && a->lanes && a->nsims > 1 &&
        !lanes_readable(a, view_rows, pic_cols)) {
        /* lanes too small to read: overlaid, and said */
        sw_field fl[1];
        int n = 0;
        char buf[96];
        snprintf(buf, sizeof buf, "(lanes need %d columns or %d rows each: overlaid here)", LANE_MIN_COLS,
                 LANE_MIN_ROWS);
        field(fl, &n, 1, buf, "(lanes: no room, overlaid)");
        fit_line(scr, 0, 0, pic_cols, SW_STYLE_DIM, fl, n);
    }
    if (graph_h > 0)
        sw_draw_graph(f, a, scr, view_rows, 0, graph_h, pic_cols);
    else if (graph_squeezed) {
        sw_field fl[1];
        int n = 0;
        field(fl, &n, 1, "(graph: the window is too short for it)", "(no room for the graph)");
        sw_screen_fill(scr, view_rows - 1, 0, 1, pic_cols, SW_STYLE_TEXT);
        fit_line(scr, view_rows - 1, 0, pic_cols, SW_STYLE_DIM, fl, n);
    }
    /* overlays above the status block; over the lesson's pane only while
     * no question waits there (an overlay never hides the quiz) */
    int over_cols = side_w > 0 && side->question_open ? pic_cols : scr->cols;
    if (a->help && a->help > sw_help_pages(pic_rows, over_cols, side != NULL))
        a->help = 0; /* past the last page: closed */
    /* the work-precision plot stays in the picture's place beside a lesson:
     * the page's text (its table) is what the plot is read against */
    /* (the parameter panel stays over the picture: the goals beside it
     * say what the values are for) */
    int overlay = (a->workprec && a->bench && side_w == 0) || (a->panel && side_w == 0) || a->help;
    /* The pane starts two columns right of the picture (a single blank
     * column reads as a space between words); its text is wrapped to one
     * column less than its width. An overlay that reaches over the pane
     * claims all of it: no fragment of the page shows beside the box. */
    if (side_w > 0 && !(overlay && over_cols > pic_cols))
        sw_side_draw(side, scr, 0, pic_cols + 2, pic_rows, side_w - 1);
    status_block(a, side, scr, 0);
    if (a->workprec && a->bench)
        sw_draw_workprec(a, scr, 0, 0, pic_rows, side_w > 0 ? pic_cols : scr->cols);
    if (a->panel)
        sw_draw_panel(a, scr, 0, 0, pic_rows, side_w > 0 ? pic_cols : over_cols);
    if (a->help)
        sw_draw_help(a, scr, 0, 0, pic_rows, over_cols, side != NULL);
}
