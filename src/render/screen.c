/* The screen grid and the frame composer: where the scene, the status
 * lines, the stability meter, the graph and the overlays go. Pure C; the
 * layout is the same in the terminal, in `--ascii` frames and in tests. */
#include "render/screen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lab/bench.h"
#include "stepwise/base.h"
#include "util/utf8.h"

int sw_screen_init(sw_screen *s, int cols, int rows, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (cols < 1 || rows < 1 || cols > SW_CANVAS_MAX_SIDE || rows > SW_CANVAS_MAX_SIDE) {
        snprintf(err, errlen, "screen size %dx%d is outside 1..%d per side", cols, rows, SW_CANVAS_MAX_SIDE);
        return SW_EINVAL;
    }
    size_t n = (size_t)cols * (size_t)rows;
    s->cp = malloc(n * sizeof *s->cp);
    s->style = malloc(n);
    s->fade = malloc(n);
    if (!s->cp || !s->style || !s->fade) {
        sw_screen_free(s);
        snprintf(err, errlen, "out of memory for a %dx%d screen", cols, rows);
        return SW_ENOMEM;
    }
    s->cols = cols;
    s->rows = rows;
    sw_screen_clear(s);
    return SW_OK;
}

void sw_screen_free(sw_screen *s)
{
    free(s->cp);
    free(s->style);
    free(s->fade);
    memset(s, 0, sizeof *s);
}

void sw_screen_clear(sw_screen *s)
{
    size_t n = (size_t)s->cols * (size_t)s->rows;
    for (size_t i = 0; i < n; i++)
        s->cp[i] = ' ';
    memset(s->style, SW_STYLE_TEXT, n);
    memset(s->fade, 0, n);
}

int sw_screen_text(sw_screen *s, int row, int col, int width, int style, const char *text)
{
    if (row < 0 || row >= s->rows || col >= s->cols || !text)
        return 0;
    const unsigned char *p = (const unsigned char *)text;
    int n = 0;
    while (*p && n < width) {
        uint32_t c = sw_utf8_next(&p);
        int x = col + n++;
        if (x < 0)
            continue;
        if (x >= s->cols)
            break;
        size_t i = (size_t)row * (size_t)s->cols + (size_t)x;
        s->cp[i] = c < 0x20 ? ' ' : c;
        s->style[i] = (unsigned char)style;
        s->fade[i] = 0;
    }
    return n;
}

void sw_screen_fill(sw_screen *s, int row, int col, int height, int width, int style)
{
    for (int r = row; r < row + height; r++)
        for (int c = col; c < col + width; c++)
            if (r >= 0 && r < s->rows && c >= 0 && c < s->cols) {
                size_t i = (size_t)r * (size_t)s->cols + (size_t)c;
                s->cp[i] = ' ';
                s->style[i] = (unsigned char)style;
                s->fade[i] = 0;
            }
}

size_t sw_screen_to_text(const sw_screen *s, char *buf, size_t len)
{
    size_t out = 0;
    for (int r = 0; r < s->rows; r++) {
        int last = s->cols - 1;
        while (last >= 0 && s->cp[(size_t)r * (size_t)s->cols + (size_t)last] == ' ')
            last--;
        for (int c = 0; c <= last; c++) {
            char u[4];
            int k = sw_utf8_encode(s->cp[(size_t)r * (size_t)s->cols + (size_t)c], u);
            if (out + (size_t)k + 2 > len) {
                if (len)
                    buf[0] = '\0';
                return 0;
            }
            memcpy(buf + out, u, (size_t)k);
            out += (size_t)k;
        }
        if (out + 2 > len) {
            if (len)
                buf[0] = '\0';
            return 0;
        }
        buf[out++] = '\n';
    }
    buf[out] = '\0';
    return out;
}

int sw_frame_init(sw_frame *f, char *err, size_t errlen)
{
    memset(f, 0, sizeof *f);
    if (sw_canvas_init(&f->canvas, 80, 20, err, errlen) != SW_OK)
        return SW_ENOMEM;
    if (sw_canvas_init(&f->plot, 40, 6, err, errlen) != SW_OK) {
        sw_canvas_free(&f->canvas);
        return SW_ENOMEM;
    }
    return SW_OK;
}

void sw_frame_free(sw_frame *f)
{
    sw_canvas_free(&f->canvas);
    sw_canvas_free(&f->plot);
    for (int i = 0; i < SW_APP_SIMS; i++)
        sw_trails_free(&f->trails[i]);
    f->have_trails = 0;
}

