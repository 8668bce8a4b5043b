/* Claims: the figures of lessons 1-5 and how each is measured. */
#include "claims.h"

static double l1_omega(void) { return cl_param("vortex", "omega"); }

/* One turn: 2π over the rotation rate, read off the linearisation (±iω). */
static double l1_turn(void)
{
    sw_spectrum sp = cl_spectrum0("vortex", NULL);
    return TWO_PI / fabs(sp.mode[0].im);
}

static double l1_gyre_swing(void) { return TWO_PI / cl_param("gyre", "omega"); }
static double l2_factor(void) { return cl_growth0("vortex", NULL, "euler", 0.1); }
static double l2_factor_formula(void) { return sqrt(1 + 0.1 * 0.1 * pow(l1_omega(), 2)); }
static double l2_turn_steps(void) { return (double)cl_steps_for("vortex", NULL, "euler", 0.1, TWO_PI); }
static double l2_power(void) { return pow(1.005, 63); }
static double l2_turn_growth(void) { return cl_vortex_radius_growth("euler", 0.1, TWO_PI); }
static double l2_sqrt116(void) { return sqrt(1 + 0.4 * 0.4); }
static double l2_factor04(void) { return cl_growth0("vortex", NULL, "euler", 0.4); }
static double l2_turn_steps04(void) { return (double)cl_steps_for("vortex", NULL, "euler", 0.4, TWO_PI); }
static double l2_turn_growth04(void) { return cl_vortex_radius_growth("euler", 0.4, TWO_PI); }

/* One Euler step's error halving Δt: the local error's order (2 for O(Δt²)). */
static double l2_local_order(void)
{
    double err[2];
    for (int i = 0; i < 2; i++) {
        sw_sim s;
        double h = 0.01 / (1 << i), truth[400];
        cl_sim_init(&s, "vortex", NULL, "euler", h);
        sw_sim_step(&s);
        ck_assert_int_eq(sw_truth_state(s.sys.scene, s.sys.p, s.t, truth), 0);
        err[i] = sw_truth_error(s.sys.ode->dim, s.sys.y, truth);
        sw_sim_free(&s);
    }
    return log2(err[0] / err[1]);
}

static double l2_samples(void) { return SW_TRUTH_SAMPLES; }
static double l2_global_order(void) { return cl_order_by_halving("vortex", NULL, "euler", 0.01); }
static double l2_report_time(void) { return sw_scene_find("vortex")->duration; }
static double l2_ratio1(void) { return cl_page_ratio(L2, "Measure the order", NULL, 1); }
static double l2_ratio3(void) { return cl_page_ratio(L2, "Measure the order", NULL, 3); }
static double l2_err(double dt) { return cl_page_error(L2, "Measure the order", "euler", dt); }
static double l2_err05(void) { return l2_err(0.05); }
static double l2_err025(void) { return l2_err(0.025); }
static double l2_err0125(void) { return l2_err(0.0125); }
static double l2_midpoint_order(void) { return cl_order_by_halving("vortex", NULL, "midpoint", 0.05); }
static double l2_rk4_order(void) { return cl_order_by_halving("vortex", NULL, "rk4", 0.1); }

/* How far Euler's ball lands from the exact one at t = 2 (the status
 * line's error: the largest state difference). */
static double l3_miss(void)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L3, "Euler in phase space");
    cl_steps_to(&a.sims[0], 2.0);
    double e = sw_app_error(&a, 0);
    cl_page_free(&r, &a);
    return e;
}

static double l3_miss_position(void)
{
    sw_sim s;
    double truth[4];
    cl_sim_init(&s, "projectile", NULL, "euler", 0.05);
    cl_steps_to(&s, 2.0);
    ck_assert_int_eq(sw_truth_state(s.sys.scene, s.sys.p, s.t, truth), 0);
    double d = hypot(s.sys.y[0] - truth[0], s.sys.y[1] - truth[1]);
    sw_sim_free(&s);
    return d;
}

static double l3_omega(void) { return cl_spectrum0("spring", "c=0").largest; }
static double l3_omega_dt(void) { return l3_omega() * 0.02; }

/* Energy factor per step: the square of the amplitude's growth ρ. */
static double l3_energy_factor(void) { return pow(cl_growth0("spring", "c=0", "euler", 0.02), 2); }
/* The meter's growth per step on the page as the app shows it. */
static double l3_meter_factor(void)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L3, "Euler on a spring");
    sw_app_meter mt;
    ck_assert_int_eq(sw_app_stability(&a, &mt), 1);
    cl_page_free(&r, &a);
    return mt.growth;
}
static double l3_steps_per_second(void) { return (double)cl_steps_for("spring", "c=0", "euler", 0.02, 1.0); }
static double l3_time_to_50(void) { return cl_time_drift_passes("spring", "c=0", "euler", 0.02, 50, 10); }
static double l3_k(void) { return cl_param("spring", "k"); }
static double l3_m(void) { return cl_param("spring", "m"); }
static double l3_beads(void) { return cl_param("chain", "n"); }

