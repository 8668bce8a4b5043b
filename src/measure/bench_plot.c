/* Work-precision output: the log-log plot as text (for the terminal and the
 * UI's `w` overlay), and every point as CSV or the plots as SVG. Reads a
 * finished sw_bench_report; measures nothing. */
#include "measure/bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/truth.h"
#include "stepwise/base.h"

/* ---- plots ---------------------------------------------------------------- */

/* The plotted coordinates of a point: cost and error, both positive and finite. */
static int plot_xy(const sw_bench_point *pt, int xaxis, double *x, double *y)
{
    *x = xaxis == SW_BENCH_X_EVALS ? (double)pt->evals : pt->seconds;
    *y = pt->error;
    return !pt->blown && *x > 0 && isfinite(*x) && *y > 0 && isfinite(*y);
}

/* Whole decades covering every plotted point of every report: 0 when none. */
static int plot_range(const sw_bench_report *const *reports, int nreports, int xaxis, int range[4])
{
    double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
    for (int k = 0; k < nreports; k++)
        for (int i = 0; i < reports[k]->nseries; i++)
            for (int j = 0; j < reports[k]->series[i].npoints; j++) {
                double v[2];
                if (!plot_xy(&reports[k]->series[i].points[j], xaxis, &v[0], &v[1]))
                    continue;
                for (int d = 0; d < 2; d++) {
                    lo[d] = fmin(lo[d], log10(v[d]));
                    hi[d] = fmax(hi[d], log10(v[d]));
                }
            }
    if (!(lo[0] <= hi[0]))
        return 0;
    for (int d = 0; d < 2; d++) {
        /* log10 of a positive finite double lies in [-324, 309]: safe to convert. */
        range[2 * d] = (int)floor(lo[d]);
        range[2 * d + 1] = (int)ceil(hi[d]);
        if (range[2 * d + 1] == range[2 * d])
            range[2 * d + 1]++;
    }
    return 1;
}

/* Map v in [lo, hi] onto 0..cells-1, clipped. */
static int cell_of(double v, double lo, double hi, int cells)
{
    double f = (v - lo) / (hi - lo) * (cells - 1);
    if (!(f >= 0))
        return 0;
    if (f > cells - 1)
        return cells - 1;
    return (int)lround(f);
}

typedef struct grid {
    char *buf;
    int width, height;
} grid;

static void put(grid *g, int row, int col, const char *text)
{
    if (row < 0 || row >= g->height)
        return;
    for (; *text && col < g->width; text++, col++)
        if (col >= 0)
            g->buf[(size_t)row * (size_t)(g->width + 1) + (size_t)col] = *text;
}

static char *at(grid *g, int row, int col)
{
    return &g->buf[(size_t)row * (size_t)(g->width + 1) + (size_t)col];
}

