/* The composer's pieces that are text first: the graph of energy drift (or
 * error) with its axes and units, the paged help screen generated from the
 * one list of controls and the parameter panel (the work-precision plot is
 * render/workprec.c). Every line is fitted or wrapped to the box it goes in. */
#include "render/screen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/text.h"
#include "stepwise/stepwise.h"

static const uint32_t sim_glyph[SW_APP_SIMS] = { SW_GLYPH_MAIN, SW_GLYPH_COMPARE1, SW_GLYPH_COMPARE2 };
static const int sim_style[SW_APP_SIMS] = { SW_STYLE_MAIN, SW_STYLE_COMPARE1, SW_STYLE_COMPARE2 };

/* Where two or more runs' curves take the same cell of the graph. */
#define SW_GLYPH_MERGED '*'

int sw_screen_wrapped(sw_screen *scr, int row, int col, int width, int max, int style, const char *text)
{
    static char lines[8][SW_TEXT_LINE];
    int n = sw_text_wrap(text, width, lines, 8);
    if (n > max) {
        scr->clipped++; /* lines left out are cut text too: the caller says less, or gives more rows */
        n = max;
    }
    if (n > 8)
        n = 8;
    for (int i = 0; i < n; i++)
        sw_screen_text(scr, row + i, col, width, style, lines[i]);
    return n;
}

/* A box as wide as the widest of size[0..nsize) (or of lines when size is
 * NULL) needs, centred, its whole rectangle cleared. */
static void box(sw_screen *scr, int row, int col, int height, int width, const char *title, const char *const *lines,
                int n, int style, const char *const *size, int nsize)
{
    if (!size) {
        size = lines;
        nsize = n;
    }
    int w = sw_text_cells(title) + 4;
    for (int i = 0; i < nsize; i++)
        if (sw_text_cells(size[i]) + 4 > w)
            w = sw_text_cells(size[i]) + 4;
    for (int i = 0; i < n; i++)
        if (sw_text_cells(lines[i]) + 4 > w)
            w = sw_text_cells(lines[i]) + 4;
    if (w > width)
        w = width;
    int h = n + 2 > height ? height : n + 2;
    int r0 = row + (height - h) / 2, c0 = col + (width - w) / 2;
    sw_screen_fill(scr, r0, c0, h, w, style);
    if (sw_text_cells(title) <= w - 4)
        sw_screen_text(scr, r0, c0 + 2, w - 4, SW_STYLE_TITLE, title);
    for (int i = 0; i < n && i < h - 2; i++)
        sw_screen_text(scr, r0 + 1 + i, c0 + 2, w - 4, style, lines[i]);
}

/* A boxed overlay of lines, centred in the rectangle, each line fitted to
 * its width (the caller wraps). */
static void sw_draw_box(sw_screen *scr, int row, int col, int height, int width, const char *title,
                        const char *const *lines, int n, int style)
{
    box(scr, row, col, height, width, title, lines, n, style, NULL, 0);
}

/* ---- the graph ---------------------------------------------------------------- */

/* The graph's value range: every run's, unless one run reaches more than
 * four times as far as all the others together (Euler's +1440 % beside
 * symplectic Euler's 3 % and backward Euler's -96 %): then the others'
 * (with 0), so that they do not share a row, and *off is the run left to
 * run past the edge (its farthest value in *far); -1 when none. */
