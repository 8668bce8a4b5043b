/* Particles with a life (fire, explosion): the cooling against its closed
 * form at each method's order, the heat force against its formula, births
 * reproducible bit for bit from the seed, located deaths and the burst at
 * their exact times, the two rates the stability theory names, fragments
 * kept above the floor. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine/forces.h"
#include "render/canvas.h"
#include "render/draw.h"
#include "sim/truth.h"
#include "stepwise/stepwise.h"

static void fire_sim(sw_sim *s, const char *scene, const char *method, double dt, const char *const *set, int nset)
{
    const sw_scene *sc = sw_scene_find(scene);
    ck_assert_ptr_nonnull(sc);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    for (int k = 0; k < nset; k++)
        ck_assert_msg(sw_scene_set(sc, p, set[k], err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_sim_init(s, sc, p, sw_integrator_find(method), dt, err, sizeof err) == SW_OK, "%s: %s",
                  method, err);
}

/* Body i's slot: θ = T - 300 K and the alive flag r, from the state. */
static double theta_of(const sw_sim *s, int i)
{
    int n = s->sys.n;
    return s->sys.y[2 * n + 2 * (n / 2 + i)];
}

static int alive_flag(const sw_sim *s, int i)
{
    int n = s->sys.n;
    return s->sys.y[2 * n + 2 * (n / 2 + i) + 1] != 0;
}

/* The heat force, written out here from its formula (force_heat.c's
 * comment), on two bodies and their slots: equal to rounding. */
START_TEST(heat_force_formula)
{
    sw_particles p;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(&p, 4, 1.0, err, sizeof err), SW_OK);
    p.mass[0] = 2.0, p.inv_mass[0] = 0.5;
    sw_force h = { .kind = SW_FORCE_HEAT, .gx = 0.1, .gy = -9.0, .k = 0.7, .buoy = 0.01, .cool = 3.0 };
    ck_assert_int_eq(sw_particles_add_force(&p, &h), SW_OK);
    ck_assert_int_eq(sw_particles_finish(&p, err, sizeof err), SW_OK);
    double y[16] = { 0.3, 1.0, -0.2, 2.0, 5.0, 0.1, 7.0, 0.4, /* v */ 1.5, -0.5, 0.2, 0.3, 800.0, 1.0, 200.0, 1.0 };
    double d[16];
    p.ode.deriv(&p, 0.0, y, d);
    const double *v = y + 8, *a = d + 8;
    for (int c = 0; c < 8; c++)
        ck_assert_double_eq(d[c], v[c]); /* x' = v, slots too */
    for (int i = 0; i < 2; i++) {
        double th = v[4 + 2 * i];
        ck_assert_double_eq_tol(a[2 * i], 0.1 - 0.7 * v[2 * i], 1e-14);
        ck_assert_double_eq_tol(a[2 * i + 1], -9.0 + 0.01 * th - 0.7 * v[2 * i + 1], 1e-13);
        ck_assert_double_eq_tol(a[4 + 2 * i], -3.0 * th, 1e-12);
        ck_assert_double_eq(a[4 + 2 * i + 1], 0.0); /* r' = 0: alive stays alive */
    }
    sw_particles_free(&p);
}
END_TEST

/* The error of body 0's θ at t = 1 against θ(0)·e^{-κt} (no birth or death
 * crosses [0, 1]: life 10 s, rate 0.5/s, cold limit far below). */
static double cooling_error(const char *method, double dt)
{
    static const char *const set[] = { "rate=0.5", "life=10", "kappa=2" };
    sw_sim s;
    fire_sim(&s, "fire", method, dt, set, 3);
    double th0 = theta_of(&s, 0);
    ck_assert_int_eq(sw_sim_run_until(&s, 1.0), 0);
    double e = fabs(theta_of(&s, 0) - th0 * exp(-2.0));
    ck_assert(alive_flag(&s, 0));
    sw_sim_free(&s);
    return e;
}

/* Each method's observed order on the cooling, log2 of the error ratio
 * from h = 0.05 to 0.025 (κh = 0.1, well inside every region), within
 * 0.25 of its order: the ratio's next term is O(h) relative, about 0.1. */
START_TEST(cooling_closed_form_order)
{
    static const struct { const char *name; int order; } m[] = {
        { "euler", 1 }, { "symplectic-euler", 1 }, { "midpoint", 2 }, { "heun", 2 },
        { "verlet", 2 }, { "rk4", 4 }, { "implicit-euler", 1 }, { "implicit-midpoint", 2 },
    };
    for (size_t k = 0; k < sizeof m / sizeof m[0]; k++) {
        double e1 = cooling_error(m[k].name, 0.05), e2 = cooling_error(m[k].name, 0.025);
        double p = log2(e1 / e2);
        ck_assert_msg(fabs(p - m[k].order) < 0.25, "%s: observed order %.3f, expected %d (errors %g, %g)",
                      m[k].name, p, m[k].order, e1, e2);
    }
}
END_TEST

