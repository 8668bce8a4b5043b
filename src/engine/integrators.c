/* The integrator family: one step function per method over flat double
 * arrays, and the table that names them. Methods know nothing of particles;
 * they see an sw_ode. Invariant: a step allocates nothing — every vector it
 * touches was handed out by sw_stepper_init. */
#include "stepwise/integrator.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

#define W(s, i) ((s)->work + (size_t)(i) * (size_t)(s)->dim)

/* out = y + a·k over n components (out may be y). */
static void axpy(int n, double *out, const double *y, double a, const double *k)
{
    for (int i = 0; i < n; i++)
        out[i] = y[i] + a * k[i];
}

static double norm_inf(int n, const double *v)
{
    double m = 0.0;
    for (int i = 0; i < n; i++) {
        double a = fabs(v[i]);
        if (!(a <= m)) /* NaN wins, so a failed iteration is never "converged" */
            m = a;
    }
    return m;
}

/* Explicit Runge-Kutta steps run over [lo, hi): the whole state for coupled
 * systems, or L1-sized slices for pointwise ones (flow fields), where every
 * stage of a slice needs only that slice. The arithmetic is the same either
 * way, so results are bit-identical; only the memory traffic differs. */
#define BLOCK 512

/* dydt over [lo, hi) at (t, y): a slice when the system allows it. */
static void eval_range(sw_ode *ode, double t, const double *y, double *dydt, int lo, int hi)
{
    if (ode->deriv_part)
        ode->deriv_part(ode->ctx, t, hi - lo, y + lo, dydt + lo);
    else
        ode->deriv(ode->ctx, t, y, dydt);
}

/* A method's step over [lo, hi); returns non-zero when its final loop saw a
 * component at or beyond the limit exponent elim (see sw_state_beyond). */
typedef unsigned range_step(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                            unsigned elim);

/* y_i's exponent field is at or beyond elim (inf and NaN always are). */
static inline unsigned beyond1(double v, unsigned elim)
{
    unsigned long long bits;
    memcpy(&bits, &v, sizeof bits);
    return (unsigned)((bits >> 52) & 0x7FF) >= elim;
}

/* Run a range step over the whole state or slice by slice, and count its
 * evaluations once per stage. The final loops test every component against
 * the sim's runaway limit as they write it, sparing the sim a pass. */
static int run_ranges(range_step *f, int stages, sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    unsigned elim = s->limit_exp ? s->limit_exp : 0x800, beyond = 0; /* 0x800: never */
    if (ode->deriv_part)
        for (int lo = 0; lo < ode->dim; lo += BLOCK)
            beyond |= f(s, ode, *t, y, h, lo, lo + BLOCK < ode->dim ? lo + BLOCK : ode->dim, elim);
    else
        beyond = f(s, ode, *t, y, h, 0, ode->dim, elim);
    s->checked = s->limit_exp != 0;
    s->beyond = beyond != 0;
    ode->evals += stages;
    *t += h;
    return 0;
}

/* x1 = x0 + h·f(t0, x0) */
static unsigned euler_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int lo, int hi,
                            unsigned elim)
{
    double *restrict k = W(s, 0);
    unsigned over = 0;
    eval_range(ode, t, y, k, lo, hi);
    for (int i = lo; i < hi; i++) {
        y[i] += h * k[i];
        over |= beyond1(y[i], elim);
    }
    return over;
}

static int step_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(euler_range, 1, s, ode, t, y, h);
}

/* Semi-implicit Euler: v1 = v0 + h·a(x0, v0), then x1 = x0 + h·v1. */
static int step_symplectic_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int half = ode->dim / 2;
    double *k = W(s, 0);
    sw_ode_eval(ode, *t, y, k);
    axpy(half, y + half, y + half, h, k + half);
    axpy(half, y, y, h, y + half);
    *t += h;
    return 0;
}

