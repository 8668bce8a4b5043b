/* The picture's pieces, each against what it must show: text fitted and
 * wrapped without a cut word, phase coordinates against the closed form,
 * the stability region against the methods' known amplification factors,
 * the camera fixed on the scene, particles off the view marked at the
 * edge, compare restarting every method together, lanes with their own
 * titles, @speed and @view. */
#include <check.h>
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "canvas_help.h"
#include "lesson/lesson.h"
#include "render/region.h"
#include "render/screen.h"
#include "render/text.h"
#include "stepwise/stepwise.h"
#include "util/num.h"

static void app_with(sw_app *a, const char *scene, const char *method, double dt, const char *set)
{
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    char buf[128];
    snprintf(buf, sizeof buf, "%s", set ? set : "");
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " "))
        ck_assert_msg(sw_scene_set(sc, p, tok, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_app_init(a, sc, p, method ? sw_integrator_find(method) : NULL, dt, err, sizeof err) == SW_OK,
                  "%s", err);
}

START_TEST(fit_drops_least_important_first)
{
    sw_field f[4] = { { "spring", "", 5 }, { "euler", "", 10 }, { "energy -26%", "E-26%", 7 },
                      { "evals 49", "", 2 } };
    char out[256];
    ck_assert_int_eq(sw_text_fit(out, sizeof out, 80, f, 4, "  "), 36);
    ck_assert_str_eq(out, "spring  euler  energy -26%  evals 49");
    /* brief forms first (the energy), then the least important field goes */
    sw_text_fit(out, sizeof out, 30, f, 4, "  ");
    ck_assert_str_eq(out, "spring  euler  E-26%  evals 49");
    sw_text_fit(out, sizeof out, 24, f, 4, "  ");
    ck_assert_str_eq(out, "spring  euler  E-26%");
    sw_text_fit(out, sizeof out, 12, f, 4, "  ");
    ck_assert_str_eq(out, "euler  E-26%");
    ck_assert_int_eq(sw_text_fit(out, sizeof out, 3, f, 4, "  "), 0);
    ck_assert_str_eq(out, "");
}
END_TEST

START_TEST(wrap_never_cuts_a_word)
{
    char lines[16][SW_TEXT_LINE];
    const char *text = "dt=0.025: error 0.0812 at t=6.28 (was 0.166 at dt=0.05), ratio 2.04, order ~1.03";
    for (int w = 12; w <= 90; w++) {
        int n = sw_text_wrap(text, w, lines, 16);
        ck_assert_int_le(n, 16);
        char joined[512] = "";
        for (int i = 0; i < n; i++) {
            ck_assert_int_le(sw_text_cells(lines[i]), w);
            strcat(joined, i ? " " : "");
            strcat(joined, lines[i]);
        }
        ck_assert_str_eq(joined, text); /* every word whole, in order */
    }
    /* a word longer than a line is split, not lost */
    ck_assert_int_eq(sw_text_wrap("/a/very/long/path/name", 8, lines, 16), 3);
    ck_assert_str_eq(lines[0], "/a/very/");
}
END_TEST

/* The spring's stretch and its rate are the closed form's u(t), u'(t). */
START_TEST(phase_point_is_the_state)
{
    sw_app a;
    app_with(&a, "spring", "rk4", 0.001, "c=0");
    ck_assert_int_eq(a.phase_coord, SW_PHASE_STRETCH);
    double q, v, y[4];
    sw_sim *s = &a.sims[0];
    sw_sim_run_until(s, 1.0);
    ck_assert(sw_phase_point(&s->sys, s->sys.y, 0, SW_PHASE_STRETCH, &q, &v));
    ck_assert_int_eq(s->sys.scene->exact(&s->sys, 1.0, y), 0);
    /* the exact state (rest + u, 0, u', 0): stretch u, rate u'; RK4 at 1e-3 agrees to 1e-9 */
    ck_assert_double_eq_tol(q, y[0] - 1.0, 1e-9);
    ck_assert_double_eq_tol(v, y[2], 1e-9);
    sw_app_free(&a);
    /* the pendulum: its angle from straight down, 30 degrees at the start */
    app_with(&a, "stiff-spring", NULL, 0, NULL);
    ck_assert_int_eq(a.phase_coord, SW_PHASE_ANGLE);
    ck_assert(sw_phase_point(&a.sims[0].sys, a.sims[0].sys.y, 0, SW_PHASE_ANGLE, &q, &v));
    ck_assert_double_eq_tol(q, 30 * SW_PI / 180, 1e-12);
    ck_assert_double_eq_tol(v, 0, 1e-15);
    sw_app_free(&a);
    /* the chain: its middle bead, across; the orbit: the radius */
    app_with(&a, "chain", NULL, 0, NULL);
    ck_assert_int_eq(a.phase_coord, SW_PHASE_Y);
    ck_assert_int_eq(a.phase_particle, (a.sims[0].sys.n - 1) / 2);
    sw_app_free(&a);
    app_with(&a, "orbit", NULL, 0, NULL);
    ck_assert_int_eq(a.phase_coord, SW_PHASE_RADIUS);
    sw_app_apply(&a, SW_ACT_PHASE_COORD, 1); /* V: the next coordinate there is */
    ck_assert_int_eq(a.phase_coord, SW_PHASE_X);
    sw_app_free(&a);
}
END_TEST