static double dim_of(const char *scene)
{
    sw_sim s;
    cl_sim_init(&s, scene, NULL, "rk4", 0.01);
    double d = s.sys.ode->dim;
    sw_sim_free(&s);
    return d;
}

static double l3_chain_dim(void) { return dim_of("chain"); }
static double l3_chain_positions(void) { return dim_of("chain") / 2; }
static double l3_particle_dim(void) { return dim_of("projectile"); }
static double l3_3d(void) { return 2 * 3; }
static double l4_e(void) { return cl_param("bounce", "e"); }

/* One ball dropped from 4 m in the bounce scene (its own contact with
 * restitution e), stepped finely: the top of its first hop. */
static double bounce_height(const char *sets)
{
    sw_sim s;
    cl_sim_init(&s, "bounce", sets, "rk4", 1e-4);
    double y[4] = { 5.0, 4.0, 0.0, 0.0 }, top = 0;
    sw_sim_set_state(&s, y);
    int bounced = 0;
    while (s.t < 3.0) {
        sw_sim_step(&s);
        if (s.sys.y[3] > 0)
            bounced = 1;
        if (bounced)
            top = fmax(top, s.sys.y[1]);
        if (bounced && s.sys.y[3] < 0)
            break;
    }
    sw_sim_free(&s);
    return top;
}

static double l4_bounce_height(void) { return bounce_height("n=1"); }
static double l4_perfect(void) { return bounce_height("n=1 e=1") / 4; }
static double l4_dead(void) { return bounce_height("n=1 e=0"); }
static double l4_e_height(void) { return 4 * l4_e(); }
static double l4_e_squared(void) { return l4_e() * l4_e(); }
static double l4_smooth_ratio(void) { return pow(2, cl_order_by_halving("projectile", NULL, "rk4", 0.05)); }
/* The energy change's reference on the projectile: the status line's
 * scale (sw_sim_energy_scale) is the kinetic energy at launch, ½m|v0|²,
 * computed here from the parameters and checked against the scale. */
static double l4_launch_ke(void)
{
    sw_sim s;
    cl_sim_init(&s, "projectile", "drag=1", "rk4", 0.05);
    double vx = cl_param("projectile", "vx"), vy = cl_param("projectile", "vy"), m = cl_param("projectile", "m");
    double ke = 0.5 * m * (vx * vx + vy * vy);
    ck_assert_double_eq_tol(sw_sim_energy_scale(&s), ke, 1e-12 * ke);
    sw_sim_free(&s);
    return ke;
}
static double l4_drag_drift(void) { return cl_drift_until("projectile", "drag=1", "rk4", 0.05, 3); }

static double l4_report_time(void) { return sw_scene_find("bounce")->duration; }

/* Swings in ten seconds: ten over the damped period 2π/ω_d (the
 * linearisation's imaginary part). */
static double l5_swings(void) { return 10 * fabs(cl_spectrum0("spring", NULL).mode[0].im) / TWO_PI; }
static double l5_stiff_omega(void) { return cl_spectrum0("spring", STIFF).largest; }
static double l5_euler_energy_factor(void) { return pow(cl_growth0("spring", STIFF, "euler", 0.005), 2); }
static double l5_arith(void) { return 1 - 10 * 0.005 + 10000 * 0.005 * 0.005; }
static double l5_blow(void) { return cl_blow_time("spring", STIFF, "euler", 0.005, 10); }
static double l5_critical(void) { return 2 * sqrt(10000 * cl_l5_m()); }

/* The decay rate of the critically damped spring's modes: -Re λ. */
static double l5_crit_rate(void)
{
    sw_spectrum sp = cl_spectrum0("spring", "k=10000 c=200");
    double worst = 0;
    for (int i = 0; i < sp.n; i++)
        worst = fmax(worst, -sp.mode[i].re);
    return worst;
}

static double l5_crit_growth(void) { return cl_growth0("spring", "k=10000 c=200", "euler", 0.005); }
static double l5_crit_arith(void) { return fabs(1 - 100 * 0.005); }

static double l5_crit_first_step(void)
{
    sw_sim s;
    cl_sim_init(&s, "spring", "k=10000 c=200", "euler", 0.005);
    sw_sim_step(&s);
    double d = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return d;
}

