/* Claims about event location (docs/performance.md's events table, lesson
 * 4's page on contacts): each figure recomputed from runs against the
 * independent truths of events_truth.c. */
#include "claims.h"
#include "events_truth.h"

#define PERF "docs/performance.md"

/* The bounce the figures use: two balls, e = 0.85, drag 0.5/s, to T = 1.9
 * (several contacts, before any ball comes to rest); the spring through its
 * anchor: k = 4, rest 0.8, stretch 2, undamped, to T = 7.3. */
static const double bounce_p[] = { 2, 9.81, 0.85, 0.5 }, spring_p[] = { 4, 1, 0, 0.8, 2, 0 };
#define BOUNCE_T 1.9
#define SPRING_T 7.3

/* Located: the mean log2 ratio over dt, dt/2, dt/4 from the method's first dt. */
static double first_dt(const char *m, int spring)
{
    double dt = strcmp(m, "euler") == 0 ? 0.002 : strcmp(m, "rk4") == 0 ? 0.02 : 0.004;
    return spring && strcmp(m, "rk4") != 0 ? dt / 2 : dt;
}

static double located(const char *scene, const char *m)
{
    int spring = strcmp(scene, "spring") == 0;
    double truth[8], errs[3];
    if (spring)
        ev_spring_truth(spring_p, SPRING_T, truth);
    else
        ev_bounce_truth(bounce_p, BOUNCE_T, truth);
    return ev_observed_order(scene, spring ? spring_p : bounce_p, m, first_dt(m, spring), SW_EVENTS_LOCATE,
                             spring ? SPRING_T : BOUNCE_T, truth, errs);
}

static double stepped(const char *scene, const char *m)
{
    int spring = strcmp(scene, "spring") == 0;
    double truth[8];
    if (spring)
        ev_spring_truth(spring_p, SPRING_T, truth);
    else
        ev_bounce_truth(bounce_p, BOUNCE_T, truth);
    return ev_step_order(scene, spring ? spring_p : bounce_p, m, spring ? SPRING_T : BOUNCE_T, truth);
}

#define ORDERS(scene, m, id)                                                                                  \
    static double loc_##id(void) { return located(scene, m); }                                                \
    static double step_##id(void) { return stepped(scene, m); }
ORDERS("bounce", "euler", b_euler)
ORDERS("bounce", "midpoint", b_midpoint)
ORDERS("bounce", "heun", b_heun)
ORDERS("bounce", "rk4", b_rk4)
ORDERS("bounce", "verlet", b_verlet)
ORDERS("spring", "euler", s_euler)
ORDERS("spring", "midpoint", s_midpoint)
ORDERS("spring", "heun", s_heun)
ORDERS("spring", "rk4", s_rk4)
ORDERS("spring", "verlet", s_verlet)

/* The largest difference of a located contact time from the closed form's,
 * rk4 at dt = 0.001 on the bounce without drag (e = 0.85) to t = 2.5. */
static double contact_time_error(void)
{
    double p[] = { 2, 9.81, 0.85, 0 }, want[64], got[64];
    int nwant = 0, ngot = 0;
    sw_sim s;
    ev_sim_of(&s, "bounce", p, "rk4", 0.001, SW_EVENTS_LOCATE);
    const sw_walls *w = &s.sys.particles.walls;
    for (int i = 0; i < 2; i++) {
        double xo, vo, *y0 = s.sys.y;
        int nh = 16;
        ev_walls_at(y0[2 * i], y0[4 + 2 * i], w->xmin, w->xmax, p[2], 2.5, &xo, &vo, want + nwant, &nh);
        nwant += nh;
        nh = 16;
        ev_floor_at(y0[2 * i + 1], y0[5 + 2 * i], p[1], p[2], 2.5, &xo, &vo, want + nwant, &nh);
        nwant += nh;
    }
    long seen = 0;
    while (s.t < 2.5 - 1e-12 && ngot < 64) {
        sw_sim_step_until(&s, 2.5);
        if (sw_sim_events_located(&s) > seen)
            got[ngot++] = sw_sim_events_last_time(&s);
        seen = sw_sim_events_located(&s);
    }
    sw_sim_free(&s);
    double worst = ngot == nwant ? 0 : INFINITY;
    for (int i = 0; i < ngot && i < nwant; i++) {
        double best = INFINITY; /* the closed-form times, matched nearest first */
        for (int j = 0; j < nwant; j++)
            best = fmin(best, fabs(got[i] - want[j]));
        worst = fmax(worst, best);
    }
    return worst;
}