/* The shaded region is where each method's amplification factor is at most
 * one: Euler 1 + z, backward Euler 1/(1 - z), RK4 1 + z + z²/2 + z³/6 + z⁴/24. */
START_TEST(region_is_the_amplification_factor)
{
    sw_truth_work *w = sw_truth_work_new();
    for (double x = -3.2; x <= 1.2; x += 0.37)
        for (double y = -3.1; y <= 3.1; y += 0.41) {
            double complex z = x + I * y;
            double euler = cabs(1 + z), be = 1 / cabs(1 - z);
            double rk4 = cabs(1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24);
            for (int order = 1; order <= 2; order++) {
                ck_assert_double_eq_tol(sw_region_growth(w, sw_integrator_find("euler"), order, x, y), euler,
                                        1e-12 * (1 + euler));
                ck_assert_double_eq_tol(sw_region_growth(w, sw_integrator_find("implicit-euler"), order, x, y), be,
                                        1e-9 * (1 + be));
                ck_assert_double_eq_tol(sw_region_growth(w, sw_integrator_find("rk4"), order, x, y), rk4,
                                        1e-12 * (1 + rk4));
            }
        }
    sw_truth_work_free(w);
}
END_TEST

static char *compose(sw_frame *f, sw_app *a, int cols, int rows)
{
    int clipped;
    return ct_compose(f, a, NULL, cols, rows, &clipped);
}

/* The region view marks the spring's Δt·λ and says whether they grow. */
START_TEST(region_view_marks_move_with_dt)
{
    sw_app a;
    app_with(&a, "spring", "rk4", 0.005, "k=10000 c=0");
    sw_app_set_view(&a, SW_VIEW_REGION);
    sw_frame f;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    char *t = compose(&f, &a, 100, 30);
    ck_assert_ptr_nonnull(strstr(t, "all inside"));
    free(t);
    for (int k = 0; k < 3; k++) /* 0.01, 0.02, 0.04: ωΔt = 4 > 2√2 */
        sw_app_apply(&a, SW_ACT_DT_DOUBLE, 1);
    t = compose(&f, &a, 100, 30);
    ck_assert_msg(strstr(t, "X 2 outside") != NULL, "%s", t);
    ck_assert_ptr_nonnull(strstr(t, "GROWS"));
    free(t);
    sw_frame_free(&f);
    sw_app_free(&a);
}
END_TEST

/* The camera stays on the scene's own view while Euler's vortex grows, and
 * particles that leave it are marked at the edge with their distance. */