/* Explicit midpoint: k1 = f(y), k2 = f(y + h/2·k1), y1 = y + h·k2. */
static unsigned midpoint_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int lo,
                               int hi, unsigned elim)
{
    double *restrict k = W(s, 0), *restrict ym = W(s, 1);
    unsigned over = 0;
    eval_range(ode, t, y, k, lo, hi);
    for (int i = lo; i < hi; i++)
        ym[i] = y[i] + 0.5 * h * k[i];
    eval_range(ode, t + 0.5 * h, ym, k, lo, hi);
    for (int i = lo; i < hi; i++) {
        y[i] += h * k[i];
        over |= beyond1(y[i], elim);
    }
    return over;
}

static int step_midpoint(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(midpoint_range, 2, s, ode, t, y, h);
}

/* Heun (explicit trapezoid): k1 = f(y), k2 = f(y + h·k1), y1 = y + h/2·(k1 + k2). */
static unsigned heun_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int lo, int hi,
                           unsigned elim)
{
    double *restrict k1 = W(s, 0), *restrict yp = W(s, 1), *restrict k2 = W(s, 2);
    unsigned over = 0;
    eval_range(ode, t, y, k1, lo, hi);
    for (int i = lo; i < hi; i++)
        yp[i] = y[i] + h * k1[i];
    eval_range(ode, t + h, yp, k2, lo, hi);
    for (int i = lo; i < hi; i++) {
        y[i] += 0.5 * h * (k1[i] + k2[i]);
        over |= beyond1(y[i], elim);
    }
    return over;
}

static int step_heun(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(heun_range, 2, s, ode, t, y, h);
}

/* Classical RK4: y1 = y + h/6·(k1 + 2k2 + 2k3 + k4). */
static unsigned rk4_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int lo, int hi,
                          unsigned elim)
{
    double *restrict k1 = W(s, 0), *restrict k2 = W(s, 1), *restrict k3 = W(s, 2), *restrict k4 = W(s, 3),
           *restrict yt = W(s, 4);
    unsigned over = 0;
    eval_range(ode, t, y, k1, lo, hi);
    for (int i = lo; i < hi; i++)
        yt[i] = y[i] + 0.5 * h * k1[i];
    eval_range(ode, t + 0.5 * h, yt, k2, lo, hi);
    for (int i = lo; i < hi; i++)
        yt[i] = y[i] + 0.5 * h * k2[i];
    eval_range(ode, t + 0.5 * h, yt, k3, lo, hi);
    for (int i = lo; i < hi; i++)
        yt[i] = y[i] + h * k3[i];
    eval_range(ode, t + h, yt, k4, lo, hi);
    for (int i = lo; i < hi; i++) {
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        over |= beyond1(y[i], elim);
    }
    return over;
}

static int step_rk4(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(rk4_range, 4, s, ode, t, y, h);
}

/* Velocity Verlet (kick-drift-kick), one evaluation per step by reusing the
 * last acceleration (FSAL):
 *   v½ = v0 + h/2·a0,  x1 = x0 + h·v½,  a1 = a(x1, ṽ1),  v1 = v½ + h/2·a1.
 * With velocity-independent forces ṽ1 does not matter and this is the
 * symplectic leapfrog. With drag, ṽ1 = v0 + h·a0 (an Euler predictor) keeps
 * the method second order: its O(h²) error enters a1 multiplied by h. */
static int step_verlet(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int half = ode->dim / 2;
    double *cache = W(s, 0), *yt = W(s, 1);
    double *x = y, *v = y + half, *a0 = cache + half;
    if (!s->have_cache)
        sw_ode_eval(ode, *t, y, cache);
    for (int i = 0; i < half; i++) {
        double vh = v[i] + 0.5 * h * a0[i];
        yt[i] = x[i] + h * vh;
        yt[half + i] = v[i] + h * a0[i];
        x[i] = yt[i];
        v[i] = vh;
    }
    sw_ode_eval(ode, *t + h, yt, cache);
    axpy(half, v, v, 0.5 * h, a0);
    s->have_cache = 1;
    *t += h;
    return 0;
}

/* Linearised backward Euler (Baraff & Witkin): one Newton step of
 * y1 = y0 + h·f(y1) from y0, i.e. (I - h·J)·Δy = h·f(y0). Exact backward
 * Euler when f is linear. */
