/* rodas4, Hairer's Rosenbrock 4(3), against theory: the order conditions of
 * its tableau in long double after mapping Hairer's transformed
 * coefficients back to the standard form, its stability function (order 4,
 * A- and L-stable) from the coefficients, its observed order on closed-form
 * problems (linear, nonlinear, non-autonomous), its step control on the
 * stiff spring, the banded chain and a flow, and a clean refusal where it
 * cannot run. No expected value is read from the code under test. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/sim.h"
#include "engine/rodas_tableau.h"
#include "engine/stepper.h"

#define S SW_RODAS_STAGES

/* The standard form (Hairer & Wanner II, IV.7): stage i is
 * (I - γh J) k_i = h f(y0 + Σ α_ij k_j) + h J Σ γ_ij k_j, y1 = y0 + Σ b_j k_j.
 * Hairer's variables u_i = Σ_j Γ_ij k_j (Γ lower, diagonal γ) give
 * A = α Γ⁻¹, C = diag(1/γ) - Γ⁻¹, m = b Γ⁻¹; so Γ⁻¹ = diag(1/γ) - C,
 * α = A Γ and b = m Γ. */
static void standard_form(long double gam[S][S], long double alpha[S][S], long double b[S],
                          long double bhat[S])
{
    long double ginv[S][S] = { { 0 } };
    for (int i = 0; i < S; i++)
        for (int j = 0; j <= i; j++)
            ginv[i][j] = i == j ? 1.0L / SW_RODAS_GAMMA : -(long double)SW_RODAS_C[i][j];
    /* Γ = (Γ⁻¹)⁻¹ by forward substitution, column by column. */
    for (int c = 0; c < S; c++)
        for (int i = 0; i < S; i++) {
            long double sum = i == c ? 1.0L : 0.0L;
            for (int j = 0; j < i; j++)
                sum -= ginv[i][j] * gam[j][c];
            gam[i][c] = sum / ginv[i][i];
        }
    for (int i = 0; i < S; i++)
        for (int j = 0; j < S; j++) {
            long double sum = 0;
            for (int k = 0; k < i; k++)
                sum += (long double)SW_RODAS_A[i][k] * gam[k][j];
            alpha[i][j] = sum;
        }
    for (int j = 0; j < S; j++) {
        long double sb = 0, sh = 0;
        for (int i = 0; i < S; i++) {
            long double mh = SW_RODAS_M[i] - (i == S - 1 ? 1.0L : 0.0L); /* embedded: y1 - k_6 */
            sb += SW_RODAS_M[i] * gam[i][j];
            sh += mh * gam[i][j];
        }
        b[j] = sb;
        bhat[j] = sh;
    }
}

/* The Rosenbrock order conditions (Hairer & Wanner II, Table IV.7.1), with
 * β_jk = α_jk + γ_jk for k < j and β'_j = Σ_k β_jk: residuals of the
 * conditions up to order p (1, 2, 4 or 8 of them) into res. */
