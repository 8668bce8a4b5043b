/* Linear stability, computed rather than quoted. The spectrum of the
 * scene's linearisation ∂f/∂y splits into modes; a method's growth per step
 * on a mode is the spectral radius of the method's own one-step map on that
 * mode's test system, found by stepping unit states with the method itself
 * (so Verlet as implemented, damping, real eigenvalues and plugins are all
 * covered, with no formula per method); the largest stable Δt is where the
 * growth of some mode first exceeds one. */
#include "sim/truth.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/flow_jacobian.h"
#include "engine/linalg.h"
#include "engine/particles_solve.h"
#include "engine/stepper.h"
#include "stepwise/stepwise.h"

/* Particle systems up to this size get every eigenvalue (dense QR on the
 * 4n×4n Jacobian, about 40 Mflop at the limit); larger coupled ones their
 * stiffest mode. */
#define DENSE_PARTICLES 32

double sw_truth_horizon(const sw_scene *sc, double stiffest)
{
    double unit = stiffest > 0 && isfinite(stiffest) ? 6.283185307179586 / stiffest : sc->duration;
    return fmax(100 * unit, 20 * sc->duration);
}

int sw_truth_growth_visible(double rho, double dt, double horizon)
{
    return rho > 1 && (horizon / dt) * log(rho) > log(1.01);
}

/* ---- a mode's test system --------------------------------------------------- */

/* y' = J y for the 2x2 matrix J of one mode: a flow (order 1) with
 * J = [[a, -b], [b, a]] (eigenvalues a ± ib), or a second-order system
 * (x, v) with J = [[0, 1], [A, B]] (roots λ, μ: B = λ + μ, A = -λμ). */
typedef struct test_system {
    sw_ode ode;
    double j[4];
} test_system;

static void test_deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)t;
    const test_system *ts = ctx;
    dydt[0] = ts->j[0] * y[0] + ts->j[1] * y[1];
    dydt[1] = ts->j[2] * y[0] + ts->j[3] * y[1];
}

/* (I - c·J) z = r by Cramer's rule. */
static int test_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t;
    (void)y;
    const test_system *ts = ctx;
    double a = 1 - c * ts->j[0], b = -c * ts->j[1], d = -c * ts->j[2], e = 1 - c * ts->j[3];
    double det = a * e - b * d;
    if (!(fabs(det) > 0) || !isfinite(det))
        return SW_EDIVERGED;
    z[0] = (e * r[0] - b * r[1]) / det;
    z[1] = (a * r[1] - d * r[0]) / det;
    return SW_OK;
}

static void test_system_init(test_system *ts, int order, const sw_mode *md)
{
    memset(ts, 0, sizeof *ts);
    if (order == 1) {
        ts->j[0] = ts->j[3] = md->re;
        ts->j[1] = -md->im;
        ts->j[2] = md->im;
    } else {
        /* B = λ + μ, A = -λμ (real: μ is λ's conjugate or both are real) */
        ts->j[1] = 1;
        ts->j[2] = -(md->re * md->pre - md->im * md->pim);
        ts->j[3] = md->re + md->pre;
    }
    ts->ode.dim = 2;
    ts->ode.order = order;
    ts->ode.deriv = test_deriv;
    ts->ode.solve = test_solve;
    ts->ode.ctx = ts;
}

/* Spectral radius of one step of size h from the stepper's method on the
 * test system. Columns of the map come from stepping the unit states; when
 * the method carries a derivative from one step to the next (FSAL: its
 * stepper keeps it in work vector 0), the map acts on the state and that
 * cache together, a 4x4 matrix. */
static double map_growth(sw_stepper *st, test_system *ts, double h)
{
    double m[16], t;
    int cached = 0;
    for (int pass = 0; pass < 2; pass++) {
        int n = cached ? 4 : 2;
        for (int col = 0; col < n; col++) {
            double y[2] = { col == 0, col == 1 };
            sw_stepper_touch(st);
            if (cached) {
                st->work[0] = col == 2;
                st->work[1] = col == 3;
                st->have_cache = 1;
            }
            t = 0;
            if (sw_stepper_step(st, &ts->ode, &t, y, h) != SW_OK)
                return NAN;
            if (!cached && st->have_cache) {
                cached = 1; /* start over on the augmented state */
                break;
            }
            m[0 * n + col] = y[0];
            m[1 * n + col] = y[1];
            if (cached) {
                m[2 * n + col] = st->work[0];
                m[3 * n + col] = st->work[1];
            }
            if (col == n - 1)
                return sw_spectral_radius(n, m);
        }
    }
    return NAN;
}

