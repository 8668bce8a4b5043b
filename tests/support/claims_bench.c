/* Claims: the order rule's figures in docs/performance.md (issue 38): the
 * rule's constants as bench.h defines them, and the measurements the text
 * quotes (the e = 0.9 orbit's round-off plateau under rkn, rodas4 on the
 * gyre), each from a sweep run here with the default configuration. */
#include "claims.h"

#define PERF "docs/performance.md"

/* One method's default sweep on scene (with sets) into *s; the report's
 * scale into *scale and its first point's assumed floor into *floor0. */
static sw_bench_series sweep(const char *scene, const char *sets, const char *m)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = cl_scene_p(scene, sets, p);
    static sw_bench_report r;
    sw_bench_config c;
    sw_bench_config_default(&c);
    c.repeats = 1; /* the errors do not depend on the timing */
    ck_assert_msg(sw_bench_init(&r, sc, p, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_bench_sweep(&r, cl_method(m), &c, err, sizeof err) == SW_OK, "%s", err);
    sw_bench_series s = r.series[0];
    sw_bench_free(&r);
    return s;
}

/* rkn on the orbit at e = 0.9: the plateau's smallest and largest error,
 * and the floor scale·(1e-13 + 4e-16·steps) assumed at its first point. */
static double plateau_low(void)
{
    sw_bench_series s = sweep("orbit", ECC, "rkn");
    ck_assert_int_ge(s.plateau, 0);
    int n;
    const sw_bench_point *pts = sw_bench_order_points(&s, &n); /* its fixed-step runs */
    double low = INFINITY;
    for (int i = s.plateau; i < n; i++)
        low = fmin(low, pts[i].error);
    return low;
}
static double plateau_high(void)
{
    sw_bench_series s = sweep("orbit", ECC, "rkn");
    ck_assert_int_ge(s.plateau, 0);
    return s.floor;
}
static double plateau_assumed(void)
{
    sw_bench_series s = sweep("orbit", ECC, "rkn");
    ck_assert_int_ge(s.plateau, 0);
    int n;
    return sw_bench_order_points(&s, &n)[s.plateau].floor;
}

/* rodas4 on the gyre: the first fitted point's error and the fit's local
 * slopes. The sweep (seconds; minutes under valgrind) is run once per
 * process and kept, and its rows are the quick tier's slow ones. */
static sw_bench_series gyre_rodas4(void)
{
    static sw_bench_series s;
    static int have;
    if (!have) {
        s = sweep("gyre", NULL, "rodas4");
        have = 1;
    }
    ck_assert_msg(isnan(s.order) && s.no_order == SW_BENCH_ORDER_PAST, "rodas4 on the gyre: %.2f (%s)", s.order,
                  sw_bench_no_order_text(&s));
    return s;
}
/* where its error reaches round-off: the first point within
 * SW_BENCH_MARGIN of its floor */
double cl_gyre_first_error(void)
{
    sw_bench_series s = gyre_rodas4();
    int n;
    const sw_bench_point *pts = sw_bench_order_points(&s, &n); /* its fixed-step runs */
    for (int i = 0; i < n; i++)
        if (!pts[i].blown && pts[i].error < SW_BENCH_MARGIN * pts[i].floor)
            return pts[i].error;
    return NAN;
}
double cl_gyre_slope_min(void) { return gyre_rodas4().slope_min; }
double cl_gyre_slope_max(void) { return gyre_rodas4().slope_max; }

/* Why an adaptive method's order is not read from its controlled runs:
 * rk45 on the orbit (e = 0.5), the growth of its accepted steps over one
 * decade of rtol, 1e-8 to 1e-9 and on (the asymptote 10^(1/5) = 1.585),
 * and the order rule applied to the controlled runs' error against their
 * mean step T/N (the slope bench printed as an order before). */
