/* The ghost's gap made visible (render/gap.c): a run and its ghost in one
 * cell drawn as '&', and the gap written beside the run with its unit, in
 * a canvas and in a whole 80x24 frame (lesson 3 page 3's 0.44 m at t = 2),
 * and a cloud of dots on its ghost. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "render/draw.h"
#include "render/gap.h"
#include "render/screen.h"
#include "stepwise/stepwise.h"

START_TEST(shared_cell_and_label)
{
    sw_app a;
    char err[SW_ERRLEN], text[4096];
    ck_assert_msg(sw_app_init(&a, sw_scene_find("spring"), NULL, sw_integrator_find("euler"), 0.02, err,
                              sizeof err) == SW_OK, "%s", err);
    const sw_sim *s = &a.sims[0];
    double other[4];
    memcpy(other, s->sys.y, sizeof other);
    other[0] += 0.003; /* 3 mm: far less than a cell */
    sw_canvas c;
    ck_assert_int_eq(sw_canvas_init(&c, 40, 12, err, sizeof err), SW_OK);
    sw_view v = s->sys.scene->view(&s->sys);
    ck_assert_int_eq(sw_canvas_set_view(&c, &v, err, sizeof err), SW_OK);
    sw_canvas_draw_system(&c, &s->sys, other, s->t, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    sw_canvas_draw_system(&c, &s->sys, s->sys.y, s->t, SW_GLYPH_MAIN, SW_STYLE_MAIN);
    double gap = sw_canvas_draw_gap(&c, &s->sys, s->sys.y, other, s->t, "ghost", SW_STYLE_GHOST);
    ck_assert_double_eq_tol(gap, 0.003, 1e-12);
    int col, row;
    ck_assert(sw_canvas_world_to_cell(&c, s->sys.y[0], s->sys.y[1], &col, &row));
    ck_assert_uint_eq(sw_canvas_codepoint(&c, col, row), SW_GLYPH_BOTH);
    sw_canvas_to_text(&c, text, sizeof text);
    ck_assert_msg(strstr(text, "gap to ghost 0.003 m"), "%s", text);
    /* apart by cells: each keeps its glyph; without a label nothing is written */
    sw_canvas_clear(&c);
    other[0] += 1.0;
    sw_canvas_draw_system(&c, &s->sys, other, s->t, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    sw_canvas_draw_system(&c, &s->sys, s->sys.y, s->t, SW_GLYPH_MAIN, SW_STYLE_MAIN);
    ck_assert(isnan(sw_canvas_draw_gap(&c, &s->sys, s->sys.y, other, s->t, NULL, SW_STYLE_GHOST)));
    ck_assert_uint_eq(sw_canvas_codepoint(&c, col, row), SW_GLYPH_MAIN);
    sw_canvas_free(&c);
    sw_app_free(&a);
}
END_TEST

/* Lesson 1's cloud (the vortex's 200 points) under rk4 with the ghost on:
 * the page says the computed dots sit on the ghost, so every cell a dot and
 * its ghost share shows '&' (the newcomer saw nothing of the ghost when a
 * cloud got no marks). */
START_TEST(cloud_on_its_ghost)
{
    sw_app a;
    char err[SW_ERRLEN];
    ck_assert_msg(sw_app_init(&a, sw_scene_find("vortex"), NULL, sw_integrator_find("rk4"), 0.05, err,
                              sizeof err) == SW_OK, "%s", err);
    const sw_sim *s = &a.sims[0];
    ck_assert_int_ge(s->sys.n, 200);
    ck_assert_int_le(s->sys.n, SW_GAP_MARK_MAX);
    sw_canvas c;
    ck_assert_int_eq(sw_canvas_init(&c, 40, 20, err, sizeof err), SW_OK);
    sw_view v = s->sys.scene->view(&s->sys);
    ck_assert_int_eq(sw_canvas_set_view(&c, &v, err, sizeof err), SW_OK);
    sw_canvas_draw_system(&c, &s->sys, s->sys.y, s->t, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    sw_canvas_draw_system(&c, &s->sys, s->sys.y, s->t, SW_GLYPH_MAIN, SW_STYLE_MAIN);
    sw_canvas_draw_gap(&c, &s->sys, s->sys.y, s->sys.y, s->t, "ghost", SW_STYLE_GHOST);
    int shared = 0, other = 0;
    for (int i = 0; i < s->sys.n; i++) {
        int col, row;
        if (!sw_canvas_world_to_cell(&c, s->sys.y[2 * i], s->sys.y[2 * i + 1], &col, &row))
            continue;
        if (sw_canvas_codepoint(&c, col, row) == SW_GLYPH_BOTH)
            shared++;
        else
            other++;
    }
    ck_assert_msg(shared > 0 && other == 0, "%d dots on their ghost drawn '&', %d not", shared, other);
    sw_canvas_free(&c);
    sw_app_free(&a);
}
END_TEST

/* The projectile under Euler at dt = 0.05, stopped at t = 2 with the ghost
 * on: an 80x24 frame writes the gap, 0.44 m (lesson 3 page 3's figure). */
START_TEST(frame_shows_gap_at_80x24)
{
    sw_app a;
    char err[SW_ERRLEN];
    ck_assert_msg(sw_app_init(&a, sw_scene_find("projectile"), NULL, sw_integrator_find("euler"), 0.05, err,
                              sizeof err) == SW_OK, "%s", err);
    sw_app_set_ghost(&a, 1);
    sw_app_set_until(&a, 2.0);
    sw_app_key(&a, 'u', 0);
    ck_assert(a.sims[0].t == 2.0);
    sw_frame f;
    sw_screen scr;
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_screen_init(&scr, 80, 24, err, sizeof err), SW_OK);
    sw_frame_compose(&f, &a, NULL, &scr);
    static char text[80 * 24 * 4 + 64];
    sw_screen_to_text(&scr, text, sizeof text);
    ck_assert_msg(strstr(text, "ghost 0.44 m"), "%s", text);
    sw_screen_free(&scr);
    sw_frame_free(&f);
    sw_app_free(&a);
}
END_TEST

Suite *make_gap_suite(void);
Suite *make_gap_suite(void)
{
    Suite *s = suite_create("gap");
    TCase *tc = tcase_create("gap");
    tcase_add_test(tc, shared_cell_and_label);
    tcase_add_test(tc, frame_shows_gap_at_80x24);
    tcase_add_test(tc, cloud_on_its_ghost);
    suite_add_tcase(s, tc);
    return s;
}
