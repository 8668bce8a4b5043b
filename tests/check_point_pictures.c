/* Pictures that show their point at 80x24 (issue 25): the stability
 * region's marks move when Δt halves on lesson 5's page and its axes stay
 * put; the work-precision plot marks shared cells '&' and names the pairs,
 * reaches the points lesson 6's table quotes, and stays beside the page's
 * text; the projectile's launch level and energy reference are said. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "app/runner.h"
#include "canvas_help.h"
#include "lesson/lesson.h"
#include "measure/bench.h"
#include "render/region.h"
#include "render/screen.h"
#include "render/workprec.h"
#include "stepwise/stepwise.h"

/* The scale: the whole region when the marks are large, 1.25 × the largest
 * mark when it is small (never below reach / 1000), the region with no mark. */
START_TEST(region_scale_choice)
{
    ck_assert_double_eq(sw_region_scale(3, 0), 3);
    ck_assert_double_eq(sw_region_scale(3, NAN), 3);
    ck_assert_double_eq(sw_region_scale(3, 2), 3);     /* 2.5 >= 1.5: the whole region */
    ck_assert_double_eq(sw_region_scale(3, 4), 5);     /* and the marks beyond it */
    ck_assert_double_eq(sw_region_scale(3, 1.2), 3);   /* 1.5 >= 1.5: the edge of the whole-region rule */
    ck_assert_double_eq_tol(sw_region_scale(3, 0.5), 0.625, 1e-15);
    ck_assert_double_eq_tol(sw_region_scale(3, 1e-9), 3e-3, 1e-15);
}
END_TEST

typedef struct marks {
    int n, col[8], row[8];
    int axis_col, axis_row;
} marks;

/* The marks ('X' or '*') and the origin ('+' where the axes cross) on the
 * region canvas. */
static marks find_marks(const sw_canvas *c)
{
    marks m = { 0 };
    m.axis_col = m.axis_row = -1;
    for (int row = 0; row < c->rows; row++)
        for (int col = 0; col < c->cols; col++) {
            uint32_t g = sw_canvas_codepoint(c, col, row);
            if ((g == 'X' || g == '*') && m.n < 8) {
                m.col[m.n] = col;
                m.row[m.n] = row;
                m.n++;
            }
        }
    int oc, orow;
    if (sw_canvas_world_to_cell(c, 0, 0, &oc, &orow)) {
        m.axis_col = oc;
        m.axis_row = orow;
    }
    return m;
}

/* The edge on a ray, against the closed forms: Euler's disc |1 + z| <= 1
 * meets the ray r·u (|u| = 1) at r = -2 Re u; RK4's region meets the
 * imaginary axis at 2√2 (|R(iy)|² = 1 - y⁶/72 + y⁸/576 = 1). The search
 * bisects to 1e-9 relative; the tolerance is 1e-8 relative, and on Euler's
 * ray a point within SW_TRUTH_NEUTRAL (1e-12) of growth 1 counts as stable,
 * which moves the edge by about 1e-12 / |Re u|. */
START_TEST(region_edge_on_ray)
{
    sw_truth_work *w = sw_truth_work_new();
    ck_assert_ptr_nonnull(w);
    const sw_integrator *euler = sw_integrator_find("euler"), *rk4 = sw_integrator_find("rk4");
    double re = -5, im = sqrt(10000 - 25), u = re / hypot(re, im);
    double e = sw_region_edge_on_ray(w, euler, 2, re, im);
    ck_assert_double_eq_tol(e, -2 * u, 1e-8 * -2 * u);
    ck_assert_double_eq_tol(sw_region_edge_on_ray(w, euler, 2, -1, 0), 2, 2e-8);
    ck_assert_double_eq_tol(sw_region_edge_on_ray(w, rk4, 2, 0, 1), 2 * sqrt(2), 3e-8);
    /* undamped under Euler: out at once (past the neutral tolerance); backward Euler: never out */
    ck_assert_double_lt(sw_region_edge_on_ray(w, euler, 2, 0, 1), 1e-5);
    ck_assert(isinf(sw_region_edge_on_ray(w, sw_integrator_find("implicit-euler"), 2, -1, 1)));
    sw_truth_work_free(w);
}
END_TEST

/* The line under the region: the edge '|' in the same column whatever the
 * ratio, each factor 2 the same notch, X out and '*' in, the ratio said. */
