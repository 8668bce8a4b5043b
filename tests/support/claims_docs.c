/* Claims: the figures of the README, the man page, docs/stability.md, the
 * authoring guide and the scenes' own strings, and how each is measured. */
#include "claims.h"
#include "measure/measure.h"

static double reference_order(void) { return sw_truth_reference_method()->order; }

/* try's measured order of a method on the run try checks, the chain at its
 * defaults to its duration, and the steps the sweep's runs span (*span)
 * of the run's (*steps). */
static double measured_on_chain(const char *m, long *span, long *steps)
{
    double order, p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("chain");
    sw_scene_defaults(sc, p);
    *steps = lround(sc->duration / sc->dt);
    sw_measure_probe pr = { .scene = sc, .p = p, .dt = sc->dt, .graded_steps = *steps, .span = span };
    return sw_measure_order_on(sw_integrator_find(m), &pr, &order, NULL, err, sizeof err) == SW_OK ? order : NAN;
}
/* the handout's my_rk4.c is rk4 */
static double measured_rk4(void) { long span, steps; return measured_on_chain("rk4", &span, &steps); }
/* examples/euler_plugin.c is Euler: the span its order is read on */
static double euler_span(void) { long span = 0, steps; measured_on_chain("euler", &span, &steps); return span; }
static double euler_span_of(void) { long span, steps; measured_on_chain("euler", &span, &steps); return steps; }
static double probe_steps(void) { return SW_MEASURE_PROBE_STEPS; }
static double order_ceiling_percent(void) { return 100 * SW_BENCH_CEILING; }
static double order_ceiling(void) { return SW_BENCH_CEILING; }

/* The hop, in mm, that the bounce's resting speed would lift a ball:
 * v²/(2g), v the largest speed a ball leaving the floor is set at rest
 * with, found by bisection on the step-boundary contact (a ball 1e-9
 * under the floor with upward speed e·v after it). */
static double bounce_rest_hop_mm(void)
{
    const sw_scene *sc = sw_scene_find("bounce");
    double p[SW_MAX_PARAMS], lo = 0, hi = 10;
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    sw_system sys;
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK)
        return NAN;
    int n = sys.n;
    for (int it = 0; it < 200; it++) {
        double v = 0.5 * (lo + hi);
        sys.y[1] = -1e-9;
        sys.y[2 * n + 1] = -v / p[2]; /* lands at v/e: leaves at v */
        sc->post_step(&sys, 0, sys.y);
        if (sys.y[2 * n + 1] == 0)
            lo = v;
        else
            hi = v;
    }
    sw_system_free(&sys);
    return 1e3 * lo * lo / (2 * p[1]);
}

/* Backward Euler's energy gain on step 3 of the stiff pendulum held above
 * its anchor (k = 100, angle = 160, dt = 1): E3 - E2. */
static double be_gain_compressed(void)
{
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("stiff-spring");
    double p[SW_MAX_PARAMS], e[4];
    sw_scene_defaults(sc, p);
    if (sw_scene_set(sc, p, "k=100", err, sizeof err) != SW_OK ||
        sw_scene_set(sc, p, "angle=160", err, sizeof err) != SW_OK)
        return NAN;
    sw_sim s;
    if (sw_sim_init(&s, sc, p, sw_integrator_find("implicit-euler"), 1.0, err, sizeof err) != SW_OK)
        return NAN;
    for (int k = 0; k < 4; k++) {
        e[k] = sw_sim_energy(&s);
        if (k < 3)
            sw_sim_step(&s);
    }
    sw_sim_free(&s);
    return e[3] - e[2];
}

/* The order each method shows when Δt halves on the default (damped)
 * spring, from a step in its asymptotic range (the error at the report time
 * against the closed form). */
static double order_on_spring(const char *m) { return cl_order_by_halving("spring", NULL, m, 0.01); }

/* First-order methods reach their asymptotic range at smaller steps. */
static double order1_on_spring(const char *m) { return cl_order_by_halving("spring", NULL, m, 0.0005); }
static double ord_euler(void) { return order1_on_spring("euler"); }
static double ord_symplectic(void) { return order1_on_spring("symplectic-euler"); }
static double ord_midpoint(void) { return order_on_spring("midpoint"); }
static double ord_heun(void) { return order_on_spring("heun"); }
static double ord_rk4(void) { return cl_order_by_halving("spring", NULL, "rk4", 0.04); }
static double ord_verlet(void) { return order_on_spring("verlet"); }
static double ord_be(void) { return order1_on_spring("implicit-euler"); }
static double ord_lbe(void) { return order1_on_spring("linear-implicit-euler"); }
static double ord_im(void) { return order_on_spring("implicit-midpoint"); }
/* yoshida4 is 4th order where the forces do not depend on v: the undamped spring. */
static double ord_yoshida(void) { return cl_order_by_halving("spring", "c=0", "yoshida4", 0.04); }
/* ... and 2nd order where a force reads v: the default (damped, c = 0.5)
 * spring and the projectile's drag, halving from the same step. */