static void graph_range(const sw_app *a, double *vmin, double *vmax, int *off, double *far)
{
    double lo[SW_APP_SIMS], hi[SW_APP_SIMS];
    *off = -1;
    *far = 0;
    *vmin = INFINITY, *vmax = -INFINITY;
    for (int i = 0; i < a->nsims; i++) {
        lo[i] = INFINITY, hi[i] = -INFINITY;
        for (int k = 0; k < a->series[i].len; k++) {
            double t = a->series[i].t[k], v = a->series[i].v[k];
            if (isfinite(t) && isfinite(v))
                lo[i] = fmin(lo[i], v), hi[i] = fmax(hi[i], v);
        }
        *vmin = fmin(*vmin, lo[i]), *vmax = fmax(*vmax, hi[i]);
    }
    if (a->nsims < 2)
        return;
    int big = 0;
    for (int i = 1; i < a->nsims; i++)
        if (fmax(fabs(lo[i]), fabs(hi[i])) > fmax(fabs(lo[big]), fabs(hi[big])))
            big = i;
    double rlo = 0, rhi = 0;
    for (int i = 0; i < a->nsims; i++)
        if (i != big && lo[i] <= hi[i])
            rlo = fmin(rlo, lo[i]), rhi = fmax(rhi, hi[i]);
    if (rhi > rlo && *vmax - *vmin > 4 * (rhi - rlo)) {
        *off = big;
        *far = fabs(hi[big]) > fabs(lo[big]) ? hi[big] : lo[big];
        *vmin = rlo, *vmax = rhi;
    }
}

