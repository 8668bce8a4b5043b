/* Integrators against theory: measured orders, Euler's energy growth,
 * stability limits, backward Euler as an exact linear solve, rk45's error
 * control, and determinism. Every expected value is computed here from the
 * closed form, not taken from the code under test. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/particles.h"
#include "stepwise/flow.h"
#include "stepwise/sim.h"
#include "engine/mistakes.h"
#include "engine/stepper.h"
#include "sim/truth.h"
#include "alloc_count.h"

/* x'' = -(k/m) x - (c/m) x' as one particle on a zero-rest-length spring to
 * the origin, started at (1, 0) at rest; the motion stays on the x axis. */
static void oscillator(sw_particles *p, double k, double c)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_particles_init(p, 1, 1.0, err, sizeof err), SW_OK);
    sw_spring *s = sw_particles_add_springs(p, 1);
    ck_assert_ptr_nonnull(s);
    *s = (sw_spring){ .a = 0, .b = -1, .k = k, .c = c, .rest = 0.0 };
    p->y[0] = 1.0;
}

/* Closed form for m = 1, under-damped: x = e^{-γt}(cos ωd t + γ/ωd sin ωd t). */
static void oscillator_exact(double k, double c, double t, double *x, double *v)
{
    double g = c / 2, wd = sqrt(k - g * g), e = exp(-g * t);
    *x = e * (cos(wd * t) + g / wd * sin(wd * t));
    *v = -e * (wd + g * g / wd) * sin(wd * t);
}

/* Largest state error at t = 10 after stepping with h. */
static double error_at_10(const char *method, double k, double c, double h)
{
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    oscillator(&p, k, c);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &p.ode, err, sizeof err), SW_OK);
    long n = lround(10.0 / h);
    double t = 0;
    for (long i = 0; i < n; i++)
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, h), SW_OK);
    double x, v;
    oscillator_exact(k, c, t, &x, &v);
    double e = fmax(fmax(fabs(p.y[0] - x), fabs(p.y[2] - v)), fmax(fabs(p.y[1]), fabs(p.y[3])));
    sw_stepper_free(&s);
    sw_particles_free(&p);
    return e;
}

static const struct { const char *name; int order; double h; } fixed[] = {
    { "euler", 1, 0.002 },          { "symplectic-euler", 1, 0.002 },
    { "midpoint", 2, 0.01 },        { "heun", 2, 0.01 },
    { "rk4", 4, 0.05 },             { "verlet", 2, 0.01 },
    { "implicit-euler", 1, 0.002 }, { "implicit-midpoint", 2, 0.01 },
};

/* Observed order: least-squares slope of log e against log h over h, h/2, h/4.
 * Theory within ±0.2; the step sizes are chosen in each method's asymptotic
 * range (errors between about 1e-2 and 1e-9, far above round-off). */
static void check_orders(double c)
{
    for (size_t m = 0; m < sizeof fixed / sizeof fixed[0]; m++) {
        double lx[3], ly[3], sx = 0, sy = 0;
        for (int j = 0; j < 3; j++) {
            double h = fixed[m].h / (1 << j);
            lx[j] = log(h);
            ly[j] = log(error_at_10(fixed[m].name, 1.0, c, h));
            sx += lx[j];
            sy += ly[j];
        }
        double num = 0, den = 0;
        for (int j = 0; j < 3; j++) {
            num += (lx[j] - sx / 3) * (ly[j] - sy / 3);
            den += (lx[j] - sx / 3) * (lx[j] - sx / 3);
        }
        double order = num / den;
        ck_assert_msg(fabs(order - fixed[m].order) <= 0.2, "%s (c = %g): observed order %.3f, theory %d",
                      fixed[m].name, c, order, fixed[m].order);
    }
}

START_TEST(orders_undamped) { check_orders(0.0); }
END_TEST

START_TEST(orders_damped) { check_orders(0.5); }
END_TEST

/* Explicit Euler maps (x, v) to (x + h v, v - h x): energy grows by exactly
 * (1 + h²) per step, so after 1000 steps by (1 + h²)^1000. 1e-12 relative
 * leaves room for ~1000 steps of round-off at 1e-16. */