static double l5_huge_rate(void) { return cl_spectrum0("spring", "k=10000 c=5000").largest; }
static double l5_huge_limit(void) { return cl_limit0("spring", "k=10000 c=5000", "euler"); }
static double l5_huge_smaller(void) { return 0.005 / l5_huge_limit(); }
static double l5_light_limit(void) { return cl_limit0("spring", STIFF, "euler"); }
static double l5_light_arith(void) { return 10.0 / 10000.0; }
static double l5_steps(void) { return (double)cl_steps_for("spring", STIFF, "euler", 0.000625, 1.0); }

/* (At Δt = 0.005 Euler blows up on this spring; the steps are counted on
 * the critically damped one, which it runs.) */
static double l5_steps_ratio(void)
{
    return l5_steps() / (double)cl_steps_for("spring", "k=10000 c=200", "euler", 0.005, 1.0);
}

static double l5_undamped_factor(void) { return pow(cl_growth0("spring", "k=10000 c=0", "euler", 0.000625), 2); }
static double l5_undamped_formula(void) { return 1 + pow(100 * 0.000625, 2); }
static double l5_undamped_limit(void) { return cl_limit0("spring", "k=10000 c=0", "euler"); }
static double two_root_two(void) { return 2 * sqrt(2); }
static double l5_wdt(void) { return l5_stiff_omega() * 0.005; }
static double l3_formula(void) { return 1 + pow(l3_omega() * 0.02, 2); }
static double two_hundred(void) { return 200; }
static double l3_phase_euler(void) { return cl_drift_at("spring", "c=0", "euler", 0.02, 10); }
static double l3_phase_be(void) { return -cl_drift_at("spring", "c=0", "implicit-euler", 0.02, 10); }
static double l3_phase_se(void) { return cl_max_abs_drift("spring", "c=0", "symplectic-euler", 0.02, 10); }

/* The damped stiff spring's oscillating mode (λ with Im λ > 0). */
static sw_mode l5_mode(void)
{
    sw_spectrum sp = cl_spectrum0("spring", STIFF);
    ck_assert_int_ge(sp.n, 1);
    sw_mode md = sp.mode[0];
    if (md.im < 0)
        md.im = -md.im, md.pim = -md.pim;
    return md;
}

static double l5_lambda_re(void) { return l5_mode().re; }
static double l5_lambda_im(void) { return l5_mode().im; }
static double l5_half_c(void) { return 10.0 / (2 * cl_l5_m()); }
static double l5_mark_re(void) { return l5_mode().re * 0.005; }
static double l5_mark_im(void) { return l5_mode().im * 0.005; }
static double l5_growth(void) { return cl_growth0("spring", STIFF, "euler", 0.005); }
/* The region view's line under the picture: the mark's |Δt·λ| over the
 * distance along its ray where Euler's region ends (the view's own
 * search, render/region_ray.c), at the page's Δt and each halving. */
static double l5_ray_ratio(double dt)
{
    sw_mode md = l5_mode();
    sw_truth_work *w = sw_truth_work_new();
    ck_assert_ptr_nonnull(w);
    double edge = sw_region_edge_on_ray(w, sw_integrator_find("euler"), 2, md.re, md.im);
    sw_truth_work_free(w);
    return hypot(md.re, md.im) * dt / edge;
}
static double l5_ray_ratio0(void) { return l5_ray_ratio(0.005); }
static double l5_ray_ratio1(void) { return l5_ray_ratio(0.0025); }
static double l5_ray_ratio2(void) { return l5_ray_ratio(0.00125); }
static double l5_ray_ratio3(void) { return l5_ray_ratio(0.000625); }
static double l5_page_dt(void) { return cl_page_dt_after(L5, "Why: outside the stability region", SW_ACT_DT_HALVE, 0); }
static double l5_growth_formula(void) { return hypot(1 + l5_mark_re(), l5_mark_im()); }
static double l2_dt_plus2(void) { return cl_page_dt_after(L2, "Bigger steps, bigger errors", SW_ACT_DT_DOUBLE, 2); }
static double l5_dt_minus3(void) { return cl_page_dt_after(L5, "Remedy 2: tiny time steps", SW_ACT_DT_HALVE, 3); }

/* The bounce page's ratios as the dt-change message prints them, and
 * whether it read the first as an order (it must not: the next differs). */
static double l4_bounce_shown1(void) { return cl_page_shown_ratio(L4, "A bounce breaks the order", NULL, 1); }
static double l4_bounce_shown2(void) { return cl_page_shown_ratio(L4, "A bounce breaks the order", NULL, 2); }
static double l4_bounce_not_order(void) { return isnan(cl_l4_ratio()) ? 0 : 1; }