void sw_draw_graph(sw_frame *f, sw_app *a, sw_screen *scr, int row, int col, int height, int width)
{
    char err[SW_ERRLEN];
    double tmin = INFINITY, tmax = -INFINITY, vmin, vmax, far;
    int off;
    for (int i = 0; i < a->nsims; i++)
        for (int k = 0; k < a->series[i].len; k++) {
            double t = a->series[i].t[k], v = a->series[i].v[k];
            if (isfinite(t) && isfinite(v))
                tmin = fmin(tmin, t), tmax = fmax(tmax, t);
        }
    graph_range(a, &vmin, &vmax, &off, &far);
    int has_energy = isfinite(sw_sim_energy_drift(&a->sims[0]));
    sw_field title[4] = {
        { "", "", 5 }, { "", "", 2 }, { "", "", 1 }, { "", "", 4 },
    };
    if (off >= 0) {
        snprintf(title[3].full, sizeof title[3].full, "%c runs past the %s, to %.3g", (char)sim_glyph[off],
                 far > 0 ? "top" : "bottom", far);
        snprintf(title[3].brief, sizeof title[3].brief, "%c off %s: %.3g", (char)sim_glyph[off],
                 far > 0 ? "top" : "foot", far);
    }
    snprintf(title[0].full, sizeof title[0].full, "%s", has_energy ? "energy drift (%)" : "error");
    snprintf(title[1].full, sizeof title[1].full, "against time t (s)");
    snprintf(title[1].brief, sizeof title[1].brief, "against t (s)");
    /* both axes are linear; the dashed row, when the values straddle it, is 0 */
    int zero_line = vmin < 0 && vmax > 0;
    snprintf(title[2].full, sizeof title[2].full, "%s", zero_line ? "(linear axes, --- is 0)" : "(linear axes)");
    snprintf(title[2].brief, sizeof title[2].brief, "%s", zero_line ? "--- is 0" : "(linear)");
    char line[SW_TEXT_LINE];
    sw_screen_fill(scr, row, col, height, width, SW_STYLE_TEXT);
    sw_text_fit(line, sizeof line, width, title, off >= 0 ? 4 : 3, " ");
    sw_screen_text(scr, row, col, width, SW_STYLE_TITLE, line);
    if (!(tmax > tmin)) {
        if (width >= 24)
            sw_screen_text(scr, row + 1, col, width, SW_STYLE_DIM, "(collecting samples...)");
        return;
    }
    if (!(vmax > vmin))
        vmax = vmin + 1e-12 + fabs(vmin) * 1e-6;
    const int lw = 9; /* "-1.23e+04" */
    int pw = width - lw - 1, ph = height - 2;
    if (pw < 4 || ph < 2)
        return;
    char lab[32];
    snprintf(lab, sizeof lab, "%.3g", vmax);
    sw_screen_text(scr, row + 1, col + lw - sw_text_cells(lab), lw, SW_STYLE_DIM, lab);
    snprintf(lab, sizeof lab, "%.3g", vmin);
    sw_screen_text(scr, row + ph, col + lw - sw_text_cells(lab), lw, SW_STYLE_DIM, lab);
    for (int r = 1; r <= ph; r++)
        sw_screen_text(scr, row + r, col + lw, 1, SW_STYLE_DIM, "|");
    /* the time axis: its ends, in seconds */
    snprintf(lab, sizeof lab, "%.3g", tmin);
    sw_screen_text(scr, row + height - 1, col + lw + 1, 10, SW_STYLE_DIM, lab);
    snprintf(lab, sizeof lab, "t=%.4g s", tmax);
    int lc = sw_text_cells(lab);
    if (lc < pw - 8)
        sw_screen_text(scr, row + height - 1, col + width - lc, lc, SW_STYLE_DIM, lab);
    if (f->plot.cols != pw || f->plot.rows != ph)
        sw_canvas_resize(&f->plot, pw, ph, err, sizeof err);
    /* Fill the plot box exactly: undo the canvas's aspect correction by
     * scaling values into a view shaped like the box. */
    sw_view v = { 0, (double)pw, 0, 2.0 * ph };
    sw_canvas_set_view(&f->plot, &v, err, sizeof err);
    sw_canvas_clear(&f->plot);
    if (vmin < 0 && vmax > 0) {
        double y0 = (0 - vmin) / (vmax - vmin) * (2.0 * ph - 1e-9);
        sw_canvas_line(&f->plot, 0, y0, pw, y0, '-', SW_STYLE_WALL);
    }
    /* Each series alone first, to learn which cells it takes; then every
     * cell shows its series' glyph, or SW_GLYPH_MERGED where two or more
     * lie on one another (no run hides behind another). */
    unsigned char *own = NULL;
    size_t cells = (size_t)pw * (size_t)ph;
    if (a->nsims > 1 && cells > f->graph_own_cap) {
        unsigned char *grown = realloc(f->graph_own, cells);
        if (grown) {
            f->graph_own = grown;
            f->graph_own_cap = cells;
        }
    }
    if (a->nsims > 1 && cells <= f->graph_own_cap) {
        own = f->graph_own;
        memset(own, 0, cells);
    }
    int merged = 0;
    for (int i = a->nsims - 1; i >= 0; i--) {
        const sw_series *s = &a->series[i];
        if (own)
            sw_canvas_clear(&f->plot);
        for (int k = 1; k < s->len; k++) {
            double x0 = (s->t[k - 1] - tmin) / (tmax - tmin) * (pw - 1e-9), x1 = (s->t[k] - tmin) / (tmax - tmin) * (pw - 1e-9);
            double y0 = (s->v[k - 1] - vmin) / (vmax - vmin) * (2.0 * ph - 1e-9), y1 = (s->v[k] - vmin) / (vmax - vmin) * (2.0 * ph - 1e-9);
            sw_canvas_line(&f->plot, x0, y0, x1, y1, sim_glyph[i], sim_style[i]);
        }
        for (int k = 0; own && k < pw * ph; k++)
            if (sw_canvas_codepoint(&f->plot, k % pw, k / pw) == sim_glyph[i])
                own[k] |= (unsigned char)(1u << i);
    }
    if (own) {
        sw_canvas_clear(&f->plot);
        if (vmin < 0 && vmax > 0) {
            double y0 = (0 - vmin) / (vmax - vmin) * (2.0 * ph - 1e-9);
            sw_canvas_line(&f->plot, 0, y0, pw, y0, '-', SW_STYLE_WALL);
        }
        for (int k = 0; k < pw * ph; k++) {
            if (!own[k])
                continue;
            int i = 0;
            while (!(own[k] & (1u << i)))
                i++;
            int many = (own[k] & (own[k] - 1)) != 0;
            merged += many;
            sw_canvas_put(&f->plot, k % pw, k / pw, many ? SW_GLYPH_MERGED : sim_glyph[i],
                          many ? SW_STYLE_GHOST : sim_style[i]);
        }
    }
    sw_screen_blit(scr, &f->plot, row + 1, col + lw + 1);
    if (merged) {
        /* the title line again, with what the merged glyph means */
        sw_field t3[4] = { title[0], title[1], { "", "", 3 }, title[3] };
        snprintf(t3[2].full, sizeof t3[2].full, "%c: runs on one another", SW_GLYPH_MERGED);
        snprintf(t3[2].brief, sizeof t3[2].brief, "%c: overlap", SW_GLYPH_MERGED);
        t3[2].prio = 3;
        sw_screen_fill(scr, row, col, 1, width, SW_STYLE_TEXT);
        sw_text_fit(line, sizeof line, width, t3, off >= 0 ? 4 : 3, " ");
        sw_screen_text(scr, row, col, width, SW_STYLE_TITLE, line);
    }
}