START_TEST(region_gauge_line)
{
    char g[4][128];
    double ratio[4] = { 5, 2.5, 1.25, 0.625 };
    int edge = -1, pos[4];
    for (int k = 0; k < 4; k++) {
        sw_region_gauge(g[k], sizeof g[k], 39, ratio[k], ratio[k] > 1);
        ck_assert_int_le((int)strlen(g[k]), 39);
        const char *bar = strchr(g[k], '|');
        ck_assert_ptr_nonnull(bar);
        if (edge < 0)
            edge = (int)(bar - g[k]);
        ck_assert_msg((int)(bar - g[k]) == edge || strchr(g[k], 'X') == bar, "the edge moved: %s", g[k]);
        const char *mark = strchr(g[k], ratio[k] > 1 ? 'X' : '*');
        ck_assert_msg(mark != NULL, "no mark: %s", g[k]);
        pos[k] = (int)(mark - g[k]);
        ck_assert_msg(ratio[k] > 1 ? pos[k] > edge : pos[k] < edge, "the mark is on the wrong side: %s", g[k]);
        if (k > 0)
            ck_assert_int_eq(pos[k - 1] - pos[k], pos[0] - pos[1]);
    }
    ck_assert_ptr_nonnull(strstr(g[0], " 5×edge"));
    ck_assert_ptr_nonnull(strstr(g[3], " 0.625×edge"));
    sw_region_gauge(g[0], sizeof g[0], 39, INFINITY, 1);
    ck_assert_ptr_nonnull(strstr(g[0], "always out"));
    ck_assert_ptr_null(strchr(g[0], '|')); /* no edge drawn where there is none to measure against */
    sw_region_gauge(g[0], sizeof g[0], 39, 0, 0);
    ck_assert_ptr_nonnull(strstr(g[0], "always in"));
    ck_assert_ptr_null(strchr(g[0], '|'));
}
END_TEST

/* What a student reads beside mark j in its row of the region drawn in
 * characters (':' inside, SW_REGION_EDGE the edge line): looking left and
 * right from the mark, past blanks, axes and labels, the first glyph of
 * the region each way (0 at the picture's border). A mark that grows must
 * meet the edge line or nothing on both sides, never the inside; one that
 * does not must meet the region (inside or its edge line) on one side at
 * least (it may sit on the line, which is inside). */
static void assert_mark_side(const sw_canvas *c, const marks *m, int j, double dt, const char *text)
{
    uint32_t mark = sw_canvas_codepoint(c, m->col[j], m->row[j]), seen[2] = { 0, 0 };
    for (int d = 0; d < 2; d++)
        for (int col = m->col[j] + (d ? 1 : -1); col >= 0 && col < c->cols && !seen[d]; col += d ? 1 : -1) {
            uint32_t g = sw_canvas_codepoint(c, col, m->row[j]);
            if (g == ':' || g == SW_REGION_EDGE)
                seen[d] = g;
        }
    for (int d = 0; d < 2; d++)
        if (mark == 'X')
            ck_assert_msg(seen[d] != ':', "dt %g: the growing mark in row %d, column %d meets the inside to its %s "
                          "with no edge line between:\n%s", dt, m->row[j], m->col[j], d ? "right" : "left", text);
        else
            ck_assert_msg(seen[d] == ':' || seen[d] == SW_REGION_EDGE || seen[!d] == ':' || seen[!d] == SW_REGION_EDGE,
                          "dt %g: the mark inside in row %d, column %d has no region on either side:\n%s", dt,
                          m->row[j], m->col[j], text);
}

/* The screen's rows from the region's title down (the picture's columns). */
static int row_of(const char *text, const char *needle)
{
    const char *p = strstr(text, needle);
    if (!p)
        return -1;
    int row = 0;
    for (const char *q = text; q < p; q++)
        row += *q == '\n';
    return row;
}

/* No tick label over the shading: every digit in the picture's rows has
 * no Braille cell or ':' of shading touching it on its row. */
static void assert_labels_clear(const sw_canvas *c, const char *text)
{
    for (int row = 0; row < c->rows; row++)
        for (int col = 0; col < c->cols; col++) {
            uint32_t g = sw_canvas_codepoint(c, col, row);
            if (!((g >= '0' && g <= '9') || g == '.'))
                continue;
            for (int d = -1; d <= 1; d += 2) {
                uint32_t n = sw_canvas_codepoint(c, col + d, row);
                ck_assert_msg(!(n >= 0x2800 && n <= 0x28ff) && n != ':', "a label touches the shading at row %d, "
                              "column %d:\n%s", row, col, text);
            }
        }
}

/* Lesson 5, "Why: outside the stability region", at 80x24: each press of
 * '-' (0.005 -> 0.0025 -> 0.00125 -> 0.000625) moves every mark to another
 * cell, the axes and the numbers under them stay where they were (the
 * scale is fixed, and said), and the line under the numbers shows the mark
 * crossing the edge: 5x, 2.5x, 1.25x out, then 0.625x in, one notch a
 * halving. */
