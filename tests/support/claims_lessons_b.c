/* Claims: the figures of lessons 6-10 and how each is measured. */
#include "claims.h"
#include "app/dt_error.h"

static double l6_ratio_mid(void) { return cl_page_ratio(L6, "Midpoint is second order", NULL, 1); }
static double l6_ratio_rk4(void) { return cl_page_ratio(L6, "RK4", "rk4", 1); }
static double l6_err(const char *m, double dt) { return cl_page_error(L6, "Error against cost", m, dt); }
static double l6_err_euler(void) { return l6_err("euler", 0.0125); }
static double l6_err_mid(void) { return l6_err("midpoint", 0.025); }
static double l6_err_rk4(void) { return l6_err("rk4", 0.05); }

static double evals_to(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    double e = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return e;
}

static double l6_steps_euler(void) { return (double)cl_steps_for("vortex", NULL, "euler", 0.0125, TWO_PI); }
static double l6_steps_mid(void) { return (double)cl_steps_for("vortex", NULL, "midpoint", 0.025, TWO_PI); }
static double l6_steps_rk4(void) { return (double)cl_steps_for("vortex", NULL, "rk4", 0.05, TWO_PI); }
static double l6_evals_euler(void) { return evals_to("vortex", NULL, "euler", 0.0125, TWO_PI); }
static double l6_evals_mid(void) { return evals_to("vortex", NULL, "midpoint", 0.025, TWO_PI); }
static double l6_evals_rk4(void) { return evals_to("vortex", NULL, "rk4", 0.05, TWO_PI); }
/* The decade marks of the plot's evaluation axis around the table's runs. */
static double l6_decade_below(void) { return pow(10, floor(log10(l6_evals_euler()))); }
static double l6_decade_above(void) { return pow(10, ceil(log10(l6_evals_rk4()))); }
static double l6_gain(void) { return l6_err_euler() / l6_err_rk4(); }
static double l6_rk4_evals(void) { return cl_evals_per_step("vortex", NULL, "rk4", 0.05, 10); }
static double l6_euler_evals(void) { return cl_evals_per_step("vortex", NULL, "euler", 0.05, 10); }
static double l6_mid_evals(void) { return cl_evals_per_step("vortex", NULL, "midpoint", 0.05, 10); }
static double l6_rk4_gain(void) { return pow(2, cl_order_by_halving("vortex", NULL, "rk4", 0.1)); }
static double l6_euler_gain(void) { return pow(2, cl_order_by_halving("vortex", NULL, "euler", 0.01)); }
static double l6_limit100(void) { return cl_limit0("spring", "k=10000 c=0", "rk4"); }
static double l6_report_time(void) { return sw_scene_find("vortex")->duration; }
static double l7_k(void) { return cl_param("stiff-spring", "k"); }
static double l7_fast(void) { return cl_spectrum0("stiff-spring", NULL).largest; }

/* The swing: the slowest mode of the linearisation at the start. */
static sw_mode l7_swing_mode(void)
{
    sw_spectrum sp = cl_spectrum0("stiff-spring", NULL);
    ck_assert_int_ge(sp.n, 2);
    return sp.mode[sp.n - 1];
}

static double l7_slow(void)
{
    sw_mode md = l7_swing_mode();
    return hypot(md.re, md.im);
}

/* Verlet's limit on the swing alone, over its limit on the whole pendulum. */
static double l7_swing_longer(void)
{
    sw_spectrum sp = cl_spectrum0("stiff-spring", NULL);
    sw_spectrum swing = sp;
    swing.n = 1;
    swing.mode[0] = l7_swing_mode();
    swing.largest = l7_slow();
    int unbounded;
    return sw_truth_limit(cl_method("verlet"), &swing, SW_DT_MAX, &unbounded) /
           sw_truth_limit(cl_method("verlet"), &sp, SW_DT_MAX, &unbounded);
}

static double l7_verlet_blow(void) { return cl_blow_time("stiff-spring", NULL, "verlet", 0.04, 10); }
/* Pages 4 and 5 stop at t = 2.5 exactly (@until 2.5): the drift there. */
static double l7_be_drift(void) { return -cl_drift_until("stiff-spring", NULL, "implicit-euler", 0.04, 2.5); }
static double l7_be_fraction(void) { return l7_be_drift() / 100; }
static double l7_lin_drift(void) { return -cl_drift_until("stiff-spring", NULL, "linear-implicit-euler", 0.04, 2.5); }

static double energy_after_steps(const char *m, double dt, int n)
{
    sw_sim s;
    cl_sim_init(&s, "stiff-spring", NULL, m, dt);
    for (int i = 0; i < n; i++)
        sw_sim_step(&s);
    ck_assert(!s.blown);
    double e = sw_sim_energy(&s);
    sw_sim_free(&s);
    return e;
}

static double l7_e0(void) { return energy_after_steps("linear-implicit-euler", 1.0, 0); }
static double l7_e1(void) { return energy_after_steps("linear-implicit-euler", 1.0, 1); }
/* The page's own huge step: 0.04 doubled five times, where + reaches. */
static double l7_e1_huge(void) { return energy_after_steps("linear-implicit-euler", 1.28, 1); }
static double l7_dt_plus5(void) { return cl_page_dt_after(L7, "One Newton step: Baraff and Witkin's large steps", SW_ACT_DT_DOUBLE, 5); }

/* Backward Euler's energy change in its first step at Δt = 1 (< 0: loses). */
static double l7_be_step(void)
{
    return energy_after_steps("implicit-euler", 1.0, 1) - energy_after_steps("implicit-euler", 1.0, 0);
}

static double l7_be_damping(void) { return cl_growth0("spring", "k=10000 c=0", "implicit-euler", 0.04); }
static double l7_be_damping_formula(void) { return 1 / sqrt(1 + pow(100 * 0.04, 2)); }

/* One Newton step against Newton to rounding on the (linear) spring. */
static double l7_linear_same(void)
{
    sw_sim a, b;
    cl_sim_init(&a, "spring", "c=0", "implicit-euler", 0.04);
    cl_sim_init(&b, "spring", "c=0", "linear-implicit-euler", 0.04);
    double worst = 0;
    for (int i = 0; i < 250; i++) {
        sw_sim_step(&a);
        sw_sim_step(&b);
        worst = fmax(worst, sw_truth_error(4, a.sys.y, b.sys.y));
    }
    sw_sim_free(&a);
    sw_sim_free(&b);
    return worst;
}

