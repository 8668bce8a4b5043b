/* Spectra of the linearisation ∂f/∂y, split into modes: a complex pair, or
 * for a particle system a real eigenvalue with its partner (the other root
 * of the mode's own equation). Flows point by point; particle systems up
 * to DENSE_PARTICLES in full (dense QR), uncoupled ones particle by
 * particle, larger coupled ones by their stiffest mode. Modes that grow
 * physically, and modes an exact symmetry keeps at rest, are left out.
 * Invariant: with a workspace, nothing allocates once it is large enough. */
#include "sim/truth_work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/flow_jacobian.h"
#include "engine/linalg.h"
#include "engine/particles_solve.h"
#include "stepwise/stepwise.h"

/* Particle systems up to this size get every eigenvalue (dense QR on the
 * 4n×4n Jacobian, about 40 Mflop at the limit); larger coupled ones their
 * stiffest mode. */
#define DENSE_PARTICLES 32


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
    if (re == 0 && im == 0 && pre == 0 && pim == 0) {
        sp->free++; /* no force and no damping on it: every method maps it by exactly 1 */
        return;
    }
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

/* A flow: each point's 2x2 block, eigenvalues tr/2 ± √(tr²/4 - det). */
static int flow_spectrum(sw_truth_work *w, sw_system *sys, double t, const double *y, sw_spectrum *sp)
{
    int n = sys->n;
    double *jac = sw_truth_scratch(w, (size_t)4 * n);
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
            double r = sqrt(-disc);
            add_mode(sp, half, r, half, -r, tol);
        } else {
            double r = sqrt(disc);
            add_mode(sp, half + r, 0, half + r, 0, tol);
            add_mode(sp, half - r, 0, half - r, 0, tol);
        }
    }
    return 0;
}

/* The modes of x'' = B x' + A x on m coordinates (A, B row-major m×m):
 * the eigenvalues of J = [[0, I], [A, B]], a complex pair as one mode, a
 * real eigenvalue with its partner. scratch: 5m² + 5m doubles. */
static int second_order_modes(int m, const double *A, const double *B, double *scratch, sw_spectrum *sp)
{
    int dim = 2 * m;
    double *J = scratch, *q = J + (size_t)dim * dim, *re = q + (size_t)m * m, *im = re + dim, *phi = im + dim;
    memset(J, 0, (size_t)dim * dim * sizeof *J);
    for (int r = 0; r < m; r++) {
        J[r * dim + m + r] = 1;
        for (int c = 0; c < m; c++) {
            J[(m + r) * dim + c] = A[r * m + c];
            J[(m + r) * dim + m + c] = B[r * m + c];
        }
    }
    int rc = m > 0 ? sw_eigenvalues(dim, J, re, im) : 0;
    if (rc != 0)
        return rc;
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
    return 0;
}

/* A particle system of at most DENSE_PARTICLES: every eigenvalue of
 * J = [[0, I], [M⁻¹Fx, M⁻¹Fv]], less the modes the state cannot reach. A
 * coordinate at rest with no force on it (v_c = 0 and a_c = 0 exactly) and
 * not coupled, through Fx or Fv, to a moving one (or to one that is, and so
 * on) stays at rest forever: an exact symmetry keeps it so, as a spring
 * stretched along x never moves in y. Its modes (the sideways swing of the
 * stretched spring) are physics the run never shows, so they are left out,
 * or Euler would be called unstable on every damped spring. */
static int dense_particles(sw_truth_work *w, sw_system *sys, const double *y, sw_spectrum *sp)
{
    sw_particles *p = &sys->particles;
    int n2 = 2 * p->n;
    size_t nn = (size_t)n2 * n2;
    /* A, B, the modes' scratch and dydt (2·n2) */
    double *A = sw_truth_scratch(w, 2 * nn + 5 * nn + 5 * (size_t)n2 + 2 * (size_t)n2);
    if (!A)
        return -1;
    double *B = A + nn, *scratch = B + nn, *dydt = scratch + 5 * nn + 5 * (size_t)n2, *f = dydt + n2;
    if (sw_particles_jacobian(p, y, A, B) != 0)
        return -1;
    double big = 0;
    for (size_t i = 0; i < nn; i++) {
        A[i] *= p->inv_mass[(i / (size_t)n2) / 2]; /* A = M⁻¹Fx, B = M⁻¹Fv */
        B[i] *= p->inv_mass[(i / (size_t)n2) / 2];
        big = fmax(big, fmax(fabs(A[i]), fabs(B[i])));
    }
    /* the coordinates the motion can reach */
    p->ode.deriv(p, 0.0, y, dydt); /* f: its acceleration half */
    /* moving: v_c or a_c not zero, or coupled through A or B to a moving
     * coordinate (a wave reaches the far end of a plucked chain) */
    int moving = 0, m = 0, grew = 1, keep[4 * DENSE_PARTICLES];
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
    return second_order_modes(m, A, B, scratch, sp);
}