START_TEST(region_marks_move_on_lesson5)
{
    ct_page pg;
    ct_page_open(&pg, "lessons/05-springs.lesson", "Why: outside the stability region");
    sw_runner *r = pg.r;
    sw_app *ap = &pg.a;
    sw_app_key(ap, 's', 1);
    ck_assert_int_eq(ap->view, SW_VIEW_REGION);
    marks prev = { 0 };
    char ticks0[256] = "";
    int gauge_col[4];
    static const char *said[4] = { " 5×edge", " 2.5×edge", " 1.25×edge", " 0.625×edge" };
    for (int k = 0; k < 4; k++) {
        int clipped;
        char *text = ct_compose(&pg.f, ap, sw_runner_side(r, ap, 80), 80, 24, &clipped);
        marks m = find_marks(&pg.f.canvas);
        ck_assert_msg(m.n == 2, "dt %g: %d marks, not the mode's two:\n%s", ap->dt, m.n, text);
        for (int j = 0; j < m.n; j++) {
            assert_mark_side(&pg.f.canvas, &m, j, ap->dt, text);
            ck_assert_msg(sw_canvas_codepoint(&pg.f.canvas, m.col[j], m.row[j]) == (k < 3 ? 'X' : '*'),
                          "dt %g: mark %d is not drawn %s:\n%s", ap->dt, j, k < 3 ? "out (X)" : "in (*)", text);
            /* just inside (0.625x): on the inside's side of the line, the inside next to it */
            if (k == 3)
                ck_assert_msg(sw_canvas_codepoint(&pg.f.canvas, m.col[j] - 1, m.row[j]) == ':',
                              "dt %g: the mark just inside is not drawn on the shading:\n%s", ap->dt, text);
        }
        ck_assert_msg(strstr(text, "scale +-0.62 fixed") != NULL, "dt %g: the scale is not said:\n%s", ap->dt, text);
        assert_labels_clear(&pg.f.canvas, text);
        if (k == 0)
            snprintf(ticks0, sizeof ticks0, "%s", pg.f.region.ticks);
        ck_assert_msg(strcmp(ticks0, pg.f.region.ticks) == 0, "dt %g: the scale's numbers changed:\n%s\n%s", ap->dt,
                      ticks0, pg.f.region.ticks);
        ck_assert_msg(strstr(pg.f.region.ticks, "-0.2") != NULL, "no numbers under the picture: '%s'",
                      pg.f.region.ticks);
        /* the gauge, as on the screen */
        int grow = row_of(text, "in :");
        ck_assert_msg(grow > 0 && strstr(pg.f.region.gauge, said[k]) != NULL, "dt %g: the line under the picture "
                      "does not say%s:\n%s", ap->dt, said[k], text);
        const char *edge = strchr(pg.f.region.gauge, '|'), *mk = strchr(pg.f.region.gauge, k < 3 ? 'X' : '*');
        ck_assert_msg(edge && mk && (k < 3 ? mk > edge : mk < edge), "dt %g: the mark is not on its side of the "
                      "edge: %s", ap->dt, pg.f.region.gauge);
        gauge_col[k] = (int)(mk - pg.f.region.gauge);
        if (k > 0)
            ck_assert_int_eq(gauge_col[k - 1] - gauge_col[k], gauge_col[0] - gauge_col[1]);
        /* the marks mirror each other across the real axis */
        ck_assert_int_eq(m.row[0] + m.row[1], 2 * m.axis_row);
        if (k > 0) {
            ck_assert_msg(m.axis_col == prev.axis_col && m.axis_row == prev.axis_row,
                          "dt %g: the axes moved from (%d, %d) to (%d, %d)", ap->dt, prev.axis_col, prev.axis_row,
                          m.axis_col, m.axis_row);
            for (int j = 0; j < 2; j++)
                ck_assert_msg(m.row[j] != prev.row[j] || m.col[j] != prev.col[j],
                              "dt %g: mark %d did not move (row %d, column %d):\n%s", ap->dt, j, m.row[j], m.col[j],
                              text);
            /* towards the origin */
            ck_assert_int_lt(abs(m.row[0] - m.axis_row), abs(prev.row[0] - prev.axis_row));
        }
        prev = m;
        free(text);
        sw_app_key(ap, '-', 1);
    }
    ct_page_close(&pg);
}
END_TEST

/* Lesson 6, "RK4's region": the view opens on the whole region (the marks
 * at ±0.5i and where their ray leaves it, 2.83i, and where a doubling past
 * it puts them); doubling Δt (0.005 -> 0.04) moves the marks, the scale
 * stays put (no rescale by itself), and at 0.04 the marks are on the
 * picture, past the edge line (farther from the real axis than the line's
 * cell on the imaginary axis, nothing of the region beside them), while
 * the line under the picture says they are out (4 / 2.83 = 1.41x). */
START_TEST(region_scale_stays_when_marks_leave)
{
    ct_page pg;
    ct_page_open(&pg, "lessons/06-runge-kutta.lesson", "RK4's region");
    sw_runner *r = pg.r;
    sw_app *ap = &pg.a;
    sw_app_key(ap, 's', 1);
    char ticks0[256] = "";
    for (int k = 0; k < 4; k++) {
        int clipped;
        char *text = ct_compose(&pg.f, ap, sw_runner_side(r, ap, 80), 80, 24, &clipped);
        marks m = find_marks(&pg.f.canvas);
        assert_labels_clear(&pg.f.canvas, text);
        if (k == 0) {
            snprintf(ticks0, sizeof ticks0, "%s", pg.f.region.ticks);
            /* the whole region: its reach on the real axis (-2.79) is numbered */
            ck_assert_msg(strstr(ticks0, "-2") != NULL && strstr(ticks0, "2") != NULL, "%s", text);
        }
        ck_assert_msg(strcmp(ticks0, pg.f.region.ticks) == 0, "dt %g: the scale changed by itself:\n%s", ap->dt, text);
        ck_assert_msg(m.n == 2, "dt %g: %d marks drawn, not 2:\n%s", ap->dt, m.n, text);
        for (int j = 0; j < m.n; j++)
            assert_mark_side(&pg.f.canvas, &m, j, ap->dt, text);
        /* the edge line's farthest cell up the imaginary axis's column */
        int line_row = -1;
        for (int row = 0; row < m.axis_row && line_row < 0; row++)
            for (int col = m.axis_col - 1; col <= m.axis_col + 1; col++)
                if (sw_canvas_codepoint(&pg.f.canvas, col, row) == SW_REGION_EDGE)
                    line_row = row;
        ck_assert_msg(line_row >= 0, "dt %g: no edge line crosses the imaginary axis:\n%s", ap->dt, text);
        int top = m.row[0] < m.row[1] ? 0 : 1;
        if (k < 3)
            ck_assert_msg(m.row[top] >= line_row, "dt %g: the mark inside is drawn above the edge line:\n%s",
                          ap->dt, text);
        else {
            ck_assert_msg(strstr(pg.f.region.gauge, "X") && strstr(pg.f.region.gauge, " 1.41×edge"),
                          "dt %g: the line under the picture does not say out, 1.41x:\n%s", ap->dt, text);
            ck_assert_msg(m.row[top] < line_row && sw_canvas_codepoint(&pg.f.canvas, m.col[top], m.row[top]) == 'X',
                          "dt %g: the mark out is not drawn X past the edge line (row %d):\n%s", ap->dt, line_row,
                          text);
        }
        free(text);
        sw_app_key(ap, '+', 1);
    }
    ct_page_close(&pg);
}
END_TEST

