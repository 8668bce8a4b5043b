/* Memory at scale (issues 26 and 41, "a million particles"): rk4 in three
 * work vectors gives the textbook four-vector rk4's bits, the chain's fused
 * rk4 gives the generic step's, and a long chain under rk4 keeps at most
 * 2.25 times its state resident. */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "stepwise/stepwise.h"
#include "stepwise/sim.h"

/* Build scene with its defaults and the given settings. */
static void build(sw_system *sys, const char *scene, const char *const *sets, int nsets)
{
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    ck_assert_ptr_nonnull(sc);
    sw_scene_defaults(sc, p);
    for (int i = 0; i < nsets; i++)
        ck_assert_msg(sw_scene_set(sc, p, sets[i], err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_system_build(sys, sc, p, err, sizeof err) == SW_OK, "%s", err);
}

/* rk4 through the stepper against the textbook form written here, with
 * four k vectors: y1 = y + h/6·(k1 + 2k2 + 2k3 + k4), the sum read left to
 * right. The stepper keeps the stage state, the latest k and the running
 * sum instead; the operations and their order are the same, so the states
 * agree bit for bit after every step (no tolerance). The chain is coupled
 * (whole-state passes), damped and under gravity; gyre and vortex are flow
 * fields (slice by slice, or the field's fused step). */
START_TEST(rk4_three_vectors_same_bits)
{
    const char *chain[] = { "n=200", "c=0.7", "g=9.81" }, *none[] = { NULL };
    struct {
        const char *scene;
        const char *const *sets;
        int nsets;
    } cases[] = { { "chain", chain, 3 }, { "chain", NULL, 0 }, { "gyre", none, 0 }, { "vortex", none, 0 } };
    for (size_t q = 0; q < sizeof cases / sizeof cases[0]; q++) {
        sw_system sys;
        build(&sys, cases[q].scene, cases[q].sets, cases[q].nsets);
        sw_ode *ode = sys.ode;
        int dim = ode->dim;
        const sw_integrator *rk4 = sw_integrator_find("rk4");
        ck_assert_int_eq(rk4->work_vectors, 3);
        sw_stepper st;
        char err[SW_ERRLEN];
        ck_assert_int_eq(sw_stepper_init(&st, rk4, ode, err, sizeof err), SW_OK);
        double *y = malloc(6 * (size_t)dim * sizeof *y), h = sys.scene->dt, t = 0, tw = 0;
        ck_assert_ptr_nonnull(y);
        double *k1 = y + dim, *k2 = k1 + dim, *k3 = k2 + dim, *k4 = k3 + dim, *yt = k4 + dim;
        memcpy(y, sys.y, (size_t)dim * sizeof *y);
        for (int step = 0; step < 5; step++) {
            ode->deriv(ode->ctx, tw, y, k1);
            for (int i = 0; i < dim; i++)
                yt[i] = y[i] + 0.5 * h * k1[i];
            ode->deriv(ode->ctx, tw + 0.5 * h, yt, k2);
            for (int i = 0; i < dim; i++)
                yt[i] = y[i] + 0.5 * h * k2[i];
            ode->deriv(ode->ctx, tw + 0.5 * h, yt, k3);
            for (int i = 0; i < dim; i++)
                yt[i] = y[i] + h * k3[i];
            ode->deriv(ode->ctx, tw + h, yt, k4);
            for (int i = 0; i < dim; i++)
                y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            tw += h;
            ck_assert_int_eq(sw_stepper_step(&st, ode, &t, sys.y, h), SW_OK);
            for (int i = 0; i < dim; i++)
                ck_assert_msg(memcmp(&sys.y[i], &y[i], sizeof y[i]) == 0, "%s step %d component %d: %.17g vs %.17g",
                              cases[q].scene, step, i, sys.y[i], y[i]);
        }
        free(y);
        sw_stepper_free(&st);
        sw_system_free(&sys);
    }
}
END_TEST

/* Step a copy of y under rk4 through ode and through a view of it with no
 * fast paths (the generic rk4_range), `steps` times, and require the same
 * bits in every component after every step, and the same runaway flag. */
static void same_as_generic(sw_ode *ode, const double *y0, double h, int steps, unsigned limit_exp, const char *what)
{
    sw_ode generic = *ode;
    generic.fast = NULL;
    const sw_integrator *rk4 = sw_integrator_find("rk4");
    sw_stepper fused_st, generic_st;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_stepper_init(&fused_st, rk4, ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&generic_st, rk4, &generic, err, sizeof err), SW_OK);
    fused_st.limit_exp = generic_st.limit_exp = limit_exp;
    int dim = ode->dim;
    double *yf = malloc(2 * (size_t)dim * sizeof *yf), *yg = yf + dim, tf = 0, tg = 0;
    ck_assert_ptr_nonnull(yf);
    memcpy(yf, y0, (size_t)dim * sizeof *yf);
    memcpy(yg, y0, (size_t)dim * sizeof *yg);
    for (int step = 0; step < steps; step++) {
        ck_assert_int_eq(sw_stepper_step(&fused_st, ode, &tf, yf, h), SW_OK);
        ck_assert_int_eq(sw_stepper_step(&generic_st, &generic, &tg, yg, h), SW_OK);
        for (int i = 0; i < dim; i++)
            ck_assert_msg(memcmp(&yf[i], &yg[i], sizeof yf[i]) == 0, "%s step %d component %d: %.17g vs %.17g", what,
                          step, i, yf[i], yg[i]);
        ck_assert_int_eq(fused_st.beyond, generic_st.beyond);
    }
    free(yf);
    sw_stepper_free(&fused_st);
    sw_stepper_free(&generic_st);
}

