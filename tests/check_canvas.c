/* The canvas rasteriser: golden frames worked out by hand from the mapping
 * in src/render/canvas.h (u = cols/2 + (x - cx)/s, w = rows/2 - (y - cy)/(2s),
 * cell = floor), the density ramp, Braille bits and UTF-8, aspect, clipping
 * of non-finite and far-off input, bounded trails (real built scenes:
 * check_canvas_scenes.c).
 * Views are chosen so no point lands on a cell boundary unless the
 * arithmetic there is exact. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/scene.h"
#include "render/camera.h"
#include "render/canvas.h"
#include "render/draw.h"
#include "render/trails.h"
#include "util/utf8.h"
#include "alloc_count.h"
#include "canvas_help.h"

/* 12x6, view ±1: s = 1/6, centre (0, 0) -> u = 6, w = 3 exactly: cell (6, 3). */
START_TEST(test_centre_point)
{
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -1, 1, -1, 1);
    sw_canvas_point(&c, 0.0, 0.0, 'o', SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n      o\n\n\n");
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 6, 3), 'o');
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 5, 3), ' ');
    ck_assert_uint_eq(sw_canvas_codepoint(&c, -1, 99), ' ');
    /* y grows upward: a point above the centre lands in a row above */
    sw_canvas_clear(&c);
    sw_canvas_point(&c, 0.05, 0.9, 'x', SW_STYLE_COMPARE1);
    ck_assert_str_eq(ct_frame(&c), "      x\n\n\n\n\n\n");
    ck_assert_int_eq(sw_canvas_style(&c, 6, 0), SW_STYLE_COMPARE1);
    sw_canvas_free(&c);
}
END_TEST

/* 12x6, view ±6: s = 1, col = floor(6 + x), row = floor(3 - y/2). The line
 * (-5.5, 5) -> (5.5, -5) runs from cell (0, 0) to (11, 5); Bresenham with
 * dx = 11, dy = 5 steps two columns per row. dx > 0, dy < 0: '\'. */
START_TEST(test_diagonal_line)
{
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -6, 6, -6, 6);
    sw_canvas_line(&c, -5.5, 5, 5.5, -5, 0, SW_STYLE_SPRING);
    ck_assert_str_eq(ct_frame(&c), "\\\\\n"
                                "  \\\\\n"
                                "    \\\\\n"
                                "      \\\\\n"
                                "        \\\\\n"
                                "          \\\\\n");
    sw_canvas_clear(&c);
    /* the mirror image rises to the right: '/' from (0, 5) to (11, 0) */
    sw_canvas_line(&c, -5.5, -5, 5.5, 5, 0, SW_STYLE_SPRING);
    ck_assert_str_eq(ct_frame(&c), "          //\n"
                                "        //\n"
                                "      //\n"
                                "    //\n"
                                "  //\n"
                                "//\n");
    ck_assert_int_eq(sw_canvas_style(&c, 0, 5), SW_STYLE_SPRING);
    sw_canvas_free(&c);
}
END_TEST

/* Same view. A horizontal spring (-3, 1)..(3, 1): cols 3..9 on row
 * floor(3 - 0.5) = 2, masses on its ends; then a vertical one at x = 0.5
 * (col 6) from y = 5 (row 0) to y = -5 (row 5), drawn later, so it wins
 * the shared cell (6, 2). */
START_TEST(test_springs_between_particles)
{
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -6, 6, -6, 6);
    sw_canvas_line(&c, -3, 1, 3, 1, 0, SW_STYLE_SPRING);
    sw_canvas_mark(&c, -3, 1, 'o', SW_STYLE_MAIN);
    sw_canvas_mark(&c, 3, 1, 'o', SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "\n\n   o-----o\n\n\n\n");
    sw_canvas_line(&c, 0.5, 5, 0.5, -5, 0, SW_STYLE_WARN);
    ck_assert_str_eq(ct_frame(&c), "      |\n"
                                "      |\n"
                                "   o--|--o\n"
                                "      |\n"
                                "      |\n"
                                "      |\n");
    ck_assert_int_eq(sw_canvas_style(&c, 6, 2), SW_STYLE_WARN);
    ck_assert_int_eq(sw_canvas_style(&c, 5, 2), SW_STYLE_SPRING);
    ck_assert_int_eq(sw_canvas_style(&c, 3, 2), SW_STYLE_MAIN);
    /* slope thresholds: |dy| <= 0.4|dx| is '-', |dx| <= 0.4|dy| is '|' */
    sw_canvas_clear(&c);
    sw_canvas_line(&c, -0.5, 0.5, 4.5, 2.4, 0, 0);   /* dy/dx = 0.38 */
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 5, 2), '-');
    sw_canvas_clear(&c);
    sw_canvas_line(&c, 0.5, -4.5, 2.5, 0.5, 0, 0);   /* dx/dy = 0.4 */
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 6, 5), '|');
    sw_canvas_free(&c);
}
END_TEST