START_TEST(euler_energy_growth)
{
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    oscillator(&p, 1.0, 0.0);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("euler"), &p.ode, err, sizeof err), SW_OK);
    double h = 0.01, t = 0, e0 = sw_particles_energy(&p, p.y);
    for (int i = 0; i < 1000; i++)
        sw_stepper_step(&s, &p.ode, &t, p.y, h);
    double ratio = sw_particles_energy(&p, p.y) / e0, expect = pow(1 + h * h, 1000);
    ck_assert_msg(fabs(ratio / expect - 1) < 1e-12, "ratio %.17g, expected %.17g", ratio, expect);
    sw_stepper_free(&s);
    sw_particles_free(&p);
}
END_TEST

/* Run x'' = -ω²x (ω = 1) at ω h for steps steps through a sim-like loop;
 * returns final energy / initial energy, or INFINITY when the state ran away
 * or went non-finite. */
static double energy_ratio(const char *method, double wh, int steps)
{
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    oscillator(&p, 1.0, 0.0);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find(method), &p.ode, err, sizeof err), SW_OK);
    double t = 0, e0 = sw_particles_energy(&p, p.y), r = 0;
    for (int i = 0; i < steps; i++) {
        if (sw_stepper_step(&s, &p.ode, &t, p.y, wh) != SW_OK || !(fabs(p.y[0]) < 1e100)) {
            r = INFINITY;
            break;
        }
    }
    if (r == 0)
        r = sw_particles_energy(&p, p.y) / e0;
    sw_stepper_free(&s);
    sw_particles_free(&p);
    return r;
}

/* Symplectic Euler and Verlet: stable for ωh < 2 (the trace of the one-step
 * matrix, 2 - (ωh)², leaves [-2, 2] beyond). Bounded means the energy stays
 * within a modest factor (the shadow energy oscillates but is bounded). */
START_TEST(stability_symplectic)
{
    const char *names[] = { "symplectic-euler", "verlet" };
    for (int i = 0; i < 2; i++) {
        double in = energy_ratio(names[i], 1.99, 10000), out = energy_ratio(names[i], 2.01, 10000);
        ck_assert_msg(in < 1e3, "%s at wh = 1.99: energy ratio %g", names[i], in);
        ck_assert_msg(out > 1e12, "%s at wh = 2.01: energy ratio %g, expected a blow-up", names[i], out);
    }
}
END_TEST

/* The spectral radius of one step of method m on x'' = -x with step h: the
 * one-step matrix read off by stepping the unit states (a spring anchored 10
 * to the left at rest length 10 pulls with exactly -x along x). */
static double step_radius(const char *method, double h)
{
    sw_particles p;
    sw_stepper st;
    char err[SW_ERRLEN];
    double m[2][2];
    ck_assert_int_eq(sw_particles_init(&p, 1, 1.0, err, sizeof err), SW_OK);
    sw_spring *sp = sw_particles_add_springs(&p, 1);
    ck_assert_ptr_nonnull(sp);
    *sp = (sw_spring){ .a = 0, .b = -1, .k = 1.0, .rest = 10.0, .ax = -10.0 };
    ck_assert_int_eq(sw_stepper_init(&st, sw_integrator_find(method), &p.ode, err, sizeof err), SW_OK);
    for (int col = 0; col < 2; col++) {
        double t = 0;
        memset(p.y, 0, 4 * sizeof *p.y);
        p.y[col ? 2 : 0] = 1e-3;
        sw_stepper_touch(&st);
        ck_assert_int_eq(sw_stepper_step(&st, &p.ode, &t, p.y, h), SW_OK);
        m[0][col] = p.y[0] / 1e-3;
        m[1][col] = p.y[2] / 1e-3;
    }
    sw_stepper_free(&st);
    sw_particles_free(&p);
    double tr = m[0][0] + m[1][1], det = m[0][0] * m[1][1] - m[0][1] * m[1][0], disc = tr * tr / 4 - det;
    return disc >= 0 ? fabs(tr / 2) + sqrt(disc) : sqrt(fabs(det));
}

/* RK4's amplification factor on the imaginary axis, |R(iωh)| with
 * R(z) = 1 + z + z²/2 + z³/6 + z⁴/24, crosses 1 at ωh = 2√2 ≈ 2.828: at 2.82
 * it is 0.979, at 2.84 it is 1.029. The rk4 step itself must have that
 * factor (to 1e-9: the spring's offset of 10 costs about 1e-12 relative). */
