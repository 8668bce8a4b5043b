/* The composer's pieces that are text first: the graph of energy drift (or
 * error) with its axes and units, the paged help screen generated from the
 * one list of controls, the parameter panel and the work-precision plot
 * with a legend that says which curves lie on one another and why methods
 * are missing. Every line is fitted or wrapped to the box it goes in. */
#include "render/screen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure/bench.h"
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

void sw_draw_box(sw_screen *scr, int row, int col, int height, int width, const char *title,
                 const char *const *lines, int n, int style)
{
    box(scr, row, col, height, width, title, lines, n, style, NULL, 0);
}

/* ---- the graph ---------------------------------------------------------------- */

void sw_draw_graph(sw_frame *f, sw_app *a, sw_screen *scr, int row, int col, int height, int width)
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
    sw_field title[2] = {
        { "", "", 2 }, { "", "", 1 },
    };
    snprintf(title[0].full, sizeof title[0].full, "%s", has_energy ? "energy drift (%)" : "error");
    snprintf(title[1].full, sizeof title[1].full, "against time t (s)");
    snprintf(title[1].brief, sizeof title[1].brief, "against t (s)");
    char line[SW_TEXT_LINE];
    sw_screen_fill(scr, row, col, height, width, SW_STYLE_TEXT);
    sw_text_fit(line, sizeof line, width, title, 2, " ");
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
        sw_field t3[3] = { title[0], title[1], { "", "", 3 } };
        snprintf(t3[2].full, sizeof t3[2].full, "%c: runs on one another", SW_GLYPH_MERGED);
        snprintf(t3[2].brief, sizeof t3[2].brief, "%c: overlap", SW_GLYPH_MERGED);
        t3[2].prio = 3;
        sw_screen_fill(scr, row, col, 1, width, SW_STYLE_TEXT);
        sw_text_fit(line, sizeof line, width, t3, 3, " ");
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
    snprintf(keys, keys_len, n <= 9 ? "1-%d" : "1-9  0", n);
    for (int i = 10; i < n; i++) {
        size_t k = strlen(keys);
        if ((int)k + 2 + (i == 10) > width || k + 3 > keys_len)
            break;
        snprintf(keys + k, keys_len - k, "%s%c", i == 10 ? "  " : " ", c->keys[i]);
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
        { "", "|L|dt: stiffest eigenvalue of the linearisation, times dt" },
        { "", "x.../step: growth per step of the worst mode (1: neutral)" },
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

/* ---- the work-precision plot ------------------------------------------------------ */

/* Which curves lie on one another (errors within 10% at every step size
 * both ran) and which methods are missing, and why (first: the plot does
 * not show them at all): measured, in words. Methods missing for the same
 * reason share a note. */
static int workprec_notes(sw_app *a, const sw_bench_report *r, char notes[][SW_TEXT_LINE], int max)
{
    int n = 0;
    char err[SW_ERRLEN];
    /* missing methods, grouped by the reason the system refuses them */
    static char reason[24][SW_ERRLEN];
    static char names[24][SW_TEXT_LINE];
    int nr = 0;
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        int in = 0;
        for (int i = 0; i < r->nseries; i++)
            in |= r->series[i].method == m;
        if (in)
            continue;
        if (sw_integrator_accepts(m, a->sims[0].sys.ode, err, sizeof err) == SW_OK)
            snprintf(err, sizeof err, "not swept");
        /* the reason without the method's own name in front of it */
        const char *why = strstr(err, m->name) == err + 1 ? err + strlen(m->name) + 3 : err;
        int g = 0;
        while (g < nr && strcmp(reason[g], why) != 0)
            g++;
        if (g == nr) {
            if (nr == 24)
                continue;
            snprintf(reason[nr], sizeof reason[nr], "%s", why);
            names[nr][0] = '\0';
            nr++;
        }
        size_t used = strlen(names[g]);
        snprintf(names[g] + used, sizeof names[g] - used, "%s%s", used ? ", " : "", m->name);
    }
    for (int g = 0; g < nr && n < max; g++)
        snprintf(notes[n++], SW_TEXT_LINE, "no %.100s: %.300s", names[g], reason[g]);
    for (int i = 0; i < r->nseries && n < max; i++)
        for (int j = i + 1; j < r->nseries && n < max; j++) {
            const sw_bench_series *s = &r->series[i], *u = &r->series[j];
            int common = 0, apart = 0;
            for (int p = 0; p < s->npoints; p++)
                for (int q = 0; q < u->npoints; q++) {
                    const sw_bench_point *x = &s->points[p], *y = &u->points[q];
                    if (x->dt != y->dt || x->rtol != y->rtol || x->blown || y->blown || !(x->error > 0) ||
                        !(y->error > 0))
                        continue;
                    common++;
                    apart += fabs(log(x->error / y->error)) > log(1.1);
                }
            if (common >= 3 && !apart)
                snprintf(notes[n++], SW_TEXT_LINE, "%c %s and %c %s coincide: errors within 10%% at all %d steps", sw_bench_marker(s->method), s->method->name,
                         sw_bench_marker(u->method), u->method->name, common);
        }
    return n;
}