/* Lesson 3, "The spring in phase space", at 80x24 after t = 10: the
 * legend names the glyphs drawn (Euler's present point o and its dotted
 * path ".", the exact curve "'"), every glyph on the picture is one the
 * legend or the axes name, and symplectic Euler's closed curve (x) is
 * drawn over the exact ellipse it hugs, not hidden under it (issue 37). */
START_TEST(phase_legend_matches_picture)
{
    ct_page pg;
    ct_page_open(&pg, "lessons/03-particles-with-mass.lesson", "The spring in phase space");
    sw_runner *r = pg.r;
    sw_app *ap = &pg.a;
    ck_assert_int_eq(ap->nsims, 3);
    sw_app_key(ap, 'v', 1);
    ck_assert_int_eq(ap->view, SW_VIEW_PHASE);
    ap->paused = 0;
    for (int i = 0; i < 4000 && ap->sims[0].t < 10; i++)
        sw_app_advance(ap, 0.05 / ap->speed, 1000000);
    ck_assert(ap->sims[0].t >= 10);
    int clipped;
    char *text = ct_compose(&pg.f, ap, sw_runner_side(r, ap, 80), 80, 24, &clipped);
    ck_assert_msg(strstr(text, "' exact") && strstr(text, "o. euler") && strstr(text, "x symp") &&
                  strstr(text, "+ impl"), "the legend does not name the glyphs drawn:\n%s", text);
    int xs = 0, ghosts = 0;
    for (int row = 0; row < pg.f.canvas.rows; row++)
        for (int col = 0; col < pg.f.canvas.cols; col++) {
            uint32_t g = sw_canvas_codepoint(&pg.f.canvas, col, row);
            ck_assert_msg(strchr(" -|+'.ox<>^v", (int)g) != NULL, "a glyph U+%04X on the picture the legend does not "
                          "name:\n%s", (unsigned)g, text);
            xs += g == 'x';
            ghosts += g == '\'';
        }
    printf("phase view, lesson 3 at t = 10: %d cells of symplectic Euler's curve, %d of the exact one showing\n", xs,
           ghosts);
    /* its curve stays within a few cells of the ellipse: drawn over it, it
     * shows most of the way round */
    ck_assert_msg(xs > 2 * ghosts, "symplectic Euler's curve is hidden under the exact one (%d x, %d '):\n%s", xs,
                  ghosts, text);
    free(text);
    ct_page_close(&pg);
}
END_TEST

/* The phase view on the projectile opens with its curve in it and says
 * which axis is which: the height y across (its name and its largest
 * value at the axis's right end), its rate vy up (at the top). */
START_TEST(phase_axes_named)
{
    const sw_scene *sc = sw_scene_find("projectile");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    sw_app a;
    ck_assert_msg(sw_app_init(&a, sc, p, NULL, sc->dt, err, sizeof err) == SW_OK, "%s", err);
    sw_app_set_view(&a, SW_VIEW_PHASE);
    sw_frame f;
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    int clipped;
    char *text = ct_compose(&f, &a, NULL, 80, 24, &clipped);
    ck_assert_msg(strstr(text, "^ vy ") != NULL, "the vertical axis is not named vy:\n%s", text);
    const char *across = strstr(text, "y ");
    int named = 0;
    for (; across; across = strstr(across + 1, "y "))
        named |= (across == text || across[-1] == ' ' || across[-1] == '-') && strstr(across, " >") &&
                 strchr(across, '\n') > strstr(across, " >");
    ck_assert_msg(named, "the horizontal axis is not named y:\n%s", text);
    ck_assert_msg(ct_count_cp(&f.canvas, '\'') > 20, "the phase view opens without the exact curve:\n%s", text);
    free(text);
    sw_frame_free(&f);
    sw_app_free(&a);
}
END_TEST

/* Lanes on lesson 3's page at 80x24: each lane wide enough to name its
 * method whole (side by side they were 12 columns: stacked instead); in a
 * window too small for any readable lane they are overlaid, and said. */
