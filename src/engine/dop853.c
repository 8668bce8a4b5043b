/* DOP853: Dormand and Prince's explicit Runge-Kutta method of order 8 with
 * Hairer's error estimate from embedded 5th- and 3rd-order solutions and his
 * step-size control (Hairer, Nørsett & Wanner, Solving ODEs I, section II.10,
 * and the code DOP853). 12 stages; the derivative at the new state is the
 * next step's first stage (FSAL), so a step costs 12 evaluations. Each stage
 * is one loop over the state (over L1-sized slices on pointwise systems);
 * nothing is copied on an accepted step. */
#include "engine/adaptive.h"

#include <math.h>

#include "stepwise/base.h"

/* The tableau as printed in DOP853 (30 digits; verified against the 200
 * order conditions up to order 8 by tests/check_dop853.c). Stage j's
 * coefficients are Aj_i; zero entries are left out. */
static const double C2 = 0.526001519587677318785587544488e-01, C3 = 0.789002279381515978178381316732e-01,
    C4 = 0.118350341907227396726757197510, C5 = 0.281649658092772603273242802490,
    C6 = 0.333333333333333333333333333333, C7 = 0.25, C8 = 0.307692307692307692307692307692,
    C9 = 0.651282051282051282051282051282, C10 = 0.6, C11 = 0.857142857142857142857142857142;
static const double A2_1 = 5.26001519587677318785587544488e-2;
static const double A3_1 = 1.97250569845378994544595329183e-2, A3_2 = 5.91751709536136983633785987549e-2;
static const double A4_1 = 2.95875854768068491816892993775e-2, A4_3 = 8.87627564304205475450678981324e-2;
static const double A5_1 = 2.41365134159266685502369798665e-1, A5_3 = -8.84549479328286085344864962717e-1,
    A5_4 = 9.24834003261792003115737966543e-1;
static const double A6_1 = 3.7037037037037037037037037037e-2, A6_4 = 1.70828608729473871279604482173e-1,
    A6_5 = 1.25467687566822425016691814123e-1;
static const double A7_1 = 3.7109375e-2, A7_4 = 1.70252211019544039314978060272e-1,
    A7_5 = 6.02165389804559606850219397283e-2, A7_6 = -1.7578125e-2;
static const double A8_1 = 3.70920001185047927108779319836e-2, A8_4 = 1.70383925712239993810214054705e-1,
    A8_5 = 1.07262030446373284651809199168e-1, A8_6 = -1.53194377486244017527936158236e-2,
    A8_7 = 8.27378916381402288758473766002e-3;
static const double A9_1 = 6.24110958716075717114429577812e-1, A9_4 = -3.36089262944694129406857109825,
    A9_5 = -8.68219346841726006818189891453e-1, A9_6 = 2.75920996994467083049415600797e1,
    A9_7 = 2.01540675504778934086186788979e1, A9_8 = -4.34898841810699588477366255144e1;
static const double A10_1 = 4.77662536438264365890433908527e-1, A10_4 = -2.48811461997166764192642586468,
    A10_5 = -5.90290826836842996371446475743e-1, A10_6 = 2.12300514481811942347288949897e1,
    A10_7 = 1.52792336328824235832596922938e1, A10_8 = -3.32882109689848629194453265587e1,
    A10_9 = -2.03312017085086261358222928593e-2;
static const double A11_1 = -9.3714243008598732571704021658e-1, A11_4 = 5.18637242884406370830023853209,
    A11_5 = 1.09143734899672957818500254654, A11_6 = -8.14978701074692612513997267357,
    A11_7 = -1.85200656599969598641566180701e1, A11_8 = 2.27394870993505042818970056734e1,
    A11_9 = 2.49360555267965238987089396762, A11_10 = -3.0467644718982195003823669022;
static const double A12_1 = 2.27331014751653820792359768449, A12_4 = -1.05344954667372501984066689879e1,
    A12_5 = -2.00087205822486249909675718444, A12_6 = -1.79589318631187989172765950534e1,
    A12_7 = 2.79488845294199600508499808837e1, A12_8 = -2.85899827713502369474065508674,
    A12_9 = -8.87285693353062954433549289258, A12_10 = 1.23605671757943030647266201528e1,
    A12_11 = 6.43392746015763530355970484046e-1;
/* The 8th-order weights (stages 2-5 have none). */
static const double B1 = 5.42937341165687622380535766363e-2, B6 = 4.45031289275240888144113950566,
    B7 = 1.89151789931450038304281599044, B8 = -5.8012039600105847814672114227,
    B9 = 3.1116436695781989440891606237e-1, B10 = -1.52160949662516078556178806805e-1,
    B11 = 2.01365400804030348374776537501e-1, B12 = 4.47106157277725905176885569043e-2;