START_TEST(stability_rk4)
{
    for (int k = 0; k < 2; k++) {
        double w = k ? 2.84 : 2.82, re = 1 - w * w / 2 + w * w * w * w / 24, im = w - w * w * w / 6;
        double theory = sqrt(re * re + im * im), amp = step_radius("rk4", w);
        ck_assert_double_eq_tol(amp, theory, 1e-9);
        ck_assert_msg(k ? amp > 1 : amp < 1, "rk4 at wh = %g: |R| = %.6f", w, amp);
    }
    ck_assert_double_lt(energy_ratio("rk4", 2.82, 10000), 1.0);
    double grow = energy_ratio("rk4", 2.84, 1000);
    ck_assert_msg(grow > 1e20, "rk4 at wh = 2.84 over 1000 steps: energy ratio %g, expected growth ~1.03^2000", grow);
}
END_TEST

/* Backward Euler damps at any step: at ωh = 100 the energy must fall. */
START_TEST(stability_implicit_euler)
{
    double r = energy_ratio("implicit-euler", 100.0, 1000);
    ck_assert_msg(r < 1e-6, "implicit-euler at wh = 100: energy ratio %g", r);
}
END_TEST

/* Backward Euler keeps damping a decayed motion without a false failure:
 * on the spring (k = m = 1, undamped, dt = 0.5) the velocity falls by
 * 1/sqrt(1.25) per step, below 1e-160 by step 1700, where the linear
 * solve's unscaled residual norms used to underflow and stop the run. */
START_TEST(implicit_euler_tiny_state)
{
    sw_sim s;
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("spring");
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(sc, p);
    p[sw_scene_param_index(sc, "k")] = 1.0;
    p[sw_scene_param_index(sc, "c")] = 0.0;
    ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find("implicit-euler"), 0.5, err, sizeof err), SW_OK);
    for (int i = 0; i < 2500; i++)
        ck_assert_msg(sw_sim_step(&s) == 0, "step %d: %s", i + 1, s.blow_reason);
    ck_assert_double_lt(fabs(s.sys.y[2]), 1e-200);
    sw_sim_free(&s);
}
END_TEST

/* Implicit midpoint is the Cayley transform on a linear oscillator: it keeps
 * the quadratic energy exactly, so only solver round-off remains. */
START_TEST(implicit_midpoint_conserves)
{
    double r = energy_ratio("implicit-midpoint", 10.0, 1000);
    ck_assert_msg(fabs(r - 1) < 1e-10, "implicit-midpoint at wh = 10: energy ratio - 1 = %g", r - 1);
}
END_TEST

/* One backward Euler step on the linear damped spring, against the 2x2 solve
 * [x1; v1] = (I - hA)^{-1} [x0; v0], A = [[0, 1], [-k, -c]], done by Cramer's rule. */
START_TEST(backward_euler_exact_linear)
{
    double k = 7.0, c = 0.3, h = 0.37;
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    oscillator(&p, k, c);
    p.y[2] = 0.25;
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("implicit-euler"), &p.ode, err, sizeof err), SW_OK);
    double t = 0;
    for (int step = 0; step < 5; step++) {
        double x0 = p.y[0], v0 = p.y[2];
        /* (I - hA) = [[1, -h], [h k, 1 + h c]] */
        double a = 1, b = -h, cc = h * k, d = 1 + h * c, det = a * d - b * cc;
        double x1 = (d * x0 - b * v0) / det, v1 = (a * v0 - cc * x0) / det;
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, h), SW_OK);
        ck_assert_double_eq_tol(p.y[0], x1, 1e-14 * fmax(1, fabs(x1)));
        ck_assert_double_eq_tol(p.y[2], v1, 1e-14 * fmax(1, fabs(v1)));
    }
    sw_stepper_free(&s);
    sw_particles_free(&p);
}
END_TEST

/* rk45 on the damped oscillator: the global error at t = 10 stays within a
 * small multiple of the requested tolerance, tightening rtol by 1000 shrinks
 * it, and a too-large first step is rejected and counted. */