double sw_truth_growth(const sw_integrator *m, int order, const sw_mode *mode, double h)
{
    if (m->flags & SW_ADAPTIVE)
        return NAN;
    test_system ts;
    test_system_init(&ts, order, mode);
    sw_stepper st;
    char err[SW_ERRLEN];
    if (sw_stepper_init(&st, m, &ts.ode, err, sizeof err) != SW_OK)
        return NAN;
    double rho = map_growth(&st, &ts, h);
    sw_stepper_free(&st);
    return rho;
}

/* One stepper per mode, kept for a scan over many steps. */
typedef struct mode_steppers {
    int n;
    test_system ts[SW_TRUTH_MODES];
    sw_stepper st[SW_TRUTH_MODES];
} mode_steppers;

static int steppers_init(mode_steppers *ms, const sw_integrator *m, const sw_spectrum *sp)
{
    char err[SW_ERRLEN];
    ms->n = 0;
    for (int k = 0; k < sp->n; k++) {
        test_system_init(&ms->ts[k], sp->order, &sp->mode[k]);
        if (sw_stepper_init(&ms->st[k], m, &ms->ts[k].ode, err, sizeof err) != SW_OK)
            return -1;
        ms->n++;
    }
    return 0;
}

static void steppers_free(mode_steppers *ms)
{
    for (int k = 0; k < ms->n; k++)
        sw_stepper_free(&ms->st[k]);
    ms->n = 0;
}

static double steppers_growth(mode_steppers *ms, double h, int *worst)
{
    double rho = 0;
    for (int k = 0; k < ms->n; k++) {
        /* the test system lives in ms: point its context there again */
        ms->ts[k].ode.ctx = &ms->ts[k];
        double g = map_growth(&ms->st[k], &ms->ts[k], h);
        if (!(g <= rho)) {
            rho = g;
            if (worst)
                *worst = k;
        }
    }
    return rho;
}

double sw_truth_growth_all(const sw_integrator *m, const sw_spectrum *sp, double h, int *worst)
{
    if (m->flags & SW_ADAPTIVE)
        return NAN;
    mode_steppers *ms = malloc(sizeof *ms);
    double rho = NAN;
    if (ms && steppers_init(ms, m, sp) == 0)
        rho = steppers_growth(ms, h, worst);
    if (ms)
        steppers_free(ms);
    free(ms);
    return sp->n == 0 && !(m->flags & SW_ADAPTIVE) ? 1.0 : rho;
}

double sw_truth_limit(const sw_integrator *m, const sw_spectrum *sp, double h_max, int *unbounded)
{
    *unbounded = 0;
    if (m->flags & SW_ADAPTIVE)
        return NAN;
    if (sp->n == 0 || !(sp->largest > 0)) {
        *unbounded = 1; /* nothing moves fast enough to constrain a step */
        return h_max;
    }
    mode_steppers *ms = malloc(sizeof *ms);
    if (!ms || steppers_init(ms, m, sp) != 0) {
        if (ms)
            steppers_free(ms);
        free(ms);
        return NAN;
    }
    /* Scan up geometrically for the first step that grows, then bisect.
     * A method growing already at |λ|·h = 0.01 has no stable step. */
    const double ok = 1.0 + SW_TRUTH_NEUTRAL;
    double lo = 0, hi = NAN, h = fmin(1e-2 / sp->largest, h_max);
    for (;;) {
        if (!(steppers_growth(ms, h, NULL) <= ok)) {
            hi = h;
            break;
        }
        lo = h;
        if (h >= h_max)
            break;
        h = fmin(h * 1.03, h_max);
    }
    if (isnan(hi)) {
        *unbounded = 1;
        steppers_free(ms);
        free(ms);
        return h_max;
    }
    if (lo > 0)
        for (int it = 0; it < 40 && hi / lo - 1 > 1e-9; it++) {
            double mid = sqrt(lo * hi);
            if (steppers_growth(ms, mid, NULL) <= ok)
                lo = mid;
            else
                hi = mid;
        }
    steppers_free(ms);
    free(ms);
    return lo;
}