/* The 3rd-order solution's weights (its error estimate is b - bhh) ... */
static const double BHH1 = 0.244094488188976377952755905512, BHH9 = 0.733846688281611857341361741547,
    BHH12 = 0.220588235294117647058823529412e-1;
/* ... and b - b5, b5 the 5th-order solution's weights. */
static const double ER1 = 0.1312004499419488073250102996e-1, ER6 = -0.1225156446376204440720569753e+1,
    ER7 = -0.4957589496572501915214079952, ER8 = 0.1664377182454986536961530415e+1,
    ER9 = -0.3503288487499736816886487290, ER10 = 0.3341791187130174790297318841,
    ER11 = 0.8192320648511571246570742613e-1, ER12 = -0.2235530786388629525884427845e-1;

/* Workspace slots. k2 and k3 are dead after stage 5, so stages 11 and 12
 * reuse them; the FSAL derivative goes where k4 was (dead after stage 12),
 * and slots 0 and 3 swap the roles of k1 and k4 from step to step. */
enum { S_K2 = 1, S_K3 = 2, S_K4 = 3, S_K5 = 4, S_K6, S_K7, S_K8, S_K9, S_K10, S_YT, S_SAVED, DOP853_VECTORS };

/* Four doubles as one value (a GNU C vector: each operation the lane-wise
 * IEEE operation). */
typedef double v4d __attribute__((vector_size(4 * sizeof(double))));

/* Component i's 5th- and 3rd-order error estimates, scaled by 1/sk, from
 * b·k, the old state y0 and the new one y1. */
static inline void dop853_errors(int i, double bk, double y0, double y1, double atol, double rtol,
                                 const double *restrict k1, const double *restrict k2, const double *restrict k3,
                                 const double *restrict k6, const double *restrict k7, const double *restrict k8,
                                 const double *restrict k9, const double *restrict k10, double *e3, double *e5)
{
    double a0 = fabs(y0), a1 = fabs(y1);
    double r = 1.0 / (atol + rtol * (a1 > a0 ? a1 : a0));
    *e3 = (bk - BHH1 * k1[i] - BHH9 * k9[i] - BHH12 * k3[i]) * r;
    *e5 = (ER1 * k1[i] + ER6 * k6[i] + ER7 * k7[i] + ER8 * k8[i] + ER9 * k9[i] + ER10 * k10[i] + ER11 * k2[i] +
           ER12 * k3[i]) * r;
}

/* The stages over len components. Every vector is a restrict parameter, so the
 * compiler knows they do not overlap and vectorises each stage loop
 * without run-time overlap checks. k11 and k12 are written into k2 and k3. */
