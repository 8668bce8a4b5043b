/* The linear stability of a method along a run: the spectra of the scene's
 * linearisation at sample times along the true solution, and each method's
 * limit and growth from them. The spectra depend on the scene, its
 * parameters and the sample times only, not on the method, and the true
 * solution behind them can be a long tight reference run (the gyre's 400
 * points: seconds), so the last run's spectra are kept and every method
 * asked about the same run reads them (`stability --all` asks ten).
 * Invariant: a method's answer is the same bit for bit whether the spectra
 * were kept or computed afresh. */
#include "sim/truth.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

/* The spectra along the last run asked about. Single-threaded, as the rest
 * of the truth module's callers are; a different run replaces it. */
typedef struct along_memo {
    const sw_scene *sc;           /* NULL: empty */
    double p[SW_MAX_PARAMS];
    double t_end;
    int samples;
    int count;                    /* spectra computed: samples 0 .. count-1 */
    int failed;                   /* 1: the spectrum at sample `count` did not converge */
    int stop_after;               /* 1: no truth beyond the start; the run stops after sample 0 */
    sw_spectrum *sp;              /* samples of them */
    double *t;
    double ref_work;              /* what the reference run spent (sw_truth_eval_work × evaluations) */
} along_memo;

static along_memo memo;

static int memo_matches(const sw_scene *sc, const double *p, double t_end, int samples)
{
    double key[SW_MAX_PARAMS];
    sw_scene_fill(sc, p, key); /* NULL: the defaults */
    return memo.sc == sc && memo.t_end == t_end && memo.samples == samples &&
           memcmp(memo.p, key, sizeof key) == 0;
}

/* Fill the memo for this run: the truth at each sample time (the start alone
 * where there is none) and its spectrum, up to the first sample with no
 * truth or whose eigenvalues do not converge. 0, or SW_ENOMEM / the truth's
 * status with err filled. */
static int memo_fill(const sw_scene *sc, const double *p, double t_end, int samples, char *err,
                     size_t errlen)
{
    if (memo_matches(sc, p, t_end, samples))
        return SW_OK;
    memo.sc = NULL;
    sw_spectrum *sp = realloc(memo.sp, (size_t)(samples > 0 ? samples : 1) * sizeof *sp);
    if (sp)
        memo.sp = sp;
    double *ts = sp ? realloc(memo.t, (size_t)(samples > 0 ? samples : 1) * sizeof *ts) : NULL;
    if (ts)
        memo.t = ts;
    if (!sp || !ts) {
        snprintf(err, errlen, "out of memory for %d spectra", samples);
        return SW_ENOMEM;
    }
    sw_truth tr;
    int rc = sw_truth_init(&tr, sc, p, err, errlen);
    if (rc != SW_OK)
        return rc;
    /* Only the sample times are asked for: the reference run's frames end
     * there, and between them it steps as its tolerance allows, not at most
     * the scene's dt. (`stability river`, 60 points over a horizon of
     * 19635 s, 100 periods of its slowest start mode: 1.1 s in frames of
     * 0.1, now 0.07 s; `stability gyre`, 400 points over 641 s: 2.2 s and
     * 1.75 s.) */
    if (samples > 1)
        tr.frame = fmin(t_end / (samples - 1), SW_DT_MAX);
    memo.count = memo.failed = memo.stop_after = 0;
    for (int k = 0; k < samples; k++) {
        double t = samples > 1 ? t_end * k / (samples - 1) : 0;
        const double *y = sw_truth_at(&tr, t);
        if (!y) {
            if (k > 0)
                break;
            y = tr.sys.y; /* no truth: the start alone */
        }
        memo.t[k] = t;
        if (sw_truth_spectrum(&tr.sys, t, y, &memo.sp[k]) != 0) {
            memo.failed = 1;
            break;
        }
        memo.count = k + 1;
        if (tr.source == SW_TRUTH_NONE) {
            memo.stop_after = 1;
            break;
        }
    }
    memo.ref_work = 0;
    if (tr.have_ref) {
        double solve, eval = sw_truth_eval_work(&tr.ref.sys, &solve);
        memo.ref_work = (double)sw_sim_evals(&tr.ref) * eval + (double)tr.ref.sys.ode->solver_iters * solve;
    }
    sw_truth_free(&tr);
    memo.sc = sc;
    sw_scene_fill(sc, p, memo.p);
    memo.t_end = t_end;
    memo.samples = samples;
    return SW_OK;
}

int sw_truth_along_run(const sw_scene *sc, const double *p, const sw_integrator *m, double t_end, int samples,
                       double h_max, double h, sw_truth_along *out, char *err, size_t errlen)
{
    *out = (sw_truth_along){ .limit = INFINITY, .unbounded = 1, .growth = NAN, .growth_lambda = NAN };
    if (!(h > 0))
        out->growth_total = NAN;
    if (memo_fill(sc, p, t_end, samples, err, errlen) != SW_OK)
        return -1;
    out->ref_work = memo.ref_work;
    for (int k = 0; k <= memo.count && k < samples; k++) {
        if (k == memo.count) {
            if (!memo.failed)
                break;
            snprintf(err, errlen, "%s: the eigenvalues of the linearisation did not converge at t = %g",
                     sc->name, memo.t[k]);
            return -1;
        }
        const sw_spectrum *sp = &memo.sp[k];
        double t = memo.t[k];
        out->stiffest = fmax(out->stiffest, sp->largest);
        int unb;
        double lim = sw_truth_limit(m, sp, h_max, &unb);
        if (!unb)
            out->unbounded = 0;
        if (lim < out->limit || isnan(lim)) {
            out->limit = lim;
            out->t_limit = t;
        }
        if (h > 0 && !isnan(lim)) {
            int worst = -1;
            double g = sw_truth_growth_all(m, sp, h, &worst);
            double seg = samples > 1 ? t_end / (samples - 1) : t_end;
            out->growth_total += log(g) * (k == 0 || k == samples - 1 ? seg / 2 : seg) / h;
            if (!(g <= out->growth)) {
                out->growth = g;
                out->t_growth = t;
                out->growth_lambda = worst >= 0 ? hypot(sp->mode[worst].re, sp->mode[worst].im) : NAN;
            }
        }
        if (isnan(lim))
            break; /* the method fails on its test systems */
        if (memo.stop_after)
            break;
    }
    out->growth_total = exp(out->growth_total);
    return 0;
}