/* bounce with one ball: walls at x = 0 and 10, floor at y = 0. View
 * (-1, 11)²: s = 1, cx = cy = 5, col = floor(x + 1), row = floor(5.5 - y/2).
 * Side walls cols 1 and 11 from the floor (row 5) up past the top; the floor
 * row 5 from col 1 to 11, drawn after the sides so the corners are '='.
 * The ball at (5, 3) is cell (6, 4). */
START_TEST(test_walls)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("bounce"), "n=1", NULL);
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -1, 11, -1, 11);
    double y[4] = { 5.0, 3.0, 0.0, 0.0 };
    sw_canvas_draw_system(&c, &sys, y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), " |         |\n"
                                " |         |\n"
                                " |         |\n"
                                " |         |\n"
                                " |    o    |\n"
                                " ===========\n");
    ck_assert_int_eq(sw_canvas_style(&c, 1, 0), SW_STYLE_WALL);
    ck_assert_int_eq(sw_canvas_style(&c, 6, 4), SW_STYLE_MAIN);
    sw_canvas_free(&c);
    sw_system_free(&sys);
}
END_TEST

/* 12x1, view (-6, 6, -1, 1): s = 1, the point (-5.5 + i, 0) is cell i.
 * Counts per cell against the documented ramp 1 + floor(log2 count). */
START_TEST(test_density_ramp)
{
    static const int counts[2][12] = {
        { 0, 1, 2, 3, 4, 7, 8, 16, 32, 64, 128, 256 },
        { 15, 31, 63, 127, 255, 1000, 5, 9, 17, 33, 65, 129 },
    };
    static const char *expect[2] = { " .::--=+*#%@\n", "=+*#%@-=+*#%\n" };
    static double xy[2 * 4000];
    sw_canvas c;
    ct_canvas_new(&c, 12, 1, -6, 6, -1, 1);
    for (int k = 0; k < 2; k++) {
        int n = 0;
        for (int i = 0; i < 12; i++)
            for (int j = 0; j < counts[k][i]; j++, n++) {
                xy[2 * n] = -5.5 + i;
                xy[2 * n + 1] = 0.0;
            }
        /* none of these may count anywhere */
        double bad[][2] = { { NAN, 0 }, { 0, NAN }, { INFINITY, 0 }, { -INFINITY, 0 },
                            { 1e308, 0 }, { 0, -1e308 }, { 6.5, 0 }, { 0, 1.5 } };
        for (size_t b = 0; b < sizeof bad / sizeof bad[0]; b++, n++) {
            xy[2 * n] = bad[b][0];
            xy[2 * n + 1] = bad[b][1];
        }
        sw_canvas_clear(&c);
        sw_canvas_density(&c, xy, n, SW_STYLE_MAIN);
        ck_assert_str_eq(ct_frame(&c), expect[k]);
    }
    sw_canvas_free(&c);
}
END_TEST

/* The vortex with 400 points on 8x4 cells (400 > 32/4): a density pass.
 * Recount independently through sw_canvas_world_to_cell and compare every
 * cell with the ramp; no point is lost (all lie within radius 1 < 1.4). */