START_TEST(lanes_readable_or_refused)
{
    ct_page pg;
    ct_page_open(&pg, "lessons/03-particles-with-mass.lesson", "The spring in phase space");
    sw_runner *r = pg.r;
    sw_app *ap = &pg.a;
    sw_app_key(ap, 'l', 1);
    ck_assert(ap->lanes);
    int clipped;
    char *text = ct_compose(&pg.f, ap, sw_runner_side(r, ap, 80), 80, 24, &clipped);
    ck_assert_msg(strstr(text, "x symplectic-euler") && strstr(text, "+ implicit-euler"), "a lane's method is cut:\n%s",
                  text);
    free(text);
    text = ct_compose(&pg.f, ap, sw_runner_side(r, ap, SW_MIN_COLS), SW_MIN_COLS, SW_MIN_ROWS, &clipped);
    ck_assert_msg(strstr(text, "x symplectic-euler") || strstr(text, "lanes"), "at %dx%d the lanes are neither "
                  "readable nor refused:\n%s", SW_MIN_COLS, SW_MIN_ROWS, text);
    free(text);
    ct_page_close(&pg);
}
END_TEST

/* Lesson 3, "Euler on a spring", the energy graph at 80x24: its axes are
 * linear, and its title says so in the picture's 40 columns (the
 * newcomer: "is it logarithmic?"). */
START_TEST(graph_says_linear)
{
    ct_page pg;
    ct_page_open(&pg, "lessons/03-particles-with-mass.lesson", "Euler on a spring");
    sw_app *ap = &pg.a;
    sw_app_key(ap, 'e', 1);
    ap->paused = 0;
    for (int i = 0; i < 200 && ap->sims[0].t < 3; i++)
        sw_app_advance(ap, 0.05 / ap->speed, 1000000);
    char *text = ct_page_screen(&pg, 80, 24);
    const char *title = strstr(text, "energy drift (%)");
    ck_assert_msg(title && strstr(title, "(linear") && strstr(title, "(linear") < strchr(title, '\n'),
                  "the graph's title does not say its axes are linear:\n%s", text);
    free(text);
    ct_page_close(&pg);
}
END_TEST

/* Lesson 3's three runs at t = 10 with the energy graph at 80x24: Euler's
 * +557 % no longer squeezes symplectic Euler (a few %) and backward Euler
 * (-86 %) into one row of '*': the scale is theirs, Euler runs past the
 * top and the title says so (issue 37). */
START_TEST(graph_keeps_small_runs_apart)
{
    ct_page pg;
    ct_page_open(&pg, "lessons/03-particles-with-mass.lesson", "The spring in phase space");
    sw_runner *r = pg.r;
    sw_app *ap = &pg.a;
    sw_app_key(ap, 'e', 1);
    ck_assert(ap->graph);
    ap->paused = 0;
    for (int i = 0; i < 4000 && ap->sims[0].t < 10; i++)
        sw_app_advance(ap, 0.05 / ap->speed, 1000000);
    int clipped;
    char *text = ct_compose(&pg.f, ap, sw_runner_side(r, ap, 80), 80, 24, &clipped);
    const char *title = strstr(text, "energy drift (%)");
    ck_assert_msg(title != NULL && strstr(title, "o off top") != NULL, "the graph does not say Euler runs past the top:\n%s",
                  text);
    /* the plot's rows: from the title's next line while they hold '|' at column 9 */
    int rows_x = 0, rows_plus = 0, shared = 0;
    for (const char *line = strchr(title, '\n') + 1; line && line[9] == '|'; ) {
        const char *end = strchr(line, '\n');
        int x = 0, plus = 0, merged = 0;
        for (const char *c = line + 10; c < end && c < line + 40; c++) {
            x |= *c == 'x';
            plus |= *c == '+';
            merged |= *c == '*';
        }
        rows_x += x;
        rows_plus += plus;
        shared += merged && !x && !plus;
        line = end ? end + 1 : NULL;
    }
    printf("graph, lesson 3 at t = 10: symplectic Euler on %d rows, backward Euler on %d\n", rows_x, rows_plus);
    ck_assert_msg(rows_plus >= 3 && shared == 0, "backward Euler's fall is not drawn apart:\n%s", text);
    free(text);
    ct_page_close(&pg);
}
END_TEST

/* bounce has no mode to mark: the view says why, and no "0 modes". */
START_TEST(region_without_modes_says_why)
{
    const sw_scene *sc = sw_scene_find("bounce");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    sw_app a;
    ck_assert_msg(sw_app_init(&a, sc, p, NULL, sc->dt, err, sizeof err) == SW_OK, "%s", err);
    sw_app_set_view(&a, SW_VIEW_REGION);
    sw_frame f;
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    int clipped;
    char *text = ct_compose(&f, &a, NULL, 80, 24, &clipped);
    ck_assert_msg(strstr(text, "0 modes") == NULL && strstr(text, "x0.000000") == NULL, "%s", text);
    ck_assert_msg(strstr(text, "no marks") != NULL && strstr(text, "×1 per step") != NULL, "%s", text);
    free(text);
    sw_frame_free(&f);
    sw_app_free(&a);
}
END_TEST

