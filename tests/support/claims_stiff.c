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

/* Evaluations (or solves) per trial step (accepted or rejected) once under
 * way, on a particle system (the stiff spring, rtol = atol = 1e-6, a
 * second): no ∂f/∂t there, whose derivative ignores t. */
static double rodas_particle_trial(int solves)
{
    sw_sim s;
    cl_sim_init(&s, "stiff-spring", NULL, "rodas4", 0.05);
    sw_sim_step(&s);
    long n1 = solves ? s.sys.ode->solves : sw_sim_evals(&s), acc1, rej1, acc, rej;
    sw_sim_step_counts(&s, &acc1, &rej1);
    ck_assert_int_eq(sw_sim_run_until(&s, 1.0), 0);
    sw_sim_step_counts(&s, &acc, &rej);
    long n = solves ? s.sys.ode->solves : sw_sim_evals(&s);
    sw_sim_free(&s);
    return (double)(n - n1) / (double)(acc + rej - acc1 - rej1);
}
static double rodas_particle_per_trial(void) { return rodas_particle_trial(0); }
static double rodas_particle_solves(void) { return rodas_particle_trial(1); }

/* 1 when '$' picks rodas4 (the fourteenth place), from the controls' table. */
static double key_hash_rodas(void) { return cl_key_picks('$', 14, "rodas4"); }

/* Lesson 9's last page: the pendulum at k = 1e6, 0.05 degrees, largest step
 * 0.1, default tolerances, from t = 0 to 2 under one method. */
typedef struct page_run { double acc, rej, evals, solves; } page_run;
static page_run l9_run(const char *m)
{
    sw_sim s;
    cl_sim_init(&s, "stiff-spring", "k=1e6 angle=0.05", m, 0.1);
    ck_assert_int_eq(sw_sim_run_until(&s, 2.0), 0);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    page_run r = { (double)acc, (double)rej, (double)sw_sim_evals(&s), (double)s.sys.ode->solves };
    sw_sim_free(&s);
    return r;
}
static double l9_rk45_acc(void) { return l9_run("rk45").acc; }
static double l9_rk45_rej(void) { return l9_run("rk45").rej; }
static double l9_rk45_evals(void) { return l9_run("rk45").evals; }
static double l9_rk45_mean_h(void) { return 2.0 / l9_run("rk45").acc; }
static double l9_rk45_one_in(void)
{
    page_run r = l9_run("rk45");
    return (r.acc + r.rej) / r.rej;
}
static double l9_rodas_acc(void) { return l9_run("rodas4").acc; }
static double l9_rodas_evals(void) { return l9_run("rodas4").evals; }
/* Solves per trial step (accepted or rejected): the stages. */
static double l9_rodas_solves(void)
{
    page_run r = l9_run("rodas4");
    return r.solves / (r.acc + r.rej);
}
static double l9_omega(void) { return sqrt(1e6 / cl_param("stiff-spring", "m")); }
static double l9_rtol(void) { return SW_RTOL_DEFAULT; }
static double key_place_rodas(void)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (strcmp(sw_integrator_at(i)->name, "rodas4") == 0)
            return i + 1;
    return NAN;
}

/* rodas4 on one bead with heavy damping (chain n = 1, c = 1e4) to the
 * report time at rtol = atol = tol, as the peer bench runs it: its
 * evaluations, or its largest state error against dop853 at 1e-13 (the
 * bench's cross-check of its reference, 1.5e-14 from GSL's rk8pd). */
static double bead_run(const char *m, double tol, double *y)
{
    sw_sim s;
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = cl_scene_p("chain", "n=1 c=1e4", p);
    cl_sim_init(&s, "chain", "n=1 c=1e4", m, sc->duration);
    sw_sim_set_tolerances(&s, tol, tol);
    ck_assert(!sw_sim_run_until(&s, sc->duration));
    memcpy(y, s.sys.y, 4 * sizeof *y);
    double evals = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return evals;
}
static double bead_error(double tol)
{
    double y[4], ref[4], e = 0;
    bead_run("rodas4", tol, y);
    bead_run("dop853", 1e-13, ref);
    for (int i = 0; i < 4; i++)
        e = fmax(e, fabs(y[i] - ref[i]));
    return e;
}
static double bead_evals_6(void) { double y[4]; return bead_run("rodas4", 2.5e-6, y); }
static double bead_evals_9(void) { double y[4]; return bead_run("rodas4", 1e-7, y); }
static double bead_error_6(void) { return bead_error(2.5e-6); }
static double bead_error_9(void) { return bead_error(1e-7); }