static double l7_im_drift(void) { return cl_max_abs_drift("stiff-spring", NULL, "implicit-midpoint", 0.04, 5); }
static double l8_e(void) { return cl_param("orbit", "e"); }
static double l8_period(void) { return cl_orbit_period(NULL); }
static double l8_rk4_5(void) { return cl_time_drift_passes("orbit", NULL, "rk4", 0.2, -5, 200); }
static double l8_rk4_5_orbits(void) { return l8_rk4_5() / l8_period(); }
static double l8_rk4_200(void) { return -cl_drift_at("orbit", NULL, "rk4", 0.2, 200); }
static double l8_verlet(void) { return cl_max_abs_drift("orbit", NULL, "verlet", 0.05, 200); }

static double l8_invariant(void)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", NULL, "verlet", 0.05);
    cl_steps_to(&s, 60);
    double d = fabs(sw_sim_drift(&s));
    sw_sim_free(&s);
    return d;
}

static double l8_euler_1(void) { return cl_drift_at("orbit", NULL, "euler", 0.05, 1); }
static double l8_euler_27(void) { return cl_drift_at("orbit", NULL, "euler", 0.05, 27); }
static double l8_euler_1_fraction(void) { return l8_euler_1() / 100; }
static double l8_rk4_31(void) { return -cl_drift_at("orbit", NULL, "rk4", 0.2, 31); }
static double l8_euler_half(void) { return cl_time_drift_passes("orbit", NULL, "euler", 0.05, 50, 100); }
static double l8_verlet_evals(void) { return cl_evals_per_step("orbit", NULL, "verlet", 0.05, 20); }
static double l8_rk4_evals(void) { return cl_evals_per_step("orbit", NULL, "rk4", 0.05, 20); }

/* Verlet's step with RK4's evaluations per second at Δt = 0.2. */
static double l8_same_work(void) { return 0.2 * l8_verlet_evals() / l8_rk4_evals(); }

/* Apoapsis over periapsis distance, and the speeds the other way round,
 * from the true state at t = 0 (periapsis) and half a period. */
static double l9_dist_ratio(void)
{
    double p[SW_MAX_PARAMS], y0[4], y1[4];
    const sw_scene *sc = cl_scene_p("orbit", ECC, p);
    ck_assert_int_eq(sw_truth_state(sc, p, 0, y0), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, cl_orbit_period(ECC) / 2, y1), 0);
    return hypot(y1[0], y1[1]) / hypot(y0[0], y0[1]);
}

static double l9_speed_ratio(void)
{
    double p[SW_MAX_PARAMS], y0[4], y1[4];
    const sw_scene *sc = cl_scene_p("orbit", ECC, p);
    ck_assert_int_eq(sw_truth_state(sc, p, 0, y0), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, cl_orbit_period(ECC) / 2, y1), 0);
    return hypot(y0[2], y0[3]) / hypot(y1[2], y1[3]);
}

static double l9_arith(void) { return (1 + 0.9) / (1 - 0.9); }

static double l9_rk4_evals(void)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", ECC, "rk4", 0.05);
    cl_steps_to(&s, cl_two_orbits());
    double e = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return e;
}

static double l9_rk4_drift(void) { return cl_drift_at("orbit", ECC, "rk4", 0.05, cl_two_orbits()); }

static rk45_run l9_rk45(double dt)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", ECC, "rk45", dt);
    double T = cl_two_orbits(), worst = 0;
    while (!s.blown && T - s.t > 1e-9) {
        sw_sim_step_until(&s, T);
        worst = fmax(worst, fabs(sw_sim_energy_drift(&s)));
    }
    ck_assert(!s.blown);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    rk45_run r = { (double)acc, (double)rej, (double)sw_sim_evals(&s), worst };
    sw_sim_free(&s);
    return r;
}

static double l9_acc04(void) { return l9_rk45(0.4).accepted; }
static double l9_rej04(void) { return l9_rk45(0.4).rejected; }
static double l9_evals04(void) { return l9_rk45(0.4).evals; }
static double l9_drift04(void) { return l9_rk45(0.4).drift; }
static double l9_acc005(void) { return l9_rk45(0.05).accepted; }
static double l9_rej005(void) { return l9_rk45(0.05).rejected; }

static double l9_rk45_stages(void)
{
    sw_sim s;
    cl_sim_init(&s, "vortex", "n=1", "rk45", 0.05);
    sw_sim_step(&s);
    double e = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return e;
}

static double l9_sim_rtol(void)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", ECC, "rk45", 0.4);
    double r = s.rtol;
    sw_sim_free(&s);
    return r;
}

static double l9_proportion(void)
{
    double evals, tight;
    cl_l9_adaptive("rk45", 1e-8, 1e-11, &evals, &tight);
    return (tight / 1e-8) / cl_l9_rk45_error_over_rtol();
}

/* Lesson 9's rk45 run (cl_l9_adaptive's) split into position and velocity
 * errors: the state error (cl_l9_rk45_error) is the velocity's. */
static void l9_split(double *pos, double *vel)
{
    sw_sim s;
    double p[SW_MAX_PARAMS], truth[4];
    const sw_scene *sc = cl_scene_p("orbit", ECC, p);
    cl_sim_init(&s, "orbit", ECC, "rk45", 0.4);
    sw_sim_set_tolerances(&s, SW_RTOL_DEFAULT, SW_ATOL_DEFAULT);
    ck_assert_int_eq(sw_sim_run_until(&s, cl_two_orbits()), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, s.t, truth), 0);
    *pos = fmax(fabs(s.sys.y[0] - truth[0]), fabs(s.sys.y[1] - truth[1]));
    *vel = fmax(fabs(s.sys.y[2] - truth[2]), fabs(s.sys.y[3] - truth[3]));
    sw_sim_free(&s);
}
static double l9_position_error(void)
{
    double pos, vel;
    l9_split(&pos, &vel);
    ck_assert_msg(vel == cl_l9_rk45_error() && vel > pos, "the state error is not the velocity's");
    return pos;
}
static double l9_position_over_rtol(void) { return l9_position_error() / SW_RTOL_DEFAULT; }
static double l9_semi_major(void)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", ECC, "rk45", 0.4);
    double x = s.sys.y[0], y = s.sys.y[1], vx = s.sys.y[2], vy = s.sys.y[3], mu = cl_param("orbit", "mu");
    sw_sim_free(&s);
    double energy = 0.5 * (vx * vx + vy * vy) - mu / hypot(x, y);
    return -mu / (2 * energy);
}

static double l9_dop853_vs_rk45(void)
{
    double e1, e2, error;
    cl_l9_adaptive("dop853", SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, &e1, &error);
    cl_l9_adaptive("rk45", SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, &e2, &error);
    return e1 / e2;
}

static double l9_tight(const char *m, int want_error)
{
    double evals, error;
    cl_l9_adaptive(m, 1e-10, 1e-13, &evals, &error);
    return want_error ? error : evals;
}