static int conditions(long double gam[S][S], long double alpha[S][S], const long double *b,
                      int p, long double *res)
{
    long double beta[S][S] = { { 0 } }, bp[S] = { 0 }, ai[S] = { 0 };
    long double g = SW_RODAS_GAMMA;
    for (int j = 0; j < S; j++)
        for (int k = 0; k < j; k++) {
            beta[j][k] = alpha[j][k] + gam[j][k];
            bp[j] += beta[j][k];
            ai[j] += alpha[j][k];
        }
    long double s1 = 0, s2 = 0, s3a = 0, s3b = 0, s4a = 0, s4b = 0, s4c = 0, s4d = 0;
    for (int j = 0; j < S; j++) {
        long double bb = 0, ba2 = 0, bbb = 0, aab = 0;
        for (int k = 0; k < j; k++) {
            bb += beta[j][k] * bp[k];
            ba2 += beta[j][k] * ai[k] * ai[k];
            aab += alpha[j][k] * bp[k];
            long double inner = 0;
            for (int l = 0; l < k; l++)
                inner += beta[k][l] * bp[l];
            bbb += beta[j][k] * inner;
        }
        s1 += b[j];
        s2 += b[j] * bp[j];
        s3a += b[j] * ai[j] * ai[j];
        s3b += b[j] * bb;
        s4a += b[j] * ai[j] * ai[j] * ai[j];
        s4b += b[j] * ai[j] * aab;
        s4c += b[j] * ba2;
        s4d += b[j] * bbb;
    }
    int n = 0;
    res[n++] = s1 - 1;
    if (p >= 2)
        res[n++] = s2 - (0.5L - g);
    if (p >= 3) {
        res[n++] = s3a - 1.0L / 3;
        res[n++] = s3b - (1.0L / 6 - g + g * g);
    }
    if (p >= 4) {
        res[n++] = s4a - 0.25L;
        res[n++] = s4b - (1.0L / 8 - g / 3);
        res[n++] = s4c - (1.0L / 12 - g / 3);
        res[n++] = s4d - (1.0L / 24 - g / 2 + 1.5L * g * g - g * g * g);
    }
    return n;
}

/* Coefficients printed to 16 digits, the largest about 34 in size: a
 * condition sums some 50 products, so rounding leaves ~1e-14; a wrong digit
 * anywhere in the first ten shows at 1e-10 or more. */
START_TEST(order_conditions)
{
    long double gam[S][S] = { { 0 } }, alpha[S][S], b[S], bhat[S], res[8];
    standard_form(gam, alpha, b, bhat);
    int n = conditions(gam, alpha, b, 4, res);
    ck_assert_int_eq(n, 8);
    for (int i = 0; i < n; i++)
        ck_assert_msg(fabsl(res[i]) < 1e-12L, "y1: condition %d off by %Lg", i, res[i]);
    n = conditions(gam, alpha, bhat, 3, res);
    for (int i = 0; i < n; i++)
        ck_assert_msg(fabsl(res[i]) < 1e-12L, "embedded: condition %d off by %Lg", i, res[i]);
    /* ...and the embedded solution is not of order 4 (else k_6 estimates nothing). */
    conditions(gam, alpha, bhat, 4, res);
    long double worst = 0;
    for (int i = 4; i < 8; i++)
        worst = fmaxl(worst, fabsl(res[i]));
    ck_assert_msg(worst > 1e-4L, "embedded solution satisfies order 4 (%Lg)", worst);
    /* α_i and d_i are the row sums of α and Γ (the times of the stages and
     * the weights of ∂f/∂t); Hairer prints them to 4 digits, exact. */
    for (int i = 0; i < S; i++) {
        long double sa = 0, sg = 0;
        for (int j = 0; j < S; j++) {
            sa += alpha[i][j];
            sg += gam[i][j];
        }
        ck_assert_msg(fabsl(sa - SW_RODAS_ALPHA[i]) < 1e-12L, "alpha_%d: %Lg", i + 1, sa);
        ck_assert_msg(fabsl(sg - SW_RODAS_D[i]) < 1e-12L, "d_%d: %Lg", i + 1, sg);
    }
    /* Stiffly accurate: the last stage's weights are y1's. */
    for (int j = 0; j < S; j++) {
        ck_assert_msg(fabsl(alpha[S - 1][j] + gam[S - 1][j] - b[j]) < 1e-12L, "b_%d", j + 1);
    }
}
END_TEST

/* R(z) for y' = λy, z = hλ, from the transformed coefficients the way the
 * step uses them: (1/γ - z) k_i = z (1 + Σ a_ij k_j) + Σ c_ij k_j. */