/* Verlet on the stiff spring (k = 1e6) to T = 2 in `steps` fixed steps:
 * its largest state error against dop853 at 1e-13 (3.0e-11 from the peer
 * bench's reference, GSL's rk8pd at 1e-13). */
static double ss_verlet_error(long steps)
{
    sw_sim s;
    double ref[4], e = 0;
    for (int run = 0; run < 2; run++) {
        cl_sim_init(&s, "stiff-spring", "k=1e6", run ? "verlet" : "dop853", 2.0 / (run ? (double)steps : 1.0));
        if (!run)
            sw_sim_set_tolerances(&s, 1e-13, 1e-13);
        ck_assert(!sw_sim_run_until(&s, 2.0));
        for (int i = 0; i < 4; i++)
            if (run)
                e = fmax(e, fabs(s.sys.y[i] - ref[i]));
            else
                ref[i] = s.sys.y[i];
        if (run)
            ck_assert_int_eq(s.steps, steps);
        sw_sim_free(&s);
    }
    return e;
}
static double ss_verlet_1024(void) { return ss_verlet_error(1024); }
static double ss_verlet_1700(void) { return ss_verlet_error(1700); }
static double ss_verlet_4000(void) { return ss_verlet_error(4000); }

/* The stiff chain n = 10 (k = 1e6, c = 100, g = 9.81) to T = 1 under
 * dop853 at 1e-13, 1e-14 and 3e-15: the largest distance between any two
 * of the three end states (the largest |y_i - y'_i| over the state). */
static double chain_spread(void)
{
    static const double tol[3] = { 1e-13, 1e-14, 3e-15 };
    double y[3][40], d = 0;
    for (int r = 0; r < 3; r++) {
        sw_sim s;
        cl_sim_init(&s, "chain", "n=10 k=1e6 c=100 g=9.81", "dop853", 1.0);
        sw_sim_set_tolerances(&s, tol[r], tol[r]);
        ck_assert(!sw_sim_run_until(&s, 1.0));
        ck_assert_int_eq(s.sys.ode->dim, 40);
        memcpy(y[r], s.sys.y, sizeof y[r]);
        sw_sim_free(&s);
    }
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++)
            for (int i = 0; i < 40; i++)
                d = fmax(d, fabs(y[a][i] - y[b][i]));
    return d;
}