/* Euler's cooling is θ(1 - κh)^k exactly: the run's θ after 10 steps
 * equals the product to rounding (1e-12 relative). */
START_TEST(cooling_euler_map)
{
    static const char *const set[] = { "rate=0.5", "life=10", "kappa=20" };
    sw_sim s;
    fire_sim(&s, "fire", "euler", 0.01, set, 3);
    double th0 = theta_of(&s, 0);
    for (int k = 0; k < 10; k++)
        sw_sim_step(&s);
    double want = th0 * pow(1.0 - 20 * 0.01, 10);
    ck_assert_double_eq_tol(theta_of(&s, 0), want, 1e-12 * th0);
    sw_sim_free(&s);
}
END_TEST

/* The same seed gives the same fire bit for bit (births included); another
 * seed another fire. */
START_TEST(fire_deterministic)
{
    static const char *const one[] = { "seed=7" }, *const two[] = { "seed=8" };
    sw_sim a, b, c;
    fire_sim(&a, "fire", "rk4", 0.02, one, 1);
    fire_sim(&b, "fire", "rk4", 0.02, one, 1);
    fire_sim(&c, "fire", "rk4", 0.02, two, 1);
    sw_sim_run_until(&a, 3.0);
    sw_sim_run_until(&b, 3.0);
    sw_sim_run_until(&c, 3.0);
    size_t bytes = (size_t)a.sys.ode->dim * sizeof *a.sys.y;
    ck_assert_int_eq(memcmp(a.sys.y, b.sys.y, bytes), 0);
    ck_assert_int_ne(memcmp(a.sys.y, c.sys.y, bytes), 0);
    int live = 0;
    for (int i = 0; i < a.sys.n / 2; i++)
        live += alive_flag(&a, i);
    /* 80 births a second, none older than 2 s: between 1 and 161 alive */
    ck_assert(live > 0 && live <= 161);
    sw_sim_free(&a);
    sw_sim_free(&b);
    sw_sim_free(&c);
}
END_TEST

/* A death by age located: body 0 (born at 0) dies at life = 0.55 s inside
 * the step from 0.5 to 0.6; located, the event's time is 0.55 to 1e-10
 * and the body is dead after; stepped over, it dies at 0.6. κ = 0 keeps
 * the cold limit away. */
START_TEST(fire_death_located)
{
    static const char *const set[] = { "rate=1", "life=0.55", "kappa=0" };
    char err[SW_ERRLEN];
    sw_sim s;
    fire_sim(&s, "fire", "rk4", 0.1, set, 3);
    ck_assert_int_eq(sw_sim_set_events(&s, SW_EVENTS_LOCATE, err, sizeof err), SW_OK);
    sw_sim_run_until(&s, 0.5);
    ck_assert(alive_flag(&s, 0));
    sw_sim_step(&s);
    ck_assert_double_eq_tol(sw_sim_events_last_time(&s), 0.55, 1e-10);
    ck_assert(!alive_flag(&s, 0));
    ck_assert_double_eq_tol(s.t, 0.6, 1e-12);
    sw_sim_free(&s);
}
END_TEST

/* A death by cold located: θ(t) = θ0 e^{-κt} crosses 50 K at
 * ln(θ0/50)/κ. rk4 with κh = 0.01 follows the exponential to a relative
 * 1e-12 or so (h⁴κ⁴t/120), so the located time matches the closed form to
 * 1e-9. */
START_TEST(fire_cold_death_located)
{
    static const char *const set[] = { "rate=0.2", "life=10", "kappa=1" };
    char err[SW_ERRLEN];
    sw_sim s;
    fire_sim(&s, "fire", "rk4", 0.01, set, 3);
    ck_assert_int_eq(sw_sim_set_events(&s, SW_EVENTS_LOCATE, err, sizeof err), SW_OK);
    double th0 = theta_of(&s, 0), when = log(th0 / 50.0);
    sw_sim_run_until(&s, when + 0.02);
    ck_assert(!alive_flag(&s, 0));
    ck_assert_double_eq_tol(sw_sim_events_last_time(&s), when, 1e-9);
    sw_sim_free(&s);
}
END_TEST

/* The stability theory names both rates: cooling κ on the slots, drag on
 * the bodies; the stiffest is κ when κ > drag. */
START_TEST(fire_two_rates)
{
    static const char *const set[] = { "kappa=40", "drag=1.5" };
    sw_sim s;
    fire_sim(&s, "fire", "euler", 0.02, set, 2);
    sw_spectrum sp;
    ck_assert_int_eq(sw_truth_spectrum(&s.sys, 0.0, s.sys.y, &sp), 0);
    ck_assert_double_eq_tol(sp.largest, 40.0, 1e-9);
    int cool = 0, drag = 0;
    for (int k = 0; k < sp.n; k++) {
        cool |= fabs(sp.mode[k].re + 40.0) < 1e-9 || fabs(sp.mode[k].pre + 40.0) < 1e-9;
        drag |= fabs(sp.mode[k].re + 1.5) < 1e-9 || fabs(sp.mode[k].pre + 1.5) < 1e-9;
    }
    ck_assert_msg(cool && drag, "modes: %d", sp.n);
    sw_sim_free(&s);
}
END_TEST

