/* The canvas on real built scenes: the spring, the orbit, the chain (and a
 * chain with a particle left out), fireworks before their births, and a view
 * that follows. Golden frames worked out from the mapping in
 * src/render/canvas.h, as in check_canvas.c. */
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
#include "alloc_count.h"
#include "canvas_help.h"

/* spring at its defaults: anchor (0, 0), mass at rest + stretch = 1.5 on the
 * x axis. 21x5 cells, view (-0.3, 1.8, -0.9, 0.9): s = max(0.1, 0.18) = 0.18,
 * cx = 0.75, cy = 0, so u = 10.5 + (x - 0.75)/0.18: anchor 6.33 -> col 6,
 * mass 14.67 -> col 14; row floor(2.5) = 2; the spring fills cols 7..13. */
START_TEST(test_spring_scene)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("spring"), NULL, NULL);
    sw_canvas c;
    ct_canvas_new(&c, 21, 5, -0.3, 1.8, -0.9, 0.9);
    long before = sw_test_allocations();
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_int_eq(sw_test_allocations(), before);
    ck_assert_str_eq(ct_frame(&c), "\n\n      #-------o\n\n\n");
    ck_assert_int_eq(sw_canvas_style(&c, 6, 2), SW_STYLE_WALL);
    ck_assert_int_eq(sw_canvas_style(&c, 10, 2), SW_STYLE_SPRING);
    ck_assert_int_eq(sw_canvas_style(&c, 14, 2), SW_STYLE_MAIN);
    /* the ghost: exact state at t = 0 (the start), its own glyph and dotted spring */
    double ex[4];
    ck_assert_int_eq(sys.scene->exact(&sys, 0.0, ex), 0);
    sw_canvas_clear(&c);
    sw_canvas_draw_system(&c, &sys, ex, 0.0, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    ck_assert_str_eq(ct_frame(&c), "\n\n      #.......'\n\n\n");
    ck_assert_int_eq(sw_canvas_style(&c, 10, 2), SW_STYLE_GHOST);
    /* the scene's own view shows anchor and mass on one row, anchor left */
    sw_view v = sys.scene->view(&sys);
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_canvas_set_view(&c, &v, err, sizeof err), SW_OK);
    int ac, ar, mc, mr;
    ck_assert(sw_canvas_world_to_cell(&c, 0.0, 0.0, &ac, &ar));
    ck_assert(sw_canvas_world_to_cell(&c, sys.y[0], sys.y[1], &mc, &mr));
    ck_assert_int_eq(ar, mr);
    ck_assert_int_lt(ac, mc);
    sw_canvas_clear(&c);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_uint_eq(sw_canvas_codepoint(&c, ac, ar), '#');
    ck_assert_uint_eq(sw_canvas_codepoint(&c, mc, mr), 'o');
    sw_canvas_free(&c);
    sw_system_free(&sys);
}
END_TEST

/* orbit: the sun 'O' at the origin, the planet at periapsis (1 - e, 0) =
 * (0.5, 0). 12x6, view ±1.5: s = 0.25, sun u = 6, w = 3 (exact) -> (6, 3),
 * planet u = 8 -> (8, 3). */
START_TEST(test_orbit_scene)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("orbit"), "e=0.5", NULL);
    sw_canvas c;
    ct_canvas_new(&c, 12, 6, -1.5, 1.5, -1.5, 1.5);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "\n\n\n      O o\n\n\n");
    ck_assert_int_eq(sw_canvas_style(&c, 6, 3), SW_STYLE_WALL);
    sw_canvas_free(&c);
    sw_system_free(&sys);
}
END_TEST

/* chain, n = 4, rest 1, pluck 0.9: anchors (0,0), (5,0), masses at x = 1..4,
 * the third (index 2) lifted to y = 0.9. 24x6, view (-0.625, 5.375, -1.25,
 * 0.75): s = 0.25, col = floor(2.5 + 4x), row = floor(2.5 - 2y): anchors
 * cols 2, 22; masses cols 6, 10, 14, 18 on row 2, the lifted one row 0.
 * Springs drawn from a to b: 1->2 is (14,0)->(10,2) '/', 3->2 is
 * (18,2)->(14,0) '\' (Bresenham: two columns per row), then the straight
 * ones, anchors and masses on top. */
static int skip_third(const sw_system *sys, double t, const double *y, int i)
{
    (void)sys, (void)t, (void)y;
    return i != 2;
}

