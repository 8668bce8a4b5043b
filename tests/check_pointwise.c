/* Flow fields written per point step Euler and RK4 with each point's stages
 * in registers (engine/pointwise.h). Those fused steps must be the generic
 * methods exactly: on every flow scene, with point counts odd and even
 * (the steps take points two at a time), the same bits after many steps (the fused step against
 * the same system with its fused steps switched off), the same runaway
 * flag when a point leaves, and the same evaluation count. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "stepwise/stepwise.h"

/* Scene `name` built with n points (defaults otherwise). */
static void build(const char *name, int n, sw_system *sys)
{
    const sw_scene *sc = sw_scene_find(name);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN], set[32];
    sw_scene_defaults(sc, p);
    snprintf(set, sizeof set, "n=%d", n);
    ck_assert_msg(sw_scene_set(sc, p, set, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_system_build(sys, sc, p, err, sizeof err) == SW_OK, "%s", err);
}

/* n points of scene `name` (defaults otherwise), `steps` steps of method at
 * the scene's dt, fused or not; the state into out (2n), the runaway flag
 * of the last step and the evaluations into *beyond and *evals. */
static void run(const char *name, int n, const char *method, int steps, int fused, double kick, double *out,
                int *beyond, long *evals)
{
    const sw_scene *sc = sw_scene_find(name);
    char err[SW_ERRLEN];
    sw_system sys;
    build(name, n, &sys);
    ck_assert_msg(sw_ode_fused_euler(sys.ode) && sw_ode_fused_rk4(sys.ode), "%s offers no fused steps", name);
    struct sw_ode_fast sliced = { .deriv_part = sys.ode->fast->deriv_part };
    if (!fused)
        sys.ode->fast = &sliced;
    sw_stepper s;
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), sys.ode, err, sizeof err), SW_OK);
    s.limit_exp = 1023 + 20; /* |y| >= 2^20 is a runaway */
    double t = 0.0;
    for (int j = 0; j < steps; j++) {
        if (j == steps - 1)
            sys.y[2 * (n / 2) + 1] += kick; /* one point, far away, before the last step */
        ck_assert_int_eq(sw_stepper_step(&s, sys.ode, &t, sys.y, sc->dt), SW_OK);
    }
    memcpy(out, sys.y, (size_t)(2 * n) * sizeof *out);
    *beyond = s.beyond;
    *evals = sys.ode->evals;
    sw_stepper_free(&s);
    sw_system_free(&sys);
}

START_TEST(fused_steps_are_the_generic_ones)
{
    const char *scenes[] = { "vortex", "river", "gyre" }, *methods[] = { "euler", "rk4" };
    const int sizes[] = { 1, 7, 300, 1031 }; /* a lone (odd) point, pairs and an odd one, even, many */
    static double a[2 * 1031], b[2 * 1031];
    for (int sc = 0; sc < 3; sc++)
        for (int m = 0; m < 2; m++)
            for (int k = 0; k < 4; k++)
                for (int kick = 0; kick < 2; kick++) {
                    int n = sizes[k], ba, bb;
                    long ea, eb;
                    double far = kick ? 4e6 : 0.0;
                    run(scenes[sc], n, methods[m], 60, 1, far, a, &ba, &ea);
                    run(scenes[sc], n, methods[m], 60, 0, far, b, &bb, &eb);
                    ck_assert_msg(memcmp(a, b, (size_t)(2 * n) * sizeof *a) == 0, "%s, %s, n = %d: fused differs",
                                  scenes[sc], methods[m], n);
                    ck_assert_int_eq(ba, bb);
                    ck_assert_int_eq(ba, kick); /* the far point is flagged, and only it */
                    ck_assert_int_eq(ea, eb);
                }
}
END_TEST

/* The runaway test's definition, written out here: some component's
 * exponent field (inf and NaN: 0x7FF) is at or beyond elim. */
static unsigned any_beyond(const double *y, int len, unsigned elim)
{
    unsigned over = 0;
    for (int i = 0; i < len; i++) {
        unsigned long long bits;
        memcpy(&bits, &y[i], sizeof bits);
        over |= (unsigned)((bits >> 52) & 0x7FF) >= elim;
    }
    return over;
}

/* The fused steps' runaway flag, and the sim's rescan, are exactly "some
 * component of the new state has an exponent at or beyond elim, or is inf
 * or NaN" (the definition above): one component set to each edge value,
 * in every slot of a pair and in an odd last point. */
START_TEST(runaway_flag_is_exact)
{
    const double edge[] = { 0x1p20, -0x1p20, 0x1.fffffffffffffp19, -0x1.fffffffffffffp19, INFINITY, -INFINITY,
                            NAN, -NAN, 1e300, 0.0 };
    const unsigned elim = 1023 + 20;
    for (int n = 1; n <= 5; n++)
        for (int m = 0; m < 2; m++)
            for (int pos = 0; pos < 2 * n; pos++)
                for (size_t v = 0; v < sizeof edge / sizeof edge[0]; v++) {
                    sw_system sys;
                    build("river", n, &sys); /* the field is finite away from the rock */
                    sys.y[pos] = edge[v];
                    sw_fused_step_fn *step = m ? sw_ode_fused_rk4(sys.ode) : sw_ode_fused_euler(sys.ode);
                    unsigned flag = step(sys.ode->ctx, 0.0, sys.y, 1e-3, elim);
                    ck_assert_msg(flag == any_beyond(sys.y, 2 * n, elim),
                                  "%s, n = %d, component %d = %g: flag %u", m ? "rk4" : "euler", n, pos, edge[v], flag);
                    /* and the sim's rescan (sw_state_beyond) says the same */
                    ck_assert_int_eq(sw_state_beyond(sys.y, 0, 2 * n, elim), (int)any_beyond(sys.y, 2 * n, elim));
                    sw_system_free(&sys);
                }
}
END_TEST

Suite *make_pointwise_suite(void);
Suite *make_pointwise_suite(void)
{
    Suite *s = suite_create("pointwise");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, fused_steps_are_the_generic_ones);
    tcase_add_test(tc, runaway_flag_is_exact);
    suite_add_tcase(s, tc);
    return s;
}