/* ---- spectra ---------------------------------------------------------------- */

/* Add mode (λ, μ) unless it is there already (as (λ, μ) or (μ, λ)), within
 * tol (1e-9 of the scale |λ|max), or it grows physically: a real part
 * above 1e-6 of the scale. Rounding in QR leaves real parts up to about
 * √ε·|J| on a defective zero eigenvalue (a spring at its rest length has
 * no sideways stiffness): a positive real part below that is taken as 0,
 * and an eigenvalue that small in size as zero. */
static void add_mode(sw_spectrum *sp, double re, double im, double pre, double pim, double tol)
{
    double noise = 1e3 * tol;
    if (re > noise || pre > noise) {
        sp->growing++;
        return;
    }
    re = re > 0 ? 0 : re;
    pre = pre > 0 ? 0 : pre;
    if (hypot(re, im) < noise)
        re = im = 0;
    if (hypot(pre, pim) < noise)
        pre = pim = 0;
    for (int k = 0; k < sp->n; k++) {
        const sw_mode *m = &sp->mode[k];
        double scale = tol + 1e-9 * (fabs(re) + fabs(im) + fabs(pre) + fabs(pim));
        int same = fabs(m->re - re) + fabs(m->im - im) + fabs(m->pre - pre) + fabs(m->pim - pim) <= scale;
        int swapped = fabs(m->re - pre) + fabs(m->im - pim) + fabs(m->pre - re) + fabs(m->pim - im) <= scale;
        if (same || swapped)
            return;
    }
    sw_mode md = { re, im, pre, pim };
    if (sp->n < SW_TRUTH_MODES) {
        sp->mode[sp->n++] = md;
        return;
    }
    /* full: keep the stiffest */
    int soft = 0;
    for (int k = 1; k < sp->n; k++)
        if (hypot(sp->mode[k].re, sp->mode[k].im) < hypot(sp->mode[soft].re, sp->mode[soft].im))
            soft = k;
    if (hypot(re, im) > hypot(sp->mode[soft].re, sp->mode[soft].im))
        sp->mode[soft] = md;
}

static int by_stiffness(const void *a, const void *b)
{
    const sw_mode *x = a, *y = b;
    double p = hypot(x->re, x->im), q = hypot(y->re, y->im);
    return (p < q) - (p > q);
}

static void finish(sw_spectrum *sp)
{
    qsort(sp->mode, (size_t)sp->n, sizeof sp->mode[0], by_stiffness);
    sp->largest = 0;
    for (int k = 0; k < sp->n; k++)
        sp->largest = fmax(sp->largest, fmax(hypot(sp->mode[k].re, sp->mode[k].im),
                                              hypot(sp->mode[k].pre, sp->mode[k].pim)));
}

/* A flow: each point's 2x2 block, eigenvalues tr/2 ± √(tr²/4 - det). */
static int flow_spectrum(sw_system *sys, double t, const double *y, sw_spectrum *sp)
{
    int n = sys->n;
    double *jac = malloc((size_t)4 * n * sizeof *jac);
    if (!jac)
        return -1;
    sw_flow_jacobian(&sys->flow, t, y, jac);
    double big = 0;
    for (int i = 0; i < 4 * n; i++)
        big = fmax(big, fabs(jac[i]));
    double tol = 1e-9 * big + 1e-300;
    for (int i = 0; i < n; i++) {
        const double *j = jac + 4 * i;
        double half = 0.5 * (j[0] + j[3]), det = j[0] * j[3] - j[1] * j[2], disc = half * half - det;
        if (disc < 0) {
            double w = sqrt(-disc);
            add_mode(sp, half, w, half, -w, tol);
        } else {
            double r = sqrt(disc);
            add_mode(sp, half + r, 0, half + r, 0, tol);
            add_mode(sp, half - r, 0, half - r, 0, tol);
        }
    }
    free(jac);
    return 0;
}