static long double abs_r(long double re, long double im, long double *out_re, long double *out_im)
{
    long double kr[S], ki[S];
    long double yr = 1, yi = 0;
    for (int i = 0; i < S; i++) {
        long double ar = 1, ai = 0, cr = 0, ci = 0;
        for (int j = 0; j < i; j++) {
            ar += SW_RODAS_A[i][j] * kr[j];
            ai += SW_RODAS_A[i][j] * ki[j];
            cr += SW_RODAS_C[i][j] * kr[j];
            ci += SW_RODAS_C[i][j] * ki[j];
        }
        long double nr = re * ar - im * ai + cr, ni = re * ai + im * ar + ci; /* z·a + c */
        long double dr = 1.0L / SW_RODAS_GAMMA - re, di = -im, dd = dr * dr + di * di;
        kr[i] = (nr * dr + ni * di) / dd;
        ki[i] = (ni * dr - nr * di) / dd;
        yr += SW_RODAS_M[i] * kr[i];
        yi += SW_RODAS_M[i] * ki[i];
    }
    if (out_re)
        *out_re = yr;
    if (out_im)
        *out_im = yi;
    return sqrtl(yr * yr + yi * yi);
}

/* Order 4 on the linear test equation: R(z) - e^z ~ C z^5, so halving z
 * divides it by 32 (within 2% at z = 1e-2: the next term is z^6). A-stable:
 * |R(iy)| <= 1 on the imaginary axis (R's poles, at 1/γ = 4, lie to the
 * right, so the maximum principle covers the left half-plane; a grid of
 * points there is checked too). L-stable: |R(z)| -> 0 as z -> -∞, as 1/|z|. */
START_TEST(stability_function)
{
    long double r1, r2;
    abs_r(-0.02L, 0, &r1, NULL);
    abs_r(-0.01L, 0, &r2, NULL);
    long double e1 = r1 - expl(-0.02L), e2 = r2 - expl(-0.01L);
    ck_assert_msg(fabsl(e1 / e2 / 32 - 1) < 0.02L, "R - e^z ratio %Lg (32 for order 4)", e1 / e2);
    for (int k = -40; k <= 80; k++) {
        long double y = powl(10.0L, k / 10.0L);
        ck_assert_msg(abs_r(0, y, NULL, NULL) <= 1 + 1e-15L, "|R(%Lgi)| > 1", y);
        for (int a = 1; a <= 8; a++) {
            long double re = -powl(10.0L, (a - 4) / 1.0L);
            ck_assert_msg(abs_r(re, y, NULL, NULL) <= 1 + 1e-15L, "|R(%Lg%+Lgi)| > 1", re, y);
        }
    }
    long double r6 = abs_r(-1e6L, 0, NULL, NULL), r8 = abs_r(-1e8L, 0, NULL, NULL);
    ck_assert_msg(r6 < 1e-5L && r8 < 1e-7L, "|R(-1e6)| = %Lg, |R(-1e8)| = %Lg", r6, r8);
    ck_assert_msg(r8 < r6 / 50, "R does not fall as 1/|z|: %Lg then %Lg", r6, r8);
}
END_TEST

/* ---- closed-form scalar problems through the engine -------------------- */

typedef struct scalar {
    int kind; /* 0: y' = -y², y = 1/(1 + t); 1: y' = -y² - sin t + cos² t, y = cos t */
    int bad_solve;
} scalar;

static void scalar_deriv(void *ctx, double t, const double *y, double *dydt)
{
    const scalar *sc = ctx;
    dydt[0] = -y[0] * y[0] + (sc->kind == 1 ? -sin(t) + cos(t) * cos(t) : 0.0);
}

/* (1 - c·(-2y)) z = r: the exact Jacobian (Rosenbrock's order needs it). */
static int scalar_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    const scalar *sc = ctx;
    (void)t;
    if (sc->bad_solve)
        return SW_EDIVERGED;
    z[0] = r[0] / (1 + 2 * c * y[0]);
    return 0;
}

/* Error at t = 2 after fixed steps h: the tolerances set so loose that every
 * trial is accepted and the step is always h_max = h. */