static double l9_tight_dop853_evals(void) { return l9_tight("dop853", 0); }
static double l9_tight_dop853_error(void) { return l9_tight("dop853", 1); }
static double l9_tight_rk45_evals(void) { return l9_tight("rk45", 0); }
static double l9_tight_rk45_error(void) { return l9_tight("rk45", 1); }

static double place_of(const char *name)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (strcmp(sw_integrator_at(i)->name, name) == 0)
            return i + 1;
    return NAN;
}

static double l9_dop853_place(void) { return place_of("dop853"); }
static double l9_dop853_after_rk45(void) { return place_of("dop853") - place_of("rk45"); }
static double l9_rk45_order(void) { return cl_method("rk45")->order; }

static double l10_ratio(const char *m)
{
    return cl_page_ratio(L10, "Check your order", m, 1);
}

static double l10_ratio_mid(void) { return l10_ratio("midpoint"); }
static double l10_ratio_rk4(void) { return l10_ratio("rk4"); }
static double l10_ratio_euler1(void) { return cl_page_shown_ratio(L10, "Check your order", "euler", 1); }
static double l10_ratio_euler2(void) { return cl_page_shown_ratio(L10, "Check your order", "euler", 2); }
static double l10_ratio_euler5(void) { return cl_page_ratio(L10, "Check your order", "euler", 5); }

/* Euler's amplitude error over the run, e^(ω²ΔtT/2) - 1: its ratio when Δt
 * halves, at the exponent the page's spring has at Δt = 0.02. */
static double l10_exponent(void)
{
    return pow(cl_spectrum0("spring", NULL).largest, 2) * 0.02 * sw_scene_find("spring")->duration / 2;
}

static double l10_ratio_formula(void)
{
    double x = l10_exponent();
    return (exp(x) - 1) / (exp(x / 2) - 1);
}

/* Euler's error at the report time T alone (the amplitude error the text
 * speaks of, the largest there), Δt = 0.02 over Δt = 0.01. */
static double euler_error_at_end(double dt)
{
    sw_sim s;
    cl_sim_init(&s, "spring", NULL, "euler", dt);
    cl_steps_to(&s, s.sys.scene->duration);
    double scratch[64], e = sw_sim_exact_error(&s, scratch);
    sw_sim_free(&s);
    return e;
}

static double l10_ratio_at_end(void) { return euler_error_at_end(0.02) / euler_error_at_end(0.01); }

/* Euler's largest position error over the samples the Δt message reads
 * (SW_TRUTH_SAMPLES to the report time, from the first a step reaches),
 * as the app measures it (app/dt_error.c), and the time it comes at. */
static double euler_worst(double dt, double *when)
{
    double p[SW_MAX_PARAMS], truth[64], worst = 0;
    const sw_scene *sc = cl_scene_p("spring", NULL, p);
    sw_sim s;
    cl_sim_init(&s, "spring", NULL, "euler", dt);
    for (int j = sw_truth_first_sample(sc->duration, dt); j <= SW_TRUTH_SAMPLES; j++) {
        double t = sw_truth_sample_time(sc->duration, j);
        ck_assert_int_eq(sw_sim_run_until(&s, t), 0);
        ck_assert_int_eq(sw_truth_state(sc, p, t, truth), 0);
        double e = sw_dt_state_error(s.sys.ode->dim, 2, s.sys.y, truth, 0);
        if (e > worst) {
            worst = e;
            *when = t;
        }
    }
    sw_sim_free(&s);
    return worst;
}

static double l10_worst_time(void) { double t; euler_worst(0.02, &t); return t; }
static double l10_worst_ratio(void) { double t; return euler_worst(0.02, &t) / euler_worst(0.01, &t); }
/* The exponent ω²Δt·t/2 at Δt = 0.02 when the largest error comes, and
 * the formula's ratio there. */
static double l10_worst_exponent(void) { return l10_exponent() * l10_worst_time() / sw_scene_find("spring")->duration; }
static double l10_worst_formula(void)
{
    double x = l10_worst_exponent();
    return (exp(x) - 1) / (exp(x / 2) - 1);
}

static double l10_duration(void) { return sw_scene_find("spring")->duration; }

/* Midpoint against Heun, the largest state difference over the run. */
static double mid_vs_heun(const char *scene)
{
    sw_sim a, b;
    cl_sim_init(&a, scene, NULL, "midpoint", 0.01);
    cl_sim_init(&b, scene, NULL, "heun", 0.01);
    double worst = 0, T = a.sys.scene->duration;
    while (a.t < T - 1e-9) {
        sw_sim_step(&a);
        sw_sim_step(&b);
        worst = fmax(worst, sw_truth_error(a.sys.ode->dim, a.sys.y, b.sys.y));
    }
    sw_sim_free(&a);
    sw_sim_free(&b);
    return worst;
}

static double l10_spring_same(void) { return mid_vs_heun("spring"); }
static double l10_chain_differ(void) { return mid_vs_heun("chain"); }
static double check_tolerance(void) { return SW_CHECK_ATOL + SW_CHECK_RTOL; }
static double two(void) { return 2; }
static double l6_twenty_eight(void) { return 0.28 * 100; }
static double key_be(void) { return cl_key_of("implicit-euler"); }
static double key_lbe(void) { return cl_key_of("linear-implicit-euler"); }
static double key_im(void) { return cl_key_of("implicit-midpoint"); }
static double key_verlet(void) { return cl_key_of("verlet"); }
static double key_euler(void) { return cl_key_of("euler"); }
static double l6_region_omega(void) { return cl_spectrum0("spring", "k=10000 c=0").largest; }
static double l6_mark(double dt) { return l6_region_omega() * dt; }
static double l6_mark_005(void) { return l6_mark(0.005); }
static double l6_mark_002(void) { return l6_mark(0.02); }
static double l6_mark_004(void) { return l6_mark(0.04); }
static double l6_dt_plus2(void) { return cl_page_dt_after(L6, "RK4's region", SW_ACT_DT_DOUBLE, 2); }
static double l6_dt_plus3(void) { return cl_page_dt_after(L6, "RK4's region", SW_ACT_DT_DOUBLE, 3); }
static double l6_inside_002(void) { return cl_growth0("spring", "k=10000 c=0", "rk4", 0.02); }
static double l6_outside_004(void) { return cl_growth0("spring", "k=10000 c=0", "rk4", 0.04); }
static double one_plus(void) { return 1 + SW_TRUTH_NEUTRAL; }
/* The region view's line under the picture at Δt = 0.04: the mark's
 * |Δt·λ| over where its ray leaves RK4's region (the view's own search). */