/* The partner of a real eigenvalue λ of a second-order system: with φ the
 * null vector of Q(λ) = λ²I - λB - A (inverse iteration), the mode's own
 * equation is x'' = b x' + a x with b = φᵀBφ/φᵀφ, so μ = b - λ. */
static double real_partner(int n2, const double *A, const double *B, double lam, double scale, double *q,
                           double *phi)
{
    /* near enough to λ that inverse iteration gains 1e7 per pass towards
     * its null vector, far enough that Q stays invertible in rounding */
    double shift = lam + 1e-7 * scale;
    for (int i = 0; i < n2; i++)
        phi[i] = 1.0 + 0.01 * i;
    for (int it = 0; it < 3; it++) {
        for (int r = 0; r < n2; r++)
            for (int c = 0; c < n2; c++)
                q[r * n2 + c] = (r == c) * shift * shift - shift * B[r * n2 + c] - A[r * n2 + c];
        if (sw_dense_solve(n2, q, phi) != 0)
            break;
        double norm = sw_norm_inf(n2, phi);
        if (!(norm > 0) || !isfinite(norm))
            return -lam;
        for (int i = 0; i < n2; i++)
            phi[i] /= norm;
    }
    double num = 0, den = 0;
    for (int r = 0; r < n2; r++) {
        double bphi = 0;
        for (int c = 0; c < n2; c++)
            bphi += B[r * n2 + c] * phi[c];
        num += phi[r] * bphi;
        den += phi[r] * phi[r];
    }
    return (den > 0 ? num / den : 0.0) - lam;
}

/* A particle system of at most DENSE_PARTICLES: every eigenvalue of
 * J = [[0, I], [M⁻¹Fx, M⁻¹Fv]], less the modes the state cannot reach. A
 * coordinate at rest with no force on it (v_c = 0 and a_c = 0 exactly) and
 * not coupled, through Fx or Fv, to a moving one (or to one that is, and so
 * on) stays at rest forever: an exact symmetry keeps it so, as a spring
 * stretched along x never moves in y. Its modes (the sideways swing of the
 * stretched spring) are physics the run never shows, so they are left out,
 * or Euler would be called unstable on every damped spring. */