static int step_implicit_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    double *r = W(s, 0), *dy = W(s, 1);
    sw_ode_eval(ode, *t, y, r);
    for (int i = 0; i < ode->dim; i++)
        r[i] *= h;
    int rc = sw_ode_solve(s, ode, *t + h, y, h, r, dy);
    if (rc != 0)
        return rc;
    axpy(ode->dim, y, y, 1.0, dy);
    *t += h;
    return 0;
}

/* Implicit midpoint: y1 = y0 + h·f(t + h/2, (y0 + y1)/2). Newton on
 * Δ = y1 - y0 with residual R(Δ) = Δ - h·f(y0 + Δ/2), Jacobian I - h/2·J. */
static int step_implicit_midpoint(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *d = W(s, 0), *ym = W(s, 1), *r = W(s, 2), *delta = W(s, 3);
    double tm = *t + 0.5 * h;
    double scale = 1.0 + norm_inf(n, y);
    double tol = s->rtol > 0 ? s->rtol * 1e-6 : 1e-12;
    memset(d, 0, (size_t)n * sizeof *d);
    for (int iter = 0; iter < 50; iter++) {
        axpy(n, ym, y, 0.5, d);
        sw_ode_eval(ode, tm, ym, r);
        for (int i = 0; i < n; i++)
            r[i] = h * r[i] - d[i]; /* -R */
        int rc = sw_ode_solve(s, ode, tm, ym, 0.5 * h, r, delta);
        if (rc != 0)
            return rc;
        axpy(n, d, d, 1.0, delta);
        s->newton_iters++;
        double step = norm_inf(n, delta);
        if (!(step == step))
            return SW_EDIVERGED;
        if (step <= tol * (scale + norm_inf(n, d))) {
            axpy(n, y, y, 1.0, d);
            *t += h;
            return 0;
        }
    }
    return SW_EDIVERGED;
}

/* Dormand–Prince 5(4) tableau. */
static const double dp_c[7] = { 0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1 };
static const double dp_a[7][6] = {
    { 0 },
    { 1.0 / 5 },
    { 3.0 / 40, 9.0 / 40 },
    { 44.0 / 45, -56.0 / 15, 32.0 / 9 },
    { 19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729 },
    { 9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656 },
    { 35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84 },
};
/* b (fifth order) is the last row of a; e = b - b̂ (fourth order). */
static const double dp_e[7] = { 71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920,
                                -17253.0 / 339200, 22.0 / 525, -1.0 / 40 };

/* One accepted Dormand–Prince step of at most h, with as many rejected trial
 * steps as the error control needs. Error norm: RMS of e_i / (atol + rtol·|y_i|). */
static int step_rk45(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    int n = ode->dim;
    double *k[7], *yt = W(s, 7), *y1 = W(s, 8);
    for (int j = 0; j < 7; j++)
        k[j] = W(s, j);
    if (!s->have_cache)
        sw_ode_eval(ode, *t, y, k[0]);
    double h = s->h_next > 0 && s->h_next < h_max ? s->h_next : h_max;
    for (int tries = 0; tries < 200; tries++) {
        for (int st = 1; st < 7; st++) {
            for (int i = 0; i < n; i++) {
                double acc = 0.0;
                for (int j = 0; j < st; j++)
                    acc += dp_a[st][j] * k[j][i];
                (st == 6 ? y1 : yt)[i] = y[i] + h * acc;
            }
            sw_ode_eval(ode, *t + dp_c[st] * h, st == 6 ? y1 : yt, k[st]);
        }
        double sum = 0.0;
        for (int i = 0; i < n; i++) {
            double e = 0.0;
            for (int j = 0; j < 7; j++)
                e += dp_e[j] * k[j][i];
            double sc = s->atol + s->rtol * fmax(fabs(y[i]), fabs(y1[i]));
            double q = h * e / sc;
            sum += q * q;
        }
        double err = sqrt(sum / n);
        if (!(err == err)) { /* non-finite trial: shrink hard */
            s->rejected++;
            h *= 0.1;
            continue;
        }
        double grow = err > 0 ? 0.9 * pow(err, -0.2) : 5.0;
        if (err <= 1.0) {
            memcpy(y, y1, (size_t)n * sizeof *y);
            memcpy(k[0], k[6], (size_t)n * sizeof *y); /* FSAL */
            s->have_cache = 1;
            *t += h;
            s->h_last = h;
            s->h_next = h * fmin(5.0, fmax(0.2, grow));
            s->accepted++;
            return 0;
        }
        s->rejected++;
        h *= fmax(0.2, grow);
        if (h < 1e-14 * fmax(1.0, fabs(*t)))
            break;
    }
    return SW_EDIVERGED;
}