/* The plot's coordinates of a point: cost and error, both positive and finite. */
static int wp_xy(const sw_bench_point *pt, int xaxis, double *x, double *y)
{
    *x = xaxis == SW_BENCH_X_EVALS ? (double)pt->evals : pt->seconds;
    *y = pt->error;
    return !pt->blown && *x > 0 && isfinite(*x) && *y > 0 && isfinite(*y);
}

/* v in [lo, hi] onto 0..cells-1. */
static int wp_cell(double v, double lo, double hi, int cells)
{
    double f = (v - lo) / (hi - lo) * (cells - 1);
    return !(f >= 0) ? 0 : f > cells - 1 ? cells - 1 : (int)lround(f);
}

/* The log-log plot itself into a grid of rows × cols characters (rows
 * plot rows, then the x axis and its labels): decade labels thinned so
 * that none touches another, lines of dots between a method's points, its
 * marker on each. Returns 0 when there is no point to plot. */
static int wp_grid(const sw_bench_report *r, int xaxis, char *g, int rows, int cols)
{
    double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
    for (int i = 0; i < r->nseries; i++)
        for (int j = 0; j < r->series[i].npoints; j++) {
            double v[2];
            if (!wp_xy(&r->series[i].points[j], xaxis, &v[0], &v[1]))
                continue;
            for (int d = 0; d < 2; d++) {
                lo[d] = fmin(lo[d], log10(v[d]));
                hi[d] = fmax(hi[d], log10(v[d]));
            }
        }
    memset(g, ' ', (size_t)(rows + 2) * (size_t)cols);
    if (!(lo[0] <= hi[0]))
        return 0;
    int range[4];
    for (int d = 0; d < 2; d++) {
        range[2 * d] = (int)floor(lo[d]);
        range[2 * d + 1] = (int)ceil(hi[d]);
        if (range[2 * d + 1] == range[2 * d])
            range[2 * d + 1]++;
    }
    int lw = 0;
    for (int d = range[2]; d <= range[3]; d++) {
        char lab[16];
        int len = snprintf(lab, sizeof lab, "1e%d", d);
        lw = len > lw ? len : lw;
    }
    int left = lw + 1, pc = cols - left; /* plot columns, right of the y axis */
#define G(rr, cc) g[(size_t)(rr) * (size_t)cols + (size_t)(cc)]
    for (int rr = 0; rr < rows; rr++)
        G(rr, lw) = '|';
    for (int cc = lw; cc < cols; cc++)
        G(rows, cc) = cc == lw ? '+' : '-';
    int last_row = -2;
    for (int d = range[3]; d >= range[2]; d--) {
        int rr = rows - 1 - wp_cell(d, range[2], range[3], rows);
        if (rr <= last_row + 1 && last_row >= 0)
            continue; /* a row between labels */
        char lab[16];
        int len = snprintf(lab, sizeof lab, "1e%d", d);
        memcpy(&G(rr, lw - len), lab, (size_t)len);
        last_row = rr;
    }
    int free_col = 0;
    for (int d = range[0]; d <= range[1]; d++) {
        int cc = left + wp_cell(d, range[0], range[1], pc);
        char lab[16];
        int len = snprintf(lab, sizeof lab, "1e%d", d), start = cc - len / 2;
        if (start < free_col || start + len > cols)
            continue;
        G(rows, cc) = '+';
        memcpy(&G(rows + 1, start), lab, (size_t)len);
        free_col = start + len + 1; /* a blank column between labels */
    }
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < r->nseries; i++) {
            const sw_bench_series *se = &r->series[i];
            int prow = -1, pcol = -1;
            for (int j = 0; j < se->npoints; j++) {
                double x, y;
                if (!wp_xy(&se->points[j], xaxis, &x, &y))
                    continue;
                int cc = left + wp_cell(log10(x), range[0], range[1], pc);
                int rr = rows - 1 - wp_cell(log10(y), range[2], range[3], rows);
                if (pass == 1)
                    G(rr, cc) = sw_bench_marker(se->method);
                else if (prow >= 0) {
                    int n = abs(cc - pcol) > abs(rr - prow) ? abs(cc - pcol) : abs(rr - prow);
                    for (int k = 1; k < n; k++) {
                        int r2 = prow + (int)lround((double)(rr - prow) * k / n);
                        int c2 = pcol + (int)lround((double)(cc - pcol) * k / n);
                        if (G(r2, c2) == ' ')
                            G(r2, c2) = '.';
                    }
                }
                prow = rr;
                pcol = cc;
            }
        }
