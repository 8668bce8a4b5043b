/* Claims: the Runge-Kutta-Nyström pair rkn (issue 27) in the README, the
 * guide, the method table and lesson 9, recomputed: its order with fixed
 * steps on Kepler's orbit, its embedded order, its evaluations per step, the
 * key that picks it, its refusal of a damped system, and the lesson's
 * evaluations at equal error on the e = 0.9 orbit; and beside them vern8's
 * and vern9's rows (their orders, evaluations per step, keys). */
#include "claims.h"

#include "engine/regularise.h"
#include "engine/rkn_tableau.h"
#include "engine/stepper.h"
#include "nystrom_run.h"

static double key_hash(void) { return cl_key_picks('#', 13, "rkn"); }
static double key_percent(void) { return cl_key_picks('%', 15, "rkn12"); }
static double key_caret(void) { return cl_key_picks('^', 16, "dop853-lc"); }
static double key_amp(void) { return cl_key_picks('&', 17, "vern8"); }
static double key_star(void) { return cl_key_picks('*', 18, "vern9"); }

/* dop853-lc's order: dop853 in Levi-Civita's variables with n fixed steps
 * to s = 100, about eight orbits (tolerances so loose that every trial is
 * accepted, the proposal clipped to the step), on the e = 0.9 orbit, where
 * u is the oscillator u'' = (h/2)·u: the largest error of u against its
 * closed form. */
static double lc_fixed_error(int n)
{
    sw_particles p;
    sw_lc lc;
    sw_stepper st;
    char err[SW_ERRLEN];
    double w[SW_LC_DIM], w0[SW_LC_DIM], S = 100.0, sig = 0;
    nys_particle(&p, 1, 0.9, 0.0);
    ck_assert_int_eq(sw_lc_init_central(&lc, &p.ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&st, cl_method("dop853"), &lc.ode, err, sizeof err), SW_OK);
    st.rtol = st.atol = 1e300;
    ck_assert_int_eq(sw_lc_from(&lc, 0.0, p.y, w0), SW_OK);
    memcpy(w, w0, sizeof w);
    for (int i = 0; i < n; i++) {
        st.h_next = S / n;
        ck_assert_int_eq(sw_stepper_step(&st, &lc.ode, &sig, w, S / n), SW_OK);
    }
    double om = sqrt(-0.5 * w0[4]), e = 0;
    for (int i = 0; i < 2; i++)
        e = fmax(e, fabs(w[i] - (w0[i] * cos(om * sig) + w0[2 + i] / om * sin(om * sig))));
    sw_stepper_free(&st);
    sw_particles_free(&p);
    return e;
}

/* 100 against 200 steps, ω·ds = 0.5 and 0.25: errors 1.6e-8 and 6.3e-11,
 * far above the run's round-off (about 1e-13 at 600 steps); 7.96. */
static double lc_order(void) { return log(lc_fixed_error(100) / lc_fixed_error(200)) / log(2.0); }

/* dop853-lc's evaluations per accepted step on the circular orbit, steps of
 * at most dt = 100 (none cut short to land). */
static double lc_per_step(void)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", "e=0", "dop853-lc", 100.0);
    sw_sim_step(&s);
    long e1 = sw_sim_evals(&s), acc, rej;
    for (int i = 0; i < 20; i++)
        sw_sim_step(&s);
    sw_sim_step_counts(&s, &acc, &rej);
    ck_assert_int_eq(rej, 0);
    double r = (double)(sw_sim_evals(&s) - e1) / (double)(acc - 1);
    sw_sim_free(&s);
    return r;
}

/* The largest state error of rkn after one period of the e = 0.5 orbit in
 * n fixed steps (its tolerances so loose that every trial is accepted and
 * the proposal is clipped to the step), against Kepler's solution. */
