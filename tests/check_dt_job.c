/* A Δt change's measurement on a worker (app/dt_job.c, issue 41): the
 * picture's thread hands the runs to a worker when they may take long, the
 * message says so meanwhile, and the figures that come in are the same
 * bits as the same measurement made on the picture's thread; a key pressed
 * again, a new method or a new scene stops the worker and nothing of it is
 * left (ASan and valgrind run this suite with CK_FORK=no). Nothing here
 * times anything: the tests wait for the worker's end, a condition. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "app/app.h"
#include "stepwise/stepwise.h"

/* scene under method at dt, every measurement on the picture's thread
 * (inline) or on the worker. */
static void app_on(sw_app *a, const char *scene, const char *method, double dt, int on_worker)
{
    char err[SW_ERRLEN];
    ck_assert_msg(sw_app_init(a, sw_scene_find(scene), NULL, sw_integrator_find(method), dt, err, sizeof err) ==
                  SW_OK, "%s", err);
    a->work_inline = on_worker ? 0 : INFINITY;
}

/* The vortex under euler at dt = 0.01 (a flow: the runs are the measurement). */
static void vortex(sw_app *a, int on_worker) { app_on(a, "vortex", "euler", 0.01, on_worker); }

/* Two apps, one key sequence: the worker's figures equal the inline ones
 * bit for bit, message included. */
static void same_as_inline_on(const char *scene, const char *method, double dt, double ratio, const char *keys)
{
    sw_app here, there;
    app_on(&here, scene, method, dt, 0);
    app_on(&there, scene, method, dt, 1);
    for (const char *k = keys; *k; k++) {
        sw_app_key(&here, *k, 0);
        sw_app_key(&there, *k, 0);
        ck_assert_ptr_null(here.dt_job);
        ck_assert_ptr_nonnull(there.dt_job);
        ck_assert_msg(strstr(there.message, "measuring the error at dt="), "%s", there.message);
        ck_assert_int_eq(there.nmeas, 0);
        ck_assert(isnan(there.error_ratio));
    }
    sw_app_dt_wait(&there);
    ck_assert_ptr_null(there.dt_job);
    ck_assert_str_eq(there.message, here.message);
    ck_assert_int_eq(there.nmeas, 2);
    ck_assert_int_eq(here.nmeas, 2);
    ck_assert_mem_eq(&there.error_ratio, &here.error_ratio, sizeof here.error_ratio);
    ck_assert_mem_eq(there.meas_err, here.meas_err, sizeof here.meas_err);
    ck_assert_msg(fabs(here.error_ratio / ratio - 1) < 0.1, "%s/%s: ratio %g, expected %g", scene, method,
                  here.error_ratio, ratio);
    sw_app_free(&here);
    sw_app_free(&there);
}

/* On the vortex, euler's ratio per halving is 2 (first order, ±10%: in
 * its asymptotic range at these steps, as check_app.c's). */
static void same_as_inline(const char *keys) { same_as_inline_on("vortex", "euler", 0.01, 2, keys); }

START_TEST(worker_gives_the_same_bits)
{
    same_as_inline("-");
    /* a particle system (the spectrum of its springs at the start, its
     * energy): rk4's 16 per halving on the spring, as check_app.c's */
    same_as_inline_on("spring", "rk4", 0.02, 16, "-");
}
END_TEST

/* A key pressed again while the worker runs: the first measurement is
 * stopped, the second's figures come in (its old step is the first's new). */
START_TEST(key_again_replaces_the_worker)
{
    same_as_inline("--");
    same_as_inline("-+");
}
END_TEST

/* The frame takes the figures when the worker is done (sw_app_advance
 * polls): waited for by its condition, never a timer. */
START_TEST(frame_takes_the_figures)
{
    sw_app a;
    vortex(&a, 1);
    sw_app_key(&a, '-', 0);
    while (a.dt_job) /* the worker's end, polled as the live loop polls it */
        sw_app_advance(&a, 0, 1);
    ck_assert_int_eq(a.nmeas, 2);
    ck_assert_msg(strstr(a.message, "ratio"), "%s", a.message);
    sw_app_free(&a);
}
END_TEST

/* A new method, a new scene or quitting stops the worker: no figure of the
 * old settings comes in afterwards, and nothing leaks. */
START_TEST(settings_change_stops_the_worker)
{
    sw_app a;
    char err[SW_ERRLEN];
    vortex(&a, 1);
    sw_app_key(&a, '-', 0);
    ck_assert_int_eq(sw_app_set_method(&a, sw_integrator_find("midpoint")), SW_OK);
    ck_assert_ptr_null(a.dt_job);
    sw_app_advance(&a, 0, 1);
    ck_assert_int_eq(a.nmeas, 0);
    ck_assert_msg(strstr(a.message, "integrator: midpoint"), "%s", a.message);
    sw_app_key(&a, '-', 0);
    ck_assert_int_eq(sw_app_set_scene(&a, sw_scene_find("spring"), NULL, err, sizeof err), SW_OK);
    ck_assert_ptr_null(a.dt_job);
    sw_app_set_scene(&a, sw_scene_find("vortex"), NULL, err, sizeof err);
    a.work_inline = 0;
    sw_app_key(&a, '+', 0);
    ck_assert_ptr_nonnull(a.dt_job);
    sw_app_free(&a); /* quitting while it runs */
    ck_assert_ptr_null(a.dt_job);
}
END_TEST

/* Where the runs cost little they stay on the picture's thread: the
 * figure is there when the key returns (the lessons' small scenes). */
START_TEST(cheap_measurement_inline)
{
    sw_app a;
    char err[SW_ERRLEN];
    ck_assert_msg(sw_app_init(&a, sw_scene_find("spring"), NULL, sw_integrator_find("rk4"), 0.02, err,
                              sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(a.work_inline, SW_APP_WORK_INLINE);
    sw_app_key(&a, '-', 0);
    ck_assert_ptr_null(a.dt_job);
    ck_assert_int_eq(a.nmeas, 2);
    sw_app_free(&a);
}
END_TEST

Suite *make_dt_job_suite(void);
Suite *make_dt_job_suite(void)
{
    Suite *s = suite_create("dt_job");
    TCase *tc = tcase_create("worker");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, worker_gives_the_same_bits);
    tcase_add_test(tc, key_again_replaces_the_worker);
    tcase_add_test(tc, frame_takes_the_figures);
    tcase_add_test(tc, settings_change_stops_the_worker);
    tcase_add_test(tc, cheap_measurement_inline);
    suite_add_tcase(s, tc);
    return s;
}