START_TEST(test_density_system)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("vortex"), "n=400", NULL);
    sw_canvas c;
    ct_canvas_new(&c, 8, 4, -1.4, 1.4, -1.4, 1.4);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    int count[4][8] = { { 0 } }, total = 0;
    for (int i = 0; i < sys.n; i++) {
        int col, row;
        if (sw_canvas_world_to_cell(&c, sys.y[2 * i], sys.y[2 * i + 1], &col, &row))
            count[row][col]++, total++;
    }
    ck_assert_int_eq(total, 400);
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 8; col++) {
            int k = count[row][col], level = 0;
            while (k > 0 && level < 9)
                k >>= 1, level++; /* level = 1 + floor(log2 count), 0 when empty */
            ck_assert_uint_eq(sw_canvas_codepoint(&c, col, row), (uint32_t)SW_DENSITY_RAMP[level]);
        }
    /* few points: one glyph each */
    sw_system few;
    ct_build(&few, sw_scene_find("vortex"), "n=3", NULL);
    sw_canvas_clear(&c);
    sw_canvas_draw_system(&c, &few, few.y, 0.0, 'x', SW_STYLE_COMPARE1);
    int marks = 0;
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 8; col++)
            marks += sw_canvas_codepoint(&c, col, row) == 'x';
    ck_assert_int_ge(marks, 1);
    ck_assert_int_le(marks, 3);
    /* Braille: flow points are dots, so every non-blank cell is U+2801..U+28FF */
    sw_canvas_set_mode(&c, SW_CANVAS_BRAILLE);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    int dotted = 0;
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 8; col++) {
            uint32_t cp = sw_canvas_codepoint(&c, col, row);
            ck_assert(cp == ' ' || (cp > 0x2800 && cp <= 0x28FF));
            dotted += cp != ' ';
        }
    ck_assert_int_gt(dotted, 4);
    sw_canvas_free(&c);
    sw_system_free(&few);
    sw_system_free(&sys);
}
END_TEST

/* One Braille cell, view ±1: s = 2, dot grid 2x4 with u = 1 + x, w = 2 - y;
 * dot (dc, dr) has its centre at (dc - 0.5, 1.5 - dr). Dot numbers from the
 * Unicode Braille block: columns (1,2,3,7) and (4,5,6,8), bit = dot - 1. */
START_TEST(test_braille_cell)
{
    static const int dot_number[4][2] = { { 1, 4 }, { 2, 5 }, { 3, 6 }, { 7, 8 } };
    sw_canvas c;
    ct_canvas_new(&c, 1, 1, -1, 1, -1, 1);
    sw_canvas_set_mode(&c, SW_CANVAS_BRAILLE);
    for (int dr = 0; dr < 4; dr++)
        for (int dc = 0; dc < 2; dc++) {
            sw_canvas_clear(&c);
            sw_canvas_point(&c, dc - 0.5, 1.5 - dr, 0, SW_STYLE_MAIN);
            ck_assert_uint_eq(sw_canvas_codepoint(&c, 0, 0), 0x2800u + (1u << (dot_number[dr][dc] - 1)));
        }
    /* dots 1 and 8: U+2881 = E2 A2 81 */
    sw_canvas_clear(&c);
    sw_canvas_point(&c, -0.5, 1.5, 0, SW_STYLE_MAIN);
    sw_canvas_point(&c, 0.5, -1.5, 0, SW_STYLE_GHOST);
    ck_assert_str_eq(ct_frame(&c), "\xe2\xa2\x81\n");
    ck_assert_int_eq(sw_canvas_style(&c, 0, 0), SW_STYLE_GHOST);
    /* all eight: U+28FF = E2 A3 BF */
    for (int dr = 0; dr < 4; dr++)
        for (int dc = 0; dc < 2; dc++)
            sw_canvas_point(&c, dc - 0.5, 1.5 - dr, 0, SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "\xe2\xa3\xbf\n");
    /* a glyph overwrites the dots, and a later dot overwrites the glyph */
    sw_canvas_mark(&c, 0, 0, '#', SW_STYLE_WALL);
    ck_assert_str_eq(ct_frame(&c), "#\n");
    sw_canvas_point(&c, 0.5, 1.5, 0, SW_STYLE_MAIN);
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 0, 0), 0x2808u);
    sw_canvas_free(&c);

    /* Two cells, view ±1: s = 1, u = 2 + 2x, w = 2 - 2y. A line at y = 0.9
     * (dot row 0) from x = -0.99 to 0.99 sets dots 1 and 4 of both cells:
     * U+2809 = E2 A0 89. */
    ct_canvas_new(&c, 2, 1, -1, 1, -1, 1);
    sw_canvas_set_mode(&c, SW_CANVAS_BRAILLE);
    sw_canvas_line(&c, -0.99, 0.9, 0.99, 0.9, 0, SW_STYLE_SPRING);
    ck_assert_str_eq(ct_frame(&c), "\xe2\xa0\x89\xe2\xa0\x89\n");
    sw_canvas_free(&c);
}
END_TEST