static double fixed_error(long n)
{
    sw_sim s;
    double p[SW_MAX_PARAMS], truth[4], T = TWO_PI;
    const sw_scene *sc = cl_scene_p("orbit", "e=0.5", p);
    cl_sim_init(&s, "orbit", "e=0.5", "rkn", T / n);
    s.stepper->rtol = s.stepper->atol = 1e300;
    s.stepper->h_next = T / n;
    double t = 0;
    for (long i = 0; i < n; i++)
        ck_assert_int_eq(sw_stepper_step(s.stepper, s.sys.ode, &t, s.sys.y, T / n), SW_OK);
    ck_assert_int_eq(sw_truth_state(sc, p, t, truth), 0);
    double e = sw_truth_error(4, s.sys.y, truth);
    sw_sim_free(&s);
    return e;
}

/* The order from halving: 200 to 400 steps a period (errors 2e-9 and
 * 4e-11, in the asymptotic range and above round-off). */
static double rkn_order(void) { return log2(fixed_error(200) / fixed_error(400)); }

/* The embedded solution's order: stepped here from the tableau (the engine
 * only uses it to estimate the error) on x'' = -x to t = 10, 20 against 40
 * steps, against cos t. */
#define FIELD(name, p, q) double name;
#define VALUE(name, p, q) (double)(p) / (q),
static const struct { SW_RKN_TABLEAU(FIELD) } E = { SW_RKN_TABLEAU(VALUE) };
#undef FIELD
#undef VALUE

static double embedded_error(int n)
{
    const double c[6] = { 0, E.C2, E.C3, E.C4, E.C5, 1 };
    const double a[6][5] = { { 0 }, { E.A21 }, { E.A31, E.A32 }, { E.A41, E.A42, E.A43 },
                                    { E.A51, E.A52, E.A53, E.A54 }, { E.BX1, E.BX2, E.BX3, E.BX4, E.BX5 } };
    const double hx[6] = { E.HX1, E.HX2, E.HX3, E.HX4, E.HX5, 0 };
    const double hv[6] = { E.HV1, E.HV2, E.HV3, E.HV4, E.HV5, E.BV6 };
    double x = 1, v = 0, h = 10.0 / n;
    for (int s = 0; s < n; s++) {
        double acc[6], sx = 0, sv = 0;
        for (int i = 0; i < 6; i++) {
            double sum = 0;
            for (int j = 0; j < i; j++)
                sum += a[i][j] * acc[j];
            acc[i] = -(x + c[i] * h * v + h * h * sum);
        }
        for (int i = 0; i < 6; i++)
            sx += hx[i] * acc[i], sv += hv[i] * acc[i];
        x += h * v + h * h * sx;
        v += h * sv;
    }
    return fmax(fabs(x - cos(10.0)), fabs(v + sin(10.0)));
}

static double embedded_order(void) { return log2(embedded_error(20) / embedded_error(40)); }

/* Evaluations per accepted step once under way (no rejection: the circular
 * orbit at dt 0.01), and on the first step (every stage: 1 + the new ones). */
static double per_step(const char *m, int first)
{
    sw_sim s;
    cl_sim_init(&s, "orbit", "e=0", m, 0.01);
    sw_sim_step(&s);
    long e1 = sw_sim_evals(&s);
    for (int i = 0; i < 20; i++)
        sw_sim_step(&s);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    ck_assert_int_eq(rej, 0);
    double r = first ? (double)e1 : (double)(sw_sim_evals(&s) - e1) / (double)(acc - 1);
    sw_sim_free(&s);
    return r;
}

static double rkn_per_step(void) { return per_step("rkn", 0); }
static double rkn_stages(void) { return per_step("rkn", 1); }
static double rkn12_per_step(void) { return per_step("rkn12", 0); }
static double vern8_per_step(void) { return per_step("vern8", 0); }
static double vern8_order(void) { return cl_method("vern8")->order; }
static double vern9_per_step(void) { return per_step("vern9", 0); }
static double vern9_order(void) { return cl_method("vern9")->order; }

/* rkn12's order with fixed steps on x'' = -x to t = 10, 4 against 6 steps
 * (errors 8e-9 and 6e-11: above round-off and asymptotic; on the orbit
 * it is still pre-asymptotic where its error is above round-off). */
static double rkn12_order(void)
{
    return log(nys_engine_error("rkn12", 0, 0.0, 10.0, 4) / nys_engine_error("rkn12", 0, 0.0, 10.0, 6)) / log(1.5);
}