static double rk45_error(double rtol, long *acc, long *rej)
{
    sw_particles p;
    sw_stepper s;
    char err[SW_ERRLEN];
    oscillator(&p, 4.0, 0.4);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("rk45"), &p.ode, err, sizeof err), SW_OK);
    s.rtol = rtol;
    s.atol = rtol * 1e-3;
    double t = 0;
    while (10.0 - t > 1e-12)
        ck_assert_int_eq(sw_stepper_step(&s, &p.ode, &t, p.y, fmin(2.0, 10.0 - t)), SW_OK);
    double x, v;
    oscillator_exact(4.0, 0.4, t, &x, &v);
    *acc = s.accepted;
    *rej = s.rejected;
    double e = fmax(fabs(p.y[0] - x), fabs(p.y[2] - v));
    sw_stepper_free(&s);
    sw_particles_free(&p);
    return e;
}

START_TEST(rk45_tolerance)
{
    long acc, rej, acc2, rej2;
    double e6 = rk45_error(1e-6, &acc, &rej), e9 = rk45_error(1e-9, &acc2, &rej2);
    ck_assert_msg(e6 < 1e-5, "rtol 1e-6: error %g", e6);
    ck_assert_msg(e9 < 1e-8, "rtol 1e-9: error %g", e9);
    ck_assert_msg(e9 < e6 / 20, "tighter tolerance did not help: %g vs %g", e9, e6);
    ck_assert_int_gt(acc, 10);
    ck_assert_int_gt(rej, 0); /* the first trial step of 2 s is far too large */
    ck_assert_int_gt(acc2, acc);
}
END_TEST

/* Methods that update x and v separately refuse a flow field. */
static void unit_field(const void *par, double t, int n, const double *x, double *v)
{
    (void)par;
    (void)t;
    for (int i = 0; i < 2 * n; i++)
        v[i] = x[i];
}

/* x' = λ(t)·x, λ(t) = -(1 + t), with its Jacobian: linear in x, changing in t. */
static void timed_field(const void *par, double t, int n, const double *x, double *v)
{
    (void)par;
    for (int i = 0; i < 2 * n; i++)
        v[i] = -(1 + t) * x[i];
}

static void timed_jac(const void *par, double t, int n, const double *x, double *jac)
{
    (void)par;
    (void)x;
    for (int i = 0; i < n; i++) {
        jac[4 * i] = jac[4 * i + 3] = -(1 + t);
        jac[4 * i + 1] = jac[4 * i + 2] = 0;
    }
}

/* Issue 24: linearly implicit Euler is one Newton step of backward Euler,
 * so f and J are taken at the same time, the step's end t1; on a field
 * linear in x it is backward Euler exactly: x1 = x0 / (1 - h·λ(t1)), for a
 * λ that changes with time (the gyre's kind of field). Taking f at t0 and
 * J at t1, as it once did, misses this by O(h²) per step. */
START_TEST(linear_implicit_euler_one_time)
{
    sw_flow f;
    sw_stepper s;
    char err[SW_ERRLEN] = "";
    ck_assert_int_eq(sw_flow_init(&f, 1, timed_field, timed_jac, NULL, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("linear-implicit-euler"), &f.ode, err, sizeof err),
                     SW_OK);
    f.y[0] = 1.0;
    f.y[1] = -0.5;
    double t = 0, h = 0.25, x[2] = { 1.0, -0.5 };
    for (int step = 0; step < 8; step++) {
        double lambda1 = -(1 + t + h);
        for (int i = 0; i < 2; i++)
            x[i] /= 1 - h * lambda1;
        ck_assert_int_eq(sw_stepper_step(&s, &f.ode, &t, f.y, h), SW_OK);
        for (int i = 0; i < 2; i++) /* a division and a solve: a few roundings */
            ck_assert_double_eq_tol(f.y[i], x[i], 1e-14 * fabs(x[i]));
    }
    sw_stepper_free(&s);
    sw_flow_free(&f);
}
END_TEST

START_TEST(second_order_refused)
{
    sw_flow f;
    sw_stepper s;
    char err[SW_ERRLEN] = "";
    ck_assert_int_eq(sw_flow_init(&f, 3, unit_field, NULL, NULL, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("verlet"), &f.ode, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "first-order"));
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("symplectic-euler"), &f.ode, err, sizeof err), SW_EINVAL);
    /* implicit methods work on flows through the per-point 2x2 solve:
     * x' = x, one backward Euler step gives x / (1 - h). */
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("implicit-euler"), &f.ode, err, sizeof err), SW_OK);
    f.y[0] = 1.0;
    double t = 0;
    ck_assert_int_eq(sw_stepper_step(&s, &f.ode, &t, f.y, 0.1), SW_OK);
    ck_assert_double_eq_tol(f.y[0], 1.0 / 0.9, 1e-6); /* finite-difference Jacobian: ~1e-7 relative */
    sw_stepper_free(&s);
    sw_flow_free(&f);
}
END_TEST