START_TEST(test_utf8)
{
    char b[4];
    ck_assert_int_eq(sw_utf8_encode('A', b), 1);
    ck_assert_int_eq(b[0], 'A');
    ck_assert_int_eq(sw_utf8_encode(0xE9, b), 2); /* é = C3 A9 */
    ck_assert(memcmp(b, "\xc3\xa9", 2) == 0);
    ck_assert_int_eq(sw_utf8_encode(0x1F600, b), 4); /* F0 9F 98 80 */
    ck_assert(memcmp(b, "\xf0\x9f\x98\x80", 4) == 0);
    ck_assert_int_eq(sw_utf8_encode(0xD800, b), 1);
    ck_assert_int_eq(b[0], '?');
    ck_assert_int_eq(sw_utf8_encode(0x110000, b), 1);
    ck_assert_int_eq(b[0], '?');
}
END_TEST

/* A circle of radius 1 on 40x20 cells, view ±1.2: s = 0.06. Its extent is
 * L = D/s = 33.3 columns and D/(2s) = 16.7 rows. Counting the cells from
 * floor(a) to floor(b) with b - a = L gives between L and L + 2 (exclusive),
 * so W - 2H lies in (-4, 2). Without the aspect correction H would be ~34.
 * In Braille, dots are square: both extents are D/(s/2) = 66.7 dots. */
START_TEST(test_aspect)
{
    sw_canvas c;
    ct_canvas_new(&c, 40, 20, -1.2, 1.2, -1.2, 1.2);
    for (int mode = 0; mode < 2; mode++) {
        sw_canvas_set_mode(&c, mode ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII);
        for (int i = 0; i < 720; i++) {
            double a = 2 * 3.14159265358979323846 * i / 720;
            sw_canvas_point(&c, cos(a), sin(a), 'o', 0);
        }
        int c0 = 99, c1 = -1, r0 = 99, r1 = -1;
        int d0 = 999, d1 = -1, e0 = 999, e1 = -1; /* dot extents */
        for (int row = 0; row < 20; row++)
            for (int col = 0; col < 40; col++) {
                uint32_t cp = sw_canvas_codepoint(&c, col, row);
                if (cp == ' ')
                    continue;
                c0 = col < c0 ? col : c0, c1 = col > c1 ? col : c1;
                r0 = row < r0 ? row : r0, r1 = row > r1 ? row : r1;
                if (mode)
                    for (int dr = 0; dr < 4; dr++)
                        for (int dc = 0; dc < 2; dc++)
                            if ((cp - 0x2800u) & (dr < 3 ? 1u << (dr + 3 * dc) : 0x40u << dc)) {
                                int x = 2 * col + dc, y = 4 * row + dr;
                                d0 = x < d0 ? x : d0, d1 = x > d1 ? x : d1;
                                e0 = y < e0 ? y : e0, e1 = y > e1 ? y : e1;
                            }
            }
        int w = c1 - c0 + 1, h = r1 - r0 + 1;
        ck_assert_msg(fabs(w - (2.0 / 0.06 + 1)) < 1.0 && fabs(h - (2.0 / 0.12 + 1)) < 1.0,
                      "%dx%d cells", w, h);
        ck_assert_int_lt(w - 2 * h, 2);
        ck_assert_int_gt(w - 2 * h, -4);
        if (mode) {
            ck_assert_msg(fabs(d1 - d0 + 1 - (2.0 / 0.03 + 1)) < 1.0, "width %d dots", d1 - d0 + 1);
            ck_assert_msg(fabs(e1 - e0 + 1 - (2.0 / 0.03 + 1)) < 1.0, "height %d dots", e1 - e0 + 1);
        }
    }
    /* a wide view is fitted by x and centred in y */
    sw_view v = { -4, 4, -1, 1 };
    char err[SW_ERRLEN];
    sw_canvas_set_mode(&c, SW_CANVAS_ASCII);
    ck_assert_int_eq(sw_canvas_set_view(&c, &v, err, sizeof err), SW_OK);
    sw_view vis = sw_canvas_visible(&c);
    ck_assert_double_eq_tol(vis.xmin, -4, 1e-12);
    ck_assert_double_eq_tol(vis.xmax, 4, 1e-12);
    ck_assert_double_eq_tol(vis.ymin, -4, 1e-12); /* s = 0.2, 20 rows x 2s = 8 */
    ck_assert_double_eq_tol(vis.ymax, 4, 1e-12);
    sw_canvas_free(&c);
}
END_TEST