int sw_bench_plot(const sw_bench_report *r, int xaxis, char *buf, int width, int height)
{
    if (!buf || width < 40 || height < 10)
        return SW_EINVAL;
    grid g = { buf, width, height };
    for (int row = 0; row < height; row++) {
        memset(at(&g, row, 0), ' ', (size_t)width);
        *at(&g, row, width) = '\n';
    }
    buf[(size_t)(width + 1) * (size_t)height] = '\0';

    /* Legend lines first: they decide how many rows the plot gets. */
    char legend[8][512];
    int nlegend = 0;
    size_t used = 0, line_max = width < 500 ? (size_t)width : 500;
    legend[0][0] = '\0';
    for (int i = 0; i < r->nseries && nlegend < 8; i++) {
        char entry[96];
        snprintf(entry, sizeof entry, "%c=%.40s", sw_bench_marker(r->series[i].method),
                 r->series[i].method->name);
        size_t len = strlen(entry);
        if (used > 0 && used + 2 + len > line_max) {
            if (++nlegend == 8)
                break;
            used = 0;
            legend[nlegend][0] = '\0';
        }
        used += (size_t)snprintf(legend[nlegend] + used, sizeof legend[0] - used, "%s%s",
                                 used ? "  " : "", entry);
    }
    if (used > 0 && nlegend < 8)
        nlegend++;
    int plot_rows = height - 3 - nlegend;
    if (plot_rows < 4) {
        nlegend = height - 7;
        plot_rows = 4;
    }

    char title[256];
    snprintf(title, sizeof title, "%.40s: largest error against %s", r->scene->name,
             xaxis == SW_BENCH_X_EVALS ? "derivative evaluations" : "wall time (s)");
    put(&g, 0, 0, title);
    for (int i = 0; i < nlegend; i++)
        put(&g, height - nlegend + i, 0, legend[i]);

    int range[4];
    const sw_bench_report *one[1] = { r };
    if (!plot_range(one, 1, xaxis, range)) {
        put(&g, 1 + plot_rows / 2, 2, "(no points: every run blew up or none was made)");
        return SW_OK;
    }
    const int margin = 7; /* "1e-10 |" */
    int top = 1, bottom = plot_rows, axis_row = plot_rows + 1, left = margin + 1;
    int plot_cols = width - left - 1;
    for (int row = top; row <= bottom; row++)
        *at(&g, row, margin - 1 + 0) = '|';
    for (int col = margin - 1; col < width - 1; col++)
        *at(&g, axis_row, col) = col == margin - 1 ? '+' : '-';
    /* Decade labels: y at the left, x under the axis; skip ones that would collide. */
    int last_row = -1;
    for (int d = range[3]; d >= range[2]; d--) {
        int row = bottom - cell_of(d, range[2], range[3], plot_rows);
        if (row == last_row)
            continue;
        char label[16];
        snprintf(label, sizeof label, "1e%d", d);
        put(&g, row, margin - 2 - (int)strlen(label), label);
        last_row = row;
    }
    int free_col = 0;
    for (int d = range[0]; d <= range[1]; d++) {
        int col = left + cell_of(d, range[0], range[1], plot_cols);
        char label[16];
        snprintf(label, sizeof label, "1e%d", d);
        int start = col - (int)strlen(label) / 2;
        if (start < free_col || start + (int)strlen(label) > width)
            continue;
        *at(&g, axis_row, col) = '+';
        put(&g, axis_row + 1, start, label);
        free_col = start + (int)strlen(label) + 1;
    }
    /* Lines first, then markers on top. */
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < r->nseries; i++) {
            const sw_bench_series *s = &r->series[i];
            char mark = sw_bench_marker(s->method);
            int prev_row = -1, prev_col = -1;
            for (int j = 0; j < s->npoints; j++) {
                double x, y;
                if (!plot_xy(&s->points[j], xaxis, &x, &y))
                    continue;
                int col = left + cell_of(log10(x), range[0], range[1], plot_cols);
                int row = bottom - cell_of(log10(y), range[2], range[3], plot_rows);
                if (pass == 1)
                    *at(&g, row, col) = mark;
                else if (prev_row >= 0) {
                    int n = abs(col - prev_col) > abs(row - prev_row) ? abs(col - prev_col) : abs(row - prev_row);
                    for (int k = 1; k < n; k++) {
                        int rr = prev_row + (int)lround((double)(row - prev_row) * k / n);
                        int cc = prev_col + (int)lround((double)(col - prev_col) * k / n);
                        if (*at(&g, rr, cc) == ' ')
                            *at(&g, rr, cc) = '.';
                    }
                }
                prev_row = row;
                prev_col = col;
            }
        }
    return SW_OK;
}

/* ---- files -------------------------------------------------------------- */

static void csv_name(FILE *out, const char *s)
{
    /* Quote when a name could break the row (plugins choose their names). */
    if (!strpbrk(s, ",\"\n\r")) {
        fputs(s, out);
        return;
    }
    fputc('"', out);
    for (; *s; s++) {
        if (*s == '"')
            fputc('"', out);
        fputc(*s, out);
    }
    fputc('"', out);
}