void sw_frame_forget(sw_frame *f)
{
    f->view_scene = NULL;
    for (int i = 0; f->have_trails && i < SW_APP_SIMS; i++)
        sw_trails_clear(&f->trails[i]);
}

/* Trails follow at most this many particles, for this many frames. */
#define TRAIL_POINTS 2000
#define TRAIL_FRAMES 90

void sw_frame_push_trails(sw_frame *f, sw_app *a)
{
    if (!a->trails)
        return;
    if (!f->have_trails) {
        char err[SW_ERRLEN];
        for (int i = 0; i < SW_APP_SIMS; i++)
            if (sw_trails_init(&f->trails[i], TRAIL_POINTS, TRAIL_FRAMES, err, sizeof err) != SW_OK)
                return;
        f->have_trails = 1;
    }
    for (int i = 0; i < a->nsims; i++)
        sw_trails_push_system(&f->trails[i], &a->sims[i].sys, a->sims[i].sys.y, a->sims[i].t);
}

/* Copy a canvas onto the screen at (row0, col0). */
static void blit(sw_screen *scr, const sw_canvas *c, int row0, int col0)
{
    for (int r = 0; r < c->rows; r++)
        for (int k = 0; k < c->cols; k++) {
            int y = row0 + r, x = col0 + k;
            if (y < 0 || y >= scr->rows || x < 0 || x >= scr->cols)
                continue;
            size_t i = (size_t)y * (size_t)scr->cols + (size_t)x;
            scr->cp[i] = sw_canvas_codepoint(c, k, r);
            scr->style[i] = (unsigned char)sw_canvas_style(c, k, r);
            scr->fade[i] = (unsigned char)sw_canvas_fade(c, k, r);
        }
}

static const uint32_t sim_glyph[SW_APP_SIMS] = { SW_GLYPH_MAIN, SW_GLYPH_COMPARE1, SW_GLYPH_COMPARE2 };
static const int sim_style[SW_APP_SIMS] = { SW_STYLE_MAIN, SW_STYLE_COMPARE1, SW_STYLE_COMPARE2 };