/* ---- help --------------------------------------------------------------------- */

#define HELP_LINES 160

/* The pick keys' help, from the integrator table and the keys' list: keys
 * "1-9  0  !" (as many as fit width) and every integrator with its key. */
static void pick_help(const sw_control *c, int width, char *keys, size_t keys_len, char *help, size_t help_len)
{
    int n = sw_integrator_count(), used;
    for (int i = 0; i < n; i++) /* a key for each: SW_PICK_KEY_COUNT >= built-ins + plugins */
        if (!c->keys[i]) {
            n = i;
            break;
        }
    /* every key in the column, run together past 0 ("1-9 0 !@#$%^"), or
     * cut with "+" where they do not fit: never left out unsaid (the help
     * text beside them names every one) */
    snprintf(keys, keys_len, n <= 9 ? "1-%d" : "1-9 0", n);
    for (int i = 10; i < n; i++) {
        size_t k = strlen(keys);
        int last = i == n - 1;
        if ((int)k + 1 + (i == 10) + (last ? 0 : 1) > width || k + 4 > keys_len) {
            snprintf(keys + k, keys_len - k, "+");
            break;
        }
        snprintf(keys + k, keys_len - k, "%s%c", i == 10 ? " " : "", c->keys[i]);
    }
    used = snprintf(help, help_len, "pick an integrator:");
    for (int i = 0; i < n && used > 0 && (size_t)used < help_len; i++)
        used += snprintf(help + used, help_len - (size_t)used, "%s %c:%s", i ? "," : "", c->keys[i],
                         sw_integrator_at(i)->name);
}

/* The help screen's lines for a box width wide: every control shown here,
 * then what the numbers and marks on screen mean; 0 when the box is too
 * narrow for help. */
static int help_lines(int width, int in_lesson, char (*buf)[SW_TEXT_LINE], const char **lines)
{
    int n = 0, count, inner = width - 4, key_w = 13;
    if (inner < 30)
        return 0;
    /* what the numbers on the status line, the meter and the picture's edges mean */
    static const struct { const char *keys, *help; } terms[] = {
        { "", "energy: change since t=0, % of the energy of the motion (above the resting state; an orbit: of |E(0)|)" },
        { "", "error: largest |y - true y| over positions and velocities" },
        { "", "stiffness·dt: the fastest rate |λ| of the system (an eigenvalue of its linearisation, the "
              "forces' straight-line fit near the state) times dt; 'of limit': the largest the method survives" },
        { "[###.......]", "dt as a share of that limit, one # per tenth: full at the limit" },
        { "", "growth x.../step: the largest factor by which one step scales any motion, a bound, often the "
              "slowest motion's (1: neutral, below: decays, above: GROWS; grows or decays slowly: too little to see in a "
              "run); "
              "wider: which mode, and the fastest's" },
        { "ev step", "events (a bounce, a crossing) stepped over; ev loc: located inside the step (x toggles)" },
        { "<  >  ^  v", "a particle past the picture's edge, on that side; the number beside the arrow (<1.42, "
                        "v43.1) is how far the farthest one is from the picture's centre (z zooms out, f follows)" },
    };
    const sw_control *controls = sw_controls(&count);
    char text[SW_TEXT_LINE], wrapped[16][SW_TEXT_LINE], pick_keys[32], pick_text[SW_TEXT_LINE];
    int nterms = (int)(sizeof terms / sizeof terms[0]);
    for (int i = 0; i < count + nterms; i++) {
        const char *keys, *help;
        if (i < count) {
            const sw_control *c = &controls[i];
            int shown = c->context == SW_CTX_PLAY || (c->context == SW_CTX_LESSON && in_lesson);
            if (!c->help_keys || !shown)
                continue;
            keys = c->help_keys;
            help = c->help;
            if (c->action == SW_ACT_PICK_METHOD) {
                pick_help(c, key_w, pick_keys, sizeof pick_keys, pick_text, sizeof pick_text);
                keys = pick_keys;
                help = pick_text;
            }
        } else {
            keys = terms[i - count].keys;
            help = terms[i - count].help;
        }
        /* the help text wraps beside its keys */
        int k = sw_text_wrap(help, inner - key_w - 1, wrapped, 16);
        for (int j = 0; j < k && j < 16 && n < HELP_LINES; j++) {
            snprintf(text, sizeof text, "%-*s %.400s", key_w, j == 0 ? keys : "", wrapped[j]);
            memcpy(buf[n], text, sizeof text);
            lines[n] = buf[n];
            n++;
        }
    }
    return n;
}

