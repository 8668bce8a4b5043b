/* The explicit adaptive methods' production steps (rk45.c, dop853.c,
 * rkn.c, rkn12.c, dop853_lc.c over the controller in adaptive.c: slices,
 * vector types, the runaway test folded in, one particle's entries, the
 * orbit's field inline) are their lecture forms
 * (engine/reference_adaptive.c: the tableau's rows over the whole state)
 * bit for bit: on every scene each method accepts, under four settings
 * of the tolerances and the largest step, STEPS steps of each from the
 * same state give the same state, time and proposed next step after every
 * step (memcmp; halfway, both proposals are made 50 times too long, so
 * that the controller's rejection is taken where the error never asks for
 * it, as on the regularised orbit), the same counts of accepted steps and rejected trials,
 * and the same count of derivative evaluations. No tolerance: the two do
 * the same IEEE operations in the same order, so any difference is a bug
 * in one. */
#include <check.h>
#include <string.h>

#include "engine/reference_adaptive.h"
#include "engine/stepper.h"
#include "stepwise/stepwise.h"
#include "same_bits.h"

enum { STEPS = 30 };

/* The tolerances and the largest step (a multiple of the scene's Δt): the
 * defaults; loose with long steps, so that trials are rejected; tight;
 * looser with very long steps (only there does dop853-lc's regularised
 * orbit reject a trial once its proposal is made too long). */
static const struct setting {
    double rtol, atol, dt_times;
} settings[] = { { SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, 1 }, { 1e-3, 1e-6, 20 }, { 1e-10, 1e-12, 1 },
                 { 1e-2, 1e-4, 10000 } };

static int same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* What a comparison saw. */
typedef struct seen {
    int compared; /* 1, or 0 when the method refuses the scene */
    long rejected;
    int sliced;
} seen;

/* Method m against its lecture form ref on scene sc with parameters p
 * under setting st. Fails at the first step that differs. */
static seen compare(const sw_integrator *m, sw_ref_adaptive_fn *ref, const sw_scene *sc, const double *p,
                    const struct setting *st)
{
    char err[SW_ERRLEN];
    seen out = { 0 };
    sw_system prod, lect;
    sb_build(sc, p, &prod);
    if (sw_integrator_accepts(m, prod.ode, err, sizeof err) != SW_OK) {
        sw_system_free(&prod);
        return out;
    }
    sb_build(sc, p, &lect);
    int dim = prod.ode->dim;
    sw_stepper *s = sw_stepper_new(m, prod.ode, err, sizeof err);
    ck_assert_msg(s != NULL, "%s on %s: %s", m->name, sc->name, err);
    s->rtol = st->rtol;
    s->atol = st->atol;
    sw_ref_adaptive r;
    ck_assert_int_eq(sw_ref_adaptive_init(&r, dim), SW_OK);
    r.rtol = st->rtol;
    r.atol = st->atol;
    double h = st->dt_times * sw_scene_dt(sc, p), tp = 0.0, tl = 0.0;
    long evals0 = prod.ode->evals, evals1 = lect.ode->evals;
    for (int step = 1; step <= STEPS; step++) {
        if (step == STEPS / 2) { /* a proposal far too long: its trial is rejected, in both */
            s->h_next *= 50;
            r.h_next *= 50;
        }
        int rp = sw_stepper_step(s, prod.ode, &tp, prod.y, h);
        int rl = ref(&r, lect.ode, &tl, lect.y, h);
        ck_assert_msg(rp == rl, "%s on %s, rtol %g, step %d: status %d against %d", m->name, sc->name, st->rtol,
                      step, rp, rl);
        if (rp != SW_OK)
            break;
        for (int i = 0; i < dim; i++)
            ck_assert_msg(same(prod.y[i], lect.y[i]),
                          "%s on %s, rtol %g, step %d, component %d of %d: production %a, lecture form %a",
                          m->name, sc->name, st->rtol, step, i, dim, prod.y[i], lect.y[i]);
        ck_assert_msg(same(tp, tl), "%s on %s, step %d: t %a against %a", m->name, sc->name, step, tp, tl);
        ck_assert_msg(same(s->h_next, r.h_next), "%s on %s, step %d: next step %a against %a", m->name, sc->name,
                      step, s->h_next, r.h_next);
        ck_assert_int_eq(s->accepted, r.accepted);
        ck_assert_msg(s->rejected == r.rejected, "%s on %s, step %d: %ld rejections against %ld", m->name,
                      sc->name, step, s->rejected, r.rejected);
    }
    ck_assert_msg(prod.ode->evals - evals0 == lect.ode->evals - evals1, "%s on %s: %ld evaluations against %ld",
                  m->name, sc->name, prod.ode->evals - evals0, lect.ode->evals - evals1);
    out = (seen){ .compared = 1, .rejected = r.rejected, .sliced = sw_ode_deriv_part(prod.ode) != NULL };
    sw_ref_adaptive_free(&r);
    sw_stepper_delete(s);
    sw_system_free(&lect);
    sw_system_free(&prod);
    return out;
}

