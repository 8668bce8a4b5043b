/* Homework 4: classical Runge-Kutta (RK4) as a stepwise plugin.
 * Alice Moreau. */
#include <stepwise/integrator.h>

/* One RK4 step: four slopes, weighted 1/6, 2/6, 2/6, 1/6. */
static int rk4_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *k1 = work;
    double *k2 = work + n;
    double *k3 = work + 2 * n;
    double *k4 = work + 3 * n;
    double *tmp = work + 4 * n;

    /* k1 = f(t, y) */
    sw_ode_eval(ode, t, y, k1);

    /* k2 = f(t + h/2, y + h/2 k1) */
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k2);

    /* k3 = f(t + h/2, y + h/2 k2) */
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k2[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k3);

    /* k4 = f(t + h, y + h k3) */
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + h * k3[i];
    sw_ode_eval(ode, t + h, tmp, k4);

    /* y += h/6 (k1 + 2 k2 + 2 k3 + k4) */
    for (int i = 0; i < n; i++)
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI,
    .name = "alice-rk4",
    .label = "RK4 (Alice)",
    .order = 4,
    .evals = 4,
    .work_vectors = 5,
    .step = rk4_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
