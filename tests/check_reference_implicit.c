/* The implicit and Rosenbrock methods' production steps (engine/implicit.c
 * with Newton's four-lane passes in implicit_wide.c, rosenbrock.c with its
 * unrolled stage passes in rosenbrock_wide.c) are their lecture forms
 * (engine/reference_implicit.c: plain loops over the whole state) bit for
 * bit: on every scene each method accepts (up to a size that keeps the test
 * short), at the scene's step and at 20 times it (where Newton needs its
 * line search and continuation, and rodas4 rejects trials), 20 steps of each
 * from the same initial state give the same state after every step
 * (memcmp), the same time, the same status and message, and the same counts
 * of evaluations, solves and Newton iterations. No tolerance: the two do
 * the same IEEE operations in the same order, so any difference is a bug in
 * one. */
#include <check.h>
#include <stdio.h>
#include <string.h>

#include "engine/reference_implicit.h"
#include "stepwise/stepwise.h"
#include "same_bits.h"

enum { STEPS = 20, DIM_MAX = 4000 };

/* Method m against its lecture form on scene sc with parameters p, step h:
 * 1 compared, 0 when m refuses the scene or it is too large. Counts the
 * steps that failed (both alike) into *failed. */
static int compare(const sw_integrator *m, sw_step_fn *lecture, const sw_scene *sc, const double *p, double h,
                   int *failed)
{
    char err[SW_ERRLEN];
    sw_system prod, lect;
    sb_build(sc, p, &prod);
    if (prod.ode->dim > DIM_MAX || sw_integrator_accepts(m, prod.ode, err, sizeof err) != SW_OK) {
        sw_system_free(&prod);
        return 0;
    }
    sb_build(sc, p, &lect);
    int dim = prod.ode->dim;
    sw_stepper *sp = sw_stepper_new(m, prod.ode, err, sizeof err);
    ck_assert_msg(sp != NULL, "%s on %s: %s", m->name, sc->name, err);
    sw_stepper *sl = sw_stepper_new(m, lect.ode, err, sizeof err);
    ck_assert_msg(sl != NULL, "%s on %s: %s", m->name, sc->name, err);
    double tp = 0.0, tl = 0.0;
    long e0 = prod.ode->evals, e1 = lect.ode->evals, s0 = prod.ode->solves, s1 = lect.ode->solves;
    for (int step = 1; step <= STEPS; step++) {
        int rp = sw_stepper_step(sp, prod.ode, &tp, prod.y, h);
        sl->why = NULL;
        int rl = lecture(sl, lect.ode, &tl, lect.y, h);
        ck_assert_msg(rp == rl, "%s on %s, step %d: status %d against %d", m->name, sc->name, step, rp, rl);
        ck_assert_msg((sp->why == NULL) == (sl->why == NULL) && (!sp->why || strcmp(sp->why, sl->why) == 0),
                      "%s on %s, step %d: \"%s\" against \"%s\"", m->name, sc->name, step,
                      sp->why ? sp->why : "-", sl->why ? sl->why : "-");
        int i = sb_first_difference(prod.y, lect.y, dim);
        ck_assert_msg(i < 0, "%s on %s (h = %g), step %d, component %d of %d: production %a, lecture form %a",
                      m->name, sc->name, h, step, i, dim, i < 0 ? 0.0 : prod.y[i], i < 0 ? 0.0 : lect.y[i]);
        ck_assert_msg(tp == tl, "%s on %s, step %d: t %a against %a", m->name, sc->name, step, tp, tl);
        if (rp != SW_OK) {
            (*failed)++;
            break;
        }
    }
    ck_assert_msg(prod.ode->evals - e0 == lect.ode->evals - e1, "%s on %s: %ld evaluations against %ld", m->name,
                  sc->name, prod.ode->evals - e0, lect.ode->evals - e1);
    ck_assert_msg(prod.ode->solves - s0 == lect.ode->solves - s1, "%s on %s: %ld solves against %ld", m->name,
                  sc->name, prod.ode->solves - s0, lect.ode->solves - s1);
    ck_assert_msg(sp->newton_iters == sl->newton_iters, "%s on %s: %ld Newton iterations against %ld", m->name,
                  sc->name, sp->newton_iters, sl->newton_iters);
    sw_stepper_delete(sl);
    sw_stepper_delete(sp);
    sw_system_free(&lect);
    sw_system_free(&prod);
    return 1;
}

/* Every method with a lecture form here on every scene it accepts, at the
 * scene's dt and at 20 dt. */
START_TEST(implicit_steps_are_the_lecture_forms)
{
    int methods = 0;
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        sw_step_fn *lecture = sw_refi_of(m->step);
        if (!lecture)
            continue;
        methods++;
        int scenes = 0, failed = 0;
        for (int j = 0; j < sw_scene_count(); j++) {
            const sw_scene *sc = sw_scene_at(j);
            double p[SW_MAX_PARAMS];
            sw_scene_defaults(sc, p);
            double h = sw_scene_dt(sc, p);
            if (compare(m, lecture, sc, p, h, &failed)) {
                scenes++;
                compare(m, lecture, sc, p, 20 * h, &failed);
            }
        }
        ck_assert_msg(scenes >= 5, "%s: compared on %d scenes", m->name, scenes);
    }
    ck_assert_int_eq(methods, 4);
}
END_TEST

/* The lookup is by the step function: each of the four has its form, and
 * an explicit method none here. */
START_TEST(every_implicit_step_has_its_form)
{
    ck_assert(sw_refi_of(sw_step_implicit_euler) == sw_refi_implicit_euler);
    ck_assert(sw_refi_of(sw_step_implicit_midpoint) == sw_refi_implicit_midpoint);
    ck_assert(sw_refi_of(sw_step_linear_implicit_euler) == sw_refi_linear_implicit_euler);
    ck_assert(sw_refi_of(sw_step_rodas4) == sw_refi_rodas4);
    ck_assert(sw_refi_of(sw_step_rk4) == NULL);
}
END_TEST

Suite *make_reference_implicit_suite(void);
Suite *make_reference_implicit_suite(void)
{
    Suite *s = suite_create("reference_implicit");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, implicit_steps_are_the_lecture_forms);
    tcase_add_test(tc, every_implicit_step_has_its_form);
    suite_add_tcase(s, tc);
    return s;
}