static const sw_integrator builtins[] = {
    { "euler", "explicit (forward) Euler", 1, 1, SW_EXPLICIT, 0.0, 1, step_euler,
      "y1 = y0 + h f(y0)" },
    { "symplectic-euler", "semi-implicit Euler", 1, 1, SW_EXPLICIT | SW_SYMPLECTIC | SW_NEEDS_SECOND_ORDER,
      2.0, 1, step_symplectic_euler, "v1 = v0 + h a(x0, v0); x1 = x0 + h v1" },
    { "midpoint", "explicit midpoint (RK2)", 2, 2, SW_EXPLICIT, 0.0, 2, step_midpoint,
      "y1 = y0 + h f(y0 + h/2 f(y0))" },
    { "heun", "Heun / explicit trapezoid (RK2)", 2, 2, SW_EXPLICIT, 0.0, 3, step_heun,
      "y1 = y0 + h/2 (f(y0) + f(y0 + h f(y0)))" },
    { "rk4", "classical Runge-Kutta", 4, 4, SW_EXPLICIT, 2.0 * 1.4142135623730951, 5, step_rk4,
      "y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4)" },
    { "verlet", "velocity Verlet (leapfrog)", 2, 1, SW_EXPLICIT | SW_SYMPLECTIC | SW_NEEDS_SECOND_ORDER,
      2.0, 2, step_verlet, "v+ = v0 + h/2 a0; x1 = x0 + h v+; v1 = v+ + h/2 a1" },
    { "implicit-euler", "backward Euler, linearised (one Newton step, CG)", 1, 1, SW_IMPLICIT,
      INFINITY, 2, step_implicit_euler, "(I - h J) dy = h f(y0)" },
    { "implicit-midpoint", "implicit midpoint, Newton", 2, 2, SW_IMPLICIT | SW_SYMPLECTIC,
      INFINITY, 4, step_implicit_midpoint, "y1 = y0 + h f((y0 + y1)/2)" },
    { "rk45", "Dormand-Prince 5(4), adaptive", 5, 6, SW_EXPLICIT | SW_ADAPTIVE, 0.0, 9, step_rk45,
      "adaptive: error estimate from an embedded 4th-order solution" },
};

#define NBUILTIN ((int)(sizeof builtins / sizeof builtins[0]))
#define MAX_EXTRA 8
static sw_integrator extra[MAX_EXTRA];
static int nextra;

int sw_integrator_count(void) { return NBUILTIN + nextra; }

const sw_integrator *sw_integrator_at(int index)
{
    if (index < 0 || index >= NBUILTIN + nextra)
        return NULL;
    return index < NBUILTIN ? &builtins[index] : &extra[index - NBUILTIN];
}

const sw_integrator *sw_integrator_find(const char *name)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (strcmp(sw_integrator_at(i)->name, name) == 0)
            return sw_integrator_at(i);
    return NULL;
}

int sw_integrator_register(const sw_integrator *method, char *err, size_t errlen)
{
    if (sw_integrator_find(method->name)) {
        snprintf(err, errlen, "an integrator named '%s' already exists", method->name);
        return SW_EINVAL;
    }
    if (nextra == MAX_EXTRA) {
        snprintf(err, errlen, "at most %d plugin integrators can be loaded", MAX_EXTRA);
        return SW_EINVAL;
    }
    extra[nextra++] = *method;
    return SW_OK;
}