static int dense_particles(sw_system *sys, const double *y, sw_spectrum *sp)
{
    sw_particles *p = &sys->particles;
    int n2 = 2 * p->n;
    size_t nn = (size_t)n2 * n2;
    double *A = malloc((3 * nn + 4 * nn + 6 * (size_t)n2 + (size_t)n2) * sizeof *A);
    if (!A)
        return -1;
    double *B = A + nn, *q = B + nn, *J = q + nn, *re = J + 4 * nn, *im = re + 2 * n2, *phi = im + 2 * n2,
           *f = phi + 2 * n2;
    int *keep = malloc((size_t)n2 * sizeof *keep);
    if (!keep) {
        free(A);
        return -1;
    }
    sw_particles_jacobian(p, y, A, B);
    double big = 0;
    for (size_t i = 0; i < nn; i++) {
        A[i] *= p->inv_mass[(i / (size_t)n2) / 2]; /* A = M⁻¹Fx, B = M⁻¹Fv */
        B[i] *= p->inv_mass[(i / (size_t)n2) / 2];
        big = fmax(big, fmax(fabs(A[i]), fabs(B[i])));
    }
    /* the coordinates the motion can reach */
    double *dydt = malloc((size_t)2 * n2 * sizeof *dydt);
    if (!dydt) {
        free(keep);
        free(A);
        return -1;
    }
    p->ode.deriv(p, 0.0, y, dydt);
    memcpy(f, dydt + n2, (size_t)n2 * sizeof *f);
    free(dydt);
    /* moving: v_c or a_c not zero, or coupled through A or B to a moving
     * coordinate (a wave reaches the far end of a plucked chain) */
    int moving = 0, m = 0, grew = 1;
    for (int c = 0; c < n2; c++) {
        keep[c] = y[n2 + c] != 0 || f[c] != 0;
        moving += keep[c];
    }
    while (grew && moving > 0) {
        grew = 0;
        for (int c = 0; c < n2; c++)
            for (int d = 0; !keep[c] && d < n2; d++)
                if (keep[d] && fabs(A[c * n2 + d]) + fabs(B[c * n2 + d]) + fabs(A[d * n2 + c]) +
                                   fabs(B[d * n2 + c]) > 1e-14 * big) {
                    keep[c] = grew = 1;
                    moving++;
                }
    }
    for (int c = 0; c < n2; c++) /* at an equilibrium nothing moves: keep all */
        if (keep[c] || moving == 0)
            keep[m++] = c;
    /* A and B on the kept coordinates, packed m×m; J = [[0, I], [A, B]] */
    for (int r = 0; r < m; r++)
        for (int c = 0; c < m; c++) {
            A[r * m + c] = A[keep[r] * n2 + keep[c]];
            B[r * m + c] = B[keep[r] * n2 + keep[c]];
        }
    int dim = 2 * m;
    memset(J, 0, (size_t)dim * dim * sizeof *J);
    for (int r = 0; r < m; r++) {
        J[r * dim + m + r] = 1;
        for (int c = 0; c < m; c++) {
            J[(m + r) * dim + c] = A[r * m + c];
            J[(m + r) * dim + m + c] = B[r * m + c];
        }
    }
    int rc = m > 0 ? sw_eigenvalues(dim, J, re, im) : 0;
    if (rc == 0) {
        double top = 0;
        for (int k = 0; k < dim; k++)
            top = fmax(top, hypot(re[k], im[k]));
        double tol = 1e-9 * top + 1e-300;
        for (int k = 0; k < dim; k++) {
            if (im[k] < -tol)
                continue; /* the conjugate of the one before */
            if (im[k] > tol)
                add_mode(sp, re[k], im[k], re[k], -im[k], tol);
            else
                add_mode(sp, re[k], 0, real_partner(m, A, B, re[k], top + 1e-300, q, phi), 0, tol);
        }
    }
    free(keep);
    free(A);
    return rc;
}

/* Particles without springs move independently: each one's 4x4 block. */
static int free_particles(sw_system *sys, const double *y, sw_spectrum *sp)
{
    sw_particles *p = &sys->particles;
    int n = p->n, rc = 0;
    sw_particles one;
    char err[SW_ERRLEN];
    double drag = sw_particles_drag(p), cx, cy, mu, part[8];
    int central = sw_particles_central(p, &cx, &cy, &mu);
    for (int i = 0; i < n && rc == 0; i++) {
        /* a one-particle system with the same per-particle forces */
        if (sw_particles_init(&one, 1, p->mass[i], err, sizeof err) != SW_OK)
            return -1;
        if (drag > 0)
            sw_particles_add_drag(&one, drag);
        if (central)
            sw_particles_add_central(&one, cx, cy, mu);
        part[0] = y[2 * i];
        part[1] = y[2 * i + 1];
        part[2] = y[2 * n + 2 * i];
        part[3] = y[2 * n + 2 * i + 1];
        sw_system tmp = *sys;
        tmp.particles = one;
        tmp.n = 1;
        rc = dense_particles(&tmp, part, sp);
        sw_particles_free(&one);
        if (!central || sp->n == SW_TRUTH_MODES)
            break; /* uniform forces: every particle has the same modes */
    }
    return rc;
}

/* A large coupled system: the eigenvalue of M⁻¹Fx largest in size by power
 * iteration — the stiffest mode, -ω² (a compressed spring adds positive
 * eigenvalues, but only of the size of its tension over length, far below
 * its stiffness) — and that mode's damping from the Rayleigh quotient of
 * M⁻¹Fv on its vector. Exact for proportional damping, as a chain has. */