int sw_help_pages(int height, int width, int in_lesson)
{
    static char buf[HELP_LINES][SW_TEXT_LINE];
    const char *lines[HELP_LINES];
    int n = help_lines(width, in_lesson, buf, lines), per_page = height - 3;
    if (n == 0 || height < 5)
        return 0;
    return (n + per_page - 1) / per_page;
}

void sw_draw_help(sw_app *a, sw_screen *scr, int row, int col, int height, int width, int in_lesson)
{
    static char buf[HELP_LINES][SW_TEXT_LINE];
    const char *lines[HELP_LINES + 1];
    int n = help_lines(width, in_lesson, buf, lines);
    if (n == 0 || height < 5) {
        a->help = 0;
        return;
    }
    int per_page = height - 3, pages = (n + per_page - 1) / per_page;
    if (a->help > pages) {
        a->help = 0; /* past the last page: closed */
        return;
    }
    int first = (a->help - 1) * per_page, shown = n - first < per_page ? n - first : per_page;
    static char footer[64];
    snprintf(footer, sizeof footer, a->help < pages ? "? next page (%d/%d)" : "? closes (%d/%d)", a->help, pages);
    const char *page[HELP_LINES + 1];
    for (int i = 0; i < shown; i++)
        page[i] = lines[first + i];
    page[shown] = footer;
    /* every page as wide as the widest, so turning a page never shows what is under it */
    box(scr, row, col, height, width, "keys", page, shown + 1, SW_STYLE_TEXT, lines, n);
}

/* ---- the parameter panel -------------------------------------------------------- */

void sw_draw_panel(sw_app *a, sw_screen *scr, int row, int col, int height, int width)
{
    static char buf[SW_MAX_PARAMS + 4][SW_TEXT_LINE];
    const char *lines[SW_MAX_PARAMS + 4];
    int n = 0;
    for (int i = 0; i < a->scene->nparams; i++, n++) {
        const sw_param *p = &a->scene->params[i];
        sw_field f[3] = { { "", "", 10 }, { "", "", 3 }, { "", "", 2 } };
        snprintf(f[0].full, sizeof f[0].full, "%s %-8s = %-10g", i == a->param_sel ? ">" : " ", p->name, a->p[i]);
        snprintf(f[0].brief, sizeof f[0].brief, "%s %s = %g", i == a->param_sel ? ">" : " ", p->name, a->p[i]);
        snprintf(f[1].full, sizeof f[1].full, "%-7s", p->unit);
        snprintf(f[2].full, sizeof f[2].full, "[%g, %g]", p->min, p->max);
        sw_text_fit(buf[n], sizeof buf[n], width - 4, f, 3, " ");
        lines[n] = buf[n];
    }
    char wrapped[4][SW_TEXT_LINE];
    int k = sw_text_wrap("Up/Down choose, Left/Right change (restarts), p closes", width - 4, wrapped, 4);
    for (int j = 0; j < k && j < 4; j++, n++) {
        memcpy(buf[n], wrapped[j], sizeof wrapped[j]);
        lines[n] = buf[n];
    }
    sw_draw_box(scr, row, col, height, width, a->scene->name, lines, n, SW_STYLE_TEXT);
}