/* A report by hand: series 0 and 1 on the same points, series 2 apart. */
static void fake_report(sw_bench_report *r)
{
    memset(r, 0, sizeof *r);
    ck_assert_int_ge(sw_integrator_count(), 12);
    r->scene = sw_scene_find("vortex");
    r->nseries = 3;
    for (int i = 0; i < 3; i++) {
        sw_bench_series *s = &r->series[i];
        s->method = sw_integrator_at(9 + i); /* markers a, b, c: no axis label has them */
        s->npoints = 4;
        for (int j = 0; j < 4; j++) {
            s->points[j].evals = 10L << j;
            s->points[j].error = i < 2 ? pow(10, -j) : 1e-6 * pow(10, -j);
        }
    }
}

/* Two series on the same points: the one drawn last shows, the other
 * takes one cell back (neither is hidden whole), and both pairs are
 * named; a series alone keeps its marker. */
START_TEST(workprec_overlap_marks)
{
    sw_bench_report *r = malloc(sizeof *r);
    fake_report(r);
    int rows = 12, cols = 40;
    char *g = malloc((size_t)(rows + 2) * (size_t)cols);
    sw_workprec_overlap ov;
    ck_assert_int_eq(sw_workprec_grid(r, NULL, 0, SW_BENCH_X_EVALS, g, rows, cols, &ov), 1);
    int seen[3] = { 0, 0, 0 };
    for (int k = 0; k < rows * cols; k++)
        for (int i = 0; i < 3; i++)
            seen[i] += g[k] == sw_bench_marker(r->series[i].method);
    ck_assert_ptr_null(memchr(g, '&', (size_t)rows * (size_t)cols));
    ck_assert_int_eq(seen[0] + seen[1], 4); /* one marker per shared cell */
    ck_assert_int_ge(seen[0], 1);           /* neither hidden whole */
    ck_assert_int_ge(seen[1], 1);
    ck_assert_int_eq(seen[2], 4);
    ck_assert_int_eq(ov.n, 2);              /* 0 under 1, and 1 under 0 where 0 took its cell back */
    ck_assert_int_eq(ov.under[0], 0);
    ck_assert_int_eq(ov.over[0], 1);
    ck_assert_int_eq(ov.under[1], 1);
    ck_assert_int_eq(ov.over[1], 0);
    /* apart: no pair */
    for (int j = 0; j < 4; j++)
        r->series[1].points[j].error = 1e3 * pow(10, -j);
    ck_assert_int_eq(sw_workprec_grid(r, NULL, 0, SW_BENCH_X_EVALS, g, rows, cols, &ov), 1);
    ck_assert_int_eq(ov.n, 0);
    free(g);
    free(r);
}
END_TEST

/* Lesson 6, "Error against cost", at 80x24 with the plot open: each row
 * of the table (euler 503, midpoint 252 × 2, rk4 126 × 4 evaluations;
 * errors 0.04, 0.00064, 3e-7) has a point of the live sweep within a
 * factor 1.2 in cost and 1.5 in error (the sweep's steps are halvings of
 * its own top step, the table's are round numbers), that point is drawn
 * (its marker, or named under the plot), and the page's table stays on the
 * screen before and after the question is answered. */
START_TEST(workprec_table_points_beside_the_text)
{
    static const struct {
        const char *method;
        double evals, error;
    } table[] = { { "euler", 503, 0.04 }, { "midpoint", 504, 0.00064 }, { "rk4", 504, 3e-7 } };
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    ct_open_page(r, &a, "lessons/06-runge-kutta.lesson", "Error against cost");
    ck_assert_int_eq(sw_app_key(&a, 'w', 1), 1);
    sw_app_sweep_wait(&a);
    ck_assert_ptr_nonnull(a.bench);
    const sw_bench_report *b = a.bench;
    for (size_t t = 0; t < sizeof table / sizeof table[0]; t++) {
        int found = 0;
        for (int i = 0; i < b->nseries; i++) {
            const sw_bench_series *s = &b->series[i];
            if (strcmp(s->method->name, table[t].method) != 0)
                continue;
            for (int j = 0; j < s->npoints; j++) {
                const sw_bench_point *pt = &s->points[j];
                if (!pt->blown && fabs(log((double)pt->evals / table[t].evals)) <= log(1.2) &&
                    fabs(log(pt->error / table[t].error)) <= log(1.5))
                    found = 1;
            }
        }
        ck_assert_msg(found, "the plot's sweep has no %s point near %g evaluations, error %g", table[t].method,
                      table[t].evals, table[t].error);
    }
    sw_frame f;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    for (int answered = 0; answered < 2; answered++) {
        if (answered)
            sw_runner_key(r, &a, 'B');
        int clipped;
        char *text = ct_compose(&f, &a, sw_runner_side(r, &a, 80), 80, 24, &clipped);
        ck_assert_msg(strstr(text, "error vs evaluations") != NULL, "the plot is not shown:\n%s", text);
        /* open: the text beside the plot; answered: the pane at its end, the feedback (its title on top) */
        ck_assert_msg(strstr(text, "Error against cost") != NULL &&
                      strstr(text, answered ? "B) " : "for one turn") != NULL,
                      "%s: the plot hides the page's text:\n%s", answered ? "answered" : "open", text);
        ck_assert_msg(strstr(text, "shared cell") != NULL || strstr(text, "no two series share") != NULL,
                      "shared cells are not said:\n%s", text);
        free(text);
    }
    sw_frame_free(&f);
    sw_app_free(&a);
    sw_runner_free(r);
    free(r);
}
END_TEST