static int stiffest_particles(sw_system *sys, const double *y, sw_spectrum *sp)
{
    sw_particles *p = &sys->particles;
    int n2 = 2 * p->n;
    double *w = malloc((size_t)3 * n2 * sizeof *w);
    if (!w)
        return -1;
    double *v = w + n2, *e = v + n2;
    /* start from neighbours moving against each other: the stiffest modes
     * of springs between neighbours are close to that, so few passes do */
    for (int i = 0; i < n2; i++)
        v[i] = ((i / 2) % 2 ? -1.0 : 1.0) * (1.0 + 0.1 * sin(1.3 * i));
    double lam = 0;
    for (int it = 0; it < 100; it++) {
        sw_particles_jacobian_apply(p, y, 1.0, 0.0, v, w, it == 0);
        double num = 0, den = 0;
        for (int i = 0; i < n2; i++) {
            w[i] *= p->inv_mass[i / 2];
            num += v[i] * w[i];
            den += v[i] * v[i];
        }
        double norm = sw_norm_inf(n2, w), next = den > 0 ? num / den : 0;
        if (!(norm > 0) || !isfinite(norm))
            break;
        for (int i = 0; i < n2; i++)
            v[i] = w[i] / norm;
        if (it > 5 && fabs(next - lam) <= 1e-9 * fabs(next))
            break;
        lam = next;
    }
    /* lam: the eigenvalue of M⁻¹Fx largest in size (stiffest when < 0) */
    sw_particles_jacobian_apply(p, y, 0.0, 1.0, v, e, 0);
    double num = 0, den = 0;
    for (int i = 0; i < n2; i++) {
        num += v[i] * e[i] * p->inv_mass[i / 2];
        den += v[i] * v[i];
    }
    double b = den > 0 ? num / den : 0, a = lam, disc = 0.25 * b * b + a;
    double tol = 1e-9 * sqrt(fabs(a)) + 1e-300;
    if (disc < 0)
        add_mode(sp, 0.5 * b, sqrt(-disc), 0.5 * b, -sqrt(-disc), tol);
    else
        add_mode(sp, 0.5 * b + sqrt(disc), 0, 0.5 * b - sqrt(disc), 0, tol);
    free(w);
    sp->complete = 0;
    return 0;
}

int sw_truth_spectrum(sw_system *sys, double t, const double *y, sw_spectrum *out)
{
    memset(out, 0, sizeof *out);
    out->complete = 1;
    int rc;
    if (sys->kind == SW_SYS_FLOW) {
        out->order = 1;
        rc = flow_spectrum(sys, t, y, out);
    } else {
        out->order = 2;
        if (sys->n <= DENSE_PARTICLES)
            rc = dense_particles(sys, y, out);
        else if (sw_particles_spring_count(&sys->particles) == 0)
            rc = free_particles(sys, y, out);
        else
            rc = stiffest_particles(sys, y, out);
    }
    finish(out);
    return rc;
}

int sw_truth_limit_along(const sw_scene *sc, const double *p, const sw_integrator *m, double t_end,
                         int samples, double h_max, double *limit, int *unbounded, double *stiffest,
                         char *err, size_t errlen)
{
    sw_truth tr;
    int rc = sw_truth_init(&tr, sc, p, err, errlen);
    if (rc != SW_OK)
        return -1;
    double best = INFINITY, largest = 0;
    *unbounded = 1;
    sw_spectrum sp;
    for (int k = 0; k < samples; k++) {
        double t = samples > 1 ? t_end * k / (samples - 1) : 0;
        const double *y = sw_truth_at(&tr, t);
        if (!y) {
            if (k > 0)
                break;
            y = tr.sys.y; /* no truth: the start alone */
        }
        if (sw_truth_spectrum(&tr.sys, t, y, &sp) != 0) {
            snprintf(err, errlen, "%s: the eigenvalues of the linearisation did not converge at t = %g",
                     sc->name, t);
            sw_truth_free(&tr);
            return -1;
        }
        largest = fmax(largest, sp.largest);
        int unb;
        double h = sw_truth_limit(m, &sp, h_max, &unb);
        if (!unb)
            *unbounded = 0;
        if (h < best)
            best = h;
        if (!tr.y || (tr.source == SW_TRUTH_NONE))
            break;
    }
    sw_truth_free(&tr);
    *limit = best;
    if (stiffest)
        *stiffest = largest;
    return 0;
}