/* 1 when rkn refuses the default (damped) spring and takes the undamped one. */
static double refuses_damped(void)
{
    sw_sim s;
    char err[SW_ERRLEN];
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = cl_scene_p("spring", NULL, p);
    if (sw_sim_init(&s, sc, p, cl_method("rkn"), 0.01, err, sizeof err) == SW_OK) {
        sw_sim_free(&s);
        return 0;
    }
    sc = cl_scene_p("spring", "c=0", p);
    if (sw_sim_init(&s, sc, p, cl_method("rkn"), 0.01, err, sizeof err) != SW_OK)
        return 0;
    sw_sim_free(&s);
    return 1;
}

/* Lesson 9's run (the e = 0.9 orbit, two orbits, largest step 0.4) at the
 * loosest rtol = atol reaching an error of target: quarter decades from
 * 1e-2 down, then bisection to 1/32 decade (as bench/bench_rkn.c
 * searches). */
static void at_equal_error(const char *m, double target, double *evals, double *error)
{
    double ev, e;
    int k;
    for (k = 0; k <= 48; k++) {
        cl_l9_adaptive(m, 1e-2 * pow(10, -0.25 * k), 1e-2 * pow(10, -0.25 * k), &ev, &e);
        if (e <= target)
            break;
    }
    ck_assert_int_le(k, 48);
    double hit = 1e-2 * pow(10, -0.25 * k), miss = hit * pow(10, 0.25);
    for (int b = 0; k > 0 && b < 3; b++) {
        double mid = sqrt(hit * miss);
        cl_l9_adaptive(m, mid, mid, &ev, &e);
        if (e <= target)
            hit = mid;
        else
            miss = mid;
    }
    cl_l9_adaptive(m, hit, hit, evals, error);
}

static double evals_within(const char *m, double target)
{
    double ev, e;
    at_equal_error(m, target, &ev, &e);
    return ev;
}

static double l9_evals(const char *m) { return evals_within(m, 1e-4); }

static double l9_rkn(void) { return l9_evals("rkn"); }
static double l9_dop853(void) { return l9_evals("dop853"); }
static double l9_rk45(void) { return l9_evals("rk45"); }
static double l9_rkn_error(void)
{
    double ev, e;
    at_equal_error("rkn", 1e-4, &ev, &e);
    return e;
}

/* The same within 1e-8, where rkn12 is for. */
static double tight_rkn12(void) { return evals_within("rkn12", 1e-8); }
static double tight_rkn(void) { return evals_within("rkn", 1e-8); }
static double tight_dop853(void) { return evals_within("dop853", 1e-8); }

/* dop853-lc on the e = 0.9 orbit to its report time at rtol = atol = tol,
 * as the bench runs it (one sim step of the whole span): its evaluations,
 * or its largest state error against Kepler's solution. */
static double lc_orbit_run(double tol, int error)
{
    sw_sim s;
    double p[SW_MAX_PARAMS], truth[4];
    const sw_scene *sc = cl_scene_p("orbit", "e=0.9", p);
    cl_sim_init(&s, "orbit", "e=0.9", "dop853-lc", sc->duration);
    sw_sim_set_tolerances(&s, tol, tol);
    ck_assert(!sw_sim_run_until(&s, sc->duration));
    ck_assert_int_eq(sc->exact(&s.sys, sc->duration, truth), 0);
    double e = 0;
    for (int i = 0; i < 4; i++)
        e = fmax(e, fabs(s.sys.y[i] - truth[i]));
    long evals = sw_sim_evals(&s);
    sw_sim_free(&s);
    return error ? e : (double)evals;
}
static double lc_evals_3(void) { return lc_orbit_run(1.4e-6, 0); }
static double lc_evals_6(void) { return lc_orbit_run(1.9e-9, 0); }
static double lc_evals_9(void) { return lc_orbit_run(1.8e-12, 0); }
static double lc_error_3(void) { return lc_orbit_run(1.4e-6, 1); }
static double lc_error_6(void) { return lc_orbit_run(1.9e-9, 1); }
static double lc_error_9(void) { return lc_orbit_run(1.8e-12, 1); }