/* The projectile's picture names its launch level and the energy's
 * reference (½m|v0|² = 62.5 J with the defaults), at 80x24 and 120x40. */
START_TEST(projectile_says_launch_and_energy)
{
    const sw_scene *sc = sw_scene_find("projectile");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    sw_app a;
    ck_assert_msg(sw_app_init(&a, sc, p, NULL, sc->dt, err, sizeof err) == SW_OK, "%s", err);
    static const int sizes[2][2] = { { 80, 24 }, { 120, 40 } };
    for (int s = 0; s < 2; s++) {
        sw_frame f;
        ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
        int clipped;
        char *text = ct_compose(&f, &a, NULL, sizes[s][0], sizes[s][1], &clipped);
        ck_assert_msg(strstr(text, "launch height") != NULL, "%s", text);
        ck_assert_msg(strstr(text, "launch kinetic energy, 62.5 J") != NULL, "%s", text);
        ck_assert_int_eq(clipped, 0);
        free(text);
        sw_frame_free(&f);
    }
    sw_app_free(&a);
}
END_TEST

/* @view box=X0,Y0,X1,Y1: parsed, checked, and the camera shows that
 * rectangle (the scene's own view is far larger). */
START_TEST(view_box_directive)
{
    const char *text = "title: T\n--- P\n@scene projectile\n@view box=5,-1.5,11,3\nx\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(sw_lesson_parse("t", text, strlen(text), &l, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(l.pages[0].has_box, 1);
    ck_assert_double_eq(l.pages[0].box[0], 5);
    ck_assert_double_eq(l.pages[0].box[1], -1.5);
    ck_assert_double_eq(l.pages[0].box[2], 11);
    ck_assert_double_eq(l.pages[0].box[3], 3);
    sw_lesson_free(&l);
    const char *bad[] = { "box=1,2,3", "box=1,2,3,4,5", "box=1,,2,3", "box=3,0,1,1", "box=0,3,1,1", "box=a,b,c,d",
                          "box=1,2,3,4,", "box=1e7,0,2e7,1", "box=", "box=nan,0,1,1" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char t[256];
        snprintf(t, sizeof t, "title: T\n--- P\n@scene projectile\n@view %s\nx\n", bad[i]);
        ck_assert_msg(sw_lesson_parse("t", t, strlen(t), &l, err, sizeof err) == SW_EINVAL, "'%s' was accepted",
                      bad[i]);
        ck_assert_msg(strstr(err, "box=") != NULL, "'%s': the message does not say what is expected: %s", bad[i], err);
        sw_lesson_free(&l);
    }
    /* the runner: the camera shows the box, and a page on another scene drops it */
    char dir[] = "/tmp/sw-viewbox-XXXXXX", path[128];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/box.lesson", dir);
    FILE *fp = fopen(path, "w");
    ck_assert_ptr_nonnull(fp);
    fputs("title: T\n--- P\n@scene projectile\n@view box=5,-1.5,11,3\nx\n--- Q\n@scene spring\ny\n", fp);
    fclose(fp);
    setenv("XDG_STATE_HOME", dir, 1);
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    ck_assert_msg(sw_runner_start(r, &a, path, 0, err, sizeof err) == SW_OK, "%s", err);
    sw_frame f;
    char ferr[SW_ERRLEN];
    ck_assert_int_eq(sw_frame_init(&f, ferr, sizeof ferr), SW_OK);
    int clipped;
    free(ct_compose(&f, &a, sw_runner_side(r, &a, 80), 80, 24, &clipped));
    sw_view vis = sw_canvas_visible(&f.canvas), nat = a.scene->view(&a.sims[0].sys);
    ck_assert_msg(vis.xmin <= 5 && vis.xmax >= 11 && vis.ymin <= -1.5 && vis.ymax >= 3,
                  "the camera shows x %g..%g, y %g..%g", vis.xmin, vis.xmax, vis.ymin, vis.ymax);
    /* fitted: one axis spans the box to a cell's rounding */
    ck_assert_msg(vis.xmax - vis.xmin < 6 * 1.05 || vis.ymax - vis.ymin < 4.5 * 1.05, "the box is not fitted");
    ck_assert_double_lt(vis.xmax - vis.xmin, nat.xmax - nat.xmin);
    sw_runner_enter(r, &a, 1);
    ck_assert_int_eq(a.have_box, 0);
    sw_frame_free(&f);
    sw_app_free(&a);
    sw_runner_free(r);
    free(r);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    ck_assert_int_eq(system(cmd), 0);
}
END_TEST

/* A page "names a difference" between a run and its ghost when its prose
 * mentions the ghost and quotes a length in metres or a growth ("grows
 * by"). Every such page must be listed below with the time its point is
 * made at, and there, at 80x24, the difference is visible (a particle and
 * its ghost in different cells) or stated ("ghost 0.44 m" beside it). */
static const struct diff_page {
    const char *file, *title;
    double t;
} diff_pages[] = {
    { "lessons/02-euler.lesson", "The spiral", 6.3 },
    { "lessons/03-particles-with-mass.lesson", "Euler in phase space", 2.0 },
};