/* Particles no force joins move independently: each one's own 2x2 blocks
 * of ∂f/∂x and ∂f/∂v, from the engine. With the same fields on every
 * particle, all have the same modes unless a field depends on position
 * (central attraction): then each particle is asked. A particle whose
 * blocks per unit mass differ from the last one asked (a hot body's heat
 * slot, engine/force_heat.c; every particle of a fluid, whose blocks are
 * its neighbours' sum) is asked too. From particle *next on, asking at
 * most `budget` of them: 1 when done, 0 when there are more to ask, else
 * the eigenvalue solver's failure. Taken in slices or whole, the same
 * particles are asked in the same order: the same spectrum. */
static int free_modes(sw_particles *p, const double *own, int central, int *next, double *last, long budget,
                      sw_spectrum *sp)
{
    double scratch[5 * 2 * 2 + 5 * 2];
    for (; *next < p->n; ++*next) {
        int i = *next;
        double A[4], B[4];
        for (int k = 0; k < 4; k++) { /* per unit mass */
            A[k] = own[8 * i + k] * p->inv_mass[i];
            B[k] = own[8 * i + 4 + k] * p->inv_mass[i];
        }
        if (i > 0 && !central && memcmp(A, last, sizeof A) == 0 && memcmp(B, last + 4, sizeof B) == 0)
            continue;
        if (budget-- <= 0)
            return 0;
        memcpy(last, A, sizeof A);
        memcpy(last + 4, B, sizeof B);
        int rc = second_order_modes(2, A, B, scratch, sp);
        if (rc != 0)
            return rc;
        if (central && sp->n == SW_TRUTH_MODES) { /* full, add_mode keeps the stiffest: the others go on */
            *next = p->n;
            return 1;
        }
    }
    return 1;
}

static int free_particles(sw_truth_work *w, sw_system *sys, const double *y, sw_spectrum *sp)
{
    sw_particles *p = &sys->particles;
    double cx, cy, mu, last[8];
    int central = sw_particles_central(p, &cx, &cy, &mu), next = 0;
    const double *own = sw_particles_own_blocks(p, y);
    (void)w;
    if (!own)
        return -1;
    int rc = free_modes(p, own, central, &next, last, p->n, sp);
    return rc == 1 ? 0 : rc;
}

/* A large coupled system: the eigenvalue of M⁻¹Fx largest in size by power
 * iteration — the stiffest mode, -ω² (a compressed spring adds positive
 * eigenvalues, but only of the size of its tension over length, far below
 * its stiffness) — and that mode's damping from the Rayleigh quotient of
 * M⁻¹Fv on its vector. Exact for proportional damping, as a chain has.
 * Power iteration on M⁻¹Fx - shift·I runs from a fixed start (neighbours
 * moving against each other: the stiffest modes of springs between
 * neighbours are close to that, so few passes do), or from the last
 * vector (warm), for at most POWER_ITERATIONS passes. It runs as a job a
 * given number of passes at a time, so the live meter spreads it over
 * frames; run whole, it is the synchronous computation, pass for pass. */
#define POWER_ITERATIONS 100

enum { JOB_MAIN, JOB_SHIFTED, JOB_DAMPING, JOB_FREE };

static void power_start(sw_spectrum_job *j, double shift, int warm)
{
    if (!warm)
        for (int i = 0; i < j->n2; i++)
            j->v[i] = ((i / 2) % 2 ? -1.0 : 1.0) * (1.0 + 0.1 * sin(1.3 * i));
    j->shift = shift;
    j->it = 0;
    j->lam = 0;
}

/* Up to `passes` passes of power iteration; 1 when it has converged or
 * used its passes (j->lam: its eigenvalue largest in size, v its vector),
 * 0 when it has more to do, -1 on failure. */