/* The chain's fused rk4 (engine/particles_chain.c) against the generic
 * rk4 step on the same system, bit for bit (no tolerance: the same
 * operations in the same order): chains shorter than, equal to and
 * longer than a tile (128 beads) and its halo, undamped and damped, with
 * and without gravity, with drag added, resting on a floor (the resting
 * contact's hold), and one that blows up (inf and NaN, the runaway flag).
 * Each case first checks that the fused step is the one taken, and a
 * chain with another force must not take it. */
START_TEST(chain_fused_rk4_same_bits)
{
    struct {
        const char *sets[4];
        int nsets, steps, extra; /* extra: 1 drag, 2 a floor with resting contact */
    } cases[] = {
        { { NULL }, 0, 20, 0 },
        { { "n=2", "g=9.81" }, 2, 20, 0 },
        { { "n=3", "c=0.5" }, 2, 20, 0 },
        { { "n=128", "c=0.7", "g=9.81" }, 3, 10, 0 },
        { { "n=129", "g=-3" }, 2, 10, 0 },
        { { "n=200", "c=0.7", "g=9.81" }, 3, 10, 0 },
        { { "n=1001", "c=0.3", "k=5000", "pluck=3" }, 4, 10, 0 },
        { { "n=300", "g=9.81" }, 2, 10, 1 },
        { { "n=40", "g=9.81", "c=0.2" }, 3, 20, 2 },
        { { "n=50", "k=1000000", "pluck=5" }, 3, 60, 0 },
    };
    for (size_t q = 0; q < sizeof cases / sizeof cases[0]; q++) {
        sw_system sys;
        char err[SW_ERRLEN], what[96];
        build(&sys, "chain", cases[q].sets, cases[q].nsets);
        sw_particles *p = &sys.particles;
        if (cases[q].extra == 1)
            ck_assert_int_eq(sw_particles_add_drag(p, 0.4), SW_OK);
        if (cases[q].extra == 2)
            p->walls = (sw_walls){ .active = 1, .sides = SW_WALL_FLOOR, .ymin = 0.0, .e = 0.5, .rest = 0.1 };
        ck_assert_int_eq(sw_particles_finish(p, err, sizeof err), SW_OK);
        ck_assert_msg(sw_ode_fused_rk4(sys.ode) != NULL, "case %zu: the fused step is not taken", q);
        snprintf(what, sizeof what, "chain %s %s %s extra %d", cases[q].sets[0] ? cases[q].sets[0] : "",
                 cases[q].nsets > 1 ? cases[q].sets[1] : "", cases[q].nsets > 2 ? cases[q].sets[2] : "",
                 cases[q].extra);
        same_as_generic(sys.ode, sys.y, sys.scene->dt, cases[q].steps, q == 9 ? 1023 + 30 : 0, what);
        sw_system_free(&sys);
    }
    sw_system sys;
    char err[SW_ERRLEN];
    build(&sys, "chain", NULL, 0);
    ck_assert_int_eq(sw_particles_add_central(&sys.particles, 5.0, 5.0, 1.0), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&sys.particles, err, sizeof err), SW_OK);
    ck_assert_msg(sw_ode_fused_rk4(sys.ode) == NULL, "a chain in a central field takes the fused step");
    sw_system_free(&sys);
}
END_TEST