/* Stepped over: how many of the ten orders the rule refuses. */
static double step_refused(void)
{
    double (*const all[])(void) = { step_b_euler, step_b_midpoint, step_b_heun, step_b_rk4, step_b_verlet,
                                    step_s_euler, step_s_midpoint, step_s_heun, step_s_rk4, step_s_verlet };
    int n = 0;
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
        n += isnan(all[i]()) ? 1 : 0;
    return n;
}

/* rk4 on the spring through its anchor, stepped over, at dt = 0.005 and 0.0025. */
static double spring_rk4_error(double dt)
{
    double truth[8];
    ev_spring_truth(spring_p, SPRING_T, truth);
    return ev_run_error("spring", spring_p, "rk4", dt, SW_EVENTS_STEP, SPRING_T, truth);
}
static double step_s_rk4_e1(void) { return spring_rk4_error(0.005); }
static double step_s_rk4_e2(void) { return spring_rk4_error(0.0025); }
/* ... and the least-squares slope through its six errors (dt 0.01 halved five times). */
static double step_s_rk4_ls(void)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int j = 0; j < 6; j++) {
        double x = -j, y = log2(spring_rk4_error(0.01 / (1 << j)));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (6 * sxy - sx * sy) / (6 * sxx - sx * sx);
}

const claim sw_claims_e[] = {
    { PERF, "| bounce | step | no order | {1.17}", step_b_midpoint, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | step | no order | 1.17 | {1.17}", step_b_heun, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | step | no order | 1.17 | 1.17 | {1.17}", step_b_rk4, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | step | no order | 1.17 | 1.17 | 1.17 | {1.17}", step_b_verlet, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "it refuses {6} of the 10 orders", step_refused, EXACT, 0, "bounce's Euler and the spring's five: with the four 1.17 rows, every 'no order' cell", NULL },
    { PERF, "its error rises from {4.03e-3} to 7.10e-3", step_s_rk4_e1, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "its error rises from 4.03e-3 to {7.10e-3}", step_s_rk4_e2, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "table printed {0.81} for it", step_s_rk4_ls, ROUNDED, 0, "the least-squares slope through all six points, the old rule", NULL },
    { PERF, "| bounce | locate | {1.00}", loc_b_euler, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | locate | 1.00 | {2.00}", loc_b_midpoint, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | locate | 1.00 | 2.00 | {2.00}", loc_b_heun, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | locate | 1.00 | 2.00 | 2.00 | {3.99}", loc_b_rk4, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| bounce | locate | 1.00 | 2.00 | 2.00 | 3.99 | {2.00}", loc_b_verlet, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| spring | locate | {1.00}", loc_s_euler, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| spring | locate | 1.00 | {2.00}", loc_s_midpoint, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| spring | locate | 1.00 | 2.00 | {2.00}", loc_s_heun, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| spring | locate | 1.00 | 2.00 | 2.00 | {4.03}", loc_s_rk4, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "| spring | locate | 1.00 | 2.00 | 2.00 | 4.03 | {2.00}", loc_s_verlet, ROUNDED, 0, R_ROUND, NULL },
    { L4, "Euler {1.00}", loc_b_euler, ROUNDED, 0, R_ROUND, NULL },
    { L4, "midpoint {2.00}", loc_b_midpoint, ROUNDED, 0, R_ROUND, NULL },
    { L4, "Heun {2.00}", loc_b_heun, ROUNDED, 0, R_ROUND, NULL },
    { L4, "Verlet {2.00}", loc_b_verlet, ROUNDED, 0, R_ROUND, NULL },
    { L4, "RK4 {3.99}", loc_b_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L4, "the same contacts leave RK4 at {1.17}", step_b_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L4, "crossing gives RK4 {4.03}", loc_s_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L4, "(it rises from {4.03e-3} to 7.10e-3", step_s_rk4_e1, ROUNDED, 0, R_ROUND, NULL },
    { L4, "(it rises from 4.03e-3 to {7.10e-3}", step_s_rk4_e2, ROUNDED, 0, R_ROUND, NULL },
    { PERF, "located contact times agree with the quadratic's roots within {1e-12}", contact_time_error, ATMOST, 0, "a bound: every located time within it", NULL },
};
const size_t sw_claims_e_n = sizeof sw_claims_e / sizeof sw_claims_e[0];