static double scalar_error(int kind, double h)
{
    scalar sc = { kind, 0 };
    sw_ode ode = { .dim = 1, .order = 1, .deriv = scalar_deriv, .solve = scalar_solve, .ctx = &sc };
    sw_stepper s;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("rodas4"), &ode, err, sizeof err), SW_OK);
    s.rtol = s.atol = 1e30;
    double t = 0, y = 1;
    long n = lround(2.0 / h);
    for (long i = 0; i < n; i++)
        ck_assert_int_eq(sw_stepper_step(&s, &ode, &t, &y, h), SW_OK);
    ck_assert_int_eq(s.rejected, 0);
    ck_assert_double_eq_tol(t, 2.0, 1e-12);
    sw_stepper_free(&s);
    return fabs(y - (kind == 0 ? 1.0 / (1.0 + t) : cos(t)));
}

/* Observed order 4 (slope within ±0.3) on a nonlinear autonomous problem and
 * a non-autonomous one (the ∂f/∂t terms): h = 0.2 .. 0.025, errors about
 * 1e-5 .. 1e-9, far above round-off and the forward difference's error. */
START_TEST(observed_order)
{
    for (int kind = 0; kind < 2; kind++) {
        double e[4], h[4];
        for (int j = 0; j < 4; j++) {
            h[j] = 0.2 / (1 << j);
            e[j] = scalar_error(kind, h[j]);
        }
        double sx = 0, sy = 0, num = 0, den = 0;
        for (int j = 0; j < 4; j++) {
            sx += log(h[j]);
            sy += log(e[j]);
        }
        for (int j = 0; j < 4; j++) {
            num += (log(h[j]) - sx / 4) * (log(e[j]) - sy / 4);
            den += (log(h[j]) - sx / 4) * (log(h[j]) - sx / 4);
        }
        double p = num / den;
        ck_assert_msg(fabs(p - 4) < 0.3, "problem %d: observed order %.3f (errors %.3g .. %.3g)", kind, p,
                      e[0], e[3]);
        ck_assert_msg(e[3] > 1e-13, "problem %d: error %.3g is at round-off", kind, e[3]);
    }
}
END_TEST

/* ---- scenes ------------------------------------------------------------- */

/* Run scene (with its assignments, NUL-separated, or none) to t_end under
 * method at tolerance rtol = atol = tol and largest step dt; the state into
 * y (at most 4096 doubles); the dimension returned; counts into *acc, *rej,
 * *evals. */
static int run_scene(const char *scene, const char *set, const char *method, double tol, double dt,
                     double t_end, double *y, long *acc, long *rej, long *evals)
{
    const sw_scene *sc = sw_scene_find(scene);
    ck_assert_ptr_nonnull(sc);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    for (const char *a = set; a && *a; a += strlen(a) + 1)
        ck_assert_int_eq(sw_scene_set(sc, p, a, err, sizeof err), SW_OK);
    sw_sim s;
    ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find(method), dt, err, sizeof err), SW_OK);
    sw_sim_set_tolerances(&s, tol, tol);
    ck_assert_int_eq(sw_sim_run_until(&s, t_end), 0);
    int dim = s.sys.ode->dim;
    ck_assert_int_le(dim, 4096);
    memcpy(y, s.sys.y, (size_t)dim * sizeof *y);
    sw_sim_step_counts(&s, acc, rej);
    if (evals)
        *evals = sw_sim_evals(&s);
    sw_sim_free(&s);
    return dim;
}

static double max_diff(int n, const double *a, const double *b)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

/* Stiff spring, k = 1e6 (ω = 1000): explicit methods need h < 2.8/ω; rodas4's
 * accepted steps average over 10x the explicit limit 2/ω at tolerance 1e-2
 * (over 5x at 1e-3: the swing's own accuracy sets them), while rk45 at the
 * same tolerance takes steps below it. The error against
 * dop853 at 1e-12 (an independent method) falls with the tolerance: within
 * 1e3 of it (the start excites the stretch, whose phase error over 160
 * periods builds up as it does for rk45), and by 10x to 1e4x per two decades
 * (10^(8/5) is the local-error law); rejections are counted, fewer than the
 * accepted steps. */
