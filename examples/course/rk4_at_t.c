/* A plausible mistake for the course's worked example (docs/grading.md):
 * RK4 with every stage evaluated at the step's start time t. Right on an
 * autonomous system (the chain), wrong where the flow changes with time
 * (the double gyre): why a plugin homework has more than one part. */
#include <stepwise/integrator.h>

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *k1 = work, *k2 = work + n, *k3 = work + 2 * n, *k4 = work + 3 * n, *tmp = work + 4 * n;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t, tmp, k2);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k2[i];
    sw_ode_eval(ode, t, tmp, k3);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + h * k3[i];
    sw_ode_eval(ode, t, tmp, k4);
    for (int i = 0; i < n; i++)
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "rk4-at-t", .label = "RK4, every stage at t",
    .order = 4, .evals = 4, .work_vectors = 5, .step = step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
