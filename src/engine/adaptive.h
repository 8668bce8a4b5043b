/* Private to the engine: the step-size controller shared by the embedded
 * explicit Runge-Kutta pairs (rk45.c, dop853.c, rkn.c, rkn12.c) and the Rosenbrock
 * method (rosenbrock.c). A method supplies a trial
 * step over a range of the state; the controller runs it over the whole
 * state or slice by slice, accepts or rejects it, and proposes the next step.
 * Invariant: nothing is copied on an accepted step — the new state is
 * written in place (the old one saved for a retry) and the first-same-as-
 * last derivative stays where the trial wrote it (s->fsal names its slot). */
#ifndef SW_ENGINE_ADAPTIVE_H
#define SW_ENGINE_ADAPTIVE_H

#include <string.h>

#include "engine/clones.h"
#include "engine/stepper.h"

/* What a trial adds up over its range. */
typedef struct sw_trial_sums {
    double err;      /* Σ (e_i / sc_i)², e the method's error estimate */
    double err3;     /* dop853: Σ (e3_i / sc_i)², its 3rd-order estimate; else 0 */
    double part[2][4]; /* dop853: err and err3 by i mod 4 (four independent chains of additions) */
    unsigned beyond; /* some new y_i at or beyond the runaway exponent */
} sw_trial_sums;

/* part[i mod 4] += q[i] for i in [0, len): four chains of additions side
 * by side, as the four lanes of one vector (lane-wise IEEE additions, the
 * bits of four scalar chains whatever the vector width; a sliced trial's
 * slices start at multiples of 4, so it adds in a whole-state order).
 * Returns the four sums added pairwise, (p0 + p1) + (p2 + p3): the error
 * norm's sum of squares in dop853, rkn and rkn12. */
SW_INLINE double sw_add_by4(double part[4], const double *q, int len)
{
    typedef double v4d __attribute__((vector_size(4 * sizeof(double))));
    v4d s;
    int i;
    memcpy(&s, part, sizeof s);
    for (i = 0; i + 4 <= len; i += 4) {
        v4d a;
        memcpy(&a, q + i, sizeof a);
        s += a;
    }
    memcpy(part, &s, sizeof s);
    for (; i < len; i++)
        part[i & 3] += q[i];
    return (part[0] + part[1]) + (part[2] + part[3]);
}

/* A trial step of size h over [lo, hi), k1 = f(t, y) in slot s->fsal: the
 * old y saved to the method's `saved` slot, the new y written into y, the
 * derivative at the new state into the other FSAL slot, and the sums added
 * to *sums in increasing i (so a sliced run adds them in the same order). */
typedef void sw_trial_fn(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                         unsigned elim, sw_trial_sums *sums);

typedef struct sw_adaptive {
    sw_trial_fn *trial;
    int evals;         /* derivative evaluations per trial */
    int slice;         /* slice length on pointwise systems (even) */
    int coupled;       /* the trial needs the whole state (a linear solve): never sliced */
    int fsal_other;    /* the FSAL derivative alternates between slot 0 and this one */
    int saved;         /* slot of the saved old state */
    double expo;       /* error ∝ h^(1/expo): proposed factor safety·err^(-expo) */
    double safety, fac_min, fac_max;
    int hairer_norm;   /* DOP853's norm from err and err3 (else the RMS of err) */
    int hold;          /* after a rejection, the accepted step does not grow (DOP853) */
    int guess_first;   /* choose the first step (Hairer's HINIT) instead of h_max */
    int predict;       /* Gustafsson's predictive control, as in RADAU5: an accepted
                        * step's proposal is also at most what the change of the
                        * error constant over the last two accepted steps predicts */
} sw_adaptive;

/* One accepted step of at most h_max; 0, or SW_EDIVERGED when the step size
 * underflows or 200 trials fail. */
int sw_adaptive_step(const sw_adaptive *m, sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max);

#endif