static double l6_ray_ratio_004(void)
{
    sw_spectrum sp = cl_spectrum0("spring", "k=10000 c=0");
    ck_assert_int_ge(sp.n, 1);
    sw_truth_work *w = sw_truth_work_new();
    ck_assert_ptr_nonnull(w);
    double edge = sw_region_edge_on_ray(w, sw_integrator_find("rk4"), 2, sp.mode[0].re, sp.mode[0].im);
    sw_truth_work_free(w);
    return hypot(sp.mode[0].re, sp.mode[0].im) * 0.04 / edge;
}
static double l7_region_swing(void) { return l7_slow() * 0.04; }
static double l7_region_stretch(void) { return l7_fast() * 0.04; }
static double l7_region_growth(void) { return cl_growth0("stiff-spring", NULL, "implicit-euler", 0.04); }

/* backward Euler divides each mode by 1 - Δt·λ: its growth is the largest 1/|1 - Δt·λ| */
static double l7_region_formula(void)
{
    sw_spectrum sp = cl_spectrum0("stiff-spring", NULL);
    double worst = 0;
    for (int k = 0; k < sp.n; k++)
        worst = fmax(worst, 1 / hypot(1 - 0.04 * sp.mode[k].re, 0.04 * sp.mode[k].im));
    return worst;
}

static double l7_dt_plus1(void) { return cl_page_dt_after(L7, "Backward Euler's region", SW_ACT_DT_DOUBLE, 1); }
static double l8_verlet_bound(void) { return cl_max_abs_drift("orbit", NULL, "verlet", 0.2, 1000); }
static double l8_rk4_100(void) { return -cl_drift_at("orbit", NULL, "rk4", 0.2, 100); }
static double l7_dt_plus3(void) { return cl_page_dt_after(L7, "Stiff: a slow swing and a fast stretch", SW_ACT_DT_DOUBLE, 3); }
/* Lesson 8's yoshida4 page: the run, the weights (the text's arithmetic),
 * the method's limit in theory and its evaluations per step. */
static double l8_yoshida(void) { return cl_max_abs_drift("orbit", NULL, "yoshida4", 0.05, 200); }
static double l8_yoshida_dt(void) { return cl_page_dt_after(L8, "Fourth order, still symplectic", SW_ACT_DT_HALVE, 0); }
static double l8_w1(void) { return 1 / (2 - cbrt(2.0)); }
static double l8_minus_w0(void) { return cbrt(2.0) * l8_w1(); }
static double l8_w_sum(void) { return 2 * l8_w1() - l8_minus_w0(); }
static double l8_w_cubes(void) { return 2 * pow(l8_w1(), 3) - pow(l8_minus_w0(), 3); }
static double l8_yoshida_wdt(void) { return cl_limit0("spring", "k=1 c=0", "yoshida4"); }
static double l8_yoshida_evals(void) { return cl_evals_per_step("orbit", NULL, "yoshida4", 0.05, 20); }
static double key_at_twelve(void)
{
    const sw_control *control;
    int arg;
    return sw_key_lookup('@', SW_CTX_PLAY, &control, &arg) && control->action == SW_ACT_PICK_METHOD &&
           sw_integrator_at(arg - 1) && strcmp(sw_integrator_at(arg - 1)->name, "yoshida4") == 0;
}
static double l8_dt_minus2(void) { return cl_page_dt_after(L8, "RK4 leaks energy", SW_ACT_DT_HALVE, 2); }
static double l9_dt_plus3(void) { return cl_page_dt_after(L9, "One step size does not fit all", SW_ACT_DT_DOUBLE, 3); }

/* How much the drift moved between t = 4 (after the fourth close pass) and two
 * orbits, as a fraction of it. */
static double l9_rk4_first(void) { return cl_drift_at("orbit", ECC, "rk4", 0.05, 1.5); }
static double l9_rk4_first_down(void) { return -l9_rk4_first(); }

/* RK4's close passes at Δt 0.05, through t = 4: the local minima of r (the
 * start, at periapsis, is the first), and which one flings the planet out
 * (the last pass before the energy turns positive, a drift above +100 %).
 * The passes come ever faster on the tightening orbit: checked here. */
#define R_PASS "the local minimum of r (RK4 at Δt 0.05), to the text's digits: ±0.05, one step"
typedef struct l9_passes { int n, out; double t[8]; } l9_passes;

static l9_passes l9_rk4_passes(void)
{
    l9_passes p = { .n = 1, .out = 0, .t = { 0 } };
    sw_sim s;
    cl_sim_init(&s, "orbit", ECC, "rk4", 0.05);
    double r2 = INFINITY, r1 = hypot(s.sys.y[0], s.sys.y[1]), t1 = s.t;
    while (s.t < 4 - 1e-9) {
        sw_sim_step(&s);
        double r = hypot(s.sys.y[0], s.sys.y[1]);
        if (r1 < r2 && r1 <= r && t1 > 0 && p.n < 8)
            p.t[p.n++] = t1;
        if (!p.out && sw_sim_energy_drift(&s) > 100)
            p.out = p.n;
        r2 = r1;
        r1 = r;
        t1 = s.t;
    }
    sw_sim_free(&s);
    ck_assert_msg(p.out > 0 && p.out == p.n, "RK4 escapes after pass %d of %d", p.out, p.n);
    for (int k = 2; k < p.n; k++)
        ck_assert_msg(p.t[k] - p.t[k - 1] < p.t[k - 1] - p.t[k - 2], "pass %d comes no faster", k + 1);
    return p;
}

static double l9_pass_out(void) { return l9_rk4_passes().out; }
static double l9_pass_out_t(void) { l9_passes p = l9_rk4_passes(); return p.t[p.out - 1]; }
static double l9_pass2_t(void) { return l9_rk4_passes().t[1]; }
static double l9_pass3_t(void) { return l9_rk4_passes().t[2]; }

static double l9_constant(void)
{
    double late = cl_drift_at("orbit", ECC, "rk4", 0.05, cl_two_orbits());
    return fabs(late - cl_drift_at("orbit", ECC, "rk4", 0.05, 4.0)) / late;
}

static double l6_region_growth(void) { return cl_growth0("spring", "k=10000 c=0", "rk4", 0.005); }
static double l6_region_drop(void) { return -cl_drift_at("spring", "k=10000 c=0", "rk4", 0.005, 4.0); }
static double cl_four(void) { return 4; }