START_TEST(camera_fixed_and_edges_marked)
{
    sw_app a;
    app_with(&a, "vortex", "euler", 0.4, NULL);
    sw_frame f;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    free(compose(&f, &a, 80, 24));
    sw_view v0 = f.view;
    for (int i = 0; i < 400; i++)
        sw_app_advance(&a, 1.0 / 60, 100000);
    char *t = compose(&f, &a, 80, 24);
    ck_assert(f.view.xmin == v0.xmin && f.view.xmax == v0.xmax && f.view.ymin == v0.ymin && f.view.ymax == v0.ymax);
    /* at Δt = 0.4 the outer ring leaves the view (x1.08 per step): arrows at the edge */
    ck_assert_msg(strchr(t, '>') && strchr(t, '<'), "%s", t);
    free(t);
    /* zoomed out by 4 the same state is back in view: no arrows */
    a.zoom = 8;
    t = compose(&f, &a, 80, 24);
    char *status = strstr(t, "o vortex");
    ck_assert_ptr_nonnull(status);
    *status = '\0';
    ck_assert_msg(!strchr(t, '>') && !strchr(t, '<'), "%s", t);
    free(t);
    sw_frame_free(&f);
    sw_app_free(&a);
    /* the canvas-level rule: a point beyond the right edge gets a '>' in the last column */
    sw_canvas c;
    ck_assert_int_eq(sw_canvas_init(&c, 40, 10, err, sizeof err), SW_OK);
    sw_view v = { -1, 1, -1, 1 };
    sw_canvas_set_view(&c, &v, err, sizeof err);
    double xy[4] = { 10, 0, 0, 0 };
    ck_assert_int_eq(sw_canvas_offscreen(&c, xy, 2, NULL, 0, 1), 1);
    int col, row;
    ck_assert(sw_canvas_world_to_cell(&c, 0, 0, &col, &row));
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 39, row), '>');
    ck_assert_uint_eq(sw_canvas_codepoint(&c, 38, row), '0'); /* "10" beside it */
    sw_canvas_free(&c);
}
END_TEST

/* Compare restarts every method together from the start; lanes give each its title. */
START_TEST(compare_restarts_together)
{
    sw_app a;
    app_with(&a, "orbit", "euler", 0.01, NULL);
    for (int i = 0; i < 30; i++)
        sw_app_apply(&a, SW_ACT_STEP, 1);
    ck_assert_double_gt(fabs(sw_sim_energy_drift(&a.sims[0])), 1e-3);
    sw_app_key(&a, 'c', 0);
    sw_app_key(&a, ' ', 0); /* (compare restarts the runs paused) */
    ck_assert_int_eq(a.nsims, 3);
    for (int i = 0; i < a.nsims; i++) {
        ck_assert_double_eq(a.sims[i].t, 0);
        ck_assert_int_eq(a.sims[i].steps, 0);
    }
    a.paused = 0;
    for (int i = 0; i < 60; i++)
        sw_app_advance(&a, 1.0 / 60, 100000);
    ck_assert_double_lt(fabs(sw_sim_energy_drift(&a.sims[1])), 1e-4); /* rk4, its own start */
    ck_assert_double_eq_tol(a.sims[1].t, a.sims[0].t, 1e-12);
    a.lanes = 1;
    sw_frame f;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    char *t = compose(&f, &a, 120, 40);
    ck_assert_msg(strstr(t, "o euler") && strstr(t, "x rk4") && strstr(t, "+ verlet"), "%s", t);
    free(t);
    sw_frame_free(&f);
    sw_app_free(&a);
}
END_TEST

/* @speed and @view are read and checked. */
START_TEST(speed_and_view_directives)
{
    const char *text = "title: T\n--- P\n@scene spring\n@speed 4\n@view phase follow lanes zoom=2\nx\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(sw_lesson_parse("t", text, strlen(text), &l, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_double_eq(l.pages[0].speed, 4);
    ck_assert_int_eq(l.pages[0].view, SW_LESSON_VIEW_PHASE);
    ck_assert_int_eq(l.pages[0].follow, 1);
    ck_assert_int_eq(l.pages[0].lanes, 1);
    ck_assert_double_eq(l.pages[0].zoom, 2);
    sw_lesson_free(&l);
    const char *bad[] = { "@speed 0", "@speed fast", "@view sideways", "@view zoom=0", "@view", "@speed 2\n@speed 3" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char t[256];
        snprintf(t, sizeof t, "title: T\n--- P\n@scene spring\n%s\nx\n", bad[i]);
        ck_assert_msg(sw_lesson_parse("t", t, strlen(t), &l, err, sizeof err) == SW_EINVAL, "'%s' was accepted", bad[i]);
        sw_lesson_free(&l);
    }
}
END_TEST

Suite *make_picture_suite(void);
Suite *make_picture_suite(void)
{
    Suite *s = suite_create("picture");
    TCase *tc = tcase_create("picture");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, fit_drops_least_important_first);
    tcase_add_test(tc, wrap_never_cuts_a_word);
    tcase_add_test(tc, phase_point_is_the_state);
    tcase_add_test(tc, region_is_the_amplification_factor);
    tcase_add_test(tc, region_view_marks_move_with_dt);
    tcase_add_test(tc, camera_fixed_and_edges_marked);
    tcase_add_test(tc, compare_restarts_together);
    tcase_add_test(tc, speed_and_view_directives);
    suite_add_tcase(s, tc);
    return s;
}