static int names_difference(const sw_lesson_page *pg)
{
    int ghost = 0, figure = 0;
    for (int b = 0; b < pg->nblocks; b++) {
        const char *t = pg->blocks[b].text;
        ghost |= strstr(t, "ghost") != NULL;
        figure |= strstr(t, "grows by") != NULL;
        for (const char *q = t; (q = strstr(q, " m")) != NULL; q += 2)
            if (q > t && q[-1] >= '0' && q[-1] <= '9' && !((q[2] >= 'a' && q[2] <= 'z') || (q[2] >= 'A' && q[2] <= 'Z')))
                figure = 1;
    }
    return ghost && figure;
}

/* "ghost 0.44 m" (a number and its unit after the word) on the screen. */
static int gap_stated(const char *text)
{
    for (const char *q = text; (q = strstr(q, "ghost ")) != NULL; q += 6) {
        const char *d = q + 6;
        if (!(*d >= '0' && *d <= '9'))
            continue;
        while ((*d >= '0' && *d <= '9') || *d == '.')
            d++;
        if (strncmp(d, " m", 2) == 0)
            return 1;
    }
    return 0;
}

START_TEST(every_named_difference_is_shown)
{
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    int checked = 0;
    for (int i = 0; i < n; i++) {
        sw_lesson l;
        ck_assert_msg(sw_lesson_load(e[i].path, &l, err, sizeof err) == SW_OK, "%s", err);
        for (int p = 0; p < l.npages; p++) {
            if (!names_difference(&l.pages[p]))
                continue;
            size_t k = 0;
            while (k < sizeof diff_pages / sizeof diff_pages[0] &&
                   !(strstr(e[i].path, diff_pages[k].file + strlen("lessons/")) &&
                     strcmp(l.pages[p].title, diff_pages[k].title) == 0))
                k++;
            ck_assert_msg(k < sizeof diff_pages / sizeof diff_pages[0],
                          "%s page %d (%s) names a difference: list it in diff_pages with its time", e[i].file, p + 1,
                          l.pages[p].title);
            sw_runner *r = malloc(sizeof *r);
            sw_app a;
            ct_open_page(r, &a, diff_pages[k].file, diff_pages[k].title);
            sw_app_set_ghost(&a, 1);
            sw_app_set_until(&a, diff_pages[k].t);
            a.paused = 0;
            for (int it = 0; it < 100000 && a.sims[0].t < diff_pages[k].t; it++)
                sw_app_advance(&a, 1.0, 100000);
            ck_assert_double_eq_tol(a.sims[0].t, diff_pages[k].t, 1e-9);
            sw_frame f;
            char ferr[SW_ERRLEN];
            ck_assert_int_eq(sw_frame_init(&f, ferr, sizeof ferr), SW_OK);
            int clipped;
            char *text = ct_compose(&f, &a, sw_runner_side(r, &a, 80), 80, 24, &clipped);
            const double *g = sw_app_ghost(&a), *y = a.sims[0].sys.y;
            ck_assert_ptr_nonnull(g);
            int apart = 0;
            for (int j = 0; j < a.sims[0].sys.n; j++) {
                int c0, r0, c1, r1;
                if (sw_canvas_world_to_cell(&f.canvas, y[2 * j], y[2 * j + 1], &c0, &r0) &&
                    sw_canvas_world_to_cell(&f.canvas, g[2 * j], g[2 * j + 1], &c1, &r1) && (c0 != c1 || r0 != r1))
                    apart = 1;
            }
            ck_assert_msg(apart || gap_stated(text), "%s, %s at t = %g: the run and its ghost share every cell and "
                          "no gap is written:\n%s", diff_pages[k].file, diff_pages[k].title, diff_pages[k].t, text);
            checked++;
            free(text);
            sw_frame_free(&f);
            sw_app_free(&a);
            sw_runner_free(r);
            free(r);
        }
        sw_lesson_free(&l);
    }
    sw_lesson_list_free(e, n);
    ck_assert_int_eq(checked, (int)(sizeof diff_pages / sizeof diff_pages[0]));
}
END_TEST

Suite *make_point_pictures_suite(void);
Suite *make_point_pictures_suite(void)
{
    Suite *s = suite_create("point_pictures");
    TCase *tc = tcase_create("point_pictures");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, region_scale_choice);
    tcase_add_test(tc, region_marks_move_on_lesson5);
    tcase_add_test(tc, region_scale_stays_when_marks_leave);
    tcase_add_test(tc, region_edge_on_ray);
    tcase_add_test(tc, region_gauge_line);
    tcase_add_test(tc, graph_says_linear);
    tcase_add_test(tc, region_without_modes_says_why);
    tcase_add_test(tc, phase_legend_matches_picture);
    tcase_add_test(tc, phase_axes_named);
    tcase_add_test(tc, lanes_readable_or_refused);
    tcase_add_test(tc, graph_keeps_small_runs_apart);
    tcase_add_test(tc, workprec_overlap_marks);
    tcase_add_test(tc, workprec_table_points_beside_the_text);
    tcase_add_test(tc, projectile_says_launch_and_energy);
    tcase_add_test(tc, view_box_directive);
    tcase_add_test(tc, every_named_difference_is_shown);
    suite_add_tcase(s, tc);
    return s;
}