START_TEST(stiff_spring_control)
{
    const char *k6 = "k=1e6\0";
    double ref[4], y[4];
    long acc, rej, evals, racc, rrej;
    run_scene("stiff-spring", k6, "dop853", 1e-13, 0.5, 1.0, ref, &acc, &rej, NULL);
    double limit = 2.0 / 1000.0;
    for (int d = 2; d <= 3; d++) {
        double tol = pow(10.0, -d);
        run_scene("stiff-spring", k6, "rodas4", tol, 0.5, 1.0, y, &acc, &rej, &evals);
        double mean_h = 1.0 / (double)acc;
        ck_assert_msg(mean_h > (d == 2 ? 10 : 5) * limit, "tol %g: rodas4 mean step %.3g, explicit limit %.3g",
                      tol, mean_h, limit);
        ck_assert_int_lt(rej, acc);
        run_scene("stiff-spring", k6, "rk45", tol, 0.5, 1.0, y, &racc, &rrej, NULL);
        ck_assert_msg(1.0 / (double)racc < 2.8 / 1000.0, "rk45 mean step %.3g", 1.0 / (double)racc);
    }
    double prev = INFINITY;
    for (int d = 6; d <= 10; d += 2) {
        double tol = pow(10.0, -d);
        run_scene("stiff-spring", k6, "rodas4", tol, 0.5, 1.0, y, &acc, &rej, NULL);
        double e = max_diff(4, y, ref);
        ck_assert_msg(e < 1e3 * tol && e > 1e-3 * tol, "tol %g: error %.3g", tol, e);
        if (prev < INFINITY)
            ck_assert_msg(e < prev / 10 && e > prev / 1e4, "tol %g: error %.3g after %.3g", tol, e, prev);
        prev = e;
        ck_assert_int_lt(rej, acc);
    }
}
END_TEST

/* The chain of 50 masses with stiff damped springs (the banded solve):
 * rodas4 at 1e-8 against dop853 at 1e-12; and a flow field whose velocity
 * changes with time (the gyre: ∂f/∂t, the per-point solve), the same way. */
START_TEST(chain_and_flow)
{
    static double ref[4096], y[4096];
    long acc, rej;
    const char *chain = "n=50\0k=1e5\0c=10\0g=9.81\0";
    run_scene("chain", chain, "dop853", 1e-12, 0.01, 0.5, ref, &acc, &rej, NULL);
    int n = run_scene("chain", chain, "rodas4", 1e-8, 0.01, 0.5, y, &acc, &rej, NULL);
    double e = max_diff(n, y, ref);
    ck_assert_msg(e < 1e-5, "chain: error %.3g", e);
    ck_assert_int_gt(acc, 0);
    run_scene("gyre", NULL, "dop853", 1e-12, 0.1, 2.0, ref, &acc, &rej, NULL);
    n = run_scene("gyre", NULL, "rodas4", 1e-8, 0.1, 2.0, y, &acc, &rej, NULL);
    e = max_diff(n, y, ref);
    ck_assert_msg(e < 1e-5, "gyre: error %.3g", e);
}
END_TEST

/* The particles' derivative, called through another function: the same
 * numbers, but a derivative the system does not vouch for as autonomous. */
static sw_deriv_fn *vouched_deriv;

static void unvouched_deriv(void *ctx, double t, const double *y, double *dydt)
{
    vouched_deriv(ctx, t, y, dydt);
}

/* rodas4 skips ∂f/∂t where the system says f ignores t: (f(t + δ) - f)/δ
 * is +0 there, so the step must be the one that evaluates it, bit for bit
 * (memcmp after every step, the same t, accepted and rejected trials),
 * one evaluation fewer a trial. A damped chain (the damping is what the
 * springs' Jacobian turns) at 20 times its dt, where trials are rejected. */