/* Non-finite and huge input: points are skipped, lines with a non-finite end
 * draw nothing, lines with huge finite ends are clipped to what is visible.
 * Run under UBSan (make sanitize) this also proves no double->int overflow. */
START_TEST(test_clipping)
{
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -6, 6, -6, 6);
    const double bad[] = { NAN, INFINITY, -INFINITY, 1e308, -1e308, 1e300, -1.7976931348623157e308,
                           12.0, -6.0 - 1e-9, 7.0 };
    int nbad = (int)(sizeof bad / sizeof bad[0]);
    for (int i = 0; i < nbad; i++)
        for (int j = 0; j < nbad; j++) {
            sw_canvas_point(&c, bad[i], bad[j], 'o', 0);
            sw_canvas_mark(&c, bad[i], bad[j], 'o', 0);
            sw_canvas_point(&c, bad[i], 0.0, 'o', 0);
            sw_canvas_point(&c, 0.0, bad[j], 'o', 0);
        }
    ck_assert_str_eq(ct_frame(&c), "\n\n\n\n\n\n");
    /* the right and bottom edges are open: u = cols or w = rows is off */
    sw_canvas_point(&c, 6.0, 0.0, 'o', 0);
    sw_canvas_point(&c, 0.0, -6.0, 'o', 0);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n\n\n\n");
    sw_canvas_point(&c, -6.0, 6.0, 'o', 0); /* the top-left corner is on */
    ck_assert_str_eq(ct_frame(&c), "o\n\n\n\n\n\n");
    sw_canvas_clear(&c);
    /* a non-finite end: nothing, even when the other end is visible */
    const double nonfinite[] = { NAN, INFINITY, -INFINITY };
    for (int i = 0; i < 3; i++) {
        sw_canvas_line(&c, nonfinite[i], 0, 0, 0, 0, 0);
        sw_canvas_line(&c, 0, 0, 1, nonfinite[i], 0, 0);
        sw_canvas_line(&c, nonfinite[i], nonfinite[i], nonfinite[i], nonfinite[i], 0, 0);
    }
    /* far off and not crossing the canvas: nothing */
    sw_canvas_line(&c, -1e308, 1e308, 1e308, 5e307, 0, 0);
    sw_canvas_line(&c, 1e300, 1e300, 2e300, -1e300, 0, 0);
    sw_canvas_line(&c, -1.7976931348623157e308, 7, 1.7976931348623157e308, 7, 0, 0);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n\n\n\n");
    /* the whole row at y = 0.5 (row floor(3 - 0.25) = 2) from ±DBL_MAX ends */
    sw_canvas_line(&c, -1.7976931348623157e308, 0.5, 1.7976931348623157e308, 0.5, 0, 0);
    ck_assert_str_eq(ct_frame(&c), "\n\n------------\n\n\n\n");
    /* y = x from -1e12 to 1e12: clipped to (-6,-6)..(6,6) (crossings exact to
     * ~1e-4, far from any cell boundary that matters: the ends clamp to
     * cells (0, 5) and (11, 0)), one cell per column as in the diagonal test */
    sw_canvas_clear(&c);
    sw_canvas_line(&c, -1e12, -1e12, 1e12, 1e12, 0, 0);
    ck_assert_int_eq(ct_count_cp(&c, '/'), 12);
    ck_assert_int_eq(ct_count_cp(&c, ' '), 72 - 12);
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 0, 5), '/');
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 11, 0), '/');
    /* from ±1e308 the crossings lose all precision (the ends are 1e292
     * apart in the last bit): only safety is promised, and the glyph */
    sw_canvas_clear(&c);
    sw_canvas_line(&c, -1e308, -1e308, 1e308, 1e308, 0, 0);
    sw_canvas_line(&c, -1.7976931348623157e308, -1.7976931348623157e308,
                   1.7976931348623157e308, 1.7976931348623157e308, 0, 0);
    ck_assert_int_eq(ct_count_cp(&c, '/') + ct_count_cp(&c, ' '), 72);
    /* from a visible point to a huge one: runs to the edge */
    sw_canvas_clear(&c);
    sw_canvas_line(&c, 0.5, 0.5, 1e308, 0.5, 0, 0);
    ck_assert_str_eq(ct_frame(&c), "\n\n      ------\n\n\n\n");
    /* slope 1/2 towards (4e307, 2e307): crosses x = 6 at y = 3.25, so cells
     * (6, 2)..(11, 1), Bresenham 3 + 3; interpolating from the far end
     * instead would lose the crossing to cancellation */
    sw_canvas_clear(&c);
    sw_canvas_line(&c, 0.5, 0.5, 4e307, 2e307, 0, 0);
    ck_assert_str_eq(ct_frame(&c), "\n         ///\n      ///\n\n\n\n");
    /* the same in Braille mode */
    sw_canvas_set_mode(&c, SW_CANVAS_BRAILLE);
    for (int i = 0; i < nbad; i++)
        for (int j = 0; j < nbad; j++) {
            sw_canvas_point(&c, bad[i], bad[j], 0, 0);
            sw_canvas_line(&c, bad[i], bad[j], -bad[j], bad[i], 0, 0);
        }
    for (int row = 0; row < 6; row++)
        for (int col = 0; col < 12; col++) {
            uint32_t cp = sw_canvas_codepoint(&c, col, row);
            ck_assert(cp == ' ' || (cp > 0x2800 && cp <= 0x28FF));
        }
    /* a system whose state went non-finite still draws its anchor only */
    sw_system sys;
    ct_build(&sys, sw_scene_find("spring"), NULL, NULL);
    double y[4] = { NAN, INFINITY, 1e308, -1e308 };
    sw_canvas_set_mode(&c, SW_CANVAS_ASCII);
    sw_canvas_draw_system(&c, &sys, y, 0.0, 0, 0);
    ck_assert_int_eq(ct_count_cp(&c, '#'), 1);
    ck_assert_int_eq(ct_count_cp(&c, ' '), 71);
    y[0] = 1e308, y[1] = 0.0; /* a huge but finite mass: the spring runs off the edge */
    sw_canvas_clear(&c);
    sw_canvas_draw_system(&c, &sys, y, 0.0, 0, 0);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n      #-----\n\n\n");
    sw_system_free(&sys);
    sw_canvas_free(&c);
}
END_TEST