START_TEST(test_chain_scene)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("chain"), "n=4", "pluck=0.9");
    sw_canvas c;
    ct_canvas_new(&c, 24, 6, -0.625, 5.375, -1.25, 0.75);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "              o\\\n"
                                "            //  \\\\\n"
                                "  #---o---o/      o---#\n"
                                "\n\n\n");
    sw_system_free(&sys);

    /* the same with particle 2 not alive: it and its two springs vanish */
    sw_scene sc = *sw_scene_find("chain");
    sc.alive = skip_third;
    ct_build(&sys, &sc, "n=4", "pluck=0.9");
    sw_canvas_clear(&c);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_str_eq(ct_frame(&c), "\n\n  #---o---o       o---#\n\n\n\n");
    /* trails of the system skip the dead particle too */
    sw_trails tr;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_trails_init(&tr, 8, 2, err, sizeof err), SW_OK);
    sw_trails_push_system(&tr, &sys, sys.y, 0.0);
    sw_canvas_clear(&c);
    sw_canvas_draw_trails(&c, &tr, SW_STYLE_TRAIL);
    ck_assert_str_eq(ct_frame(&c), "\n\n      :   :       :\n\n\n\n");
    sw_trails_free(&tr);
    sw_system_free(&sys);
    sw_canvas_free(&c);
}
END_TEST

/* A crowded system (more points than a quarter of the cells) is drawn as
 * a density for the main run, but a ghost or a compared run keeps its own
 * glyph, or without colour it could not be told from the main run. */
START_TEST(test_crowd_keeps_other_glyphs)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("vortex"), "n=200", NULL);
    sw_canvas c;
    ct_canvas_new(&c, 20, 10, -2, 2, -2, 2);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    int ghost = ct_count_cp(&c, SW_GLYPH_GHOST), dots = ct_count_cp(&c, '.') + ct_count_cp(&c, ':');
    ck_assert_int_gt(ghost, 10);
    ck_assert_int_eq(dots, 0);
    sw_canvas_clear(&c);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_int_eq(ct_count_cp(&c, SW_GLYPH_GHOST), 0);
    ck_assert_int_gt(ct_count_cp(&c, '.') + ct_count_cp(&c, ':'), 10);
    sw_canvas_free(&c);
    sw_system_free(&sys);
}
END_TEST

/* fireworks at t = 0: every spark waits unborn, so nothing is drawn. */
START_TEST(test_fireworks_unborn)
{
    sw_system sys;
    ct_build(&sys, sw_scene_find("fireworks"), NULL, NULL);
    sw_canvas c;
    sw_view v = sys.scene->view(&sys);
    char err[SW_ERRLEN];
    ct_canvas_new(&c, 40, 12, 0, 1, 0, 1);
    ck_assert_int_eq(sw_canvas_set_view(&c, &v, err, sizeof err), SW_OK);
    sw_canvas_draw_system(&c, &sys, sys.y, 0.0, 0, SW_STYLE_MAIN);
    ck_assert_int_eq(ct_count_cp(&c, ' '), 40 * 12);
    sw_canvas_free(&c);
    sw_system_free(&sys);
}
END_TEST

/* Following a view: grows past an escaping point by margin x span, then
 * holds while the point stays inside (no jitter); never shrinks. */
START_TEST(test_view_follow)
{
    sw_view v = { -1, 1, -1, 1 };
    double inside[] = { 0.5, 0.5, -0.9, 0.9, NAN, 0.0, INFINITY, 5.0 };
    ck_assert_int_eq(sw_view_follow(&v, inside, 4, 0.25), 0);
    ck_assert(v.xmin == -1 && v.xmax == 1 && v.ymin == -1 && v.ymax == 1);
    double out[] = { 1.2, 0.0 };
    ck_assert_int_eq(sw_view_follow(&v, out, 1, 0.25), 1);
    ck_assert_double_eq_tol(v.xmax, 1.2 + 0.25 * 2, 1e-12);
    ck_assert(v.xmin == -1 && v.ymin == -1 && v.ymax == 1);
    for (int i = 0; i < 5; i++) {
        out[0] = 1.2 + 0.1 * i; /* creeping on, but inside the margin */
        ck_assert_int_eq(sw_view_follow(&v, out, 1, 0.25), 0);
    }
    out[0] = 1.8, out[1] = -1.5;
    ck_assert_int_eq(sw_view_follow(&v, out, 1, 0.25), 1);
    ck_assert_double_eq_tol(v.xmax, 1.8 + 0.25 * 2.7, 1e-12);
    ck_assert_double_eq_tol(v.ymin, -1.5 - 0.25 * 2, 1e-12);
    /* a blow-up far away is ignored */
    double far[] = { 1e300, 0.0, 0.0, -1e308 };
    sw_view before = v;
    ck_assert_int_eq(sw_view_follow(&v, far, 2, 0.25), 0);
    ck_assert(memcmp(&v, &before, sizeof v) == 0);
}
END_TEST

Suite *make_canvas_scenes_suite(void);
Suite *make_canvas_scenes_suite(void)
{
    Suite *s = suite_create("canvas_scenes");
    TCase *tc = tcase_create("scenes");
    tcase_add_test(tc, test_spring_scene);
    tcase_add_test(tc, test_orbit_scene);
    tcase_add_test(tc, test_chain_scene);
    tcase_add_test(tc, test_fireworks_unborn);
    tcase_add_test(tc, test_crowd_keeps_other_glyphs);
    tcase_add_test(tc, test_view_follow);
    suite_add_tcase(s, tc);
    return s;
}