static double ord_yoshida_damped(void) { return cl_order_by_halving("spring", NULL, "yoshida4", 0.04); }
static double ord_yoshida_drag(void) { return cl_order_by_halving("projectile", NULL, "yoshida4", 0.04); }
static double yoshida_wdt(void) { return cl_limit0("spring", "k=1 c=0", "yoshida4"); }
/* The largest step lesson 9 has rk45 take (cl_l9_adaptive runs at it). */
static double readme_l9_largest_step(void)
{
    return cl_page_dt_after(L9, "One step size does not fit all", SW_ACT_DT_DOUBLE, 3);
}
static double table_order(const char *m) { return cl_method(m)->order; }
static double ord_rk45(void) { return table_order("rk45"); }

/* Evaluations per step on the stiff pendulum (nonlinear: Newton iterates). */
static double ev(const char *m) { return cl_evals_per_step("stiff-spring", NULL, m, 0.005, 50); }
static double ev_euler(void) { return ev("euler"); }
static double ev_symplectic(void) { return ev("symplectic-euler"); }
static double ev_midpoint(void) { return ev("midpoint"); }
static double ev_heun(void) { return ev("heun"); }
static double ev_rk4(void) { return ev("rk4"); }
static double ev_verlet(void) { return ev("verlet"); }
static double ev_be(void) { return ev("implicit-euler"); }
static double ev_lbe(void) { return ev("linear-implicit-euler"); }
static double ev_im(void) { return ev("implicit-midpoint"); }
static double ev_yoshida(void) { return ev("yoshida4"); }

/* 1 when the key '@' picks yoshida4 (the twelfth place), from the controls' table. */
static double key_at_yoshida(void) { return cl_key_picks('@', 12, "yoshida4"); }

/* Euler's energy on the undamped ω = 1 spring after N = 50 steps of h = 0.1,
 * against (1 + h²)^N. */
static double euler_energy_growth(void)
{
    sw_sim s;
    cl_sim_init(&s, "spring", "k=1 m=1 c=0 stretch=0.2", "euler", 0.1);
    for (int i = 0; i < 50; i++)
        sw_sim_step(&s);
    double r = 1 + sw_sim_energy_drift(&s) / 100;
    sw_sim_free(&s);
    return r;
}

static double euler_energy_formula(void) { return pow(1 + 0.1 * 0.1, 50); }
static double symplectic_wdt(void) { return cl_limit0("spring", "k=1 c=0", "symplectic-euler"); }
static double spring_zeta(void) { return cl_l5_c() / (2 * sqrt(cl_l5_k() * cl_l5_m())); }
static double euler_damped_over_zeta(void) { return cl_limit0("spring", NULL, "euler") * cl_spring_omega() / spring_zeta(); }
static double rk4_damped(void) { return cl_limit0("spring", NULL, "rk4") * cl_spring_omega(); }

/* Backward Euler on the stiff pendulum: the largest ω·Δt in 1, 10, ... 1e4
 * up to which no step in 20 raised the energy (1e4: Δt = 100). */
static double be_never_gains(void)
{
    double ok = 0;
    for (double wdt = 1; wdt <= 1e4 * 1.0001; wdt *= 10) {
        sw_sim s;
        cl_sim_init(&s, "stiff-spring", NULL, "implicit-euler", wdt / 100);
        double e = sw_sim_energy(&s);
        int rose = 0;
        for (int i = 0; i < 20 && !rose; i++) {
            if (sw_sim_step(&s))
                rose = 1;
            double e1 = sw_sim_energy(&s);
            rose |= e1 > e + 1e-12 * fabs(e);
            e = e1;
        }
        sw_sim_free(&s);
        if (rose)
            break;
        ok = wdt;
    }
    return ok;
}

static double lesson_count(void)
{
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    sw_lesson_list_free(e, n);
    return n;
}

static double dt_min(void) { return SW_DT_MIN; }
static double dt_max(void) { return SW_DT_MAX; }
static double rtol_default(void) { return SW_RTOL_DEFAULT; }
static double atol_default(void) { return SW_ATOL_DEFAULT; }
static double check_rtol(void) { return SW_CHECK_RTOL; }
static double check_atol(void) { return SW_CHECK_ATOL; }

static sw_stability_config stab_config(void)
{
    sw_stability_config c;
    sw_stability_config_default(&c);
    return c;
}

static double stab_samples(void) { return stab_config().samples; }
static double stab_low(void) { return stab_config().low; }
static double stab_rel_tol(void) { return 100 * stab_config().rel_tol; }

/* Euler's theory on the undamped spring is "none": it grows already at the
 * smallest |λ|·Δt probed. */
static double euler_grows_at_low(void)
{
    return cl_growth0("spring", "k=1 c=0", "euler", stab_low()) > 1 ? stab_low() : NAN;
}

/* Backward Euler's theory limit is unbounded: no growth up to this Δt. */
static double be_unbounded_to(void)
{
    sw_spectrum sp = cl_spectrum0("spring", "k=1 c=0");
    int unbounded = 0;
    double h = sw_truth_limit(cl_method("implicit-euler"), &sp, SW_DT_MAX, &unbounded);
    return unbounded ? h : NAN;
}

/* The horizon in periods of the stiffest mode (a slow spring, ω = 0.1,
 * where the periods dominate) and in report times (a stiff one). */
static double horizon_periods(void)
{
    const sw_scene *sc = sw_scene_find("spring");
    return sw_truth_horizon(sc, 0.1) / (TWO_PI / 0.1);
}