SW_CLONES static void dop853_range(sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim,
                         double atol, double rtol, const double *restrict k1, double *restrict k2,
                         double *restrict k3, double *restrict k4, double *restrict k5, double *restrict k6,
                         double *restrict k7, double *restrict k8, double *restrict k9, double *restrict k10,
                         double *restrict yt, double *restrict saved, sw_trial_sums *sums)
{
    int i;
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A2_1 * k1[i]);
    sw_eval_slice(ode, t + C2 * h, len, yt, k2);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A3_1 * k1[i] + A3_2 * k2[i]);
    sw_eval_slice(ode, t + C3 * h, len, yt, k3);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A4_1 * k1[i] + A4_3 * k3[i]);
    sw_eval_slice(ode, t + C4 * h, len, yt, k4);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A5_1 * k1[i] + A5_3 * k3[i] + A5_4 * k4[i]);
    sw_eval_slice(ode, t + C5 * h, len, yt, k5);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A6_1 * k1[i] + A6_4 * k4[i] + A6_5 * k5[i]);
    sw_eval_slice(ode, t + C6 * h, len, yt, k6);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A7_1 * k1[i] + A7_4 * k4[i] + A7_5 * k5[i] + A7_6 * k6[i]);
    sw_eval_slice(ode, t + C7 * h, len, yt, k7);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A8_1 * k1[i] + A8_4 * k4[i] + A8_5 * k5[i] + A8_6 * k6[i] + A8_7 * k7[i]);
    sw_eval_slice(ode, t + C8 * h, len, yt, k8);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A9_1 * k1[i] + A9_4 * k4[i] + A9_5 * k5[i] + A9_6 * k6[i] + A9_7 * k7[i] +
                            A9_8 * k8[i]);
    sw_eval_slice(ode, t + C9 * h, len, yt, k9);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A10_1 * k1[i] + A10_4 * k4[i] + A10_5 * k5[i] + A10_6 * k6[i] + A10_7 * k7[i] +
                            A10_8 * k8[i] + A10_9 * k9[i]);
    sw_eval_slice(ode, t + C10 * h, len, yt, k10);
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A11_1 * k1[i] + A11_4 * k4[i] + A11_5 * k5[i] + A11_6 * k6[i] + A11_7 * k7[i] +
                            A11_8 * k8[i] + A11_9 * k9[i] + A11_10 * k10[i]);
    sw_eval_slice(ode, t + C11 * h, len, yt, k2); /* k11 */
    for (i = 0; i < len; i++)
        yt[i] = y[i] + h * (A12_1 * k1[i] + A12_4 * k4[i] + A12_5 * k5[i] + A12_6 * k6[i] + A12_7 * k7[i] +
                            A12_8 * k8[i] + A12_9 * k9[i] + A12_10 * k10[i] + A12_11 * k2[i]);
    sw_eval_slice(ode, t + h, len, yt, k3); /* k12 */
    /* The new state in place (the old one saved for a retry), its runaway
     * test, and both error terms, each scaled by sk = atol + rtol·max(|y0|,
     * |y1|) and squared, into k5 and k4 (free until the FSAL evaluation
     * below): one loop that vectorises. The sums add the terms by i mod 4
     * (four chains of additions side by side, as the four lanes of one
     * vector: lane-wise IEEE additions, the bits of four scalar chains;
     * slices start at multiples of 4, so a sliced pass adds in the same
     * order as a whole-state one). */
    unsigned long long over = 0, add = sw_beyond_add(elim);
    for (i = 0; i < len; i++) {
        double y0 = y[i], e3, e5;
        double bk = B1 * k1[i] + B6 * k6[i] + B7 * k7[i] + B8 * k8[i] + B9 * k9[i] + B10 * k10[i] +
                    B11 * k2[i] + B12 * k3[i];
        double y1 = y0 + h * bk;
        saved[i] = y0;
        y[i] = y1;
        over |= sw_beyond_bits(y1, add);
        dop853_errors(i, bk, y0, y1, atol, rtol, k1, k2, k3, k6, k7, k8, k9, k10, &e3, &e5);
        k5[i] = e5 * e5;
        k4[i] = e3 * e3;
    }
    double (*part)[4] = sums->part;
    v4d s5, s3;
    memcpy(&s5, part[0], sizeof s5);
    memcpy(&s3, part[1], sizeof s3);
    for (i = 0; i + 4 <= len; i += 4) {
        v4d a5, a3;
        memcpy(&a5, k5 + i, sizeof a5);
        memcpy(&a3, k4 + i, sizeof a3);
        s5 += a5;
        s3 += a3;
    }
    memcpy(part[0], &s5, sizeof s5);
    memcpy(part[1], &s3, sizeof s3);
    for (; i < len; i++) {
        part[0][i & 3] += k5[i];
        part[1][i & 3] += k4[i];
    }
    sums->err = (part[0][0] + part[0][1]) + (part[0][2] + part[0][3]);
    sums->err3 = (part[1][0] + part[1][1]) + (part[1][2] + part[1][3]);
    sums->beyond |= sw_beyond_any(over);
    sw_eval_slice(ode, t + h, len, y, k4); /* FSAL: the next step's k1 */
}

/* The FSAL pair (k1 and k4's slots) and the saved state are state-long
 * (they outlive a slice); the other stage vectors are slice-local. */
static void dop853_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                         unsigned elim, sw_trial_sums *sums)
{
    dop853_range(ode, t, y + lo, h, hi - lo, elim, s->atol, s->rtol, SW_WORK(s, s->fsal) + lo, SW_WORK(s, S_K2),
                 SW_WORK(s, S_K3), SW_WORK(s, s->fsal ? 0 : S_K4) + lo, SW_WORK(s, S_K5), SW_WORK(s, S_K6),
                 SW_WORK(s, S_K7), SW_WORK(s, S_K8), SW_WORK(s, S_K9), SW_WORK(s, S_K10), SW_WORK(s, S_YT),
                 SW_WORK(s, S_SAVED) + lo, sums);
}

static const sw_adaptive dop853 = {
    .trial = dop853_trial,
    .evals = 12,
    .slice = 256,
    .fsal_other = S_K4,
    .saved = S_SAVED,
    .expo = 1.0 / 8,
    .safety = 0.9,
    .fac_min = 1.0 / 3,
    .fac_max = 6.0,
    .hairer_norm = 1,
    .hold = 1,
    .guess_first = 1,
};

/* Keep the table entry's workspace in step with the slots above. */
_Static_assert(DOP853_VECTORS == 12, "dop853 needs 12 work vectors (integrators.c)");

int sw_step_dop853(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&dop853, s, ode, t, y, h_max);
}
