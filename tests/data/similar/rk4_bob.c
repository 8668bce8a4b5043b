/*
 * rk4.c -- Bob Tanaka, CS 559 homework 4
 *
 * Classical RK4 written with a Butcher tableau: the stage states are built
 * by one helper, and the update is a weighted sum over the stages.
 */
#include <stepwise/integrator.h>

#define STAGES 4

static const double c_nodes[STAGES] = { 0.0, 0.5, 0.5, 1.0 };
static const double b_weights[STAGES] = { 1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6 };

/* out = base + a * slope, over n entries */
static void axpy(int n, double a, const double *slope, const double *base, double *out)
{
    int i = 0;
    while (i < n) {
        out[i] = base[i] + a * slope[i];
        ++i;
    }
}

static int bob_rk4(sw_ode *ode, double t, double *y, double h, double *work)
{
    const int n = ode->dim;
    double *k[STAGES];
    double *stage_y = work + STAGES * n;
    int s;

    for (s = 0; s < STAGES; ++s)
        k[s] = work + s * n;

    sw_ode_eval(ode, t, y, k[0]);
    for (s = 1; s < STAGES; ++s) {
        /* RK4's tableau is diagonal: stage s uses only the slope before it */
        axpy(n, c_nodes[s] * h, k[s - 1], y, stage_y);
        sw_ode_eval(ode, t + c_nodes[s] * h, stage_y, k[s]);
    }

    for (int i = 0; i < n; ++i) {
        double sum = 0.0;
        for (s = 0; s < STAGES; ++s)
            sum += b_weights[s] * k[s][i];
        y[i] = y[i] + h * sum;
    }
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI,
    .name = "bob-rk4",
    .label = "Runge-Kutta, tableau form",
    .order = 4,
    .evals = STAGES,
    .work_vectors = STAGES + 1,
    .step = bob_rk4,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