const claim sw_claims_k[] = {
    { PERF, "dop853's own runs at 1e-13, 1e-14 and 3e-15 end up to {2.8e-9} apart", chain_spread, ROUNDED, 0, "the largest state distance between any two of the three runs", NULL },
    { PERF, "verlet is within it at 1024 steps ({8.3e-4})", ss_verlet_1024, ROUNDED, 0, "the largest state error at T against dop853 at 1e-13", NULL },
    { PERF, "swings from {1.9e-4} (1700 steps) to 2.1e-3 (4000 steps)", ss_verlet_1700, ROUNDED, 0, "the largest state error at T against dop853 at 1e-13", NULL },
    { PERF, "swings from 1.9e-4 (1700 steps) to {2.1e-3} (4000 steps)", ss_verlet_4000, ROUNDED, 0, "the largest state error at T against dop853 at 1e-13", NULL },
    { PERF, "rodas4 at rtol = atol = 2.5e-6 and 1e-7 makes {205} and 169 evaluations", bead_evals_6, EXACT, 0, "the run the peer bench times", NULL },
    { PERF, "rodas4 at rtol = atol = 2.5e-6 and 1e-7 makes 205 and {169} evaluations", bead_evals_9, EXACT, 0, "the run the peer bench times", NULL },
    { PERF, "and 169 evaluations within {1e-6} and 1e-9", bead_error_6, ATMOST, 0, "the largest state error against dop853 at 1e-13", NULL },
    { PERF, "and 169 evaluations within 1e-6 and {1e-9}", bead_error_9, ATMOST, 0, "the largest state error against dop853 at 1e-13", NULL },
    { L9, "could ring at ω = {1000} rad/s", l9_omega, REL, 1e-12, R_MATH, NULL },
    { L9, "so its steps average {0.0014} s", l9_rk45_mean_h, ROUNDED, 0, "two seconds over the accepted steps, to the text's digits", NULL },
    { L9, "rejects a step in {four}", l9_rk45_one_in, ABS, 0.5, "trials per rejection, to the nearest whole number", NULL },
    { L9, "Two seconds cost it {1481} accepted steps", l9_rk45_acc, EXACT, 0, R_COUNT, NULL },
    { L9, "1481 accepted steps, {500} rejected and 11887 evaluations", l9_rk45_rej, EXACT, 0, R_COUNT, NULL },
    { L9, "1481 accepted steps, 500 rejected and {11887} evaluations", l9_rk45_evals, EXACT, 0, R_COUNT, NULL },
    { L9, "with the Jacobian J {six} times a step", l9_rodas_solves, EXACT, 0, "linear solves per trial step, counted", NULL },
    { L9, "Press $ (the {14}th method)", key_place_rodas, EXACT, 0, "rodas4's place in the method table", NULL },
    { L9, "Press $ (the 14th method)", key_hash_rodas, EXACT, 0, "'$' picks rodas4", cl_one },
    { L9, "run two seconds: {188} steps, 1237 evaluations", l9_rodas_acc, EXACT, 0, R_COUNT, NULL },
    { L9, "run two seconds: 188 steps, {1237} evaluations", l9_rodas_evals, EXACT, 0, R_COUNT, NULL },
    { L9, "the stretch rings by {1.3e-6} m", ring, ROUNDED, 0, R_MATH, NULL },
    { L9, "at rtol = {1e-6} every method", l9_rtol, EXACT, 0, "the tolerance a sim starts with", NULL },
    { PERF, "amplitude of m g (1 - cos 30°)/k = {1.3e-6} m, 1.3e-3 m/s", ring, ROUNDED, 0, R_MATH, NULL },
    { PERF, "amplitude of m g (1 - cos 30°)/k = 1.3e-6 m, {1.3e-3} m/s", ring_speed, ROUNDED, 0, R_MATH, NULL },
    { PERF, "(stiff-spring at rtol 1e-2, {36} steps a second against rk45's 600", rodas_steps, EXACT, 0, R_COUNT, NULL },
    { PERF, "(stiff-spring at rtol 1e-2, 36 steps a second against rk45's {600}", rk45_steps, ABS, 50, "\"600\": to the hundred", NULL },
    { PERF, "rodas4 spends {7} evaluations and 6 solves a step", rodas_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { PERF, "∂f/∂t it takes; {6} on a particle system", rodas_particle_per_trial, EXACT, 0, "evaluations per trial step once under way", NULL },
    { README, "one Jacobian a step | {4} | 6 + 6 linear solves", rodas_order, EXACT, 0, "the method's order in the table", NULL },
    { README, "one Jacobian a step | 4 | {6} + 6 linear solves", rodas_particle_per_trial, EXACT, 0, "evaluations per trial step once under way on a particle system", NULL },
    { README, "one Jacobian a step | 4 | 6 + {6} linear solves", rodas_particle_solves, EXACT, 0, "solves per trial step once under way on a particle system", NULL },
    { README, "one matrix ({7} evaluations on a flow field", rodas_per_step, EXACT, 0, "evaluations per accepted step once under way on the vortex, a flow field", NULL },
    { INTEGRATORS, "L-stable (Hairer); {6} evals on particles\",\n      .order = 4, .evals = 7,", rodas_particle_per_trial, EXACT, 0, "evaluations per trial step once under way on a particle system", NULL },
    { INTEGRATORS, "L-stable (Hairer); 6 evals on particles\",\n      .order = 4, .evals = {7},", rodas_per_step, EXACT, 0, "evaluations per accepted step once under way on a flow field", NULL },
    { README, "`!`, `@`, `#`, `$`, `%`, `^`, `&` and `*` pick one", key_hash_rodas, EXACT, 0, "'$' picks the fourteenth method, rodas4", cl_one },
    { GUIDE, "`$` the fourteenth, rodas4", key_hash_rodas, EXACT, 0, "'$' picks the fourteenth method, rodas4", cl_one },
};
const size_t sw_claims_k_n = sizeof sw_claims_k / sizeof sw_claims_k[0];