START_TEST(test_bad_sizes_and_views)
{
    sw_canvas c;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_canvas_init(&c, 0, 5, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "0x5"));
    sw_canvas_free(&c);
    ck_assert_int_eq(sw_canvas_init(&c, 5000, 5000, err, sizeof err), SW_EINVAL);
    sw_canvas_free(&c);
    ct_canvas_new(&c, 12, 6, -6, 6, -6, 6);
    const sw_view bad[] = { { NAN, 1, 0, 1 }, { 0, INFINITY, 0, 1 }, { 1, 1, 0, 1 }, { 2, 1, 0, 1 },
                            { 0, 1, 3, 3 }, { -1e308, 1e308, 0, 1 }, { 0, 1, -1e308, 1e308 } };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err[0] = '\0';
        ck_assert_int_eq(sw_canvas_set_view(&c, &bad[i], err, sizeof err), SW_EINVAL);
        ck_assert_ptr_nonnull(strstr(err, "xmin < xmax"));
    }
    /* the old view stands */
    sw_canvas_point(&c, -5.5, 5, 'o', 0);
    ck_assert_str_eq(ct_frame(&c), "o\n\n\n\n\n\n");
    /* resize: new size, same view, blank; bad size keeps the old canvas */
    ck_assert_int_eq(sw_canvas_resize(&c, 0, 3, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(c.cols, 12);
    ck_assert_int_eq(c.rows, 6);
    ck_assert_int_eq(sw_canvas_resize(&c, 6, 3, err, sizeof err), SW_OK);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n");
    /* view ±6 on 6x3: s = 2, col = floor(3 + x/2), row = floor(1.5 - y/4) */
    sw_canvas_point(&c, -5.5, 5, 'o', 0);
    sw_canvas_point(&c, 5.5, -5, 'x', 0);
    ck_assert_str_eq(ct_frame(&c), "o\n\n     x\n");
    /* to_text writes nothing unless everything fits */
    char small[8] = "zzzzzzz";
    ck_assert_uint_eq(sw_canvas_to_text(&c, small, sizeof small), 10);
    ck_assert_str_eq(small, "");
    ck_assert_uint_eq(sw_canvas_to_text(&c, NULL, 0), 10);
    ck_assert_uint_ge(sw_canvas_text_size(&c), 11);
    sw_canvas_free(&c);
    sw_canvas_free(&c); /* freeing twice is allowed */
}
END_TEST

/* Trails: capacity 4, one particle stepping one cell right per push along
 * row 2 (s = 1 view, y = 0.5). After six pushes frames 2..5 remain with ages
 * 3, 2, 1, 0: fade 1 + floor(2a/4) = 2, 2, 1, 1, so "..::" from col 2. */
START_TEST(test_trails)
{
    sw_trails tr;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_trails_init(&tr, 0, 4, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_trails_init(&tr, 1 << 12, 1 << 12, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_trails_init(&tr, 1, 4, err, sizeof err), SW_OK);
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -6, 6, -6, 6);
    for (int i = 0; i < 6; i++) {
        double xy[2] = { -5.5 + i, 0.5 };
        sw_trails_push(&tr, xy, 1);
    }
    sw_canvas_draw_trails(&c, &tr, SW_STYLE_TRAIL);
    ck_assert_str_eq(ct_frame(&c), "\n\n  ..::\n\n\n\n");
    ck_assert_int_eq(sw_canvas_fade(&c, 2, 2), 2);
    ck_assert_int_eq(sw_canvas_fade(&c, 5, 2), 1);
    ck_assert_int_eq(sw_canvas_style(&c, 5, 2), SW_STYLE_TRAIL);
    /* the particle drawn on top of its own trail */
    sw_canvas_mark(&c, -0.5, 0.5, 'o', SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "\n\n  ..:o\n\n\n\n");
    ck_assert_int_eq(sw_canvas_fade(&c, 5, 2), 0);

    /* ten times the capacity of pushes: still four frames, same memory, no
     * allocation, and at most four cells drawn */
    const double *mem = tr.xy;
    int most = 0, head_max = 0;
    long before = sw_test_allocations(); /* no Check asserts inside: they allocate */
    for (int i = 0; i < 40; i++) {
        double xy[2] = { -5.5 + (i % 12), 2.5 - (i % 6) };
        sw_trails_push(&tr, xy, 1);
        most = tr.count > most ? tr.count : most;
        head_max = tr.head > head_max ? tr.head : head_max;
    }
    sw_canvas_clear(&c);
    sw_canvas_draw_trails(&c, &tr, SW_STYLE_TRAIL);
    ck_assert_int_eq(sw_test_allocations(), before);
    ck_assert_int_eq(most, 4);
    ck_assert_int_eq(head_max, 3);
    ck_assert_ptr_eq(tr.xy, mem);
    ck_assert_int_eq(tr.count, 4);
    ck_assert_int_eq(ct_count_cp(&c, ':') + ct_count_cp(&c, '.'), 4);
    /* clear forgets; NaN and missing points leave nothing */
    sw_trails_clear(&tr);
    sw_canvas_clear(&c);
    sw_canvas_draw_trails(&c, &tr, SW_STYLE_TRAIL);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n\n\n\n");
    double nan_xy[2] = { NAN, 0.0 };
    sw_trails_push(&tr, nan_xy, 1);
    sw_trails_push(&tr, nan_xy, 0);
    sw_canvas_draw_trails(&c, &tr, SW_STYLE_TRAIL);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n\n\n\n");
    sw_trails_free(&tr);
    sw_trails_free(&tr);
    sw_canvas_free(&c);
}
END_TEST

Suite *make_canvas_suite(void);
Suite *make_canvas_suite(void)
{
    Suite *s = suite_create("canvas");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_centre_point);
    tcase_add_test(tc, test_diagonal_line);
    tcase_add_test(tc, test_springs_between_particles);
    tcase_add_test(tc, test_walls);
    tcase_add_test(tc, test_density_ramp);
    tcase_add_test(tc, test_density_system);
    tcase_add_test(tc, test_braille_cell);
    tcase_add_test(tc, test_utf8);
    tcase_add_test(tc, test_aspect);
    tcase_add_test(tc, test_clipping);
    tcase_add_test(tc, test_bad_sizes_and_views);
    tcase_add_test(tc, test_trails);
    suite_add_tcase(s, tc);
    return s;
}
