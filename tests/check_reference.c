/* The explicit fixed-step methods' production steps (engine/explicit.c:
 * slice by slice, the runaway test folded in, a flow field's fused steps)
 * are their lecture forms (engine/reference.c: plain loops over the whole
 * state) bit for bit: on every scene each method accepts, at its default
 * parameters and step, 50 steps of each from the same initial state give
 * the same state after every step (memcmp), the same time and the same
 * count of derivative evaluations. No tolerance: the two do the same IEEE
 * operations in the same order, so any difference is a bug in one. */
#include <check.h>
#include <stdio.h>
#include <string.h>

#include "engine/reference.h"
#include "engine/stepper.h"
#include "stepwise/stepwise.h"
#include "same_bits.h"

enum { STEPS = 50 };

/* How the production step ran on a system: the system's fused step, slice
 * by slice, or one pass over the whole state. */
enum { FUSED, SLICED, WHOLE, PATHS };

static int path_of(const sw_integrator *m, const sw_ode *ode)
{
    if ((m->step == sw_step_euler && sw_ode_fused_euler(ode)) || (m->step == sw_step_rk4 && sw_ode_fused_rk4(ode)))
        return FUSED;
    return sw_ode_deriv_part(ode) && ode->dim > SW_SLICE ? SLICED : WHOLE;
}

/* Method m against its reference form on scene sc with parameters p: the
 * path the production step took (+1), or 0 when m refuses the scene.
 * Fails at the first step whose state differs. */
static int compare(const sw_integrator *m, sw_ref_step_fn *ref, const sw_scene *sc, const double *p)
{
    char err[SW_ERRLEN];
    sw_system prod, lect;
    sb_build(sc, p, &prod);
    if (sw_integrator_accepts(m, prod.ode, err, sizeof err) != SW_OK) {
        sw_system_free(&prod);
        return 0;
    }
    sb_build(sc, p, &lect);
    int dim = prod.ode->dim;
    ck_assert_int_eq(lect.ode->dim, dim);
    ck_assert_msg(memcmp(prod.y, lect.y, (size_t)dim * sizeof *prod.y) == 0, "%s: two builds differ", sc->name);
    sw_stepper *s = sw_stepper_new(m, prod.ode, err, sizeof err);
    ck_assert_msg(s != NULL, "%s on %s: %s", m->name, sc->name, err);
    int path = path_of(m, prod.ode);
    sw_ref r;
    ck_assert_int_eq(sw_ref_init(&r, dim), SW_OK);
    double h = sw_scene_dt(sc, p), tp = 0.0, tl = 0.0;
    long evals0 = prod.ode->evals, evals1 = lect.ode->evals;
    for (int step = 1; step <= STEPS; step++) {
        ck_assert_int_eq(sw_stepper_step(s, prod.ode, &tp, prod.y, h), SW_OK);
        ref(&r, lect.ode, tl, lect.y, h);
        tl += h;
        int i = sb_first_difference(prod.y, lect.y, dim);
        ck_assert_msg(i < 0, "%s on %s, step %d, component %d of %d: production %a, lecture form %a", m->name,
                      sc->name, step, i, dim, i < 0 ? 0.0 : prod.y[i], i < 0 ? 0.0 : lect.y[i]);
        ck_assert_msg(tp == tl, "%s on %s, step %d: t %a against %a", m->name, sc->name, step, tp, tl);
    }
    ck_assert_msg(prod.ode->evals - evals0 == lect.ode->evals - evals1, "%s on %s: %ld evaluations against %ld",
                  m->name, sc->name, prod.ode->evals - evals0, lect.ode->evals - evals1);
    sw_ref_free(&r);
    sw_stepper_delete(s);
    sw_system_free(&lect);
    sw_system_free(&prod);
    return path + 1;
}

/* Every method with a lecture form on every scene at its defaults, and on
 * each pointwise (flow) scene again with 1031 points, so that the state is
 * cut into several slices and an odd last point ends the fused loops; each
 * of the three production paths must have been taken. */
START_TEST(production_steps_are_the_lecture_forms)
{
    int methods = 0, taken[PATHS] = { 0 };
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        sw_ref_step_fn *ref = sw_ref_of(m->step);
        if (!ref)
            continue;
        methods++;
        int scenes = 0;
        for (int j = 0; j < sw_scene_count(); j++) {
            const sw_scene *sc = sw_scene_at(j);
            double p[SW_MAX_PARAMS];
            char err[SW_ERRLEN];
            sw_scene_defaults(sc, p);
            int path = compare(m, ref, sc, p);
            if (!path)
                continue;
            scenes++;
            taken[path - 1]++;
            sw_system sys;
            sb_build(sc, p, &sys);
            int pointwise = sw_ode_deriv_part(sys.ode) != NULL;
            sw_system_free(&sys);
            if (pointwise) {
                ck_assert_msg(sw_scene_set(sc, p, "n=1031", err, sizeof err) == SW_OK, "%s: %s", sc->name, err);
                int again = compare(m, ref, sc, p);
                ck_assert_msg(again > 0, "%s refuses %s with n=1031", m->name, sc->name);
                taken[again - 1]++;
            }
        }
        ck_assert_msg(scenes > 0, "%s: no scene to compare on", m->name);
    }
    ck_assert_int_ge(methods, 7); /* at least explicit.c's seven (every_explicit_step_has_its_form) */
    for (int i = 0; i < PATHS; i++)
        ck_assert_msg(taken[i] > 0, "production path %d never taken", i);
}
END_TEST

/* Each production step of explicit.c has its lecture form, and only those:
 * the lookup is by the step function, so a row that changes its step (or a
 * plugin's) finds none. */
START_TEST(every_explicit_step_has_its_form)
{
    sw_step_fn *steps[] = { sw_step_euler, sw_step_symplectic_euler, sw_step_midpoint, sw_step_heun,
                            sw_step_rk4, sw_step_verlet, sw_step_yoshida4 };
    sw_ref_step_fn *refs[] = { sw_ref_euler, sw_ref_symplectic_euler, sw_ref_midpoint, sw_ref_heun,
                               sw_ref_rk4, sw_ref_verlet, sw_ref_yoshida4 };
    for (int i = 0; i < 7; i++)
        ck_assert(sw_ref_of(steps[i]) == refs[i]);
    ck_assert(sw_ref_of(sw_step_rk45) == NULL);
    ck_assert(sw_ref_of(sw_step_implicit_euler) == NULL);
}
END_TEST

Suite *make_reference_suite(void);
Suite *make_reference_suite(void)
{
    Suite *s = suite_create("reference");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, production_steps_are_the_lecture_forms);
    tcase_add_test(tc, every_explicit_step_has_its_form);
    suite_add_tcase(s, tc);
    return s;
}