START_TEST(autonomous_skips_time_derivative)
{
    const sw_scene *sc = sw_scene_find("chain");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    ck_assert_int_eq(sw_scene_set(sc, p, "n=30", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_scene_set(sc, p, "c=10", err, sizeof err), SW_OK);
    sw_system skip, eval;
    ck_assert_int_eq(sw_system_build(&skip, sc, p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_system_build(&eval, sc, p, err, sizeof err), SW_OK);
    vouched_deriv = eval.ode->deriv;
    eval.ode->deriv = unvouched_deriv;
    const sw_integrator *m = sw_integrator_find("rodas4");
    sw_stepper *a = sw_stepper_new(m, skip.ode, err, sizeof err), *b = sw_stepper_new(m, eval.ode, err, sizeof err);
    ck_assert_ptr_nonnull(a);
    ck_assert_ptr_nonnull(b);
    double ta = 0, tb = 0, h = 20 * sw_scene_dt(sc, p);
    int dim = skip.ode->dim;
    long ea = skip.ode->evals, eb = eval.ode->evals;
    for (int step = 0; step < 20; step++) {
        ck_assert_int_eq(sw_stepper_step(a, skip.ode, &ta, skip.y, h), SW_OK);
        ck_assert_int_eq(sw_stepper_step(b, eval.ode, &tb, eval.y, h), SW_OK);
        ck_assert_msg(memcmp(skip.y, eval.y, (size_t)dim * sizeof *skip.y) == 0, "step %d: states differ", step);
        ck_assert(ta == tb);
    }
    ck_assert_int_eq(a->accepted, b->accepted);
    ck_assert_int_eq(a->rejected, b->rejected);
    ck_assert_int_gt(a->rejected, 0); /* the rejection path was taken too */
    long trials = a->accepted + a->rejected;
    ck_assert_int_eq((eval.ode->evals - eb) - (skip.ode->evals - ea), trials);
    sw_stepper_delete(b);
    sw_stepper_delete(a);
    sw_system_free(&eval);
    sw_system_free(&skip);
}
END_TEST

/* Where it cannot run: a system above the dense fallback's size with no
 * solve is refused with a message naming the method; a solve that always
 * fails ends the step with SW_EDIVERGED and a reason, after a bounded
 * number of trials, never a hang. */
START_TEST(refusals)
{
    static double y[100];
    scalar sc = { 0, 0 };
    sw_ode big = { .dim = 100, .order = 1, .deriv = scalar_deriv, .ctx = &sc };
    sw_stepper s;
    char err[SW_ERRLEN] = "";
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("rodas4"), &big, err, sizeof err), SW_EINVAL);
    ck_assert_msg(strstr(err, "rodas4") && strstr(err, "Jacobian"), "message: %s", err);
    scalar bad = { 0, 1 };
    sw_ode ode = { .dim = 1, .order = 1, .deriv = scalar_deriv, .solve = scalar_solve, .ctx = &bad };
    ck_assert_int_eq(sw_stepper_init(&s, sw_integrator_find("rodas4"), &ode, err, sizeof err), SW_OK);
    double t = 0;
    y[0] = 1;
    ck_assert_int_eq(sw_stepper_step(&s, &ode, &t, y, 0.1), SW_EDIVERGED);
    ck_assert_ptr_nonnull(s.why);
    ck_assert_double_eq(t, 0.0);
    ck_assert_double_eq(y[0], 1.0);
    ck_assert_int_le(s.rejected, 200);
    sw_stepper_free(&s);
}
END_TEST

Suite *make_rosenbrock_suite(void);
Suite *make_rosenbrock_suite(void)
{
    Suite *s = suite_create("rosenbrock");
    TCase *tc = tcase_create("theory");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, order_conditions);
    tcase_add_test(tc, stability_function);
    tcase_add_test(tc, observed_order);
    tcase_add_test(tc, stiff_spring_control);
    tcase_add_test(tc, chain_and_flow);
    tcase_add_test(tc, refusals);
    tcase_add_test(tc, autonomous_skips_time_derivative);
    suite_add_tcase(s, tc);
    return s;
}
