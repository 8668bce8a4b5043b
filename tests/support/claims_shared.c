/* Claims: measurements more than one part of the table uses. */
#include "claims.h"

double cl_l2_ratio2(void) { return cl_page_ratio(L2, "Measure the order", NULL, 2); }
double cl_l4_ratio(void) { return cl_page_ratio(L4, "A bounce breaks the order", NULL, 1); }
double cl_l5_k(void) { return cl_param("spring", "k"); }
double cl_l5_c(void) { return cl_param("spring", "c"); }
double cl_l5_m(void) { return cl_param("spring", "m"); }

/* RK4's limit in ω·Δt on an undamped oscillator. */
double cl_rk4_wdt(void) { return cl_limit0("spring", "k=1 c=0", "rk4"); }
double cl_verlet_wdt(void) { return cl_limit0("spring", "k=1 c=0", "verlet"); }
double cl_l7_verlet_theory(void) { return cl_stability("stiff-spring", NULL, "verlet").theory; }
double cl_l7_verlet_measured(void) { return cl_stability("stiff-spring", NULL, "verlet").dt; }
double cl_zero(void) { return 0; }
double cl_rounding(void) { return 1e-12; }
double cl_l7_im_limit(void) { return cl_stability("stiff-spring", NULL, "implicit-midpoint").dt; }

/* Kepler's period from the energy: a = -μ/2E, T = 2π√(a³/μ). */
double cl_orbit_period(const char *sets)
{
    sw_sim s;
    double p[SW_MAX_PARAMS];
    cl_sim_init(&s, "orbit", sets, "rk4", 0.01);
    cl_scene_p("orbit", sets, p);
    double mu = p[sw_scene_param_index(s.sys.scene, "mu")], a = -mu / (2 * sw_sim_energy(&s));
    sw_sim_free(&s);
    return TWO_PI * sqrt(a * a * a / mu);
}

double cl_two_orbits(void) { return 2 * cl_orbit_period(ECC); }

/* rk45's evaluations: per accepted step once under way (a smooth flow, no
 * rejections), and in its first step (every stage new). */
double cl_adaptive_per_step(const char *m)
{
    sw_sim s;
    cl_sim_init(&s, "vortex", "n=1", m, 0.05);
    sw_sim_step(&s);
    long e1 = sw_sim_evals(&s);
    for (int i = 0; i < 20; i++)
        sw_sim_step(&s);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    ck_assert_int_eq(rej, 0);
    double r = (double)(sw_sim_evals(&s) - e1) / (double)(acc - 1);
    sw_sim_free(&s);
    return r;
}

double cl_l9_rk45_per_step(void) { return cl_adaptive_per_step("rk45"); }
double cl_dop853_per_step(void) { return cl_adaptive_per_step("dop853"); }
double cl_ord_dop853(void) { return cl_method("dop853")->order; }

/* An adaptive run of the e = 0.9 orbit to two orbits at largest step 0.4
 * and tolerances (rtol, atol): its evaluations and its error against Kepler. */
void cl_l9_adaptive(const char *m, double rtol, double atol, double *evals, double *error)
{
    sw_sim s;
    double p[SW_MAX_PARAMS], truth[4];
    const sw_scene *sc = cl_scene_p("orbit", ECC, p);
    cl_sim_init(&s, "orbit", ECC, m, 0.4);
    sw_sim_set_tolerances(&s, rtol, atol);
    ck_assert_int_eq(sw_sim_run_until(&s, cl_two_orbits()), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, s.t, truth), 0);
    *evals = (double)sw_sim_evals(&s);
    *error = sw_truth_error(4, s.sys.y, truth);
    sw_sim_free(&s);
}

double cl_l9_rk45_error(void)
{
    double evals, error;
    cl_l9_adaptive("rk45", SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, &evals, &error);
    return error;
}

double cl_l9_rk45_error_over_rtol(void) { return cl_l9_rk45_error() / SW_RTOL_DEFAULT; }
double cl_verlet_measured_wdt(void) { return cl_stability("spring", "k=1 c=0", "verlet").dt; }
double cl_rk4_measured_wdt(void) { return cl_stability("spring", "k=1 c=0", "rk4").dt; }
double cl_spring_omega(void) { return sqrt(cl_l5_k() / cl_l5_m()); }
double cl_rk4_damped_measured(void) { return cl_stability("spring", NULL, "rk4").dt * cl_spring_omega(); }
double cl_key_rk4(void) { return cl_key_of("rk4"); }
double cl_key_rk45(void) { return cl_key_of("rk45"); }
double cl_rk4_small_stretch(void) { return cl_stability("spring", "stretch=0.2", "rk4").dt * cl_spring_omega(); }
double cl_one(void) { return 1; }