int sw_bench_write_csv(FILE *out, const sw_bench_report *const *reports, int nreports, char *err,
                       size_t errlen)
{
    fputs("scene,method,dt,rtol,h,error,evals,solves,steps,seconds,repeats,blown,blow_time,"
          "in_fit,order,reference\n", out);
    /* where a scene has no exact solution: the truth module's reference run */
    const char *reference = sw_truth_reference_method()->name;
    for (int k = 0; k < nreports; k++) {
        const sw_bench_report *r = reports[k];
        for (int i = 0; i < r->nseries; i++) {
            const sw_bench_series *s = &r->series[i];
            /* an adaptive method's controlled runs, then its fixed steps
             * (rtol 0: the rows its order is fitted from) */
            for (int j = 0; j < s->npoints + s->nfixed; j++) {
                const sw_bench_point *pt = j < s->npoints ? &s->points[j] : &s->fixed[j - s->npoints];
                csv_name(out, r->scene->name);
                fputc(',', out);
                csv_name(out, s->method->name);
                fprintf(out, ",%.17g,%.17g,%.17g,%.17g,%ld,%ld,%ld,%.17g,%d,%d,%.17g,%d,%.17g,%s\n",
                        pt->dt, pt->rtol, pt->h, pt->error, pt->evals, pt->solves, pt->steps,
                        pt->seconds, pt->repeats, pt->blown, pt->blown ? pt->blow_time : NAN,
                        pt->in_fit, s->order, r->source == SW_BENCH_EXACT ? "exact" : reference);
            }
        }
    }
    if (fflush(out) != 0 || ferror(out)) {
        snprintf(err, errlen, "could not write the CSV");
        return SW_EIO;
    }
    return SW_OK;
}

static void xml_text(FILE *out, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", out); break;
        case '<': fputs("&lt;", out); break;
        case '>': fputs("&gt;", out); break;
        case '"': fputs("&quot;", out); break;
        case '\'': fputs("&apos;", out); break;
        default: fputc(*s, out);
        }
    }
}

static const char *const palette[] = {
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
    "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22",
};
#define NPALETTE ((int)(sizeof palette / sizeof palette[0]))

static const char *method_color(const sw_integrator *m)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (sw_integrator_at(i) == m)
            return palette[i % NPALETTE];
    return palette[NPALETTE - 1];
}

/* SVG layout, in px. */
#define SVG_W 1000
#define PANEL_W 400
#define PANEL_H 280
#define PANEL_LEFT 90  /* room for y tick labels */
#define PANEL_GAP 80
#define ROW_H 420
#define ROW_TOP 40

static void svg_panel(FILE *out, const sw_bench_report *r, int xaxis, double x0, double y0)
{
    int range[4];
    const sw_bench_report *one[1] = { r };
    fprintf(out, "<g class=\"panel\" data-scene=\"");
    xml_text(out, r->scene->name);
    fprintf(out, "\" data-x=\"%s\">\n", xaxis == SW_BENCH_X_EVALS ? "evals" : "time");
    fprintf(out, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%d\" height=\"%d\" fill=\"#ffffff\" "
                 "stroke=\"#444444\"/>\n", x0, y0, PANEL_W, PANEL_H);
    if (!plot_range(one, 1, xaxis, range)) {
        range[0] = -6;
        range[1] = 0;
        range[2] = -12;
        range[3] = 0;
    }
    double sx = PANEL_W / (double)(range[1] - range[0]), sy = PANEL_H / (double)(range[3] - range[2]);
    /* x axis: a decade tick and grid line each, labels below. */
    fprintf(out, "<g class=\"axis\" data-axis=\"x\">\n");
    fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#000000\"/>\n", x0,
            y0 + PANEL_H, x0 + PANEL_W, y0 + PANEL_H);
    int xstep = (range[1] - range[0] + 7) / 8;
    for (int d = range[0]; d <= range[1]; d += xstep) {
        double x = x0 + (d - range[0]) * sx;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#dddddd\"/>\n", x,
                y0, x, y0 + PANEL_H);
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"12\" text-anchor=\"middle\">1e%d</text>\n",
                x, y0 + PANEL_H + 16, d);
    }
    fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"13\" text-anchor=\"middle\">%s</text>\n",
            x0 + PANEL_W / 2.0, y0 + PANEL_H + 36,
            xaxis == SW_BENCH_X_EVALS ? "derivative evaluations" : "wall time (s)");
    fprintf(out, "</g>\n<g class=\"axis\" data-axis=\"y\">\n");
    fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#000000\"/>\n", x0, y0,
            x0, y0 + PANEL_H);
    int ystep = (range[3] - range[2] + 9) / 10;
    for (int d = range[2]; d <= range[3]; d += ystep) {
        double y = y0 + PANEL_H - (d - range[2]) * sy;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#dddddd\"/>\n", x0,
                y, x0 + PANEL_W, y);
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"12\" text-anchor=\"end\">1e%d</text>\n",
                x0 - 6, y + 4, d);
    }
    fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"13\" text-anchor=\"middle\" "
                 "transform=\"rotate(-90 %.2f %.2f)\">largest state error</text>\n",
            x0 - 52, y0 + PANEL_H / 2.0, x0 - 52, y0 + PANEL_H / 2.0);
    fprintf(out, "</g>\n");
    for (int i = 0; i < r->nseries; i++) {
        const sw_bench_series *s = &r->series[i];
        const char *color = method_color(s->method);
        fprintf(out, "<g class=\"series\" data-method=\"");
        xml_text(out, s->method->name);
        fprintf(out, "\" stroke=\"%s\" fill=\"%s\">\n<polyline fill=\"none\" stroke-width=\"1.5\" "
                     "points=\"", color, color);
        int first = 1;
        for (int j = 0; j < s->npoints; j++) {
            double x, y;
            if (!plot_xy(&s->points[j], xaxis, &x, &y))
                continue;
            fprintf(out, "%s%.2f,%.2f", first ? "" : " ", x0 + (log10(x) - range[0]) * sx,
                    y0 + PANEL_H - (log10(y) - range[2]) * sy);
            first = 0;
        }
        fprintf(out, "\"/>\n");
        for (int j = 0; j < s->npoints; j++) {
            double x, y;
            if (!plot_xy(&s->points[j], xaxis, &x, &y))
                continue;
            fprintf(out, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"2.5\"/>\n",
                    x0 + (log10(x) - range[0]) * sx, y0 + PANEL_H - (log10(y) - range[2]) * sy);
        }
        fprintf(out, "</g>\n");
    }
    fprintf(out, "</g>\n");
}