/* Resident KiB of this process (VmRSS), or -1 where /proc cannot say. */
static long resident_kib(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    long kib = -1;
    char line[256];
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, "VmRSS:", 6) == 0)
            kib = strtol(line + 6, NULL, 10);
    if (f)
        fclose(f);
    return kib;
}

/* Whether transparent huge pages are on for every mapping: then touching a
 * few bytes of a large untouched row may make 2 MiB of it resident, and
 * resident memory no longer measures what the engine touches. */
static int huge_pages_always(void)
{
    FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    char line[128] = "";
    if (f) {
        if (!fgets(line, sizeof line, f))
            line[0] = '\0';
        fclose(f);
    }
    return strstr(line, "[always]") != NULL;
}

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

/* Whether this runs under valgrind (its preloaded library), whose own
 * memory would count as ours. */
static int under_valgrind(void)
{
    const char *pre = getenv("LD_PRELOAD");
    return pre && (strstr(pre, "vgpreload") || strstr(pre, "valgrind"));
}

/* The chain at n = 200000 under rk4: building it and taking two steps may
 * make at most 2.25 times its state resident (the state: 4n doubles, 32
 * bytes a bead; issue 41 asks for at most three times). Measured at 48.4
 * bytes a bead in the suite's process, 53.7-53.8 in a forked child: the
 * state and the masses and inverse masses (16), and in a child some of
 * the allocator's own; the springs are a line of three (no array), the
 * compiled model writes no per-bead list, the fused rk4 works in a tile
 * of fixed size and the stepper's three work vectors are never touched.
 * The limit, 72, leaves 18 bytes a bead (3.4 MiB here) above the worst
 * measured for the allocator's rounding; it was 224 (twice bench_base.c's hand-fused loop, 112),
 * measured 212, before the fused step. A freshly allocated page counts
 * once touched; memory reused from earlier tests in this process was
 * resident already and counts as nothing, so the measure can only err
 * low. Skipped under AddressSanitizer and valgrind (shadow memory), where
 * /proc is missing, and with huge pages always on. */
START_TEST(chain_rk4_memory)
{
    enum { N = 200000 };
    long before = resident_kib();
    if (SANITIZED || before < 0 || huge_pages_always() || under_valgrind())
        return;
    const char *sets[] = { "n=200000" };
    sw_system sys;
    build(&sys, "chain", sets, 1);
    sw_stepper st;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_stepper_init(&st, sw_integrator_find("rk4"), sys.ode, err, sizeof err), SW_OK);
    double t = 0;
    for (int step = 0; step < 2; step++)
        ck_assert_int_eq(sw_stepper_step(&st, sys.ode, &t, sys.y, sys.scene->dt), SW_OK);
    double per_bead = (resident_kib() - before) * 1024.0 / N;
    double state = 4.0 * N * sizeof(double) / N;
    ck_assert_msg(per_bead <= 2.25 * state, "%.1f bytes a bead resident, over 2.25 times the state's %.1f",
                  per_bead, state);
    sw_stepper_free(&st);
    sw_system_free(&sys);
}
END_TEST

Suite *make_memory_suite(void);
Suite *make_memory_suite(void)
{
    Suite *s = suite_create("memory");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, rk4_three_vectors_same_bits);
    tcase_add_test(tc, chain_fused_rk4_same_bits);
    tcase_add_test(tc, chain_rk4_memory);
    suite_add_tcase(s, tc);
    return s;
}