static double horizon_reports(void)
{
    const sw_scene *sc = sw_scene_find("spring");
    return sw_truth_horizon(sc, 1e4) / sc->duration;
}

/* The growth over the horizon at which it counts as visible: bisect ρ. */
static double visible_growth(void)
{
    double lo = 1, hi = 1.01, dt = 1, horizon = 100;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (sw_truth_growth_visible(mid, dt, horizon))
            hi = mid;
        else
            lo = mid;
    }
    return pow(hi, horizon / dt);
}

static double raised_level(const char *scene, const char *m)
{
    sw_sim s;
    cl_sim_init(&s, scene, NULL, m, 0.01);
    double r = sw_watch_raised_level(&s);
    sw_sim_free(&s);
    return r;
}

static double raised_plain(void) { return raised_level("spring", "rk4"); }
static double raised_symplectic(void) { return raised_level("spring", "verlet"); }
static double raised_orbit(void) { return raised_level("orbit", "rk4"); }

/* M past this is the run blowing up: feed the watch a jump. */
static double watch_bound(void)
{
    double lo = 1, hi = 1e6;
    for (int i = 0; i < 100; i++) {
        double mid = sqrt(lo * hi);
        sw_watch w;
        sw_watch_init(&w, 1.0, 1e9);
        sw_watch_add(&w, 0.0, 1.0);
        if (sw_watch_add(&w, 0.01, mid) == SW_WATCH_BOUND)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

static double watch_windows(void) { return SW_WATCH_WINDOWS; }
static double vortex_growth(void) { return cl_growth0("vortex", NULL, "euler", 0.3); }
static double vortex_formula(void) { return sqrt(1 + 0.3 * 0.3); }
static double spring_energy_growth(void) { return pow(cl_growth0("spring", "c=0", "euler", 0.05), 2); }
static double spring_energy_formula(void) { return 1 + 10 * 0.05 * 0.05; }
static double orbit_period_mu4(void) { return cl_orbit_period("mu=4"); }
static double orbit_period_formula(void) { return TWO_PI / sqrt(4); }
static double projectile_ratio(void) { return pow(2, cl_order_by_halving("projectile", NULL, "euler", 0.01)); }
/* The order the ratio lesson 4's bounce page shows at its first halving
 * stands for (the message does not read it as an order: the next differs). */
static double bounce_order(void) { return log2(cl_page_shown_ratio(L4, "A bounce breaks the order", NULL, 1)); }

/* Symplectic Euler from rest on the undamped ω = 1 spring at ωΔt = 1: the
 * mean of M (the motion's energy over its start) over a long run. */
static double symplectic_mean_m(void)
{
    sw_sim s;
    cl_sim_init(&s, "spring", "k=1 c=0 stretch=0.01", "symplectic-euler", 1.0);
    double y0[4], sum = 0;
    memcpy(y0, s.sys.y, sizeof y0);
    double m0 = sw_watch_measure(&s, y0);
    int n = 20000;
    for (int i = 0; i < n; i++) {
        sw_sim_step(&s);
        sum += sw_watch_measure(&s, y0) / m0;
    }
    sw_sim_free(&s);
    return sum / n;
}

static double symplectic_mean_formula(void) { return 1 / (1 - pow(1.0 / 2, 2)); }

/* The lowest x RK4 reaches on the default spring at Δt = 0.9 (ωΔt = 2.85,
 * inside the linear limit 2.938): below 0 is through the anchor. */
static double rk4_through_anchor(void)
{
    sw_sim s;
    cl_sim_init(&s, "spring", NULL, "rk4", 0.9);
    double lowest = s.sys.y[0];
    for (int i = 0; i < 400 && !s.blown; i++) {
        sw_sim_step(&s);
        lowest = fmin(lowest, s.sys.y[0]);
    }
    sw_sim_free(&s);
    return lowest;
}

static double four(void) { return 4; }
static double twenty(void) { return 20; }

static double bench_default_repeats(void)
{
    sw_bench_config c;
    sw_bench_config_default(&c);
    return c.repeats;
}

static double bench_quick_min(void)
{
    sw_bench_config c;
    sw_bench_config_quick(&c);
    return c.min_points;
}

static double bench_quick_max(void)
{
    sw_bench_config c;
    sw_bench_config_quick(&c);
    return c.max_points;
}

static double bench_quick_runs(void)
{
    sw_bench_config c;
    sw_bench_config_quick(&c);
    return c.repeats;
}

static double truth_samples(void) { return SW_TRUTH_SAMPLES; }
static double stab_agree(void) { return 100 * SW_STABILITY_AGREE; }
static double stab_shrink(void) { return 1 / SW_STABILITY_SHRINK; }
static double stab_longer(void) { return SW_STABILITY_LONGER; }
static double stab_longest(void) { return SW_STABILITY_LONGER * SW_STABILITY_LONGER; }

/* The drift the status line shows, against (E - E0)/(E0 - E_rest) worked
 * out here from the energies (the stiff pendulum after 100 steps). */
static double drift_definition(void)
{
    sw_sim s;
    cl_sim_init(&s, "stiff-spring", NULL, "implicit-euler", 0.04);
    double e0 = sw_sim_energy(&s), rest = sw_sim_energy_floor(&s);
    for (int i = 0; i < 100; i++)
        sw_sim_step(&s);
    double mine = 100 * (sw_sim_energy(&s) - e0) / (e0 - rest), shown = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return fabs(mine - shown) / fabs(mine);
}

static double guide_dt_min(void) { return SW_DT_MIN; }
static double max_bytes(void) { return SW_LESSON_MAX_BYTES; }
static double max_line(void) { return SW_LESSON_MAX_LINE; }
static double max_title(void) { return SW_LESSON_MAX_TITLE; }
static double max_pages(void) { return SW_LESSON_MAX_PAGES; }
static double max_prose(void) { return SW_LESSON_MAX_PROSE; }
static double max_blocks(void) { return SW_LESSON_MAX_BLOCKS; }
static double max_goals(void) { return SW_LESSON_MAX_GOALS; }
static double max_answers(void) { return SW_LESSON_MAX_ANSWERS; }
static double max_compare(void) { return SW_LESSON_MAX_COMPARE; }
static double max_names(void) { return SW_LESSON_MAX_NAMES; }
static double max_files(void) { return SW_LESSON_MAX_FILES; }

/* The slack of ==, <= and >= in goals: the largest relative shortfall at
 * which "dt >= 0.2" still holds, by bisection on the goal itself. */
static double goal_slack(void)
{
    sw_lesson lesson;
    char err[SW_LESSON_ERRLEN];
    const char *text = "title: t\n--- p\n@scene spring\nText.\n@goal dt >= 0.2\n@hint h\n";
    ck_assert_msg(sw_lesson_parse("t", text, strlen(text), &lesson, err, sizeof err) == SW_OK, "%s", err);
    double lo = 0, hi = 1e-6;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        sw_lesson_obs obs;
        sw_lesson_obs_init(&obs);
        obs.dt = 0.2 * (1 - mid);
        if (sw_lesson_goal_met(&lesson.pages[0].goals[0], &obs))
            lo = mid;
        else
            hi = mid;
    }
    sw_lesson_free(&lesson);
    return lo;
}

/* The meter's growth on stiff-spring, rk4, Δt 0.028, as the app shows it
 * (issue 38: it is the largest factor over the modes). Checked here to be
 * the slow swing's: |R(iωΔt)| of rk4's own polynomial R(z) = 1 + z + z²/2 +
 * z³/6 + z⁴/24, computed here, at the smaller of the two frequencies. */
static double rk4_factor(double theta)
{
    double re = 1 - theta * theta / 2 + pow(theta, 4) / 24, im = theta - pow(theta, 3) / 6;
    return hypot(re, im);
}

static double meter_stiff_rk4(void)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = cl_scene_p("stiff-spring", NULL, p);
    sw_app a;
    ck_assert_int_eq(sw_app_init(&a, sc, p, cl_method("rk4"), 0.028, err, sizeof err), SW_OK);
    sw_app_meter mt;
    ck_assert_int_eq(sw_app_stability(&a, &mt), 1);
    sw_app_free(&a);
    sw_spectrum sp = cl_spectrum0("stiff-spring", NULL);
    ck_assert_int_eq(sp.n, 2);
    double slow = fmin(hypot(sp.mode[0].re, sp.mode[0].im), hypot(sp.mode[1].re, sp.mode[1].im));
    ck_assert_msg(fabs(mt.growth - rk4_factor(slow * 0.028)) <= 1e-12, "meter %.12f, slow swing %.12f", mt.growth,
                  rk4_factor(slow * 0.028));
    return mt.growth;
}