/* Lesson 3's undamped spring (c = 0) under Euler at Δt = 0.02: the
 * energy the linear factor 1 + (ωΔt)² per step predicts at t = 10, and
 * when the mass first passes its anchor (from there the force is not
 * linear in the stretch). */
static double l3_linear_prediction(void)
{
    double k = cl_param("spring", "k"), m = cl_param("spring", "m"), dt = 0.02;
    return 100 * (pow(1 + k / m * dt * dt, round(10 / dt)) - 1);
}
static double l3_steps_to_10(void) { return (double)cl_steps_for("spring", "c=0", "euler", 0.02, 10.0); }
static double l3_crosses_anchor(void)
{
    sw_sim s;
    cl_sim_init(&s, "spring", "c=0", "euler", 0.02);
    while (s.t < 10 && s.sys.y[0] > 0) /* the anchor at the origin, the mass on +x */
        sw_sim_step(&s);
    double t = s.sys.y[0] <= 0 ? s.t : NAN;
    sw_sim_free(&s);
    return t;
}

/* Lesson 1's page on the meter: what its meter reads. */
static sw_app_meter l1_meter(double *dt)
{
    sw_runner r;
    sw_app a;
    sw_app_meter m;
    cl_lesson_page(&r, &a, L1, "The stability meter");
    ck_assert(sw_app_stability(&a, &m));
    *dt = a.dt;
    cl_page_free(&r, &a);
    return m;
}
static double l1_lines_dt(void) { double dt; l1_meter(&dt); return dt; }
static double l1_lines_stiff(void) { double dt; return l1_meter(&dt).stiff; }
static double l1_lines_limit(void) { double dt; sw_app_meter m = l1_meter(&dt); return m.stiff * m.limit; }
static double l1_lines_limit_dt(void) { double dt; return l1_meter(&dt).limit; }
static double l1_lines_dt_over_limit(void) { double dt; sw_app_meter m = l1_meter(&dt); return dt / (m.stiff * m.limit); }

/* Lesson 5's last page: the meter's limit and its undamped one. */
static sw_app_meter l5_meter(void)
{
    sw_runner r;
    sw_app a;
    sw_app_meter m;
    cl_lesson_page(&r, &a, L5, "Remedy 3: better integration");
    sw_app_set_method(&a, sw_integrator_find("rk4"));
    ck_assert(sw_app_stability(&a, &m));
    cl_page_free(&r, &a);
    return m;
}
static double l5_meter_limit(void) { sw_app_meter m = l5_meter(); return m.stiff * m.limit; }
static double l5_meter_undamped(void) { sw_app_meter m = l5_meter(); return m.stiff * m.limit_undamped; }

/* RK4 on the parabola (no drag): the status line's error at t = 2. */
static double l4_parabola_error(void)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L4, "Gravity");
    cl_steps_to(&a.sims[0], 2.0);
    double e = sw_app_error(&a, 0);
    cl_page_free(&r, &a);
    return e;
}

/* Lesson 4's located page: the error the dt message measures (its own
 * runs, the page's events mode) at the page's dt and half of it. */
static double l4_located_error(void)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L4, "Find the moment of impact");
    const sw_integrator *m = a.sims[0].method;
    double e = fmax(sw_app_measure(&a, m, a.dt), sw_app_measure(&a, m, 0.5 * a.dt));
    cl_page_free(&r, &a);
    return e;
}

/* How many times a lesson 5 page slows the run (its @speed). */
static double l5_slowed(const char *title)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L5, title);
    double slowed = 1 / a.speed;
    cl_page_free(&r, &a);
    return slowed;
}
static double l5_blow_slowed(void) { return l5_slowed("The stiff spring explodes"); }
static double l5_honey_slowed(void) { return l5_slowed("Remedy 1: heavy damping"); }

/* Energy at t = 1 over its start, Euler at Δt = 0.00125 on the c = 10 spring. */
static double l5_grows_fourfold(void) { return 1 + cl_drift_at("spring", STIFF, "euler", 0.00125, 1.0) / 100; }
static double l5_falls(void) { return cl_drift_at("spring", STIFF, "euler", 0.000625, 1.0); }

