/* Dormand–Prince 5(4): the adaptive explicit method with an embedded
 * fourth-order error estimate, FSAL, and rtol/atol step control. */
#include "engine/stepper.h"

#include <math.h>
#include <string.h>

#include "stepwise/base.h"

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
int sw_step_rk45(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    int n = ode->dim;
    double *k[7], *yt = SW_WORK(s, 7), *y1 = SW_WORK(s, 8);
    for (int j = 0; j < 7; j++)
        k[j] = SW_WORK(s, j);
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