static int power_passes(sw_spectrum_job *j, sw_particles *p, const double *y, long *passes)
{
    int n2 = j->n2;
    double *v = j->v, *w = j->w;
    for (; j->it < POWER_ITERATIONS; j->it++) {
        if (*passes <= 0)
            return 0;
        if (!j->assembled) { /* the blocks at y, first (a slice of its own when sliced) */
            if (!sw_particles_own_blocks(p, y))
                return -1;
            j->assembled = 1;
            if (j->sliced) {
                *passes = 0;
                return 0;
            }
        }
        --*passes;
        if (sw_particles_jacobian_apply(p, y, 1.0, 0.0, v, w, 0) != 0)
            return -1;
        double num = 0, den = 0;
        for (int i = 0; i < n2; i++) {
            w[i] *= p->inv_mass[i / 2];
            if (j->shift != 0)
                w[i] -= j->shift * v[i];
            num += v[i] * w[i];
            den += v[i] * v[i];
        }
        double norm = sw_norm_inf(n2, w), next = den > 0 ? num / den : 0;
        if (!(norm > 0) || !isfinite(norm))
            return 1;
        for (int i = 0; i < n2; i++)
            v[i] = w[i] / norm;
        if (j->it > 5 && fabs(next - j->lam) <= 1e-9 * fabs(next))
            return 1;
        j->lam = next;
    }
    return 1;
}

/* The stiffest mode from the job's eigenvalue: its damping from M⁻¹Fv on v. */
static void stiffest_mode(sw_spectrum_job *j, sw_particles *p, const double *y, sw_spectrum *sp)
{
    int n2 = j->n2;
    double *v = j->v, *e = j->w, lam = j->lam_main;
    (void)sw_particles_jacobian_apply(p, y, 0.0, 1.0, v, e, 0); /* (the blocks are there) */
    double num = 0, den = 0;
    for (int i = 0; i < n2; i++) {
        num += v[i] * e[i] * p->inv_mass[i / 2];
        den += v[i] * v[i];
    }
    double b = den > 0 ? num / den : 0, a = lam, disc = 0.25 * b * b + a;
    double tol = 1e-9 * sqrt(fabs(a)) + 1e-300;
    sp->growing = j->growing;
    if (disc < 0)
        add_mode(sp, 0.5 * b, sqrt(-disc), 0.5 * b, -sqrt(-disc), tol);
    else
        add_mode(sp, 0.5 * b + sqrt(disc), 0, 0.5 * b - sqrt(disc), 0, tol);
    sp->complete = 0;
}

/* Run the job on for up to `passes` passes (each one product with the
 * Jacobian; the first also assembles its blocks at y). 1 with sp filled,
 * 0 when there is more to do, -1 on failure. */
static int job_run(sw_spectrum_job *j, sw_particles *p, const double *y, long passes, sw_spectrum *sp)
{
    for (;;) {
        int rc = power_passes(j, p, y, &passes);
        if (rc <= 0)
            return rc;
        if (j->stage == JOB_MAIN) {
            j->lam_main = j->lam;
            j->growing = 0;
            j->stage = JOB_DAMPING;
            if (j->lam > 0) { /* a mode that grows physically (a tidal stretch) is the largest: the
                                 stiffest oscillation is the most negative, the largest of M⁻¹Fx - lam I */
                j->stage = JOB_SHIFTED;
                power_start(j, j->lam_main, 0);
                continue;
            }
        } else if (j->stage == JOB_SHIFTED) {
            double below = j->lam;
            if (below + j->lam_main < 0) {
                j->growing = 1;
                j->lam_main = below + j->lam_main;
            }
            j->stage = JOB_DAMPING;
        }
        memset(sp, 0, sizeof *sp);
        sp->order = 2;
        /* lam_main: the eigenvalue of M⁻¹Fx largest in size (stiffest when < 0) */
        stiffest_mode(j, p, y, sp);
        finish(sp);
        /* v is the main iteration's vector unless a shifted one replaced it */
        j->warm_ok = !j->growing && j->lam_main == j->lam_main && j->shift == 0;
        j->active = 0;
        return 1;
    }
}

static int stiffest_particles(sw_truth_work *ws, sw_system *sys, const double *y, sw_spectrum *sp)
{
    sw_particles *p = &sys->particles;
    int n2 = 2 * p->n;
    double *w = sw_truth_scratch(ws, (size_t)2 * n2);
    if (!w)
        return -1;
    sw_spectrum_job j = { .active = 1, .stage = JOB_MAIN, .n2 = n2, .v = w + n2, .w = w };
    power_start(&j, 0.0, 0);
    int growing = sp->growing;
    if (job_run(&j, p, y, (long)3 * POWER_ITERATIONS, sp) != 1)
        return -1;
    sp->growing += growing;
    return 0;
}

