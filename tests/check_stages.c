/* The stages of one step (sim/stages.c): each method's evaluations are
 * counted, and combined by the method's own formula (written here from the
 * textbook tableau, independently of the engine) they give the state the
 * recording step ended in, and the run's next step, bit for bit. Bitwise
 * equality is the right tolerance: the recording runs the engine's own
 * step function, and -std=c11 keeps the compiler from fusing a*b+c. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/lecture.h"
#include "sim/stages.h"
#include "stepwise/stepwise.h"

static void sim_on(sw_sim *s, const char *scene, const char *set, const char *method, double dt)
{
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find(scene);
    ck_assert_ptr_nonnull(sc);
    double p[SW_MAX_PARAMS];
    for (int i = 0; i < sc->nparams; i++)
        p[i] = sc->params[i].def;
    if (set) { /* one "NAME=VALUE" */
        const char *eq = strchr(set, '=');
        int found = 0;
        for (int i = 0; i < sc->nparams; i++)
            if (strlen(sc->params[i].name) == (size_t)(eq - set) && !strncmp(sc->params[i].name, set, (size_t)(eq - set))) {
                p[i] = strtod(eq + 1, NULL);
                found = 1;
            }
        ck_assert_msg(found, "no parameter %s", set);
    }
    ck_assert_msg(sw_sim_init(s, sc, p, sw_integrator_find(method), dt, err, sizeof err) == SW_OK, "%s", err);
}