int sw_integrator_accepts(const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen)
{
    if ((m->flags & SW_NEEDS_SECOND_ORDER) && ode->order != 2) {
        snprintf(err, errlen,
                 "'%s' updates velocities and positions separately and needs a system with "
                 "masses; this is a first-order flow field (use euler, midpoint, heun, rk4, "
                 "implicit-euler, implicit-midpoint or rk45)", m->name);
        return SW_EINVAL;
    }
    if ((m->flags & SW_IMPLICIT) && !ode->solve && ode->dim > SW_DENSE_MAX) {
        snprintf(err, errlen, "'%s' needs a Jacobian this system does not provide "
                 "(dimension %d is above the dense fallback's %d)", m->name, ode->dim, SW_DENSE_MAX);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_stepper_init(sw_stepper *s, const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    int rc = sw_integrator_accepts(m, ode, err, errlen);
    if (rc != SW_OK)
        return rc;
    s->method = m;
    s->dim = ode->dim;
    s->rtol = SW_RTOL_DEFAULT;
    s->atol = SW_ATOL_DEFAULT;
    size_t len = (size_t)(m->work_vectors > 0 ? m->work_vectors : 1) * (size_t)ode->dim;
    s->work = calloc(len, sizeof *s->work);
    if ((m->flags & SW_IMPLICIT) && !ode->solve) {
        size_t d = (size_t)ode->dim;
        s->dense = calloc(d * d + 3 * d, sizeof *s->dense);
        if (!s->dense) {
            free(s->work);
            s->work = NULL;
        }
    }
    if (!s->work) {
        snprintf(err, errlen, "out of memory for %s workspace (%d doubles)", m->name, ode->dim);
        return SW_ENOMEM;
    }
    return SW_OK;
}

void sw_stepper_free(sw_stepper *s)
{
    free(s->work);
    free(s->dense);
    s->work = s->dense = NULL;
}

void sw_stepper_touch(sw_stepper *s) { s->have_cache = 0; }

int sw_stepper_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    s->checked = 0;
    return s->method->step(s, ode, t, y, h);
}

/* Dense fallback: J by forward differences, one column per evaluation, then
 * (I - c·J) z = r by Gaussian elimination with partial pivoting. */
static int dense_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                       const double *r, double *z)
{
    int n = ode->dim;
    double *a = s->dense, *f0 = a + (size_t)n * n, *yp = f0 + n, *f1 = yp + n;
    sw_ode_eval(ode, t, y, f0);
    memcpy(yp, y, (size_t)n * sizeof *yp);
    for (int j = 0; j < n; j++) {
        double eps = 1e-7 * fmax(1.0, fabs(y[j]));
        yp[j] = y[j] + eps;
        sw_ode_eval(ode, t, yp, f1);
        yp[j] = y[j];
        for (int i = 0; i < n; i++)
            a[i * n + j] = (i == j) - c * (f1[i] - f0[i]) / eps;
    }
    memcpy(z, r, (size_t)n * sizeof *z);
    for (int col = 0; col < n; col++) {
        int piv = col;
        for (int i = col + 1; i < n; i++)
            if (fabs(a[i * n + col]) > fabs(a[piv * n + col]))
                piv = i;
        if (!(fabs(a[piv * n + col]) > 0))
            return SW_EDIVERGED;
        if (piv != col) {
            for (int j = 0; j < n; j++) {
                double tmp = a[col * n + j];
                a[col * n + j] = a[piv * n + j];
                a[piv * n + j] = tmp;
            }
            double tmp = z[col];
            z[col] = z[piv];
            z[piv] = tmp;
        }
        for (int i = col + 1; i < n; i++) {
            double f = a[i * n + col] / a[col * n + col];
            for (int j = col; j < n; j++)
                a[i * n + j] -= f * a[col * n + j];
            z[i] -= f * z[col];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double acc = z[i];
        for (int j = i + 1; j < n; j++)
            acc -= a[i * n + j] * z[j];
        z[i] = acc / a[i * n + i];
    }
    return SW_OK;
}

int sw_ode_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                 const double *r, double *z)
{
    ode->solves++;
    if (ode->solve)
        return ode->solve(ode->ctx, t, y, c, r, z);
    return dense_solve(s, ode, t, y, c, r, z);
}