/* The fast stretch: along the spring the force's Jacobian is -k/m whatever
 * the state, so ω = √(k/m), from the scene's parameters. */
static double stretch_stiff_rk4(void)
{
    return rk4_factor(sqrt(cl_param("stiff-spring", "k") / cl_param("stiff-spring", "m")) * 0.028);
}
static double dt_0028(void) { return 0.028; }

const claim sw_claims_d[] = {
    { README, "on stiff-spring with rk4 at Δt {0.028} the", dt_0028, EXACT, 0, R_COUNT, NULL },
    { README, "meter reads ×{0.999999997}, the slow swing's factor", meter_stiff_rk4, ROUNDED, 0, "what the meter shows, to its digits; checked to be the slow swing's |R(iωΔt)|", NULL },
    { README, "shrinks by ×{0.930667} a step", stretch_stiff_rk4, ROUNDED, 0, "rk4's |R(iωΔt)| at ω = √(k/m), computed here", NULL },
    /* README: what the tool claims, the integrator table */
    { README, "the ratio approaches 2^p once Δt is small enough", ord_rk4, ABS, 0.1, "rk4's order halving Δt from 0.04 on the spring: 4 within 0.1", four },
    { README, "| euler | explicit (forward) Euler | {1} | 1 |", ord_euler, ABS, 0.1, "the order measured halving Δt on the damped spring", NULL },
    { README, "| euler | explicit (forward) Euler | 1 | {1} |", ev_euler, EXACT, 0, "evaluations per step measured", NULL },
    { README, "| symplectic-euler | semi-implicit Euler: v then x | {1} | 1 |", ord_symplectic, ABS, 0.1, "as above", NULL },
    { README, "| symplectic-euler | semi-implicit Euler: v then x | 1 | {1} |", ev_symplectic, EXACT, 0, "as above", NULL },
    { README, "| midpoint | explicit midpoint (RK2) | {2} | 2 |", ord_midpoint, ABS, 0.1, "as above", NULL },
    { README, "| midpoint | explicit midpoint (RK2) | 2 | {2} |", ev_midpoint, EXACT, 0, "as above", NULL },
    { README, "| heun | Heun / explicit trapezoid (RK2) | {2} | 2 |", ord_heun, ABS, 0.1, "as above", NULL },
    { README, "| heun | Heun / explicit trapezoid (RK2) | 2 | {2} |", ev_heun, EXACT, 0, "as above", NULL },
    { README, "| rk4 | classical Runge–Kutta | {4} | 4 |", ord_rk4, ABS, 0.1, "as above (from Δt = 0.04: rounding stays below the error)", NULL },
    { README, "| rk4 | classical Runge–Kutta | 4 | {4} |", ev_rk4, EXACT, 0, "as above", NULL },
    { README, "| verlet | velocity Verlet (leapfrog) | {2} | 1", ord_verlet, ABS, 0.1, "as above", NULL },
    { README, "| verlet | velocity Verlet (leapfrog) | 2 | {1} (reuses the last acceleration) |", ev_verlet, EXACT, 0, "after the first step", NULL },
    { README, "| implicit-euler | backward Euler, Newton's method to rounding, direct solve | {1} |", ord_be, ABS, 0.1, "as above", NULL },
    { README, "direct solve | 1 | ≥ {1} + solves |", ev_be, ATLEAST, 0, "Newton iterates: at least one evaluation per step", NULL },
    { README, "(Baraff–Witkin's \"large steps\") | {1} | 1 + a linear solve |", ord_lbe, ABS, 0.1, "as above", NULL },
    { README, "(Baraff–Witkin's \"large steps\") | 1 | {1} + a linear solve |", ev_lbe, EXACT, 0, "one Newton step: one evaluation", NULL },
    { README, "| implicit-midpoint | implicit midpoint, Newton's method to rounding | {2} |", ord_im, ABS, 0.1, "as above", NULL },
    { README, "Newton's method to rounding | 2 | ≥ {2} + solves |", ev_im, ATLEAST, 0, "Newton iterates: at least two evaluations per step", NULL },
    { README, "| rk45 | Dormand–Prince 5(4), adaptive (rtol/atol) | {5} | 6", ord_rk45, EXACT, 0, "the method's order in the table", NULL },
    { README, "(rtol/atol) | 5 | {6} (reuses the last stage) |", cl_l9_rk45_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { README, "| dop853 | Dormand–Prince 8(5,3) (Hairer), adaptive (rtol/atol) | {8} |", cl_ord_dop853, EXACT, 0, "the method's order in the table", NULL },
    { README, "(Hairer), adaptive (rtol/atol) | 8 | {12} (reuses the last stage) |", cl_dop853_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { INTEGRATORS, "\"Dormand-Prince 8(5,3), adaptive (Hairer)\", .order = 8, .evals = {12},", cl_dop853_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { README, "is about {3·10⁴} times rtol", cl_l9_rk45_error_over_rtol, ABS, 5000, "one significant figure (rk45 at largest step 0.4 on e = 0.9: 3.4·10⁴; at the scene's dt 0.01 it is 2.4·10⁴)", NULL },
    { README, "with {0.4} as its largest step (lesson 9's setting)", readme_l9_largest_step, EXACT, 0, "lesson 9's page's step after three presses of +, the step the row above runs at", NULL },
    { README, "`1`–`9`, `{0}`, `!`, `@`, `#`, `$`, `%`, `^`, `&` and `*` pick one", cl_key_rk45, EXACT, 0, "the key that picks the tenth method", NULL },
    { README, "`1`–`9`, `0`, `!`, `@`, `#`, `$`, `%`, `^`, `&` and `*` pick one", key_at_yoshida, EXACT, 0, "'@' picks the twelfth method, yoshida4", cl_one },
    { README, "Verlet substeps of w1·h, w0·h, w1·h | {4} (2 where", ord_yoshida, ABS, 0.1, "the order measured halving Δt from 0.04 on the undamped spring", NULL },
    { README, "| 4 ({2} where a force reads the velocity: drag, damping) |", ord_yoshida_damped, ABS, 0.1, "the order measured halving Δt from 0.04 on the damped default spring (Verlet's velocity predictor errs at second order)", NULL },
    { README, "| 4 ({2} where a force reads the velocity: drag, damping) |", ord_yoshida_drag, ABS, 0.1, "as above, on the projectile with drag", NULL },
    { README, "(2 where a force reads the velocity: drag, damping) | {3} (reuses the last acceleration) |", ev_yoshida, EXACT, 0, "after the first step", NULL },
    { README, "the {eleven} lessons in `lessons/`", lesson_count, EXACT, 0, R_COUNT, NULL },
    { README, "Euler's energy growth (1 + h²)^N", euler_energy_growth, REL, 1e-9, "Euler's energy on the ω = 1 spring after 50 steps of 0.1", euler_energy_formula },
    { README, "(ωh = {2} for symplectic Euler and Verlet", symplectic_wdt, ABS, 1e-6, "symplectic Euler's limit in theory (bisected to 1e-9)", NULL },
    { README, "(ωh = {2} for symplectic Euler and Verlet", cl_verlet_wdt, ABS, 1e-6, "Verlet's limit in theory", NULL },
    { README, "(ωh = {2} for symplectic Euler and Verlet", cl_verlet_measured_wdt, REL, 0.001, "Verlet's limit measured (bisection to 0.01 %)", NULL },
    { README, "symplectic Euler and Verlet, {2√2} for RK4", cl_rk4_wdt, ABS, 1e-6, "RK4's limit in theory", NULL },
    { README, "symplectic Euler and Verlet, {2√2} for RK4", cl_rk4_measured_wdt, REL, 0.001, "RK4's limit measured", NULL },
    { README, "their damped values: Euler {2}ζ", euler_damped_over_zeta, ABS, 1e-6, "Euler's damped limit over ζ on the default spring", NULL },
    { README, "RK4 {2.938} at ζ = 0.079 in theory", rk4_damped, ROUNDED, 0, R_ROUND, NULL },
    { README, "RK4 2.938 at ζ = {0.079} in theory", spring_zeta, ROUNDED, 0, "ζ = c/2√(km) of the default spring", NULL },
    { README, "on the default spring RK4 measures {2.815}", cl_rk4_damped_measured, ROUNDED, 0, "the measured limit, ω·Δt to the text's digits", NULL },
    { README, "it throws the mass through its anchor", rk4_through_anchor, ATMOST, 0, "at Δt = 0.9 (ωΔt 2.85) the mass reaches x < 0", cl_zero },
    { README, "with a smaller stretch it measures {2.938} too", cl_rk4_small_stretch, ROUNDED, 0, "measured at stretch 0.2", NULL },
    { README, "stiff pendulum up to ω·Δt = {10⁴}", be_never_gains, ATLEAST, 0, "no step of 20 raised the energy at ω·Δt = 1, 10, ... 1e4", NULL },
    /* `stepwise list integrators` prints each cl_method's order and evaluations
     * per step from the table in src/engine/integrators.c ("+solve" after an
     * implicit cl_method's count: at least that many, and linear solves) */
    { INTEGRATORS, "\"explicit (forward) Euler\", .order = {1}, .evals = 1,", ord_euler, ABS, 0.1, "the order measured halving Δt on the damped spring", NULL },
    { INTEGRATORS, "\"explicit (forward) Euler\", .order = 1, .evals = {1},", ev_euler, EXACT, 0, "evaluations per step measured", NULL },
    { INTEGRATORS, "\"semi-implicit Euler\", .order = {1}, .evals = 1,", ord_symplectic, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"semi-implicit Euler\", .order = 1, .evals = {1},", ev_symplectic, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"explicit midpoint (RK2)\", .order = {2}, .evals = 2,", ord_midpoint, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"explicit midpoint (RK2)\", .order = 2, .evals = {2},", ev_midpoint, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"Heun / explicit trapezoid (RK2)\", .order = {2}, .evals = 2,", ord_heun, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"Heun / explicit trapezoid (RK2)\", .order = 2, .evals = {2},", ev_heun, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"classical Runge-Kutta\", .order = {4}, .evals = 4,", ord_rk4, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"classical Runge-Kutta\", .order = 4, .evals = {4},", ev_rk4, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"velocity Verlet (leapfrog)\", .order = {2}, .evals = 1,", ord_verlet, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"velocity Verlet (leapfrog)\", .order = 2, .evals = {1},", ev_verlet, EXACT, 0, "after the first step", NULL },
    { INTEGRATORS, "\"Yoshida 4th-order symplectic (2nd where a force reads v)\", .order = {4},", ord_yoshida, ABS, 0.1, "as the README's row", NULL },
    { INTEGRATORS, "\"Yoshida {4}th-order symplectic (2nd where", ord_yoshida, ABS, 0.1, "as the README's row", NULL },
    { INTEGRATORS, "\"Yoshida 4th-order symplectic ({2}nd where a force reads v)\"", ord_yoshida_damped, ABS, 0.1, "as the README's row", NULL },
    { INTEGRATORS, "\"Yoshida 4th-order symplectic ({2}nd where a force reads v)\"", ord_yoshida_drag, ABS, 0.1, "as the README's row", NULL },
    { INTEGRATORS, "(2nd where a force reads v)\", .order = 4,\n      .evals = {3},", ev_yoshida, EXACT, 0, "after the first step", NULL },
    { INTEGRATORS, ".stability = {1.5734019474345401},", yoshida_wdt, ABS, 1e-6, "the truth module's limit from the method's own one-step map (bisected to 1e-9)", NULL },
    { INTEGRATORS, "\"backward Euler (Newton to rounding, direct solve)\", .order = {1}, .evals = 1,", ord_be, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"backward Euler (Newton to rounding, direct solve)\", .order = 1, .evals = {1},", ev_be, ATLEAST, 0, "\"1+solve\": Newton iterates, at least one evaluation", NULL },
    { INTEGRATORS, "\"linearly implicit Euler (one Newton step)\", .order = {1}, .evals = 1,", ord_lbe, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"linearly implicit Euler (one Newton step)\", .order = 1, .evals = {1},", ev_lbe, EXACT, 0, "one Newton step: one evaluation", NULL },
    { INTEGRATORS, "\"implicit midpoint (Newton to rounding)\", .order = {2}, .evals = 2,", ord_im, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"implicit midpoint (Newton to rounding)\", .order = 2, .evals = {2},", ev_im, ATLEAST, 0, "\"2+solve\": Newton iterates, at least two evaluations", NULL },
    { INTEGRATORS, "\"Dormand-Prince 5(4), adaptive\", .order = 5, .evals = {6},", cl_l9_rk45_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    /* man page */
    { MAN, "Step size, in [{1e\\-9}, 1000]", dt_min, EXACT, 0, R_COUNT, NULL },
    { MAN, "state error at {16} times spread to the report time", truth_samples, EXACT, 0,
      "the truth module's sample times (SW_TRUTH_SAMPLES)", NULL },
    { MAN, "Step size, in [1e\\-9, {1000}]", dt_max, EXACT, 0, R_COUNT, NULL },
    { MAN, "(defaults {1e\\-6} and 1e\\-9). The implicit", rtol_default, EXACT, 0, R_COUNT, NULL },
    { MAN, "(defaults 1e\\-6 and {1e\\-9}). The implicit", atol_default, EXACT, 0, R_COUNT, NULL },
    { MAN, "Comparison tolerances; defaults {1e\\-9} and 1e\\-9", check_rtol, EXACT, 0, R_COUNT, NULL },
    { MAN, "Comparison tolerances; defaults 1e\\-9 and {1e\\-9}", check_atol, EXACT, 0, R_COUNT, NULL },
    { MAN, "The small sweep the UI uses ({6}\\-8 step sizes, one run each)", bench_quick_min, EXACT, 0, R_COUNT, NULL },
    { MAN, "The small sweep the UI uses (6\\-{8} step sizes, one run each)", bench_quick_max, EXACT, 0, R_COUNT, NULL },
    { MAN, "The small sweep the UI uses (6\\-8 step sizes, {one} run each)", bench_quick_runs, EXACT, 0, R_COUNT, NULL },
    { MAN, "Timing repeats per point, 1..15 (default {3})", bench_default_repeats, EXACT, 0, R_COUNT, NULL },
    { MAN, "with a {ten\\-thousandfold} smaller copy of the motion", stab_shrink, REL, 1e-12, R_COUNT, NULL },
    { MAN, "Where the two differ by more than {2}% a line says why", stab_agree, REL, 1e-12, R_COUNT, NULL },
    { "docs/plugins.md", "else its first {64} steps; then halved,", probe_steps, EXACT, 0, R_COUNT, NULL },
    { "docs/plugins.md", "the error at that run's dt is {1} % of the state", order_ceiling_percent, EXACT, 0, "the sweep's error ceiling, SW_BENCH_CEILING", NULL },
    { "docs/plugins.md", "on the first {15} of the chain's 500 steps", euler_span, EXACT, 0, "the span sw_measure_order_on reads Euler's order on, on try's chain", NULL },
    { "docs/plugins.md", "on the first 15 of the chain's {500} steps", euler_span_of, EXACT, 0, "the chain's duration over its dt", NULL },
    { "docs/grading.md", "else its first {64} steps; in either", probe_steps, EXACT, 0, R_COUNT, NULL },
    { "docs/grading.md", "the graded dt is {1e-2} of the state or more", order_ceiling, EXACT, 0, "the sweep's error ceiling, SW_BENCH_CEILING", NULL },
    { "docs/grading.md", "read on its first {15} of 500 steps", euler_span, EXACT, 0, "as docs/plugins.md's", NULL },
    { "docs/grading.md", "read on its first 15 of {500} steps", euler_span_of, EXACT, 0, "as docs/plugins.md's", NULL },
    { "docs/scenes.md", "slower than √(2g·h), h = {1} mm (too slow", bounce_rest_hop_mm, REL, 1e-9, "the hop height at the scene's resting speed, from a 1-ball run", NULL },
    { "docs/plugins.md", "order      claimed 4, measured {4.06}", measured_rk4, ROUNDED, 0, "sw_measure_order_on rk4 on the chain, as try prints it", NULL },
    /* docs/stability.md (its table: tests/e2e/test_stability_doc.sh) */
    { STAB, "It is taken at {16} times along the true solution", stab_samples, EXACT, 0, R_COUNT, NULL },
    { STAB, "\"none\" means the method grows already at |λ|·Δt = {0.01}", euler_grows_at_low, EXACT, 0, "the smallest |λ|·Δt probed, where Euler grows", NULL },
    { STAB, "\"unbounded\" that no mode grows at any Δt up to {1000}", be_unbounded_to, EXACT, 0, "backward Euler's theory runs to this Δt", NULL },
    { STAB, "over the horizon, {100} periods of the stiffest mode", horizon_periods, REL, 1e-12, "the horizon of a slow spring (ω = 0.1) in periods", NULL },
    { STAB, "and at least {20} report times", horizon_reports, REL, 1e-12, "the horizon of a stiff one in report times", NULL },
    { STAB, "report times: ρ^(T/Δt) > {1.01}", visible_growth, REL, 1e-9, "growth at which the meter calls it visible, bisected", NULL },
    { STAB, "when M passes {1000}, when", watch_bound, REL, 1e-6, "the level of M at which the watch says energy x1000, bisected", NULL },
    { STAB, "a twentieth of the run", watch_windows, EXACT, 0, R_COUNT, twenty },
    { STAB, "passes a level ({3} for a method that is not symplectic", raised_plain, EXACT, 0, R_COUNT, NULL },
    { STAB, "gain a little; {30} for a symplectic one", raised_symplectic, EXACT, 0, R_COUNT, NULL },
    { STAB, "k = 100, angle = 160, Δt = 1), step 3 gains {8.2e-3} J", be_gain_compressed, ROUNDED, 0, "backward Euler's E3 - E2 on the compressed stiff pendulum", NULL },
    { STAB, "{2} for an orbit, where M = 2 is the planet escaping", raised_orbit, EXACT, 0, R_COUNT, NULL },
    { STAB, "whose energy started from rest averages up to 1/(1 − (|λ|Δt/2)²)", symplectic_mean_m, REL, 1e-3, "symplectic Euler from rest at ωΔt = 1: mean M over 20000 steps", symplectic_mean_formula },
    { STAB, "same motion shrunk {ten-thousandfold} towards it", stab_shrink, REL, 1e-12, R_COUNT, NULL },
    { STAB, "Bisection between a stable and an unstable Δt runs to {0.01} %", stab_rel_tol, REL, 1e-12, R_COUNT, NULL },
    { STAB, "the step\nis probed again over {4} and then", stab_longer, EXACT, 0, "SW_STABILITY_LONGER; test_long_probes checks the horizon a result states", NULL },
    { STAB, "probed again over 4 and then {16} times the horizon", stab_longest, EXACT, 0, "two rounds of SW_STABILITY_LONGER", NULL },
    { STAB, "They agree within {2} % wherever", stab_agree, REL, 1e-12, R_COUNT, NULL },
    { STAB, "On linear scenes the two agree within {2} % for every method", stab_agree, REL, 1e-12,
      "SW_STABILITY_AGREE, what tests/check_stability_linear.c holds every method to", NULL },
    { STAB, "gains energy on the nonlinear stiff pendulum above Δt ≈ {0.19}", cl_l7_im_limit, ROUNDED, 0, "the limit the stability lab measures", NULL },
    /* scenes: what `stepwise list` and `describe` print */
    { "src/scenes/flow_scenes.c", "every step multiplies the radius by sqrt(1 + (w dt)^2)", vortex_growth, REL, 1e-12, "ρ of Euler's map at Δt = 0.3", vortex_formula },
    { "src/scenes/spring_scenes.c", "explicit Euler gains energy every step: (1 + (w dt)^2) per step", spring_energy_growth, REL, 1e-12, "ρ² of Euler's map on the undamped spring at Δt = 0.05", spring_energy_formula },
    { "src/scenes/spring_scenes.c", "implicit midpoint gains energy on this nonlinear spring above dt {0.19}", cl_l7_im_limit, ROUNDED, 0, "the limit the stability lab measures", NULL },
    { "src/scenes/orbit.c", "Kepler's exact ellipse, period 2 pi / sqrt(mu)", orbit_period_mu4, REL, 1e-12, "Kepler's period from the energy at mu = 4", orbit_period_formula },
    { "src/scenes/flow_scenes.c", "measured against a tight-tolerance {8}th-order", reference_order, EXACT, 0, "the order of the truth module's reference method", NULL },
    { "src/scenes/ball_scenes.c", "halve the step and the miss distance {halves}", projectile_ratio, ABS, 0.3, "the ratio halving Δt from 0.01: the lessons' tolerance for 2", NULL },
    { "src/scenes/ball_scenes.c", "error becomes O(dt)", bounce_order, ABS, 0.5, "the order lesson 4's page measures on the bounce", cl_one },
    /* lessons/README.md, the authoring guide */
    { GUIDE, "| `@dt STEP` | the step size, in [{1e-9}, 1000] seconds |", guide_dt_min, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| `@dt STEP` | the step size, in [1e-9, {1000}] seconds |", dt_max, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "`>=` forgive a relative difference of {1e-9}", goal_slack, REL, 1e-6, "the slack of a >= goal, bisected", NULL },
    { GUIDE, "(E - E0)/(E0 - E_rest) in percent", drift_definition, ATMOST, 0, "the drift the goals see against the definition worked out here (1e-12)", cl_rounding },
    { GUIDE, "`0` the tenth, rk45;", cl_key_rk45, EXACT, 0, "the key that picks rk45", cl_zero },
    { GUIDE, "`@` the twelfth, yoshida4", key_at_yoshida, EXACT, 0, "'@' picks the twelfth method, yoshida4", cl_one },
    { GUIDE, "| file size | {262144} bytes (256 KiB) |", max_bytes, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| line length | {1000} bytes |", max_line, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| lesson and page titles | {80} characters |", max_title, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| pages per lesson | {64} |", max_pages, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| prose per page | {6000} bytes |", max_prose, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| paragraphs and verbatim blocks per page | {64} |", max_blocks, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| goals per page | {8} |", max_goals, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| answers per question | {6} |", max_answers, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| methods in `@compare` | {2} |", max_compare, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| names after `in` | {4} |", max_names, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| lesson files in one directory | {256} |", max_files, EXACT, 0, R_COUNT, NULL },
};
const size_t sw_claims_d_n = sizeof sw_claims_d / sizeof sw_claims_d[0];