#define PERF "docs/performance.md"
#define R_HUNDRED "\"about\": to the nearest hundred"

const claim sw_claims_r[] = {
    { PERF, "dop853-lc at rtol = atol = 1.4e-6, 1.9e-9 and 1.8e-12 makes {185}, 256 and 496", lc_evals_3, EXACT, 0, "the evaluations of the run the bench times", NULL },
    { PERF, "dop853-lc at rtol = atol = 1.4e-6, 1.9e-9 and 1.8e-12 makes 185, {256} and 496", lc_evals_6, EXACT, 0, "the evaluations of the run the bench times", NULL },
    { PERF, "dop853-lc at rtol = atol = 1.4e-6, 1.9e-9 and 1.8e-12 makes 185, 256 and {496}", lc_evals_9, EXACT, 0, "the evaluations of the run the bench times", NULL },
    { PERF, "evaluations (errors within {1e-3}, 1e-6 and 1e-9", lc_error_3, ATMOST, 0, "the run's largest state error against Kepler's solution", NULL },
    { PERF, "evaluations (errors within 1e-3, {1e-6} and 1e-9", lc_error_6, ATMOST, 0, "the run's largest state error against Kepler's solution", NULL },
    { PERF, "evaluations (errors within 1e-3, 1e-6 and {1e-9}", lc_error_9, ATMOST, 0, "the run's largest state error against Kepler's solution", NULL },
    { README, "`!`, `@`, `#`, `$`, `%`, `^`, `&` and `*` pick one", key_caret, EXACT, 0, "'^' picks the sixteenth method, dop853-lc", cl_one },
    { README, "`%`, `^`, `&` and `*` pick one", key_amp, EXACT, 0, "'&' picks the seventeenth method, vern8", cl_one },
    { README, "`^`, `&` and `*` pick one", key_star, EXACT, 0, "'*' picks the eighteenth method, vern9", cl_one },
    { GUIDE, "`*` the eighteenth, vern9", key_star, EXACT, 0, "'*' picks the eighteenth method, vern9", cl_one },
    { README, "| vern9 | Verner's \"most efficient\" 9(8) pair (RKV98.IIa), adaptive (rtol/atol) | {9} |", vern9_order, EXACT, 0, "the method's order in the table (tests/check_vern.c measures 9.46 on fixed steps)", NULL },
    { README, "(RKV98.IIa), adaptive (rtol/atol) | 9 | {16} (15 stages and the new state) |", vern9_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { GUIDE, "`&` the seventeenth, vern8", key_amp, EXACT, 0, "'&' picks the seventeenth method, vern8", cl_one },
    { README, "| vern8 | Verner's \"most efficient\" 8(7) pair (RKV87.IIa), adaptive (rtol/atol) | {8} |", vern8_order, EXACT, 0, "the method's order in the table (tests/check_vern.c measures 8.39 on fixed steps)", NULL },
    { README, "(RKV87.IIa), adaptive (rtol/atol) | 8 | {13} (12 stages and the new state) |", vern8_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { README, "a clock that slows there | {8} | 12", lc_order, ABS, 0.3, "fixed steps in s on the e = 0.9 orbit's oscillator u, 100 to 200 steps: 7.96", NULL },
    { README, "a clock that slows there | 8 | {12} (FSAL; 13 on a step from a state it did not leave) |", lc_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { INTEGRATORS, "\"dop853 in Levi-Civita's variables: the Kepler problem regularised\", .order = {8}, .evals = 12,", lc_order, ABS, 0.3, "as the README's row", NULL },
    { INTEGRATORS, "\"dop853 in Levi-Civita's variables: the Kepler problem regularised\", .order = 8, .evals = {12},", lc_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { GUIDE, "`^` the sixteenth, dop853-lc", key_caret, EXACT, 0, "'^' picks the sixteenth method, dop853-lc", cl_one },
    { README, "`1`–`9`, `0`, `!`, `@`, `#`, `$`, `%`, `^`, `&` and `*` pick one", key_hash, EXACT, 0, "'#' picks the thirteenth method, rkn", cl_one },
    { README, "`#`, `$`, `%`, `^`, `&` and `*` pick one", key_percent, EXACT, 0, "'%' picks the fifteenth method, rkn12", cl_one },
    { README, "at tight tolerances: refused where a force reads velocities | {12} | 17", rkn12_order, ABS, 0.5, "fixed steps on x'' = -x to t = 10, 4 to 6 steps: 11.96", NULL },
    { README, "at tight tolerances: refused where a force reads velocities | 12 | {17} (16 stages and the new state) |", rkn12_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { INTEGRATORS, "\"Runge-Kutta-Nystrom 12(10), adaptive (Dormand, El-Mikkawy, Prince)\", .order = {12}, .evals = 17,", rkn12_order, ABS, 0.5, "as the README's row", NULL },
    { INTEGRATORS, "\"Runge-Kutta-Nystrom 12(10), adaptive (Dormand, El-Mikkawy, Prince)\", .order = 12, .evals = {17},", rkn12_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { GUIDE, "`%` the fifteenth, rkn12", key_percent, EXACT, 0, "'%' picks the fifteenth method, rkn12", cl_one },
    { L9, "target, rkn12 (press %) spends", key_percent, EXACT, 0, "'%' picks rkn12", cl_one },
    { L9, "spends {17} evaluations a step on 12th order", rkn12_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { L9, "spends 17 evaluations a step on {12}th order", rkn12_order, ABS, 0.5, "as the README's row", NULL },
    { L9, "within 1e-8 it needs about {1100}, dop853", tight_rkn12, ABS, 50, R_HUNDRED, NULL },
    { L9, "dop853 about {3300} and rkn about 4200", tight_dop853, ABS, 50, R_HUNDRED, NULL },
    { L9, "dop853 about 3300 and rkn about {4200}", tight_rkn, ABS, 50, R_HUNDRED, NULL },
    { README, "refused where a force reads velocities | {6} | 5", rkn_order, ABS, 0.3, "fixed steps on the e = 0.5 orbit, 200 to 400 a period: 5.9", NULL },
    { README, "refused where a force reads velocities | 6 | {5} (reuses the last stage) |", rkn_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { INTEGRATORS, "\"Runge-Kutta-Nystrom 6(4), adaptive (Dormand, El-Mikkawy, Prince)\", .order = {6}, .evals = 5,", rkn_order, ABS, 0.3, "as the README's row", NULL },
    { INTEGRATORS, "\"Runge-Kutta-Nystrom 6(4), adaptive (Dormand, El-Mikkawy, Prince)\", .order = 6, .evals = {5},", rkn_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { GUIDE, "`#` the thirteenth, rkn", key_hash, EXACT, 0, "'#' picks the thirteenth method, rkn", cl_one },
    { L9, "rkn pairs a {6}th-order answer", rkn_order, ABS, 0.3, "as the README's row", NULL },
    { L9, "with a {4}th-order one from six stages", embedded_order, ABS, 0.3, "the embedded solution stepped from the tableau on x'' = -x: 3.97", NULL },
    { L9, "with a 4th-order one from {six} stages", rkn_stages, EXACT, 0, "the first step evaluates every stage", NULL },
    { L9, "{five} of them new (the last, at the new position, starts the next step)", rkn_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { L9, "To end two orbits within {1e-4} of the true orbit", l9_rkn_error, ATMOST, 0, "rkn's error at the setting found", NULL },
    { L9, "rkn needs about {1100} evaluations", l9_rkn, ABS, 50, R_HUNDRED, NULL },
    { L9, "dop853 about {1400} and rk45 about 1800", l9_dop853, ABS, 50, R_HUNDRED, NULL },
    { L9, "dop853 about 1400 and rk45 about {1800}", l9_rk45, ABS, 50, R_HUNDRED, NULL },
    { L9, "a damped spring) rkn refuses the system and says why", refuses_damped, EXACT, 0, "the damped spring refused, the undamped one taken", cl_one },
    { L9, "Switch to rkn (press #, or i", key_hash, EXACT, 0, "'#' picks rkn", cl_one },
};
const size_t sw_claims_r_n = sizeof sw_claims_r / sizeof sw_claims_r[0];