static sw_bench_series orbit_rk45(void)
{
    static sw_bench_series s; /* one sweep for the six rows */
    static int have;
    if (!have) {
        s = sweep("orbit", NULL, "rk45");
        have = 1;
    }
    return s;
}
/* The controlled point at rtol 10^-from and the next (10x tighter). */
static const sw_bench_point *decade(int from)
{
    static sw_bench_series s;
    s = orbit_rk45();
    for (int i = 0; i + 1 < s.npoints; i++)
        if (s.points[i].rtol > 0 && fabs(log10(s.points[i].rtol) + from) < 0.01)
            return &s.points[i];
    ck_abort_msg("rk45 on the orbit: no controlled run at rtol 1e-%d", from);
    return NULL;
}
static double controlled_growth(int from) { return (double)decade(from)[1].steps / (double)decade(from)[0].steps; }
/* ... and how much its error falls over the same decades (10 where the
 * error is proportional to the tolerance) */
static double controlled_fall(int from) { return decade(from)[0].error / decade(from)[1].error; }
static double fall_8(void) { return controlled_fall(8); }
static double fall_9(void) { return controlled_fall(9); }
static double fall_10(void) { return controlled_fall(10); }
static double growth_8(void) { return controlled_growth(8); }
static double growth_9(void) { return controlled_growth(9); }
static double growth_10(void) { return controlled_growth(10); }
static double fifth_root_10(void) { return pow(10.0, 0.2); }
static double controlled_slope(const char *scene, const char *sets, const char *m)
{
    double p[SW_MAX_PARAMS], h[SW_BENCH_MAX_POINTS], e[SW_BENCH_MAX_POINTS];
    long steps[SW_BENCH_MAX_POINTS];
    char err[SW_ERRLEN];
    static sw_bench_report r;
    static sw_bench_series fit;
    sw_bench_config c;
    sw_bench_config_default(&c);
    c.repeats = 1;
    c.fine = 0; /* the tolerances on to round-off, as bench swept them when it read this slope */
    ck_assert_msg(sw_bench_init(&r, cl_scene_p(scene, sets, p), p, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_bench_sweep(&r, cl_method(m), &c, err, sizeof err) == SW_OK, "%s", err);
    const sw_bench_series *s = &r.series[0];
    for (int i = 0; i < s->npoints; i++) {
        h[i] = s->points[i].h;
        e[i] = s->points[i].blown ? NAN : s->points[i].error;
        steps[i] = s->points[i].steps;
    }
    double order = sw_bench_order_rule(h, e, steps, s->npoints, r.scale, SW_BENCH_CEILING, &fit);
    sw_bench_free(&r);
    return order;
}
static double controlled_orbit(void) { return controlled_slope("orbit", NULL, "rk45"); }
static double controlled_gyre(void) { return controlled_slope("gyre", NULL, "rk45"); }

static double above(void) { return SW_BENCH_ABOVE; }
static double stall(void) { return SW_BENCH_STALL; }
static double margin(void) { return SW_BENCH_MARGIN; }
static double span(void) { return SW_BENCH_MIN_SPAN; }
static double band_abs(void) { return SW_BENCH_BAND_ABS; }
static double band_rel(void) { return SW_BENCH_BAND_REL; }
static double min_fit(void) { return SW_BENCH_MIN_FIT; }

/* docs/performance.md's stability table: spring k = m = 1, c = 0 (ω = 1),
 * what `stepwise stability` measures, and the default spring's Euler limit. */
#define UNDAMPED "k=1 m=1 c=0"
static double st_se(void) { return cl_stability("spring", UNDAMPED, "symplectic-euler").dt; }
static double st_rk4(void) { return cl_stability("spring", UNDAMPED, "rk4").dt; }
static double st_verlet(void) { return cl_stability("spring", UNDAMPED, "verlet").dt; }
static double st_rk4_theory(void) { return 2 * sqrt(2.0); }
static double st_se_below(void) { return 100 * (1 - st_se() / 2); }
/* rk4 and verlet: the larger relative distance from 2√2 and 2, in % */
static double st_close(void) { return 100 * fmax(fabs(st_rk4() / (2 * sqrt(2.0)) - 1), fabs(st_verlet() / 2 - 1)); }
static double st_euler_damped(void) { return cl_stability("spring", NULL, "euler").dt; }
static double st_euler_formula(void) { return cl_param("spring", "c") / cl_param("spring", "k"); }
static double st_euler_k1(void) { return cl_param("spring", "c") / 1.0; }
static double two(void) { return 2; }
static double st_stretch(void) { return cl_param("spring", "stretch"); }
static double st_rest(void) { return cl_param("spring", "rest"); }

static double samples(void) { return SW_TRUTH_SAMPLES; }
static double work_key(void) { return SW_WORK_KEY; }
static double work_inline(void) { return SW_APP_WORK_INLINE; }
/* the bounce page's report time, which the message measures to */
static double bounce_report(void) { return sw_scene_find("bounce")->duration; }

const claim sw_claims_o[] = {
    { PERF, "SW_WORK_KEY ({1e8} state evaluations)", work_key, EXACT, 0, R_COUNT, NULL },
    { PERF, "`SW_APP_WORK_INLINE` ({1e6} state evaluations", work_inline, EXACT, 0, R_COUNT, NULL },
    { "docs/architecture.md", "`SW_APP_WORK_INLINE`, {1e6} state evaluations", work_inline, EXACT, 0, R_COUNT, NULL },
    { L4, "largest position error at {16} times spread to t = 3", samples, EXACT, 0, "SW_TRUTH_SAMPLES: the message's sample times", NULL },
    { L4, "largest position error at 16 times spread to t = {3}, at", bounce_report, EXACT, 0, "bounce's report time", NULL },
    { PERF, "| symplectic-euler | {1.8611} | 1.861 | 2 |", st_se, ROUNDED, 0, "what stability measures", NULL },
    { PERF, "| symplectic-euler | 1.8611 | {1.861} | 2 |", st_se, ROUNDED, 0, "ω·dt with ω = 1", NULL },
    { PERF, "| symplectic-euler | 1.8611 | 1.861 | {2} |", two, EXACT, 0, "|1 - h²ω²/2| <= 1 up to hω = 2", NULL },
    { PERF, "| rk4 | {2.8283} | 2.828 | 2.828 (2√2) |", st_rk4, ROUNDED, 0, "what stability measures", NULL },
    { PERF, "| rk4 | 2.8283 | {2.828} | 2.828 (2√2) |", st_rk4, ROUNDED, 0, "ω·dt with ω = 1", NULL },
    { PERF, "| rk4 | 2.8283 | 2.828 | {2.828} (2√2) |", st_rk4_theory, ROUNDED, 0, R_MATH, NULL },
    { PERF, "| verlet | {1.9982} | 1.998 | 2 |", st_verlet, ROUNDED, 0, "what stability measures", NULL },
    { PERF, "| verlet | 1.9982 | {1.998} | 2 |", st_verlet, ROUNDED, 0, "ω·dt with ω = 1", NULL },
    { PERF, "rk4 and verlet land within {0.1} % of 2√2 and 2", st_close, ATMOST, 0, "a bound on both", NULL },
    { PERF, "Symplectic Euler is found {7} % below its linear limit", st_se_below, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "h ≤ 2γ/ω0² = c/k = {0.05} (found", st_euler_formula, EXACT, 0, "c/k at the default spring", NULL },
    { PERF, "(found {0.049999}, tested)", st_euler_damped, ROUNDED, 0, "what stability measures on the default spring", NULL },
    { PERF, "at k = 1 the same formula gives {0.5}", st_euler_k1, EXACT, 0, "c/k with k = 1", NULL },
    { PERF, "read it as \"below 2, near {1.86}\"", st_se, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "the amplitude (stretch {0.5} against rest 1)", st_stretch, EXACT, 0, R_COUNT, NULL },
    { PERF, "the amplitude (stretch 0.5 against rest {1})", st_rest, EXACT, 0, R_COUNT, NULL },
    { PERF, "no finer point's error falls below {0.75} of", stall, EXACT, 0, "SW_BENCH_STALL", NULL },
    { PERF, "(a slope more than {0.3} above the method's", above, EXACT, 0, "SW_BENCH_ABOVE", NULL },
    { MAN, "local slopes agreeing, at most {0.3} above the", above, EXACT, 0, "SW_BENCH_ABOVE", NULL },
    { PERF, "accepted steps on the orbit grow {1.54}, 1.58, 1.59 times", growth_8, ROUNDED, 0, "steps at rtol 1e-9 over 1e-8", NULL },
    { PERF, "grow 1.54, {1.58}, 1.59 times", growth_9, ROUNDED, 0, "steps at rtol 1e-10 over 1e-9", NULL },
    { PERF, "grow 1.54, 1.58, {1.59} times", growth_10, ROUNDED, 0, "steps at rtol 1e-11 over 1e-10", NULL },
    { PERF, "it falls {10.6}, 11.3, 11.4 times", fall_8, ROUNDED, 0, "error at rtol 1e-8 over 1e-9", NULL },
    { PERF, "falls 10.6, {11.3}, 11.4 times", fall_9, ROUNDED, 0, "error at rtol 1e-9 over 1e-10", NULL },
    { PERF, "falls 10.6, 11.3, {11.4} times", fall_10, ROUNDED, 0, "error at rtol 1e-10 over 1e-11", NULL },
    { PERF, "10^(1/5) = {1.585} is the asymptote", fifth_root_10, ROUNDED, 0, R_MATH, NULL },
    { PERF, "reads {5.27} on the orbit and 5.41", controlled_orbit, ROUNDED, 0, "the rule on the controlled runs", NULL },
    { PERF, "5.27 on the orbit and {5.41}\non the gyre", controlled_gyre, ROUNDED, 0, "the rule on the controlled runs", NULL },
    { PERF, "on the orbit at e = 0.9 stall at {3.3e-10} to 8.9e-10", plateau_low, ROUNDED, 0, "rkn's smallest error on its plateau, default sweep", NULL },
    { PERF, "stall at 3.3e-10 to {8.9e-10},\nnot the", plateau_high, ROUNDED, 0, "rkn's largest error on its plateau: the series' floor", NULL },
    { PERF, "not the {4.1e-11} that", plateau_assumed, ROUNDED, 0, "the assumed floor at the plateau's first point", NULL },
    { PERF, "error at least {10} times the", margin, EXACT, 0, "SW_BENCH_MARGIN", NULL },
    { PERF, "at least {3} of them, errors", min_fit, EXACT, 0, "SW_BENCH_MIN_FIT", NULL },
    { PERF, "the steps spanning a factor {2}, the local slopes", span, EXACT, 0, "SW_BENCH_MIN_SPAN", NULL },
    { PERF, "within {0.15} + 0.03·order of each other", band_abs, EXACT, 0, "SW_BENCH_BAND_ABS", NULL },
    { PERF, "within 0.15 + {0.03}·order of each other", band_rel, EXACT, 0, "SW_BENCH_BAND_REL", NULL },
    { PERF, "until it reaches round-off ({1.3e-10}) before", cl_gyre_first_error, ROUNDED, 0, "rodas4's first error at round-off on the gyre", NULL },
    { PERF, "slopes agree ({2.84}\n  to 3.18 at", cl_gyre_slope_min, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "slopes agree (2.84\n  to {3.18} at", cl_gyre_slope_max, ROUNDED, 0, R_ROUND, NULL },
};
const size_t sw_claims_o_n = sizeof sw_claims_o / sizeof sw_claims_o[0];