int sw_bench_write_svg(FILE *out, const sw_bench_report *const *reports, int nreports, char *err,
                       size_t errlen)
{
    int height = ROW_TOP + (nreports > 0 ? nreports : 1) * ROW_H;
    fprintf(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                 "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\">\n",
            SVG_W, height, SVG_W, height);
    fprintf(out, "<title>stepwise bench: error against cost</title>\n");
    fprintf(out, "<rect x=\"0\" y=\"0\" width=\"%d\" height=\"%d\" fill=\"#fafafa\"/>\n", SVG_W, height);
    fprintf(out, "<text x=\"20\" y=\"26\" font-size=\"18\">stepwise bench: largest state error at the "
                 "report time against cost (log-log)</text>\n");
    for (int k = 0; k < nreports; k++) {
        const sw_bench_report *r = reports[k];
        double y0 = ROW_TOP + k * ROW_H;
        fprintf(out, "<g class=\"scene\" data-scene=\"");
        xml_text(out, r->scene->name);
        fprintf(out, "\">\n<text x=\"20\" y=\"%.2f\" font-size=\"15\" font-weight=\"bold\">", y0 + 24);
        xml_text(out, r->scene->name);
        if (r->source == SW_BENCH_EXACT)
            fprintf(out, " (exact solution at t = %g)</text>\n", r->t_report);
        else
            fprintf(out, " (%s reference at t = %g)</text>\n", sw_truth_reference_method()->name, r->t_report);
        fprintf(out, "<g class=\"legend\">\n");
        for (int i = 0; i < r->nseries; i++) {
            double lx = 20 + (i % 7) * 135, ly = y0 + 46 + (i / 7) * 18;
            const char *color = method_color(r->series[i].method);
            fprintf(out, "<rect x=\"%.2f\" y=\"%.2f\" width=\"14\" height=\"4\" fill=\"%s\"/>"
                         "<text x=\"%.2f\" y=\"%.2f\" font-size=\"12\">", lx, ly - 4, color, lx + 18, ly);
            xml_text(out, r->series[i].method->name);
            fprintf(out, "</text>\n");
        }
        fprintf(out, "</g>\n");
        svg_panel(out, r, SW_BENCH_X_TIME, PANEL_LEFT, y0 + 80);
        svg_panel(out, r, SW_BENCH_X_EVALS, PANEL_LEFT + PANEL_W + PANEL_GAP, y0 + 80);
        fprintf(out, "</g>\n");
    }
    fprintf(out, "</svg>\n");
    if (fflush(out) != 0 || ferror(out)) {
        snprintf(err, errlen, "could not write the SVG");
        return SW_EIO;
    }
    return SW_OK;
}