const claim sw_claims_b[] = {
    /* lesson 6 */
    { L6, "multiplies the swing by ×{0.999895}", l6_region_growth, ROUNDED, 0, "the meter's growth per step: RK4 at ωΔt = 0.5 on the undamped spring", NULL },
    { L6, "so by t = {4} the energy is down", cl_four, EXACT, 0, R_COUNT, NULL },
    { L6, "the energy is down {15.5} %", l6_region_drop, ROUNDED, 0, "minus the energy drift at t = 4, RK4 at Δt = 0.005 on k = 10000, c = 0", NULL },
    { L6, "divide the error by 2² = {4}. Measure it:", l6_ratio_mid, ABS, 0.5, R_RATIO, NULL },
    { L6, "divide the error by 2⁴ = {16}. Switch", l6_ratio_rk4, ABS, 2, R_RATIO, NULL },
    { L6, "  euler      0.0125   {503}    0.04", l6_steps_euler, EXACT, 0, R_COUNT, NULL },
    { L6, "  euler      0.0125   503    {0.04}", l6_err_euler, ROUNDED, 0, R_ROUND, NULL },
    { L6, "  midpoint   0.025    {252}    0.00064", l6_steps_mid, EXACT, 0, R_COUNT, NULL },
    { L6, "  midpoint   0.025    252    {0.00064}", l6_err_mid, ROUNDED, 0, R_ROUND, NULL },
    { L6, "  rk4        0.05     {126}    0.0000003", l6_steps_rk4, EXACT, 0, R_COUNT, NULL },
    { L6, "  rk4        0.05     126    {0.0000003}", l6_err_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L6, "at ~{503} evaluations Euler", l6_evals_euler, EXACT, 0, R_COUNT, NULL },
    { L6, "Euler (Δt 0.0125) errs {0.040}", l6_err_euler, ROUNDED, 0, R_ROUND, NULL },
    { L6, "midpoint (0.025) {6.4e-4}", l6_err_mid, ROUNDED, 0, R_ROUND, NULL },
    { L6, "RK4 (0.05) {3.1e-7}", l6_err_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L6, "about {500} evaluations of g for one turn", l6_evals_mid, REL, 0.02, "\"about 500\": the three runs take 503 and 504", NULL },
    { L6, "about {500} evaluations of g for one turn", l6_evals_rk4, REL, 0.02, "\"about 500\": the three runs take 503 and 504", NULL },
    { L6, "its points near {500} evaluations", l6_evals_mid, REL, 0.02, "\"near 500\": the three runs take 503 and 504", NULL },
    { L6, "between the {1e2} and 1e3 marks", l6_decade_below, EXACT, 0, "the plot's decade mark below the table's 503 evaluations", NULL },
    { L6, "between the 1e2 and {1e3} marks", l6_decade_above, EXACT, 0, "the plot's decade mark above the table's 504 evaluations", NULL },
    { L6, "RK4 is about {100 000} times more accurate than Euler", l6_gain, REL, 0.5, "one significant figure: 50 000 to 150 000", NULL },
    { L6, "RK4 costs {four} evaluations per step, Euler one", l6_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L6, "RK4 costs four evaluations per step, Euler {one}", l6_euler_evals, EXACT, 0, R_COUNT, NULL },
    { L6, "Two evaluations of g per step instead of one", l6_mid_evals, EXACT, 0, R_COUNT, two },
    { L6, "@hint Press {5}, or i until the status line says rk4.", cl_key_rk4, EXACT, 0, "the key that picks the method", NULL },
    { L6, "When does a {4}-evaluation step pay?", l6_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L6, "each halving of Δt gains {16}× for RK4", l6_rk4_gain, ABS, 2, "the goals' tolerance for 16", NULL },
    { L6, "gains 16× for RK4 against {2}× for Euler", l6_euler_gain, ABS, 0.3, "the goals' tolerance for 2", NULL },
    { L6, "oscillator it blows up once ωΔt > 2√2 ≈ {2.83}", cl_rk4_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L6, "@answer a) About {0.028} | Yes: 2.83 / 100.", l6_limit100, ROUNDED, 0, R_ROUND, NULL },
    { L6, "its edge there is at 2√2 ≈ {2.83}", cl_rk4_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L6, "This spring has ω = {100}", l6_region_omega, ROUNDED, 0, R_ROUND, NULL },
    { L6, "the marks Δt·λ sit at ±{0.5}i", l6_mark_005, ROUNDED, 0, R_ROUND, NULL },
    { L6, "at Δt = {0.02} the marks are at ±2i", l6_dt_plus2, EXACT, 0, "the step two presses of + give", NULL },
    { L6, "the marks are at ±{2}i, still inside", l6_mark_002, ROUNDED, 0, R_ROUND, NULL },
    { L6, "still inside; at", l6_inside_002, ATMOST, 0, "inside: RK4's growth at ωΔt = 2 is at most one", one_plus },
    { L6, "Δt = {0.04} they are at ±4i", l6_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L6, "they are at ±{4}i, outside the region", l6_mark_004, ROUNDED, 0, R_ROUND, NULL },
    { L6, "outside the region, and the meter says GROWS", l6_outside_004, ATLEAST, 0, "outside: RK4's growth at ωΔt = 4 is above one", one_plus },
    { L6, "the line under the numbers says {1.41}×edge", l6_ray_ratio_004, ROUNDED, 0, R_ROUND, NULL },
    { L6, "@hint Press + three times: 0.01, 0.02, {0.04}.", l6_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L6, "ωΔt would be {28}", l6_twenty_eight, EXACT, 0, R_MATH, NULL },
    { L6, "over one turn (t = {2π})", l6_report_time, REL, 1e-12, R_COUNT, NULL },
    /* lesson 7 */
    { L7, "(k = {10000},", l7_k, EXACT, 0, R_COUNT, NULL },
    { L7, "ω = {100} rad/s). Measured", l7_fast, ROUNDED, 0, R_ROUND, NULL },
    { L7, "(about {3} rad/s)", l7_slow, ABS, 0.5, R_ABOUT, NULL },
    { L7, "fast stretch of the spring at ω = {100} rad/s", l7_fast, ROUNDED, 0, R_ROUND, NULL },
    { L7, "Verlet is stable while ωΔt < {2}", cl_verlet_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L7, "so the fast stretch limits Δt to {0.02}", cl_l7_verlet_theory, ROUNDED, 0, "the limit in theory along the run, to the text's digits", NULL },
    { L7, "so the fast stretch limits Δt to {0.02}", cl_l7_verlet_measured, ROUNDED, 0, "the limit measured by the stability lab, to the text's digits", NULL },
    { L7, "the swing alone would be fine with steps {ten} times longer", l7_swing_longer, ATLEAST, 0, "Verlet's limit on the swing's mode alone over its limit on the pendulum", NULL },
    { L7, "@hint Press + three times: 0.01, 0.02, {0.04}.", l7_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L7, "at Δt = 0.04 Verlet blows up within {a} second", l7_verlet_blow, ATMOST, 0, "\"within a second\": before t = 1", NULL },
    { L7, "by t = 2.5 about {two thirds} of the swing's energy is gone", l7_be_fraction, ABS, 0.02, "\"about two thirds\": within two percentage points", NULL },
    { L7, "0.04 removes {65} % of the swing's energy by t = 2.5", l7_be_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "the one-step linearised version {81} %", l7_lin_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "one Newton step removes about {81} % of the swing's", l7_lin_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "where backward Euler removed {65} %", l7_be_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "lifts the energy from {-8.50} J to +45.6 J", l7_e0, ROUNDED, 0, R_ROUND, NULL },
    { L7, "lifts the energy from -8.50 J to {+45.6} J", l7_e1_huge, ROUNDED, 0, R_ROUND, NULL },
    { L7, "at Δt = {1.28} (+ five times)", l7_dt_plus5, EXACT, 0, "the step five presses of + give", NULL },
    { L7, "gains energy ({-8.50} J to", l7_e0, ROUNDED, 0, R_ROUND, NULL },
    { L7, "({-8.50} J to +38.4 J) where", l7_e0, ROUNDED, 0, R_ROUND, NULL },
    { L7, "(-8.50 J to {+38.4} J) where backward Euler loses it", l7_e1, ROUNDED, 0, R_ROUND, NULL },
    { L7, "where backward Euler loses energy at any Δt here", l7_be_step, ATMOST, 0, "its first step at Δt = 1 loses energy (every Δt: tests/check_truth.c)", cl_zero },
    { L7, "on a linear spring it shrinks every oscillation by 1/√(1 + (ωΔt)²) per step", l7_be_damping, REL, 1e-9, "ρ of backward Euler's map at ωΔt = 4", l7_be_damping_formula },
    { L7, "On a linear spring it is exactly backward Euler", l7_linear_same, ATMOST, 0, "to rounding: 1e-12 over 250 steps", cl_rounding },
    { L7, "keeps the energy within {0.3} % at 0.04", l7_im_drift, ATMOST, 0.5, "a bound the run comes within half of", NULL },
    { L7, "starts to gain energy above Δt ≈ {0.19} (try", cl_l7_im_limit, ROUNDED, 0, "the limit the stability lab measures, to the text's digits", NULL },
    { L7, "nonlinear spring above Δt ≈ {0.19} (stepwise", cl_l7_im_limit, ROUNDED, 0, "the limit the stability lab measures, to the text's digits", NULL },
    { L7, "press {7} if you switched away.", key_be, EXACT, 0, "the key that picks the method", NULL },
    { L7, "linear-implicit-euler (press {8})", key_lbe, EXACT, 0, "the key that picks the method", NULL },
    { L7, "@hint The page chose implicit-midpoint; press {9} if you switched away.", key_im, EXACT, 0, "the key that picks the method", NULL },
    { L7, "A step divides each mode by 1 - Δt·λ", l7_region_growth, REL, 1e-9, "ρ of backward Euler's map is the largest 1/|1 - Δt·λ|", l7_region_formula },
    { L7, "(near ±{0.125}i at Δt = 0.04)", l7_region_swing, ROUNDED, 0, R_ROUND, NULL },
    { L7, "the stretch's (±{4}i, beyond that", l7_region_stretch, ROUNDED, 0, R_ROUND, NULL },
    { L7, "beyond that at {0.08}: past the picture's edge", l7_dt_plus1, EXACT, 0, "the step one press of + gives", NULL },
    { L7, "@hint Press + once: {0.08}.", l7_dt_plus1, EXACT, 0, "the step one press of + gives", NULL },
    /* lesson 8 */
    { L8, "(eccentricity {0.5}; one orbit", l8_e, EXACT, 0, R_COUNT, NULL },
    { L8, "takes 2π ≈ {6.3} seconds", l8_period, ROUNDED, 0, "Kepler's period from the scene's energy", NULL },
    { L8, "(e = 0.5, period {2π})", l8_period, REL, 1e-12, "Kepler's period from the scene's energy", NULL },
    { L8, "loses {5} % of the energy by t ≈ 31", l8_rk4_31, ROUNDED, 0, R_ROUND, NULL },
    { L8, "loses 5 % of the energy by t ≈ {31}", l8_rk4_5, ROUNDED, 0, "the first time the drift passes -5 %, to the text's digits", NULL },
    { L8, "after about {five} orbits more than 5 % of the energy is gone", l8_rk4_5_orbits, ABS, 0.5, R_ABOUT, NULL },
    { L8, "and {35} % by t = 200", l8_rk4_200, ROUNDED, 0, R_ROUND, NULL },
    { L8, "stays within {0.7} % for 200 s", l8_verlet, ATMOST, 0.15, "a bound the run comes within 15 % of", NULL },
    { L8, "when the line is short, stays near {1e-15}", l8_invariant, MAGNITUDE, 1, "\"near\": within a factor ten", NULL },
    { L8, "Euler at Δt 0.05 gains {60} % in its first close pass", l8_euler_1, ROUNDED, 0, "the drift at t = 1, after the pass, to the text's digits", NULL },
    { L8, "gains 60 % in its first close pass (within {one} second)", l8_euler_half, ATMOST, 0, "the drift passes 50 % before t = 1", NULL },
    { L8, "and {99} % by the second (t = 27)", l8_euler_27, ROUNDED, 0, R_ROUND, NULL },
    { L8, "within {half} a second, the energy jumps by more than half", l8_euler_half, ATMOST, 0, "the first time the drift passes 50 %", NULL },
    { L8, "within half a second, the energy jumps by more than {half}", l8_euler_1_fraction, ATLEAST, 0, "the drift after the pass, as a fraction", NULL },
    { L8, "Velocity Verlet costs {one} evaluation per step, RK4 four", l8_verlet_evals, EXACT, 0, R_COUNT, NULL },
    { L8, "Velocity Verlet costs one evaluation per step, RK4 {four}", l8_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L8, "So at Δt = {0.05} Verlet does the same work per second as RK4 at Δt = 0.2", l8_same_work, EXACT, 0, R_COUNT, NULL },
    { L8, "@hint Press - twice: 0.1, {0.05}.", l8_dt_minus2, EXACT, 0, "the step two presses of - give", NULL },
    { L8, "@hint Use verlet (press {6})", key_verlet, EXACT, 0, "the key that picks the method", NULL },
    { L8, "its energy wobbles within {12.3} % however", l8_verlet_bound, ATMOST, 0.05, "the largest wobble over 1000 s, a bound it comes within 5 % of", NULL },
    { L8, "by t = 100 its energy is down {15.5} %", l8_rk4_100, ROUNDED, 0, R_ROUND, NULL },
    { L8, "@hint Press {6}, or i until the status line says verlet.", key_verlet, EXACT, 0, "the key that picks the method", NULL },
    { L8, "@hint Press {1}, or I until the status line says euler.", key_euler, EXACT, 0, "the key that picks the method", NULL },
    { L8, "fourth order) at Δt {0.05} keeps the energy", l8_yoshida_dt, EXACT, 0, "the page's Δt", NULL },
    { L8, "keeps the energy within {0.013} % over 200 s", l8_yoshida, ATMOST, 0.05, "a bound the run comes within 5 % of", NULL },
    { L8, "w1 = 1/(2 - 2^(1/3)) ≈ {1.351}", l8_w1, ROUNDED, 0, R_MATH, NULL },
    { L8, "w0 = -2^(1/3)·w1 ≈ -{1.702}", l8_minus_w0, ROUNDED, 0, R_MATH, NULL },
    { L8, "(2·w1 + w0 = 1,", l8_w_sum, REL, 1e-15, "the weights sum to one step (to rounding)", cl_one },
    { L8, "2·w1³ + w0³ = 0)", l8_w_cubes, ABS, 1e-14, "the h³ terms cancel (to rounding)", cl_zero },
    { L8, "next one's first: {three} evaluations a step", l8_yoshida_evals, EXACT, 0, R_COUNT, NULL },
    { L8, "its energy stays within {0.013} % for 200 s", l8_yoshida, ATMOST, 0.05, "a bound the run comes within 5 % of", NULL },
    { L8, "Verlet's wandered {0.7} %", l8_verlet, ATMOST, 0.15, "a bound the run comes within 15 % of", NULL },
    { L8, "ω·Δt below {1.57}, against", l8_yoshida_wdt, ROUNDED, 0, "yoshida4's limit in theory, to the text's digits", NULL },
    { L8, "against Verlet's {2}.", cl_verlet_wdt, ABS, 1e-6, "Verlet's limit in theory", NULL },
    { L8, "Press @, or i until the status line says yoshida4.", key_at_twelve, EXACT, 0, "'@' picks the twelfth method, yoshida4", cl_one },
    /* lesson 9 */
    { L9, "whips past it {nineteen} times closer", l9_dist_ratio, REL, 1e-9, "apoapsis over periapsis of the true orbit", NULL },
    { L9, "nineteen times closer and {nineteen} times faster", l9_speed_ratio, REL, 1e-9, "the speeds at periapsis and apoapsis of the true orbit", NULL },
    { L9, "(1 + e)/(1 - e) = {19}", l9_arith, REL, 1e-12, R_MATH, NULL },
    { L9, "RK4 at fixed Δt 0.05 ({1008} evaluations)", l9_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L9, "(energy +{1250} %, then constant", l9_rk4_drift, REL, 0.004, "three significant figures", NULL },
    { L9, "(energy {-122} % by t = 1.5)", l9_rk4_first, ROUNDED, 0, R_ROUND, NULL },
    { L9, "(its energy down {122} % by t = 1.5)", l9_rk4_first_down, ROUNDED, 0, "the same drift, its sign said in words", NULL },
    { L9, "the fourth, at t ≈ {2.9}, flings it out", l9_pass_out_t, ROUNDED, 0, "the pass after which the energy is positive: " R_PASS, NULL },
    { L9, "the {fourth}, at t ≈ 2.9, flings it out", l9_pass_out, EXACT, 0, "passes counted as minima of r, the start the first", NULL },
    { L9, "orbit (at t ≈ {1.9} and 2.55); the", l9_pass2_t, ROUNDED, 0, "the second pass: " R_PASS, NULL },
    { L9, "orbit (at t ≈ 1.9 and {2.55}); the", l9_pass3_t, ROUNDED, 0, "the third pass: " R_PASS, NULL },
    { L9, "flings it out (up {1250} %, then constant", l9_rk4_drift, REL, 0.004, "three significant figures", NULL },
    { L9, "(up 1250 %, then {constant}: it has escaped)", l9_constant, ABS, 0.001, "as for \"constant\" below", NULL },
    { L9, "fourth, at t ≈ {2.9}, flings it away", l9_pass_out_t, ROUNDED, 0, "as above", NULL },
    { L9, "the {fourth}, at t ≈ 2.9, flings it away", l9_pass_out, EXACT, 0, "as above", NULL },
    { L9, "tightening orbit (t ≈ {1.9}, 2.55); the", l9_pass2_t, ROUNDED, 0, "as above", NULL },
    { L9, "tightening orbit (t ≈ 1.9, {2.55}); the", l9_pass3_t, ROUNDED, 0, "as above", NULL },
    { L9, "at its {fourth} close pass (t ≈ 2.9) RK4", l9_pass_out, EXACT, 0, "as above", NULL },
    { L9, "at its fourth close pass (t ≈ {2.9}) RK4", l9_pass_out_t, ROUNDED, 0, "as above", NULL },
    { L9, "passes, at t ≈ {1.9}, 2.55 and 2.9, last", l9_pass2_t, ROUNDED, 0, "as above", NULL },
    { L9, "passes, at t ≈ 1.9, {2.55} and 2.9, last", l9_pass3_t, ROUNDED, 0, "as above", NULL },
    { L9, "passes, at t ≈ 1.9, 2.55 and {2.9}, last", l9_pass_out_t, ROUNDED, 0, "as above", NULL },
    { L9, "+1250 %, then {constant}: the planet has escaped", l9_constant, ABS, 0.001, "the drift moves less than 0.1 % of itself from t = 4 to two orbits", NULL },
    { L9, "@hint Press + three times: 0.1, 0.2, {0.4}.", l9_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L9, "about {120} accepted, 50 rejected", l9_acc04, ABS, 10, "\"about 120\": within ten", NULL },
    { L9, "about 120 accepted, {50} rejected", l9_rej04, ABS, 5, "\"about 50\": within five", NULL },
    { L9, "{1027} evaluations, energy", l9_evals04, EXACT, 0, R_COUNT, NULL },
    { L9, "energy off by {0.002} % at worst", l9_drift04, ROUNDED, 0, "the largest |drift| over the run, to the text's digits", NULL },
    { L9, "largest step: {293} accepted, 28 rejected)", l9_acc005, EXACT, 0, R_COUNT, NULL },
    { L9, "largest step: 293 accepted, {28} rejected)", l9_rej005, EXACT, 0, R_COUNT, NULL },
    { L9, "rk45's energy is off by {a few thousandths} of a percent", l9_drift04, ABS, 0.004, "\"a few thousandths\": 0.001 to 0.009", NULL },
    { L9, "it needs about {1000} evaluations, as many as RK4 spent", l9_evals04, REL, 0.05, "\"about 1000\": within 5 %", NULL },
    { L9, "a 5th-order answer and a 4th-order one from the same {seven} stages", l9_rk45_stages, EXACT, 0, "the first step evaluates every stage", NULL },
    { L9, "({six} new evaluations: the", cl_l9_rk45_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { L9, "takes each step twice at once: a {5}th-order answer", l9_rk45_order, EXACT, 0, "the method's order in the table", NULL },
    { L9, "@hint Press {0} (zero), or i until the status line says rk45.", cl_key_rk45, EXACT, 0, "the key that picks the method", NULL },
    { L9, "The tolerance (rtol = {1e-6}) bounds each step's error", l9_sim_rtol, EXACT, 0, "the tolerance a sim starts with", NULL },
    { L9, "position is off by about {0.0015} and its velocity", l9_position_error, ROUNDED, 0, "rk45 at largest step 0.4 (the page's): the largest position component's error against Kepler at two orbits", NULL },
    { L9, "and its velocity by about {0.034} (lengths", cl_l9_rk45_error, ROUNDED, 0, "the state error, whose largest component is a velocity (checked there)", NULL },
    { L9, "semi-major axis, {1}): the", l9_semi_major, ABS, 1e-12, "a = -μ/(2E) from the start's energy", NULL },
    { L9, "position error alone is some {1500} times rtol", l9_position_over_rtol, REL, 0.01, "two significant figures", NULL },
    { L9, "Ask for less per step and the run's error falls in proportion", l9_proportion, MAGNITUDE, 0.3, "error over rtol at rtol 1e-8 against at 1e-6: within a factor two", cl_one },
    { L9, "dop853, {twelve} new evaluations per step", cl_dop853_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { L9, "Dormand and Prince also paired an {8}th-order answer", cl_ord_dop853, EXACT, 0, "the method's order in the table", NULL },
    { L9, "At this loose tolerance it costs about what rk45 does", l9_dop853_vs_rk45, ABS, 0.2, "dop853's evaluations over rk45's at rtol 1e-6, largest step 0.4: within 20 %", cl_one },
    { L9, "two orbits cost dop853 {2690} evaluations", l9_tight_dop853_evals, EXACT, 0, "rtol 1e-10, atol 1e-13 (bench's 1e-3·rtol), largest step 0.4", NULL },
    { L9, "for an error of {9e-8}, and rk45", l9_tight_dop853_error, ROUNDED, 0, "as above, the error against Kepler", NULL },
    { L9, "and rk45 {4591} for 2e-6", l9_tight_rk45_evals, EXACT, 0, "as above", NULL },
    { L9, "and rk45 4591 for {2e-6}", l9_tight_rk45_error, ROUNDED, 0, "as above", NULL },
    { L9, "(press i once: it is the {11}th method)", l9_dop853_place, EXACT, 0, "dop853's place in the list", NULL },
    { L9, "under rk45. Switch to dop853 (press i {once}", l9_dop853_after_rk45, EXACT, 0, "places from rk45 to dop853", NULL },
    /* lesson 10 */
    { L10, "A correct midpoint gives a ratio near {4}, RK4 near 16", l10_ratio_mid, ABS, 0.5, "the lessons' tolerance for 4", NULL },
    { L10, "A correct midpoint gives a ratio near 4, RK4 near {16}", l10_ratio_rk4, ABS, 2, "the lessons' tolerance for 16", NULL },
    { L10, "A first-order method shows {2.3}, then 2.1", l10_ratio_euler1, ROUNDED, 0, "the ratio the status line shows for euler, to the text's digits", NULL },
    { L10, "A first-order method shows 2.3, then {2.1}", l10_ratio_euler2, ROUNDED, 0, "as above, halving again", NULL },
    { L10, "until the ratio settles near {2}: Euler's", l10_ratio_euler5, ABS, 0.1, "the fifth halving, from Δt = 0.00125", NULL },
    { L10, "Euler's amplitude error at time t grows like e^(ω²Δt·t/2) - 1", l10_ratio_at_end, REL, 0.01, "the ratio (e^x - 1)/(e^(x/2) - 1) at x = ω²ΔtT/2 = 1 against Euler's error at T, Δt 0.02 over 0.01", l10_ratio_formula },
    { L10, "Euler's amplitude error at time t grows like e^(ω²Δt·t/2) - 1", l10_worst_ratio, REL, 0.01, "the same ratio at x = ω²Δt·t/2 for t where the largest error comes, against the largest errors' ratio", l10_worst_formula },
    { L10, "The ratio shown is of the largest error over the 10 s run", l10_ratio_euler1, REL, 1e-9, "the message's ratio is the largest position errors' over the samples, recomputed here", l10_worst_ratio },
    { L10, "over the {10} s run, which comes", l10_duration, EXACT, 0, "the spring's report time", NULL },
    { L10, "which comes near t = {5} (exponent", l10_worst_time, ABS, 0.625, "the sample of the largest error, Δt 0.02: one sample spacing (T/16)", NULL },
    { L10, "(exponent {0.5} at Δt = 0.02: the", l10_worst_exponent, ABS, 1e-9, "ω²Δt·t/2 = 10·0.02·5/2, to rounding", NULL },
    { L10, "at Δt = 0.02: the formula gives {2.3})", l10_worst_formula, ROUNDED, 0, R_MATH, NULL },
    { L10, "at t = {10} (exponent 1) the", l10_duration, EXACT, 0, "the spring's report time", NULL },
    { L10, "(exponent {1}) the errors'", l10_exponent, ABS, 1e-9, "ω²ΔtT/2 = 10·0.02·10/2, to rounding", NULL },
    { L10, "the errors' ratio is {2.6}, as", l10_ratio_at_end, ROUNDED, 0, "Euler's error at T, Δt 0.02 over 0.01, to the text's digits", NULL },
    { L10, "ratio is {2.6}, as the formula gives too", l10_ratio_formula, ROUNDED, 0, R_MATH, NULL },
    { L10, "what does an error ratio of {2} say about the order?", cl_l2_ratio2, ABS, 0.3, "lesson 2's measurement, with the lessons' tolerance for 2", NULL },
    { L10, "midpoint and Heun agree to {rounding}", l10_spring_same, ATMOST, 0, "1e-12 over the report time", NULL },
    { L10, "Grade on the chain: on the one-dimensional spring", l10_chain_differ, ATLEAST, 0, "on the chain midpoint and Heun differ by more than check's tolerance", check_tolerance },
};
const size_t sw_claims_b_n = sizeof sw_claims_b / sizeof sw_claims_b[0];