/* Every explicit adaptive method on every scene at its defaults under
 * each setting, on the orbit at e = 0.9, and on each pointwise (flow)
 * scene again with 1031 points, so that rk45 and dop853 cut the state into slices with an odd
 * last point. Each method must have been compared on some scene and have
 * rejected some trial (the controller's both branches), and the sliced
 * path must have been taken. */
START_TEST(production_steps_are_the_lecture_forms)
{
    int methods = 0, sliced = 0;
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        sw_ref_adaptive_fn *ref = sw_ref_adaptive_of(m->step);
        if (!ref)
            continue;
        methods++;
        int scenes = 0;
        long rejected = 0;
        for (int j = 0; j < sw_scene_count(); j++) {
            const sw_scene *sc = sw_scene_at(j);
            double p[SW_MAX_PARAMS];
            char err[SW_ERRLEN];
            sw_scene_defaults(sc, p);
            for (size_t i = 0; i < sizeof settings / sizeof settings[0]; i++) {
                seen got = compare(m, ref, sc, p, &settings[i]);
                scenes += got.compared;
                rejected += got.rejected;
                if (i == 0 && got.sliced) {
                    ck_assert_msg(sw_scene_set(sc, p, "n=1031", err, sizeof err) == SW_OK, "%s: %s", sc->name, err);
                    seen again = compare(m, ref, sc, p, &settings[i]);
                    sliced += again.compared;
                    sw_scene_defaults(sc, p);
                }
            }
        }
        /* and the orbit again at e = 0.9, the close pass that shrinks the
         * steps (and that dop853-lc, on the orbit alone, lands on Newton's
         * method): each method's second scene at least */
        const sw_scene *orbit = sw_scene_find("orbit");
        double p[SW_MAX_PARAMS];
        char err[SW_ERRLEN];
        ck_assert(orbit != NULL);
        sw_scene_defaults(orbit, p);
        ck_assert_msg(sw_scene_set(orbit, p, "e=0.9", err, sizeof err) == SW_OK, "%s", err);
        for (size_t i = 0; i < sizeof settings / sizeof settings[0]; i++) {
            seen got = compare(m, ref, orbit, p, &settings[i]);
            scenes += got.compared;
            rejected += got.rejected;
        }
        ck_assert_msg(scenes > 0, "%s: no scene to compare on", m->name);
        ck_assert_msg(rejected > 0, "%s: no trial rejected, the controller's other branch untried", m->name);
    }
    ck_assert_int_ge(methods, 7); /* rk45, dop853, rkn, rkn12, dop853-lc, vern8, vern9 (every_adaptive_step_has_its_form) */
    ck_assert_msg(sliced > 0, "no sliced run compared");
}
END_TEST

/* Every explicit adaptive method of the table has its lecture form, each
 * paired with its own: a new one is named here until it gets one. */
START_TEST(every_adaptive_step_has_its_form)
{
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        if ((m->flags & SW_ADAPTIVE) && (m->flags & SW_EXPLICIT) && !(m->flags & SW_PLUGIN))
            ck_assert_msg(sw_ref_adaptive_of(m->step) != NULL, "%s has no lecture form in reference_adaptive.c",
                          m->name);
    }
    ck_assert(sw_ref_adaptive_of(sw_step_rk45) == sw_ref_rk45);
    ck_assert(sw_ref_adaptive_of(sw_step_dop853) == sw_ref_dop853);
    ck_assert(sw_ref_adaptive_of(sw_step_rkn) == sw_ref_rkn);
    ck_assert(sw_ref_adaptive_of(sw_step_rkn12) == sw_ref_rkn12);
    ck_assert(sw_ref_adaptive_of(sw_step_dop853_lc) == sw_ref_dop853_lc);
    ck_assert(sw_ref_adaptive_of(sw_step_vern8) == sw_ref_vern8);
    ck_assert(sw_ref_adaptive_of(sw_step_vern9) == sw_ref_vern9);
    ck_assert(sw_ref_adaptive_of(sw_step_rodas4) == NULL);
    ck_assert(sw_ref_adaptive_of(sw_step_rk4) == NULL);
}
END_TEST

Suite *make_reference_adaptive_suite(void);
Suite *make_reference_adaptive_suite(void)
{
    Suite *s = suite_create("reference_adaptive");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, production_steps_are_the_lecture_forms);
    tcase_add_test(tc, every_adaptive_step_has_its_form);
    suite_add_tcase(s, tc);
    return s;
}