/* One particle's modes (a 4x4 QR and the partners' inverse iteration,
 * some 16 thousand instructions) cost about as much as this many
 * components of a power pass: a free-particle job's budget per pass. */
#define FREE_COST 512

int sw_truth_spectrum_sliced(const sw_system *sys, long slice)
{
    if (sys->kind != SW_SYS_PARTICLES || sys->n <= DENSE_PARTICLES)
        return 0;
    if (!sw_particles_coupled(&sys->particles))
        return (double)FREE_COST * sys->n > (double)slice;
    return (double)POWER_ITERATIONS * 2.0 * sys->n > (double)slice;
}

int sw_spectrum_job_start(sw_spectrum_job *j, const sw_system *sys, double t)
{
    int n2 = 2 * sys->n, warm = j->warm_ok && j->n2 == n2 && j->v;
    if ((size_t)n2 > j->cap) {
        free(j->buf);
        j->buf = malloc((size_t)2 * n2 * sizeof *j->buf);
        j->cap = j->buf ? (size_t)n2 : 0;
        warm = 0;
        if (!j->buf)
            return -1;
    }
    j->n2 = n2;
    j->v = j->buf + n2;
    j->w = j->buf;
    j->t = t;
    j->active = 1;
    j->assembled = 0;
    j->sliced = 1;
    j->stage = JOB_MAIN;
    j->growing = 0;
    j->warm_ok = 0;
    power_start(j, 0.0, warm);
    j->own = NULL;
    if (!sw_particles_coupled(&sys->particles)) {
        j->stage = JOB_FREE;
        j->next = 0;
        memset(&j->part, 0, sizeof j->part);
        j->part.complete = 1;
        j->part.order = 2;
    }
    return 0;
}

/* A free-particle job: the blocks at y on the first call, then up to
 * passes · 2n / FREE_COST particles a call. */
static int free_job_run(sw_spectrum_job *j, sw_particles *p, const double *y, long passes, sw_spectrum *out)
{
    if (!j->own) {
        double cx, cy, mu;
        j->central = sw_particles_central(p, &cx, &cy, &mu);
        if (!(j->own = sw_particles_own_blocks(p, y)))
            return -1;
    }
    double budget = (double)passes * j->n2 / FREE_COST;
    int rc = free_modes(p, j->own, j->central, &j->next, j->last, budget < 1 ? 1 : (long)budget, &j->part);
    if (rc != 1)
        return rc == 0 ? 0 : -1;
    *out = j->part;
    finish(out);
    j->active = 0;
    return 1;
}

int sw_spectrum_job_run(sw_spectrum_job *j, sw_system *sys, const double *y, long passes, sw_spectrum *out)
{
    if (!j->active)
        return -1;
    int rc = j->stage == JOB_FREE ? free_job_run(j, &sys->particles, y, passes < 1 ? 1 : passes, out)
                                  : job_run(j, &sys->particles, y, passes < 1 ? 1 : passes, out);
    if (rc < 0)
        j->active = 0;
    return rc;
}

void sw_spectrum_job_free(sw_spectrum_job *j)
{
    free(j->buf);
    memset(j, 0, sizeof *j);
}

int sw_truth_spectrum_with(sw_truth_work *w, sw_system *sys, double t, const double *y, sw_spectrum *out)
{
    memset(out, 0, sizeof *out);
    out->complete = 1;
    int rc;
    if (sys->kind == SW_SYS_FLOW) {
        out->order = 1;
        rc = flow_spectrum(w, sys, t, y, out);
    } else {
        out->order = 2;
        if (!sw_particles_coupled(&sys->particles))
            rc = free_particles(w, sys, y, out);
        else if (sys->n <= DENSE_PARTICLES)
            rc = dense_particles(w, sys, y, out);
        else
            rc = stiffest_particles(w, sys, y, out);
    }
    finish(out);
    return rc;
}

int sw_truth_spectrum(sw_system *sys, double t, const double *y, sw_spectrum *out)
{
    sw_truth_work *w = sw_truth_work_new();
    int rc = w ? sw_truth_spectrum_with(w, sys, t, y, out) : -1;
    sw_truth_work_free(w);
    return rc;
}