/* The explosion: the burst located at t0 = 0.73 to 1e-10; the same seed the
 * same fragments; every fragment above the floor after bouncing (step
 * mode reflects at the step's end, so y >= 0 at every step). */
START_TEST(explosion_burst_and_floor)
{
    static const char *const set[] = { "t0=0.73", "n=50" };
    char err[SW_ERRLEN];
    sw_sim a, b;
    fire_sim(&a, "explosion", "verlet", 0.01, set, 2);
    fire_sim(&b, "explosion", "verlet", 0.01, set, 2);
    ck_assert_int_eq(sw_sim_set_events(&a, SW_EVENTS_LOCATE, err, sizeof err), SW_OK);
    sw_sim_run_until(&a, 0.8);
    ck_assert_double_eq_tol(sw_sim_events_last_time(&a), 0.73, 1e-10);
    ck_assert(theta_of(&a, 0) > 0);
    for (int k = 0; k < 400; k++) {
        sw_sim_step(&b);
        for (int i = 0; i < 50; i++)
            ck_assert(b.sys.y[2 * i + 1] >= 0);
    }
    sw_sim c;
    fire_sim(&c, "explosion", "verlet", 0.01, set, 2);
    for (int k = 0; k < 400; k++)
        sw_sim_step(&c);
    ck_assert_int_eq(memcmp(b.sys.y, c.sys.y, (size_t)b.sys.ode->dim * sizeof *b.sys.y), 0);
    sw_sim_free(&a);
    sw_sim_free(&b);
    sw_sim_free(&c);
}
END_TEST

/* Drawn by temperature: three fragments at 0.1, 0.5 and 0.9 of the
 * hottest a fragment is born (1.2·1200 K above ambient) are drawn ',', 'o'
 * and '@'; the heat slots are not drawn at all. */
START_TEST(drawn_by_temperature)
{
    static const char *const set[] = { "n=3", "t0=0" };
    sw_sim s;
    fire_sim(&s, "explosion", "verlet", 0.01, set, 2);
    double *y = s.sys.y, frac[3] = { 0.1, 0.5, 0.9 };
    int n = s.sys.n;
    for (int i = 0; i < 3; i++) {
        y[2 * i] = -2.0 + 2.0 * i;
        y[2 * i + 1] = 1.0;
        y[2 * n + 2 * (3 + i)] = frac[i] * 1.2 * 1200.0;
    }
    sw_canvas c;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_canvas_init(&c, 40, 12, err, sizeof err), SW_OK);
    sw_view v = { -4, 4, -0.5, 3 };
    ck_assert_int_eq(sw_canvas_set_view(&c, &v, err, sizeof err), SW_OK);
    sw_canvas_draw_system(&c, &s.sys, y, s.t, 0, SW_STYLE_MAIN);
    static const uint32_t want[3] = { ',', 'o', '@' };
    int drawn = 0;
    for (int i = 0; i < 3; i++) {
        int col, row;
        ck_assert(sw_canvas_world_to_cell(&c, y[2 * i], y[2 * i + 1], &col, &row));
        ck_assert_uint_eq(sw_canvas_codepoint(&c, col, row), want[i]);
    }
    for (int row = 0; row < 12; row++)
        for (int col = 0; col < 40; col++) {
            uint32_t g = sw_canvas_codepoint(&c, col, row);
            drawn += g == ',' || g == 'o' || g == '@';
        }
    ck_assert_int_eq(drawn, 3); /* the slots (dose, age) are not drawn */
    sw_canvas_free(&c);
    sw_sim_free(&s);
}
END_TEST

/* Bad input: a pool beyond the limit is refused with a message. */
START_TEST(fire_pool_limit)
{
    const sw_scene *sc = sw_scene_find("fire");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    ck_assert_int_eq(sw_scene_set(sc, p, "rate=5000", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_scene_set(sc, p, "life=10", err, sizeof err), SW_OK);
    sw_system sys;
    ck_assert_int_eq(sw_system_build(&sys, sc, p, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "at most"));
}
END_TEST

Suite *make_fire_suite(void);
Suite *make_fire_suite(void)
{
    Suite *s = suite_create("fire");
    TCase *tc = tcase_create("particles with a life");
    tcase_add_test(tc, heat_force_formula);
    tcase_add_test(tc, cooling_closed_form_order);
    tcase_add_test(tc, cooling_euler_map);
    tcase_add_test(tc, fire_deterministic);
    tcase_add_test(tc, fire_death_located);
    tcase_add_test(tc, fire_cold_death_located);
    tcase_add_test(tc, fire_two_rates);
    tcase_add_test(tc, explosion_burst_and_floor);
    tcase_add_test(tc, fire_pool_limit);
    tcase_add_test(tc, drawn_by_temperature);
    tcase_set_timeout(tc, 60);
    suite_add_tcase(s, tc);
    return s;
}