#undef G
    return 1;
}

/* The work-precision overlay takes the whole rectangle it is given, so the
 * plot uses all the room there is: a title, the plot, a legend of markers,
 * the notes that fit whole, and what w does next (it cycles: against
 * evaluations, against wall time, closed). */
void sw_draw_workprec(sw_app *a, sw_screen *scr, int row, int col, int height, int width)
{
    static char notes[8][SW_TEXT_LINE], wrapped[24][SW_TEXT_LINE];
    const sw_bench_report *r = a->bench;
    int xaxis = a->workprec == 1 ? SW_BENCH_X_EVALS : SW_BENCH_X_TIME, inner = width - 2, c0 = col + 1;
    if (inner < 1 || height < 1)
        return;
    sw_screen_fill(scr, row, col, height, width, SW_STYLE_TEXT);
    char buf[SW_TEXT_LINE], line[SW_TEXT_LINE];
    sw_field tf[3];
    int nt = 0;
    memset(tf, 0, sizeof tf);
    snprintf(tf[0].full, sizeof tf[0].full, "work-precision: error against %s",
             xaxis == SW_BENCH_X_EVALS ? "derivative evaluations" : "wall time (s)");
    snprintf(tf[0].brief, sizeof tf[0].brief, "error vs %s", xaxis == SW_BENCH_X_EVALS ? "evaluations" : "time (s)");
    tf[nt++].prio = 10;
    snprintf(tf[1].full, sizeof tf[1].full, "(%s)", r->scene->name);
    tf[nt++].prio = 3;
    if (sw_text_fit(line, sizeof line, inner, tf, nt, "  ") > 0)
        sw_screen_text(scr, row, c0, inner, SW_STYLE_TITLE, line);
    /* the key's next step, always on the last row */
    sw_field kf[1];
    memset(kf, 0, sizeof kf);
    snprintf(kf[0].full, sizeof kf[0].full, "%s", xaxis == SW_BENCH_X_EVALS ? "w: the same against wall time" : "w closes");
    snprintf(kf[0].brief, sizeof kf[0].brief, "%s", xaxis == SW_BENCH_X_EVALS ? "w: against time" : "");
    kf[0].prio = 10;
    int foot = height > 1 && sw_text_fit(line, sizeof line, inner, kf, 1, "  ") > 0;
    if (foot)
        sw_screen_text(scr, row + height - 1, c0, inner, SW_STYLE_DIM, line);
    /* the legend: every method's marker and name (brief names before a third row) */
    sw_field lg[SW_BENCH_MAX_METHODS];
    int nl = 0;
    for (int i = 0; i < r->nseries && nl < SW_BENCH_MAX_METHODS; i++, nl++) {
        memset(&lg[nl], 0, sizeof lg[nl]);
        char name[64];
        snprintf(lg[nl].full, sizeof lg[nl].full, "%c=%.60s", sw_bench_marker(r->series[i].method),
                 r->series[i].method->name);
        sw_text_brief_name(r->series[i].method->name, name, sizeof name);
        if (name[0])
            snprintf(lg[nl].brief, sizeof lg[nl].brief, "%c=%.40s", sw_bench_marker(r->series[i].method), name);
        lg[nl].prio = 10;
    }
    char legend[4][SW_TEXT_LINE];
    int lrows = 1, dropped = 1;
    while (lrows < 4 && (sw_text_fit_rows(legend, lrows, inner, lg, nl, "  ", &dropped), dropped))
        lrows++;
    lrows = nl ? sw_text_fit_rows(legend, lrows, inner, lg, nl, "  ", NULL) : 0;
    /* the plot keeps WP_MIN_ROWS rows (and its axis and labels); whole notes fill what is left */
    int body = height - 1 - foot - lrows, plot_min = 6;
    int nn = workprec_notes(a, r, notes, 8), nw = 0, dropped_notes = 0;
    for (int i = 0; i < nn; i++) {
        char part[8][SW_TEXT_LINE];
        int k = sw_text_wrap(notes[i], inner, part, 8);
        if (k > 8 || nw + k + 1 > body - plot_min - 2 || nw + k > 23) {
            dropped_notes = nn - i;
            break;
        }
        for (int j = 0; j < k; j++)
            memcpy(wrapped[nw++], part[j], SW_TEXT_LINE);
    }
    if (dropped_notes) {
        /* a row says that notes are left out: the last whole note's, or one of its own */
        snprintf(buf, sizeof buf, "(%d %snote%s: a larger window shows %s)", dropped_notes, nw ? "more " : "",
                 dropped_notes > 1 ? "s" : "", dropped_notes > 1 ? "them" : "it");
        if (sw_text_cells(buf) > inner)
            snprintf(buf, sizeof buf, "(%d %snote%s left out)", dropped_notes, nw ? "more " : "",
                     dropped_notes > 1 ? "s" : "");
        if (sw_text_cells(buf) <= inner && (nw > 0 || body - plot_min - 2 >= 1))
            snprintf(wrapped[nw > 0 ? nw - 1 : nw++], SW_TEXT_LINE, "%s", buf);
    }
    int prows = body - nw - 2, pcols = inner;
    if (prows < 3 || pcols < 16) {
        snprintf(buf, sizeof buf, "the plot needs %d more row%s and %d more column%s here: a larger window "
                 "shows it", prows < 3 ? 3 - prows : 0, 3 - prows == 1 ? "" : "s", pcols < 16 ? 16 - pcols : 0,
                 16 - pcols == 1 ? "" : "s");
        int k = sw_text_wrap(buf, inner, wrapped, 24);
        int room = height - 1 - foot;
        if (k <= room)
            for (int j = 0; j < k; j++)
                sw_screen_text(scr, row + 1 + j, c0, inner, SW_STYLE_TEXT, wrapped[j]);
        return;
    }
    /* one buffer for every frame (no allocation per frame while the plot is open) */
    static char g[256 * 512];
    if (pcols > 512)
        pcols = 512;
    if (prows + 2 > 256)
        prows = 254;
    int have = wp_grid(r, xaxis, g, prows, pcols);
    int rr = row + 1;
    for (int k = 0; have && k < prows + 2; k++, rr++) {
        int len = pcols;
        while (len > 0 && g[(size_t)k * (size_t)pcols + (size_t)len - 1] == ' ')
            len--;
        snprintf(line, sizeof line, "%.*s", len, g + (size_t)k * (size_t)pcols);
        sw_screen_text(scr, rr, c0, inner, SW_STYLE_TEXT, line);
    }
    if (!have)
        sw_screen_wrapped(scr, row + 1 + prows / 2, c0, inner, 2, SW_STYLE_TEXT,
                          "(no points: every run blew up or none was made)");
    rr = row + 1 + prows + 2;
    for (int k = 0; k < lrows; k++)
        sw_screen_text(scr, rr++, c0, inner, SW_STYLE_DIM, legend[k]);
    for (int k = 0; k < nw; k++)
        sw_screen_text(scr, rr++, c0, inner, SW_STYLE_TEXT, wrapped[k]);
}