/* The run's next state from the recorded stages, by the method's formula. */
static void combine(const sw_stages *r, double *out)
{
    int n = r->dim, half = n / 2;
    double h = r->h;
    const double *y = r->y0;
    const char *m = r->method->name;
    for (int i = 0; i < n; i++) {
        const double *k1 = r->st[0].k, *k2 = r->st[1].k, *k3 = r->st[2].k, *k4 = r->st[3].k;
        if (!strcmp(m, "euler"))
            out[i] = y[i] + h * k1[i];
        else if (!strcmp(m, "midpoint"))
            out[i] = y[i] + h * k2[i];
        else if (!strcmp(m, "heun"))
            out[i] = y[i] + 0.5 * h * (k1[i] + k2[i]);
        else if (!strcmp(m, "rk4"))
            out[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    if (!strcmp(m, "symplectic-euler"))
        for (int i = 0; i < half; i++) {
            out[half + i] = y[half + i] + h * r->st[0].k[half + i];
            out[i] = y[i] + h * out[half + i];
        }
    if (!strcmp(m, "verlet")) /* two half kicks around a drift */
        for (int i = 0; i < half; i++) {
            double vh = y[half + i] + 0.5 * h * r->st[0].k[half + i];
            out[i] = y[i] + h * vh;
            out[half + i] = vh + 0.5 * h * r->st[1].k[half + i];
        }
}

/* Record after `before` steps, check the count, the combination and the
 * run's own next step, all bit for bit. */
static void check_method(const char *scene, const char *set, const char *method, double dt, int before, int stages)
{
    sw_sim s;
    sw_stages r = { 0 };
    char why[SW_ERRLEN];
    sim_on(&s, scene, set, method, dt);
    for (int i = 0; i < before; i++)
        sw_sim_step(&s);
    long evals = sw_sim_evals(&s);
    double t = s.t;
    ck_assert_msg(sw_stages_record(&r, &s, why, sizeof why) == SW_OK, "%s", why);
    ck_assert_msg(r.n == stages, "%s on %s: %d stages, want %d", method, scene, r.n, stages);
    ck_assert(sw_sim_evals(&s) == evals && s.t == t); /* the run is not touched */
    int n = r.dim;
    double out[2048];
    ck_assert_int_le(n, 2048);
    combine(&r, out);
    ck_assert_msg(memcmp(out, r.y1, (size_t)n * sizeof *out) == 0, "%s on %s: stages do not combine to the step",
                  method, scene);
    sw_sim_step(&s);
    ck_assert_msg(memcmp(s.sys.y, r.y1, (size_t)n * sizeof *out) == 0, "%s on %s: recorded step differs from the run's",
                  method, scene);
    sw_stages_free(&r);
    sw_sim_free(&s);
}

START_TEST(stages_combine_to_the_step)
{
    /* vortex: a flow with the fused Euler and RK4 paths and slices; spring
     * (damped, so velocity-dependent) and orbit: particles */
    static const char *const scenes[][2] = { { "vortex", "n=3" }, { "spring", NULL }, { "orbit", NULL } };
    static const struct { const char *m; int n; } rk[] = { { "euler", 1 }, { "midpoint", 2 }, { "heun", 2 }, { "rk4", 4 } };
    for (size_t i = 0; i < 3; i++)
        for (size_t j = 0; j < 4; j++)
            check_method(scenes[i][0], scenes[i][1], rk[j].m, 0.05, 7, rk[j].n);
    check_method("spring", NULL, "symplectic-euler", 0.05, 7, 1);
    check_method("orbit", NULL, "symplectic-euler", 0.05, 7, 1);
    /* Verlet's two half kicks: a0 evaluated on the first step, then kept
     * from the last step (first same as last) */
    check_method("spring", NULL, "verlet", 0.05, 0, 2);
    check_method("spring", NULL, "verlet", 0.05, 7, 2);
    check_method("orbit", NULL, "verlet", 0.05, 7, 2);
}
END_TEST

/* The stage points themselves: midpoint's second slope is taken at the
 * half step, RK4's k4 at the full step from k3; Verlet's kept a0 is noted. */
START_TEST(stages_are_where_the_method_looks)
{
    sw_sim s;
    sw_stages r = { 0 };
    char why[SW_ERRLEN];
    sim_on(&s, "vortex", "n=1", "midpoint", 0.5);
    ck_assert(sw_stages_record(&r, &s, why, sizeof why) == SW_OK);
    for (int i = 0; i < r.dim; i++)
        ck_assert(r.st[1].y[i] == r.y0[i] + 0.5 * r.h * r.st[0].k[i]);
    ck_assert(r.st[1].t == 0.25 && !r.st[0].cached);
    sw_sim_set_method(&s, sw_integrator_find("rk4"), why, sizeof why);
    ck_assert(sw_stages_record(&r, &s, why, sizeof why) == SW_OK);
    for (int i = 0; i < r.dim; i++)
        ck_assert(r.st[3].y[i] == r.y0[i] + r.h * r.st[2].k[i]);
    ck_assert(r.st[3].t == 0.5);
    sw_sim_free(&s);
    sim_on(&s, "spring", NULL, "verlet", 0.05);
    sw_sim_step(&s);
    ck_assert(sw_stages_record(&r, &s, why, sizeof why) == SW_OK);
    ck_assert(r.st[0].cached && !r.st[1].cached && r.st[1].t == s.t + 0.05);
    sw_stages_free(&r);
    sw_sim_free(&s);
}
END_TEST

/* The true path over the step: on the vortex (ω = 1) from (1, 0) at t = 0
 * the exact motion is the unit circle, (cos t, sin t). The reference run
 * is held to rtol 1e-12, so 1e-9 leaves room for its accumulated error
 * over one step while catching any wrong time or particle. */
START_TEST(stages_true_path_is_the_exact_motion)
{
    sw_sim s;
    sw_stages r = { 0 };
    char why[SW_ERRLEN];
    sim_on(&s, "vortex", "n=1", "euler", 1.0);
    ck_assert(s.sys.y[0] == 1 && s.sys.y[1] == 0);
    ck_assert(sw_stages_record(&r, &s, why, sizeof why) == SW_OK);
    ck_assert_int_eq(sw_stages_true_path(&r, &s), SW_OK);
    ck_assert_int_eq(r.path_n, SW_STAGES_PATH + 1);
    for (int j = 0; j < r.path_n; j++) {
        double t = 1.0 * j / SW_STAGES_PATH;
        ck_assert_double_eq_tol(r.path[2 * j], cos(t), 1e-9);
        ck_assert_double_eq_tol(r.path[2 * j + 1], sin(t), 1e-9);
    }
    /* and Euler's step leaves it: |y1| = sqrt(1 + h²) */
    ck_assert_double_eq_tol(hypot(r.y1[0], r.y1[1]), sqrt(2.0), 1e-15);
    sw_stages_free(&r);
    sw_sim_free(&s);
}
END_TEST

/* Methods without a stage breakdown say so in one line, and why. */
START_TEST(stages_not_drawn_say_why)
{
    static const struct { const char *m, *why; } cases[] = {
        { "implicit-euler", "stages: not drawn for implicit-euler \xe2\x80\x94 it solves an equation, see lesson 7" },
        { "rk45", "stages: not drawn for rk45 \xe2\x80\x94 it chooses its own steps, see lesson 9" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sw_sim s;
        sw_stages r = { 0 };
        char why[SW_ERRLEN];
        sim_on(&s, "spring", NULL, cases[i].m, 0.05);
        ck_assert(sw_stages_record(&r, &s, why, sizeof why) == SW_EINVAL);
        ck_assert_str_eq(why, cases[i].why);
        ck_assert_int_eq(r.n, 0);
        sw_stages_free(&r);
        sw_sim_free(&s);
    }
}
END_TEST

/* Every method's row tells the stage view something: a lecture form whose
 * every view lights a line it has and draws a stage the method's own step
 * records (on the damped spring, or the orbit where a method refuses the spring), or in a
 * few words why there is none, which the view prints. A row with neither
 * (an embedder's method) is said to give none, never passed over. */
START_TEST(stages_every_row_says)
{
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        const sw_stage_script *sc = m->lecture;
        ck_assert_msg(!sc != !m->no_lecture, "%s: a lecture form or why not, one of them", m->name);
        sw_sim s;
        sw_stages r = { 0 };
        char why[SW_ERRLEN], want[SW_ERRLEN];
        /* the damped spring, or the orbit for a method that refuses it
         * (x'' = f(x) only, one body only) */
        const sw_scene *sc_on = sw_scene_find("spring");
        if (sw_sim_init(&s, sc_on, NULL, m, 0.05, why, sizeof why) != SW_OK) {
            sc_on = sw_scene_find("orbit");
            ck_assert_msg(sw_sim_init(&s, sc_on, NULL, m, 0.05, why, sizeof why) == SW_OK, "%s: %s", m->name, why);
        }
        sw_sim_step(&s); /* a method that keeps a derivative has one now */
        int rc = sw_stages_record(&r, &s, why, sizeof why);
        if (!sc) {
            snprintf(want, sizeof want, "stages: not drawn for %s \xe2\x80\x94 %s", m->name, m->no_lecture);
            ck_assert_int_eq(rc, SW_EINVAL);
            ck_assert_str_eq(why, want);
        } else {
            ck_assert_msg(rc == SW_OK, "%s: %s", m->name, why);
            int lines = 0;
            while (lines < SW_STAGE_LINES && sc->lines[lines])
                lines++;
            ck_assert_msg(sc->nviews >= 1 && sc->nviews <= SW_STAGE_VIEWS, "%s: %d views", m->name, sc->nviews);
            for (int v = 0; v < sc->nviews; v++) {
                ck_assert_msg(sc->views[v].line >= 0 && sc->views[v].line < lines, "%s: view %d lights line %d of %d",
                              m->name, v + 1, sc->views[v].line, lines);
                ck_assert_msg(sc->views[v].stage >= 0 && sc->views[v].stage < r.n, "%s: view %d draws stage %d of %d",
                              m->name, v + 1, sc->views[v].stage, r.n);
                ck_assert_msg(sc->views[v].label && sc->views[v].caption, "%s: view %d unlabelled", m->name, v + 1);
            }
        }
        sw_stages_free(&r);
        sw_sim_free(&s);
    }
    sw_integrator bare = *sw_integrator_find("yoshida4");
    bare.no_lecture = NULL;
    char why[SW_ERRLEN];
    ck_assert_int_eq(sw_stages_supported(&bare, why, sizeof why), 0);
    ck_assert_str_eq(why, "stages: not drawn for yoshida4 \xe2\x80\x94 its row gives no lecture form of its step");
}
END_TEST

Suite *make_stages_suite(void);
Suite *make_stages_suite(void)
{
    Suite *s = suite_create("stages");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, stages_combine_to_the_step);
    tcase_add_test(tc, stages_are_where_the_method_looks);
    tcase_add_test(tc, stages_true_path_is_the_exact_motion);
    tcase_add_test(tc, stages_not_drawn_say_why);
    tcase_add_test(tc, stages_every_row_says);
    suite_add_tcase(s, tc);
    return s;
}