/* The dense finite-difference fallback (no solve callback) gives the same
 * backward Euler step as the analytic solve, to finite-difference accuracy. */
START_TEST(dense_fallback)
{
    sw_particles a, b;
    sw_stepper sa, sb;
    char err[SW_ERRLEN];
    oscillator(&a, 5.0, 0.2);
    oscillator(&b, 5.0, 0.2);
    b.ode.solve = NULL;
    ck_assert_int_eq(sw_stepper_init(&sa, sw_integrator_find("implicit-euler"), &a.ode, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_stepper_init(&sb, sw_integrator_find("implicit-euler"), &b.ode, err, sizeof err), SW_OK);
    ck_assert_ptr_nonnull(sb.dense);
    double ta = 0, tb = 0;
    for (int i = 0; i < 10; i++) {
        sw_stepper_step(&sa, &a.ode, &ta, a.y, 0.1);
        sw_stepper_step(&sb, &b.ode, &tb, b.y, 0.1);
    }
    for (int i = 0; i < 4; i++)
        ck_assert_double_eq_tol(a.y[i], b.y[i], 1e-6);
    sw_stepper_free(&sa);
    sw_stepper_free(&sb);
    sw_particles_free(&a);
    sw_particles_free(&b);
}
END_TEST

/* Steps allocate nothing: counted through the linker's --wrap. */
START_TEST(steps_do_not_allocate)
{
    for (int m = 0; m < sw_integrator_count(); m++) {
        const sw_integrator *method = sw_integrator_at(m);
        if (method->flags & SW_PLUGIN)
            continue;
        sw_particles p;
        sw_stepper s;
        char err[SW_ERRLEN];
        oscillator(&p, 3.0, 0.1);
        if (sw_integrator_accepts(method, &p.ode, err, sizeof err) != SW_OK) { /* rkn: no damping */
            sw_particles_free(&p);
            oscillator(&p, 3.0, 0.0);
        }
        if (sw_integrator_accepts(method, &p.ode, err, sizeof err) != SW_OK) { /* dop853-lc: one body */
            sw_particles_free(&p);
            ck_assert_int_eq(sw_particles_init(&p, 1, 1.0, err, sizeof err), SW_OK);
            ck_assert_int_eq(sw_particles_add_central(&p, 0.0, 0.0, 1.0), SW_OK);
            p.y[0] = 0.5, p.y[3] = 1.5;
        }
        ck_assert_int_eq(sw_stepper_init(&s, method, &p.ode, err, sizeof err), SW_OK);
        double t = 0;
        long before = sw_test_allocations();
        for (int i = 0; i < 200; i++)
            sw_stepper_step(&s, &p.ode, &t, p.y, 0.01);
        ck_assert_msg(sw_test_allocations() == before, "%s allocated in its step", method->name);
        sw_stepper_free(&s);
        sw_particles_free(&p);
    }
}
END_TEST

/* FNV-1a over the bytes of a state. */
static uint64_t fnv1a(const double *y, int n)
{
    const unsigned char *b = (const unsigned char *)y;
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < (size_t)n * sizeof *y; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t scene_hash(const char *scene, const char *method, int steps)
{
    sw_sim s;
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find(scene);
    ck_assert_int_eq(sw_sim_init(&s, sc, NULL, sw_integrator_find(method), sc->dt, err, sizeof err), SW_OK);
    for (int i = 0; i < steps; i++)
        sw_sim_step(&s);
    uint64_t h = fnv1a(s.sys.y, s.sys.ode->dim);
    sw_sim_free(&s);
    return h;
}

/* Determinism: the same settings give the same bits, run after run. The
 * spring under euler uses only +, -, *, / and sqrt (correctly rounded in
 * IEEE 754), so its hash is pinned across builds; other scenes (which call
 * libm's sin, cos, exp) are compared between two fresh runs. */
START_TEST(determinism)
{
    const char *pairs[][2] = { { "chain", "implicit-euler" }, { "orbit", "rk45" }, { "gyre", "rk4" },
                               { "bounce", "verlet" }, { "fireworks", "symplectic-euler" } };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        ck_assert_msg(scene_hash(pairs[i][0], pairs[i][1], 500) == scene_hash(pairs[i][0], pairs[i][1], 500),
                      "%s under %s differs between two runs", pairs[i][0], pairs[i][1]);
    uint64_t h = scene_hash("spring", "euler", 1000);
    ck_assert_msg(h == UINT64_C(0x095f00958ddb901f), "spring/euler hash %llx changed", (unsigned long long)h);
}
END_TEST

/* Issue 24: "stable runs of backward Euler only lose energy" is not so on
 * a non-convex potential. Backward Euler's energy change is
 * E1 - E0 = -½|v1 - v0|² - ½ Δxᵀ ∇²V(ξ) Δx for some ξ on the step, which
 * is positive where the potential curves down along the step: a pendulum
 * on a spring held above its anchor, the spring compressed by gravity.
 * The test solves backward Euler itself (Newton on x1 = x0 + h v0 +
 * h² a(x1), analytic Jacobian, to rounding) from the scene's documented
 * start (docs/scenes.md, 'stiff-spring'), checks stepwise's implicit-euler
 * energies against it to 1e-9 relative (both solve to rounding; the
 * difference is the order of operations), and that some step gains
 * energy by more than 1e-6 J (a million times what rounding moves it). */
static double spring_energy(double k, double rest, double g, const double *x, const double *v)
{
    double d = hypot(x[0], x[1]) - rest;
    return 0.5 * (v[0] * v[0] + v[1] * v[1]) + 0.5 * k * d * d + g * x[1];
}

static void spring_accel(double k, double rest, double g, const double *x, double *a, double jac[2][2])
{
    double r = hypot(x[0], x[1]), u[2] = { x[0] / r, x[1] / r }, f = -k * (r - rest);
    a[0] = f * u[0];
    a[1] = f * u[1] - g;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            jac[i][j] = -k * u[i] * u[j] + f / r * ((i == j) - u[i] * u[j]);
}

START_TEST(backward_euler_gains_on_compressed_spring)
{
    static const struct { double k, angle, dt; } cases[] = { { 100, 160, 1 }, { 400, 170, 0.5 } };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double k = cases[c].k, rest = 1, g = 9.81, m = 1, h = cases[c].dt;
        double alpha = cases[c].angle * M_PI / 180, len = rest + m * g / k;
        double x[2] = { len * sin(alpha), -len * cos(alpha) }, v[2] = { 0, 0 };
        char err[SW_ERRLEN], set[64];
        const sw_scene *sc = sw_scene_find("stiff-spring");
        double p[SW_MAX_PARAMS];
        sw_scene_defaults(sc, p);
        snprintf(set, sizeof set, "k=%.17g", k);
        ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
        snprintf(set, sizeof set, "angle=%.17g", cases[c].angle);
        ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
        sw_sim s;
        ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find("implicit-euler"), h, err, sizeof err), SW_OK);
        double gain = 0, e_prev = spring_energy(k, rest, g, x, v);
        for (int step = 1; step <= 8; step++) {
            double x1[2] = { x[0], x[1] }; /* from the start, as stepwise's Newton */
            for (int it = 0; it < 100; it++) { /* G(x1) = x1 - x0 - h v0 - h² a(x1) */
                double a[2], jac[2][2];
                spring_accel(k, rest, g, x1, a, jac);
                double gv[2] = { x1[0] - x[0] - h * v[0] - h * h * a[0], x1[1] - x[1] - h * v[1] - h * h * a[1] };
                double m00 = 1 - h * h * jac[0][0], m01 = -h * h * jac[0][1];
                double m10 = -h * h * jac[1][0], m11 = 1 - h * h * jac[1][1], det = m00 * m11 - m01 * m10;
                double dx = -(m11 * gv[0] - m01 * gv[1]) / det, dy = -(m00 * gv[1] - m10 * gv[0]) / det;
                x1[0] += dx;
                x1[1] += dy;
                if (fabs(dx) + fabs(dy) <= 1e-15 * (fabs(x1[0]) + fabs(x1[1])))
                    break;
            }
            v[0] = (x1[0] - x[0]) / h;
            v[1] = (x1[1] - x[1]) / h;
            x[0] = x1[0];
            x[1] = x1[1];
            double e = spring_energy(k, rest, g, x, v);
            ck_assert_int_eq(sw_sim_step(&s), 0);
            double ours = sw_sim_energy(&s);
            ck_assert_msg(fabs(ours - e) <= 1e-9 * fabs(e), "k=%g angle=%g step %d: stepwise %.17g, "
                          "independent %.17g", k, cases[c].angle, step, ours, e);
            gain = fmax(gain, e - e_prev);
            e_prev = e;
            if (gain > 1e-6)
                break; /* shown; later steps may take another root of the implicit equation */
        }
        ck_assert_msg(gain > 1e-6, "k=%g angle=%g dt=%g: backward Euler never gained energy (largest "
                      "step change %g J)", k, cases[c].angle, h, gain);
        sw_sim_free(&s);
    }
}
END_TEST

