/* Claims: rodas4's figures in docs/performance.md, the README, the method
 * table and the lesson guide (its key), each recomputed here from a run,
 * the scene's parameters or the controls' table. */
#include "claims.h"
#include "util/num.h"

#define PERF "docs/performance.md"

/* The stiff spring at k = 1e6 (other parameters the scene's defaults):
 * m g (1 - cos θ)/k, the stretch the start leaves ringing, and ω times it. */
static double ring(void)
{
    double m = cl_param("stiff-spring", "m"), g = cl_param("stiff-spring", "g");
    double theta = cl_param("stiff-spring", "angle") * SW_PI / 180.0;
    return m * g * (1 - cos(theta)) / 1e6;
}
static double ring_speed(void) { return ring() * sqrt(1e6 / cl_param("stiff-spring", "m")); }

/* Accepted steps over the first second at rtol = atol = 1e-2, largest step
 * 0.5 (the bench's loosest point). */
static double steps_1s(const char *m)
{
    sw_sim s;
    cl_sim_init(&s, "stiff-spring", "k=1e6", m, 0.5);
    sw_sim_set_tolerances(&s, 1e-2, 1e-2);
    ck_assert_int_eq(sw_sim_run_until(&s, 1.0), 0);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    sw_sim_free(&s);
    return (double)acc;
}
static double rodas_steps(void) { return steps_1s("rodas4"); }
static double rk45_steps(void) { return steps_1s("rk45"); }

/* Evaluations per accepted step once under way, on a 1-point vortex
 * (claims_shared.c): five stages, the FSAL derivative and ∂f/∂t. */
static double rodas_per_step(void) { return cl_adaptive_per_step("rodas4"); }
static double rodas_order(void) { return cl_method("rodas4")->order; }

/* 1 when '#' picks rodas4 (the thirteenth place), from the controls' table. */
static double key_hash_rodas(void)
{
    const sw_control *control;
    int arg;
    return sw_key_lookup('#', SW_CTX_PLAY, &control, &arg) && control->action == SW_ACT_PICK_METHOD &&
           arg == 13 && sw_integrator_at(arg - 1) && strcmp(sw_integrator_at(arg - 1)->name, "rodas4") == 0;
}

const claim sw_claims_s[] = {
    { PERF, "amplitude of m g (1 - cos 30°)/k = {1.3e-6} m, 1.3e-3 m/s", ring, ROUNDED, 0, R_MATH, NULL },
    { PERF, "amplitude of m g (1 - cos 30°)/k = 1.3e-6 m, {1.3e-3} m/s", ring_speed, ROUNDED, 0, R_MATH, NULL },
    { PERF, "(stiff-spring at rtol 1e-2, {36} steps a second against rk45's 600", rodas_steps, EXACT, 0, R_COUNT, NULL },
    { PERF, "(stiff-spring at rtol 1e-2, 36 steps a second against rk45's {600}", rk45_steps, ABS, 50, "\"600\": to the hundred", NULL },
    { PERF, "rodas4 spends {7} evaluations and 6 solves a step", rodas_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { README, "one Jacobian a step | {4} | 7 + 6 linear solves", rodas_order, EXACT, 0, "the method's order in the table", NULL },
    { README, "one Jacobian a step | 4 | {7} + 6 linear solves", rodas_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { INTEGRATORS, "adaptive, L-stable (Hairer)\", 4, {7},", rodas_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { GUIDE, "`#` the thirteenth, rodas4", key_hash_rodas, EXACT, 0, "'#' picks the thirteenth method, rodas4", cl_one },
};
const size_t sw_claims_s_n = sizeof sw_claims_s / sizeof sw_claims_s[0];
