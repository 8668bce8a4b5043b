/* An honest classmate: the classical Runge-Kutta method, as
 * docs/plugins.md teaches it. The test names it (@NAME@) per student; it
 * must pass, keep its file byte for byte, and its row must be right. */
#include <stepwise/integrator.h>

static int rk4_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *k1 = work, *k2 = work + n, *k3 = work + 2 * n, *k4 = work + 3 * n, *tmp = work + 4 * n;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k2);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k2[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k3);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + h * k3[i];
    sw_ode_eval(ode, t + h, tmp, k4);
    for (int i = 0; i < n; i++)
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "@NAME@", .label = "RK4 (@NAME@)",
    .order = 4, .evals = 4, .work_vectors = 5, .step = rk4_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