/* What the rest of the tool reads from the rows, checked whole: one
 * reference for the truth module (adaptive, and able to step any scene:
 * flows too), one method that finds a resting state (implicit: it takes
 * SW_DT_MAX steps), compare's partners ranked 1, 2, ... with no rank
 * twice, twins that name each other with a question each, and mistake
 * lists whose every entry can step what its method steps. */
START_TEST(rows_hold_what_the_tool_reads)
{
    int refs = 0, rests = 0, ranks[64] = { 0 }, top = 0, n = sw_integrator_count();
    ck_assert_int_le(n, 64);
    for (int i = 0; i < n; i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (m->reference) {
            refs++;
            ck_assert_msg((m->flags & SW_ADAPTIVE) && !(m->flags & SW_NEEDS_SECOND_ORDER), "%s", m->name);
            ck_assert_ptr_eq(sw_truth_reference_method(), m);
        }
        if (m->resting) {
            rests++;
            ck_assert_msg(m->flags & SW_IMPLICIT, "%s", m->name);
        }
        ck_assert_int_ge(m->compare, 0);
        ck_assert_int_lt(m->compare, 64);
        if (m->compare) {
            ck_assert_msg(!ranks[m->compare]++, "compare rank %d twice", m->compare);
            top = m->compare > top ? m->compare : top;
        }
        if (m->twin) {
            const sw_integrator *t = sw_integrator_find(m->twin);
            ck_assert_msg(t && t != m && t->twin && !strcmp(t->twin, m->name) && m->twin_hint, "%s", m->name);
        }
        for (const sw_mistake *mk = m->mistakes; mk && mk->kind; mk++) {
            ck_assert_msg(mk->hint && mk->method.step && mk->method.work_vectors > 0, "%s: %s", m->name, mk->kind);
            ck_assert_msg((mk->method.flags & SW_NEEDS_SECOND_ORDER) == (m->flags & SW_NEEDS_SECOND_ORDER),
                          "%s: %s", m->name, mk->method.name);
        }
    }
    ck_assert_int_eq(refs, 1);
    ck_assert_int_eq(rests, 1);
    ck_assert_int_ge(top, 2); /* compare needs two partners */
    for (int r = 1; r <= top; r++)
        ck_assert_msg(ranks[r] == 1, "compare rank %d missing", r);
}
END_TEST

Suite *make_integrators_suite(void);
Suite *make_integrators_suite(void)
{
    Suite *s = suite_create("integrators");
    TCase *tc = tcase_create("theory");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, orders_undamped);
    tcase_add_test(tc, orders_damped);
    tcase_add_test(tc, euler_energy_growth);
    tcase_add_test(tc, stability_symplectic);
    tcase_add_test(tc, stability_rk4);
    tcase_add_test(tc, stability_implicit_euler);
    tcase_add_test(tc, implicit_euler_tiny_state);
    tcase_add_test(tc, implicit_midpoint_conserves);
    tcase_add_test(tc, backward_euler_exact_linear);
    tcase_add_test(tc, backward_euler_gains_on_compressed_spring);
    tcase_add_test(tc, rk45_tolerance);
    tcase_add_test(tc, second_order_refused);
    tcase_add_test(tc, linear_implicit_euler_one_time);
    tcase_add_test(tc, dense_fallback);
    tcase_add_test(tc, steps_do_not_allocate);
    tcase_add_test(tc, determinism);
    tcase_add_test(tc, rows_hold_what_the_tool_reads);
    suite_add_tcase(s, tc);
    return s;
}