static void draw_scene(sw_frame *f, sw_app *a, int rows, int cols)
{
    char err[SW_ERRLEN];
    sw_canvas *c = &f->canvas;
    if (c->cols != cols || c->rows != rows)
        sw_canvas_resize(c, cols, rows, err, sizeof err);
    sw_canvas_set_mode(c, a->braille ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII);
    const sw_sim *main = &a->sims[0];
    if (f->view_scene != a->scene || main->t == 0) {
        f->view = a->scene->view(&main->sys);
        f->view_scene = a->scene;
    }
    sw_view_follow(&f->view, main->sys.y, main->sys.n, 0.25);
    sw_canvas_set_view(c, &f->view, err, sizeof err);
    sw_canvas_clear(c);
    if (a->trails && f->have_trails)
        for (int i = a->nsims - 1; i >= 0; i--)
            sw_canvas_draw_trails(c, &f->trails[i], SW_STYLE_TRAIL);
    const double *g = a->ghost ? sw_app_ghost(a) : NULL;
    if (g)
        sw_canvas_draw_system(c, &main->sys, g, main->t, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    for (int i = a->nsims - 1; i >= 0; i--)
        sw_canvas_draw_system(c, &a->sims[i].sys, a->sims[i].sys.y, a->sims[i].t, sim_glyph[i], sim_style[i]);
}

/* The stability meter: the stiffest mode's |λ|·Δt against the method's
 * limit on the current linearisation (a bar), and the growth per step ρ of
 * the worst mode under this method at this Δt, with enough digits that a
 * neutral ρ = 1 reads as one. When the run's energy grows although every
 * mode is stable, the line says so: that growth is nonlinear. */
static void meter(sw_app *a, char *buf, size_t len, int *style)
{
    sw_app_meter m;
    *style = SW_STYLE_STATUS;
    if (!sw_app_stability(a, &m)) {
        if (a->sims[0].method->flags & SW_ADAPTIVE)
            snprintf(buf, len, "%s chooses its own steps: no fixed-step limit", a->sims[0].method->name);
        else
            buf[0] = '\0';
        return;
    }
    char lim[48], bar[16] = "";
    double ldt = m.stiff * a->dt;
    if (m.unbounded)
        snprintf(lim, sizeof lim, "stable at any dt");
    else if (m.limit > 0) {
        snprintf(lim, sizeof lim, "limit %.3g", m.stiff * m.limit);
        int fill = (int)fmin(10.0, fmax(0.0, floor(10.0 * a->dt / m.limit + 1e-9)));
        bar[0] = '[';
        for (int i = 0; i < 10; i++)
            bar[i + 1] = i < fill ? '#' : '.';
        bar[11] = ']';
        bar[12] = '\0';
    } else
        snprintf(lim, sizeof lim, "no stable dt");
    const char *verdict = m.grows ? "GROWS"
                          : m.slow ? "grows, too slowly to see"
                          : m.growth < 1 - SW_TRUTH_NEUTRAL ? "decays" : "neutral";
    int run_grows = a->watch.verdict != SW_WATCH_STEADY;
    snprintf(buf, len, "|L|dt=%.3g %s%s%s  x%.6f/step %s%s", ldt, bar, *bar ? " " : "", lim, m.growth, verdict,
             run_grows && !m.grows ? "; run's energy grows: nonlinear" : "");
    if (m.grows || run_grows || (m.limit > 0 && !m.unbounded && a->dt > 0.9 * m.limit))
        *style = SW_STYLE_WARN;
}

static void draw_graph(sw_frame *f, sw_app *a, sw_screen *scr, int row, int col, int height, int width)
{
    char err[SW_ERRLEN];
    double tmin = INFINITY, tmax = -INFINITY, vmin = INFINITY, vmax = -INFINITY;
    for (int i = 0; i < a->nsims; i++)
        for (int k = 0; k < a->series[i].len; k++) {
            double t = a->series[i].t[k], v = a->series[i].v[k];
            if (!isfinite(t) || !isfinite(v))
                continue;
            tmin = fmin(tmin, t), tmax = fmax(tmax, t);
            vmin = fmin(vmin, v), vmax = fmax(vmax, v);
        }
    int has_energy = isfinite(sw_sim_energy_drift(&a->sims[0]));
    char title[96];
    snprintf(title, sizeof title, " %s against t ", has_energy ? "energy drift %" : "error");
    sw_screen_fill(scr, row, col, height, width, SW_STYLE_TEXT);
    sw_screen_text(scr, row, col, width, SW_STYLE_TITLE, title);
    if (!(tmax > tmin)) {
        sw_screen_text(scr, row + 1, col, width, SW_STYLE_DIM, " (collecting samples...)");
        return;
    }
    if (!(vmax > vmin))
        vmax = vmin + 1e-12 + fabs(vmin) * 1e-6;
    char lab[32];
    snprintf(lab, sizeof lab, "%.3g", vmax);
    sw_screen_text(scr, row + 1, col, 10, SW_STYLE_DIM, lab);
    snprintf(lab, sizeof lab, "%.3g", vmin);
    sw_screen_text(scr, row + height - 1, col, 10, SW_STYLE_DIM, lab);
    int pw = width - 11, ph = height - 1;
    if (pw < 4 || ph < 2)
        return;
    if (f->plot.cols != pw || f->plot.rows != ph)
        sw_canvas_resize(&f->plot, pw, ph, err, sizeof err);
    /* Fill the plot box exactly: undo the canvas's aspect correction by
     * scaling values into a view shaped like the box. */
    sw_view v = { 0, (double)pw, 0, 2.0 * ph };
    sw_canvas_set_view(&f->plot, &v, err, sizeof err);
    sw_canvas_clear(&f->plot);
    for (int i = a->nsims - 1; i >= 0; i--) {
        const sw_series *s = &a->series[i];
        for (int k = 1; k < s->len; k++) {
            double x0 = (s->t[k - 1] - tmin) / (tmax - tmin) * (pw - 1e-9), x1 = (s->t[k] - tmin) / (tmax - tmin) * (pw - 1e-9);
            double y0 = (s->v[k - 1] - vmin) / (vmax - vmin) * (2.0 * ph - 1e-9), y1 = (s->v[k] - vmin) / (vmax - vmin) * (2.0 * ph - 1e-9);
            sw_canvas_line(&f->plot, x0, y0, x1, y1, sim_glyph[i], sim_style[i]);
        }
    }
    blit(scr, &f->plot, row + 1, col + 11);
}

/* A boxed overlay of lines, centred; lines may be NULL-terminated early. */
static void overlay(sw_screen *scr, const char *title, const char *const *lines, int n, int style)
{
    int w = (int)strlen(title) + 4;
    for (int i = 0; i < n; i++)
        if ((int)strlen(lines[i]) + 4 > w)
            w = (int)strlen(lines[i]) + 4;
    if (w > scr->cols)
        w = scr->cols;
    int h = n + 2 > scr->rows ? scr->rows : n + 2;
    int r0 = (scr->rows - h) / 2, c0 = (scr->cols - w) / 2;
    sw_screen_fill(scr, r0, c0, h, w, style);
    sw_screen_text(scr, r0, c0 + 2, w - 4, SW_STYLE_TITLE, title);
    for (int i = 0; i < n && i < h - 2; i++)
        sw_screen_text(scr, r0 + 1 + i, c0 + 2, w - 4, style, lines[i]);
}

/* The help screen, generated from the one list of controls. */
static void help_overlay(sw_screen *scr, int in_lesson)
{
    static char buf[48][96];
    const char *lines[48];
    int n = 0, count;
    const sw_control *controls = sw_controls(&count);
    for (int i = 0; i < count && n < 46; i++) {
        const sw_control *c = &controls[i];
        int shown = c->context == SW_CTX_PLAY || (c->context == SW_CTX_LESSON && in_lesson);
        if (!c->help_keys || !shown)
            continue;
        snprintf(buf[n], sizeof buf[n], "%-13s %s", c->help_keys, c->help);
        lines[n] = buf[n];
        n++;
    }
    /* what the numbers on the status line and the meter mean */
    static const char *const terms[] = {
        "energy: change since t=0, % of the energy of the motion",
        "        (above the resting state; an orbit: of |E(0)|)",
        "error:  largest |y - true y| over positions and velocities",
        "|L|dt:  stiffest eigenvalue of the linearisation, times dt",
        "x.../step: growth per step of the worst mode (1: neutral)",
    };
    for (size_t i = 0; i < sizeof terms / sizeof terms[0] && n < 46; i++)
        lines[n++] = terms[i];
    snprintf(buf[n], sizeof buf[n], "%s", "press ? again to close");
    lines[n] = buf[n];
    n++;
    overlay(scr, "keys", lines, n, SW_STYLE_TEXT);
}

static void panel_overlay(sw_app *a, sw_screen *scr)
{
    static char buf[SW_MAX_PARAMS + 1][96];
    const char *lines[SW_MAX_PARAMS + 1];
    int n = 0;
    for (int i = 0; i < a->scene->nparams; i++, n++) {
        const sw_param *p = &a->scene->params[i];
        snprintf(buf[n], sizeof buf[n], "%s %-8s = %-10g %-7s [%g, %g]", i == a->param_sel ? ">" : " ", p->name,
                 a->p[i], p->unit, p->min, p->max);
        lines[n] = buf[n];
    }
    snprintf(buf[n], sizeof buf[n], "Up/Down choose, Left/Right change (restarts), p closes");
    lines[n] = buf[n];
    n++;
    overlay(scr, a->scene->name, lines, n, SW_STYLE_TEXT);
}

/* How each kind of side-pane line looks. */
static int side_style(sw_side_kind kind)
{
    static const int styles[] = {
        [SW_SIDE_TEXT] = SW_STYLE_TEXT, [SW_SIDE_VERBATIM] = SW_STYLE_STATUS, [SW_SIDE_TITLE] = SW_STYLE_TITLE,
        [SW_SIDE_OK] = SW_STYLE_OK, [SW_SIDE_BAD] = SW_STYLE_BAD, [SW_SIDE_DIM] = SW_STYLE_DIM,
        [SW_SIDE_HINT] = SW_STYLE_WARN,
    };
    return kind >= 0 && kind < (int)(sizeof styles / sizeof styles[0]) ? styles[kind] : SW_STYLE_TEXT;
}

void sw_frame_compose(sw_frame *f, sw_app *a, const sw_side *side, sw_screen *scr)
{
    sw_screen_clear(scr);
    if (scr->cols < SW_MIN_COLS || scr->rows < SW_MIN_ROWS) {
        char m[96];
        snprintf(m, sizeof m, "terminal too small: %dx%d, stepwise needs %dx%d", scr->cols, scr->rows,
                 SW_MIN_COLS, SW_MIN_ROWS);
        sw_screen_text(scr, 0, 0, scr->cols, SW_STYLE_BAD, m);
        sw_screen_text(scr, 1, 0, scr->cols, SW_STYLE_DIM, "enlarge the window, or press q to quit");
        return;
    }
    int status_rows = a->nsims + 3;
    int scene_cols = scr->cols, scene_rows = scr->rows - status_rows, side_col = -1, side_row = -1;
    int side_w = 0, side_h = 0;
    if (side && side->nlines > 0) {
        if (side->width > 0 && scr->cols - side->width >= 40) {
            side_w = side->width;
            scene_cols = scr->cols - side_w - 1;
            side_col = scene_cols + 1;
            side_row = 0;
            side_h = scene_rows;
        } else {
            side_h = scene_rows / 2;
            scene_rows -= side_h;
            side_row = scene_rows;
            side_col = 0;
            side_w = scr->cols;
        }
    }
    int graph_h = a->graph ? (scene_rows >= 20 ? 8 : scene_rows / 3) : 0;
    draw_scene(f, a, scene_rows - graph_h, scene_cols);
    blit(scr, &f->canvas, 0, 0);
    if (graph_h > 0)
        draw_graph(f, a, scr, scene_rows - graph_h, 0, graph_h, scene_cols);
    if (side_w > 0) {
        /* Too long for the pane: scroll, and say there is more. */
        int first = side->scroll ? *side->scroll : 0, max_first = side->nlines - side_h;
        first = first > max_first ? max_first : first;
        first = first < 0 ? 0 : first;
        if (side->scroll)
            *side->scroll = first;
        for (int i = 0; first + i < side->nlines && i < side_h; i++)
            sw_screen_text(scr, side_row + i, side_col, side_w,
                           side_style(side->kinds ? side->kinds[first + i] : SW_SIDE_TEXT), side->lines[first + i]);
        if (first > 0)
            sw_screen_text(scr, side_row, side_col + side_w - 9, 9, SW_STYLE_DIM, "(Up: more)");
        if (first < max_first)
            sw_screen_text(scr, side_row + side_h - 1, side_col + side_w - 11, 11, SW_STYLE_DIM, "(Down: more)");
    }

    /* status block */
    int row = scr->rows - status_rows;
    char line[512];
    for (int i = 0; i < a->nsims; i++) {
        char glyph[4] = { (char)sim_glyph[i], ' ', '\0' };
        sw_app_status(a, i, line, sizeof line);
        sw_screen_text(scr, row, 0, 2, sim_style[i], glyph);
        sw_screen_text(scr, row++, 2, scr->cols - 2, a->sims[i].blown ? SW_STYLE_BAD : SW_STYLE_STATUS, line);
    }
    int st;
    meter(a, line, sizeof line, &st);
    size_t used = strlen(line);
    if (a->paused)
        snprintf(line + used, sizeof line - used, "%sPAUSED", used ? "   " : "");
    else if (a->slowmo > 1.05)
        snprintf(line + used, sizeof line - used, "%sslow motion x%.1f", used ? "   " : "", a->slowmo);
    used = strlen(line);
    if (a->speed != 1)
        snprintf(line + used, sizeof line - used, "%sspeed x%g", used ? "   " : "", a->speed);
    if (a->record_path[0]) {
        used = strlen(line);
        snprintf(line + used, sizeof line - used, "%sREC %s", used ? "   " : "", a->record_path);
    }
    sw_screen_text(scr, row++, 0, scr->cols, st, line);
    sw_screen_text(scr, row++, 0, scr->cols, SW_STYLE_TEXT, a->message);
    sw_screen_text(scr, row, 0, scr->cols, SW_STYLE_DIM,
                   side ? "n next page  h hint  i method  +/- dt  space pause  r reset  ? help  q quit"
                        : "i method  +/- dt  space pause  r reset  c compare  g ghost  ? help  q quit");

    const sw_sim *m = &a->sims[0];
    if (m->blown) {
        snprintf(line, sizeof line, " BLOWN UP at step %ld, t = %.4g: %s. Press r to reset. ", m->blow_step,
                 m->blow_time, m->blow_reason);
        int w = (int)strlen(line) < scene_cols ? (int)strlen(line) : scene_cols;
        sw_screen_text(scr, (scene_rows - graph_h) / 2, (scene_cols - w) / 2, w, SW_STYLE_BAD, line);
    }
    if (a->workprec && a->bench) {
        static char plot[(120 + 1) * 40 + 1];
        int w = scr->cols - 4 < 120 ? scr->cols - 4 : 120, h = scr->rows - 4 < 40 ? scr->rows - 4 : 40;
        if (w >= 40 && h >= 10 &&
            sw_bench_plot(a->bench, a->workprec == 1 ? SW_BENCH_X_EVALS : SW_BENCH_X_TIME, plot, w, h) == SW_OK) {
            const char *lines[40];
            int n = 0;
            for (char *p = plot; *p && n < h; n++) {
                lines[n] = p;
                char *nl = strchr(p, '\n');
                if (!nl)
                    break;
                *nl = '\0';
                p = nl + 1;
            }
            overlay(scr, "work-precision (w)", lines, n, SW_STYLE_TEXT);
        }
    }
    if (a->panel)
        panel_overlay(a, scr);
    if (a->help)
        help_overlay(scr, side != NULL);
}