const claim sw_claims_a[] = {
    /* lesson 1 */
    { L1, "g(x) = ω(-y, x) with ω = {1} rad/s", l1_omega, EXACT, 0, R_COUNT, NULL },
    { L1, "dt={0.05}   the time step Δt", l1_lines_dt, EXACT, 0, "the page's Δt, as the status line prints it (the next page's too)", NULL },
    { L1, "stiffness·dt … of limit {2.83}", l1_lines_limit, ROUNDED, 0, "the meter's limit on this page (RK4's 2√2 on the vortex's ±i)", NULL },
    { L1, "Here |λ| = {1} per second", l1_lines_stiff, ROUNDED, 0, "the meter's |λ| on this page", NULL },
    { L1, "stiffness·dt = {1} × Δt may grow", l1_lines_stiff, ROUNDED, 0, R_ROUND, NULL },
    { L1, "Δt = {0.05} s and the limit reads", l1_lines_dt, EXACT, 0, R_COUNT, NULL },
    { L1, "and the limit reads {2.83}. Up to", l1_lines_limit, ROUNDED, 0, R_ROUND, NULL },
    { L1, "@answer b) {2.83} s | Yes", l1_lines_limit_dt, ROUNDED, 0, "the largest stable Δt: the limit over |λ|", NULL },
    { L1, "@answer c) {0.0177} s", l1_lines_dt_over_limit, ROUNDED, 0, "Δt over the limit, the wrong answer's figure", NULL },
    { L1, "one full turn takes 2π/ω ≈ {6.3} seconds", l1_turn, ROUNDED, 0, R_ROUND, NULL },
    { L1, "swings back and forth every {10} seconds", l1_gyre_swing, ABS, 1e-5, "the default ω = 0.628319 is 2π/10 to 6 digits", NULL },
    /* lesson 2 */
    { L2, "(Δt²/2)·x'': the local error is O(Δt{²})", l2_local_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "Euler's global error is {first} order", l2_global_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "multiplies the radius by √(1 + (ωΔt)²)", l2_factor, REL, 1e-12, "the growth per step from the one-step map is the formula to rounding", l2_factor_formula },
    { L2, "Δt = 0.1 that is a factor {1.005} per step", l2_factor, ROUNDED, 0, R_ROUND, NULL },
    { L2, "One turn takes {63} steps", l2_turn_steps, EXACT, 0, R_COUNT, NULL },
    { L2, "1.005⁶³ ≈ {1.37}", l2_power, ROUNDED, 0, R_MATH, NULL },
    { L2, "the radius grows by 1.005⁶³ ≈ {1.37}", l2_turn_growth, ROUNDED, 0, "the radius after 63 steps of the run, to the text's digits", NULL },
    { L2, "the radius grows by √1.16 ≈ {1.08} per step", l2_sqrt116, ROUNDED, 0, R_MATH, NULL },
    { L2, "At Δt = 0.4 the radius grows by √1.16 ≈ {1.08}", l2_factor04, ROUNDED, 0, R_ROUND, NULL },
    { L2, "({16} steps)", l2_turn_steps04, EXACT, 0, R_COUNT, NULL },
    { L2, "has more than {tripled} in size", l2_turn_growth04, ATLEAST, 0, "\"more than tripled\": at least 3", NULL },
    { L2, "(one turn, t = {6.28})", l2_report_time, ROUNDED, 0, R_ROUND, NULL },
    { L2, "Euler is order 1, so expect a ratio near {2}", l2_ratio1, ABS, 0.3, R_RATIO, NULL },
    { L2, "each the largest along the run (at {16} times spread over it)", l2_samples, EXACT, 0,
      "the truth module's sample times (SW_TRUTH_SAMPLES)", NULL },
    { L2, "The ratio stays near 2 ({2.03}, then 2.01)", cl_l2_ratio2, ROUNDED, 0, "the ratio the status line shows, to the text's digits", NULL },
    { L2, "The ratio stays near 2 (2.03, then {2.01})", l2_ratio3, ROUNDED, 0, "the ratio the status line shows, to the text's digits", NULL },
    { L2, "about {0.17} at Δt = 0.05", l2_err05, ROUNDED, 0, R_ROUND, NULL },
    { L2, "{0.08} at 0.025", l2_err025, ROUNDED, 0, R_ROUND, NULL },
    { L2, "{0.04} at 0.0125", l2_err0125, ROUNDED, 0, R_ROUND, NULL },
    { L2, "methods whose error falls as Δt{²}, or Δt⁴", l2_midpoint_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "methods whose error falls as Δt², or Δt{⁴}", l2_rk4_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "@hint Press + twice: 0.1, 0.2, {0.4}.", l2_dt_plus2, EXACT, 0, "the step two presses of + give", NULL },
    /* lesson 3 */
    { L3, "Euler's ball lands off the mark (by about {0.44} m here)", l3_miss, ROUNDED, 0, "the status line's error at t = 2, to the text's digits", NULL },
    { L3, "Euler's ball lands off the mark (by about {0.44} m here)", l3_miss_position, ROUNDED, 0, "the distance of the ball from the exact one at t = 2, to the text's digits", NULL },
    { L3, "Here k = {10} and m = 1", l3_k, EXACT, 0, R_COUNT, NULL },
    { L3, "Here k = 10 and m = {1}", l3_m, EXACT, 0, R_COUNT, NULL },
    { L3, "so ω = {3.16} rad/s", l3_omega, ROUNDED, 0, R_ROUND, NULL },
    { L3, "ωΔt = {0.063}: a factor", l3_omega_dt, ROUNDED, 0, R_ROUND, NULL },
    { L3, "a factor {1.004} per step", l3_energy_factor, ROUNDED, 0, "ρ² from the one-step map, to the text's digits", NULL },
    { L3, "shows growth ×{1.002} per step", l3_meter_factor, ROUNDED, 0, "what the meter shows on this page, to the text's digits", NULL },
    { L3, "multiplies the energy of this oscillation by 1 + (ωΔt)² every step", l3_energy_factor, REL, 1e-12, "ρ² of Euler's one-step map is 1 + (ωΔt)² to rounding", l3_formula },
    { L3, "per step, {50} steps per second", l3_steps_per_second, EXACT, 0, R_COUNT, NULL },
    { L3, "let it run about {two} seconds; the energy drift climbs past 50 %", l3_time_to_50, ABS, 0.25, "\"about two seconds\": within a quarter of a second", NULL },
    { L3, "for this chain of {10} beads in 2-D?", l3_beads, EXACT, 0, R_COUNT, NULL },
    { L3, "This chain has {10} beads", l3_beads, EXACT, 0, R_COUNT, NULL },
    { L3, "@answer c) {40} | Yes: 10 beads × (x, y, vx, vy).", l3_chain_dim, EXACT, 0, R_COUNT, NULL },
    { L3, "@answer b) {20} | That is the positions alone", l3_chain_positions, EXACT, 0, R_COUNT, NULL },
    { L3, "@answer b) {4}: position (x, y) and velocity (vx, vy)", l3_particle_dim, EXACT, 0, R_COUNT, NULL },
    { L3, "In 3-D, as in the lecture, it is {6}.", l3_3d, EXACT, 0, R_MATH, NULL },
    { L3, "By t = 10 Euler's energy is up {557} %", l3_phase_euler, ROUNDED, 0, R_ROUND, NULL },
    { L3, "The factor 1.004 per step predicts +{636} % for Euler's 500 steps", l3_linear_prediction, ROUNDED, 0, "(1 + (ωΔt)²)^(T/Δt) - 1 with the page's k, m, Δt and T = 10", NULL },
    { L3, "predicts +636 % for Euler's {500} steps", l3_steps_to_10, EXACT, 0, R_COUNT, NULL },
    { L3, "It gains less because at t = {6.96} its swing", l3_crosses_anchor, ROUNDED, 0, "the first step Euler's mass is past its anchor (x < 0), at Δt = 0.02", NULL },
    { L3, "backward Euler's down {86} %", l3_phase_be, ROUNDED, 0, R_ROUND, NULL },
    { L3, "only wobbles, within {3.3} %", l3_phase_se, ATMOST, 0.1, "a bound the run comes within 10 % of", NULL },
    /* lesson 4 */
    { L4, "restitution e (here {0.8})", l4_e, EXACT, 0, R_COUNT, NULL },
    { L4, "e = 1 is a perfect bounce", l4_perfect, ABS, 0.002, "a ball from 4 m with e = 1 rises back to 4 m (contact at step ends: 1e-3)", cl_one },
    { L4, "e = {0} a dead stop", l4_dead, ABS, 0.002, "with e = 0 it does not rise again", NULL },
    { L4, "the speed is multiplied by {0.8}, the height", l4_e, EXACT, 0, R_COUNT, NULL },
    { L4, "@answer b) {2.56} m | Yes", l4_bounce_height, ABS, 0.005, "the first hop of a ball dropped from 4 m in the scene, at Δt = 1e-4 (contact is found at step ends: an error of order Δt·v ≈ 1e-3)", NULL },
    { L4, "the height by 0.8² = {0.64}", l4_e_squared, EXACT, 0, R_MATH, NULL },
    { L4, "@answer a) {3.2} m | That multiplies the height by e", l4_e_height, ABS, 1e-12, R_MATH, NULL },
    { L4, "here it falls by {1.86}, and at the", l4_bounce_shown1, ROUNDED, 0, "the ratio the message shows at the first halving", NULL },
    { L4, "next halving by only {1.52}", l4_bounce_shown2, ROUNDED, 0, "the ratio the message shows at the next halving", NULL },
    { L4, "next halving by only 1.52 (\"not an order yet\")", l4_bounce_not_order, ATMOST, 0, "the ratio is NaN (not read as an order) after the first halving", cl_zero },
    { L4, "RK4's position error would fall {16}-fold", l4_smooth_ratio, ABS, 2, "a ratio measured on the smooth projectile (drag on): the goals' tolerance for 16", NULL },
    { L4, "stepwise measures the error to t = {3} at both step sizes", l4_report_time, EXACT, 0, R_COUNT, NULL },
    { L4, "a percentage of the kinetic energy at launch, {62.5} J", l4_launch_ke, EXACT, 0, "½m|v0|² from the scene's parameters, equal to the status line's energy scale", NULL },
    { L4, "with drag = 1 the change reads {-204} % by t = 3", l4_drag_drift, ROUNDED, 0, R_ROUND, NULL },
    { "docs/scenes.md", "kinetic energy ½ m |v0|² ({62.5} J with the defaults)", l4_launch_ke, EXACT, 0, "½m|v0|² from the scene's parameters, equal to the status line's energy scale", NULL },
    { L4, "RK4 follows it to within {rounding} error", l4_parabola_error, ATMOST, 0, "the status line's error at t = 2 below 1e-12", NULL },
    { L4, "the message reports {rounding}-level errors", l4_located_error, ATMOST, 0, "the dt message's own runs with events located, at the page's dt and half: below 1e-12", NULL },
    /* lesson 5 */
    { L5, "(The meter reads limit {2.91}:", l5_meter_limit, ROUNDED, 0, "the meter's limit on the page, RK4 with the spring's damping", NULL },
    { L5, "a wide window shows the undamped {2.83} beside it", l5_meter_undamped, ROUNDED, 0, "the meter's undamped limit on the page", NULL },
    { L5, "\"(limit with this damping; {2.83}", l5_meter_undamped, ROUNDED, 0, "the meter's undamped limit on the page, as its field reads", NULL },
    { L5, "Here k = {10} N/m, damping c = 0.5, mass 1 kg", cl_l5_k, EXACT, 0, R_COUNT, NULL },
    { L5, "Here k = 10 N/m, damping c = {0.5}, mass 1 kg", cl_l5_c, EXACT, 0, R_COUNT, NULL },
    { L5, "Here k = 10 N/m, damping c = 0.5, mass {1} kg", cl_l5_m, EXACT, 0, R_COUNT, NULL },
    { L5, "the mass swings about {five} times in ten seconds", l5_swings, ABS, 0.5, R_ABOUT, NULL },
    { L5, "so it vibrates at ω = √(k/m) = {100} rad/s", l5_stiff_omega, ROUNDED, 0, R_ROUND, NULL },
    { L5, "Numbers: k = 10000, m = 1 so ω = {100}", l5_stiff_omega, ROUNDED, 0, R_ROUND, NULL },
    { L5, "Per step, Euler multiplies this spring's energy by about 1 - cΔt + kΔt²", l5_euler_energy_factor, REL, 1e-12, "ρ² of Euler's map, exactly the formula for m = 1", l5_arith },
    { L5, "that is 1 - 0.05 + 0.25 = {1.2}", l5_arith, ABS, 1e-12, R_MATH, NULL },
    { L5, "that is 1 - 0.05 + 0.25 = {1.2}: the damping", l5_euler_energy_factor, ROUNDED, 0, "ρ² of Euler's one-step map on the damped spring is exactly 1 - cΔt + kΔt² (m = 1)", NULL },
    { L5, "watch: it is slowed {four} times", l5_blow_slowed, EXACT, 0, "the page's @speed, 1/4", NULL },
    { L5, "and watch, slowed {sixteen} times", l5_honey_slowed, EXACT, 0, "the page's @speed, 1/16", NULL },
    { L5, "Press space; within {a} second the spring blows up", l5_blow, ATMOST, 0, "\"within a second\": before t = 1", NULL },
    { L5, "critically damped (c = 2√(km))", l5_critical, EXACT, 0, R_MATH, two_hundred },
    { L5, "both its modes now decay at rate {100} per second", l5_crit_rate, REL, 1e-6, "a double eigenvalue: its computed split is about √ε", NULL },
    { L5, "Euler multiplies each by |1 - 100Δt| = {0.5} per step", l5_crit_arith, EXACT, 0, R_MATH, NULL },
    { L5, "|1 - 100Δt| = {0.5} per step: the motion dies out", l5_crit_growth, REL, 1e-6, "ρ of the one-step map on a double eigenvalue (split about √ε)", NULL },
    { L5, "The energy still rises in the very first step, by {25} %", l5_crit_first_step, ROUNDED, 0, R_ROUND, NULL },
    { L5, "the mass relaxes at rate c/m = {5000} per second", l5_huge_rate, REL, 0.001, "the fast root (c + √(c² - 4km))/2m is c/m - k/c: 4998", NULL },
    { L5, "Euler needs Δt below {2/5000} for that", l5_huge_limit, REL, 0.001, "the limit 2/4998 from the one-step map against 2/5000", NULL },
    { L5, "a step {12.5} times smaller", l5_huge_smaller, ROUNDED, 0, R_ROUND, NULL },
    { L5, "that is Δt < c/k = {0.001}", l5_light_limit, REL, 1e-6, "Euler's limit from the one-step map on the damped spring is c/k", NULL },
    { L5, "that is Δt < c/k = {0.001}.", l5_light_arith, EXACT, 0, R_MATH, NULL },
    { L5, "@answer a) Any Δt below {0.001} | That was the limit with c = 10", l5_light_limit, REL, 1e-6, "as above", NULL },
    { L5, "@hint Press - three times: 0.0025, 0.00125, {0.000625}.", l5_dt_minus3, EXACT, 0, "the step three presses of - give", NULL },
    { L5, "@hint At Δt = 0.000625 the energy falls;", l5_falls, ATMOST, 0, "the drift at t = 1 is negative", cl_zero },
    { L5, "at 0.00125 it still grows, to {four} times its start by t = 1", l5_grows_fourfold, ABS, 0.25, "four to the nearest quarter", NULL },
    { L5, "Switch to rk4 (press {5}, or i", cl_key_rk4, EXACT, 0, "the key that picks the method", NULL },
    { L5, "@hint Press {5}, or i until the status line says rk4.", cl_key_rk4, EXACT, 0, "the key that picks the method", NULL },
    { L5, "{1600} steps for one simulated second", l5_steps, EXACT, 0, R_COUNT, NULL },
    { L5, "{eight} times as many as at Δt = 0.005", l5_steps_ratio, EXACT, 0, R_COUNT, NULL },
    { L5, "its energy grows by 1 + (ωΔt)² every step", l5_undamped_factor, REL, 1e-12, "ρ² of Euler's map on the undamped spring at Δt = 0.000625", l5_undamped_formula },
    { L5, "With c = 0 the factor 1 + kΔt² is above 1 for every Δt", l5_undamped_limit, EXACT, 0, "no stable step: the limit in theory is 0", cl_zero },
    { L5, "RK4 is stable on an oscillator while ωΔt < 2√2 ≈ {2.83}", cl_rk4_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L5, "while ωΔt < 2√2 ≈ {2.83}; here", two_root_two, ROUNDED, 0, R_MATH, NULL },
    { L5, "here ωΔt = {0.5}", l5_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L5, "here λ = {-5} ± 99.9i", l5_lambda_re, ROUNDED, 0, R_ROUND, NULL },
    { L5, "here λ = -5 ± {99.9}i", l5_lambda_im, ROUNDED, 0, R_ROUND, NULL },
    { L5, "(decay rate c/2m = {5}, ω ≈ 100)", l5_half_c, EXACT, 0, R_MATH, NULL },
    { L5, "(decay rate c/2m = 5, ω ≈ {100})", l5_stiff_omega, ROUNDED, 0, R_ROUND, NULL },
    { L5, "Euler multiplies a mode by 1 + Δt·λ per step", l5_growth, REL, 1e-12, "ρ of Euler's one-step map is |1 + Δt·λ| to rounding", l5_growth_formula },
    { L5, "The marks are Δt·λ = {-0.025} ± 0.5i", l5_mark_re, ROUNDED, 0, R_ROUND, NULL },
    { L5, "The marks are Δt·λ = -0.025 ± {0.5}i", l5_mark_im, ROUNDED, 0, R_ROUND, NULL },
    { L5, "|1 + Δt·λ| = {1.095} per step", l5_growth, ROUNDED, 0, "the meter's growth per step, to the text's digits", NULL },
    { L5, "once Δt is below c/k = {0.001}", l5_light_limit, REL, 1e-6, "Euler's limit from the one-step map on the damped spring is c/k", NULL },
    { L5, "out the mark is: {5}×edge, five times", l5_ray_ratio0, REL, 1e-6, "the edge is found by bisection to 1e-9 relative", NULL },
    { L5, "the edge's distance, at Δt = {0.005}.", l5_page_dt, EXACT, 0, "the page's own Δt", NULL },
    { L5, "one notch left: {2.5}×edge, 1.25×edge", l5_ray_ratio1, REL, 1e-6, "as above", NULL },
    { L5, "one notch left: 2.5×edge, {1.25}×edge", l5_ray_ratio2, REL, 1e-6, "as above", NULL },
    { L5, "then {0.625}×edge, inside.", l5_ray_ratio3, REL, 1e-6, "as above", NULL },
};
const size_t sw_claims_a_n = sizeof sw_claims_a / sizeof sw_claims_a[0];
