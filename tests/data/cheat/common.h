/* Shared by the order-probe cheaters (tests/e2e/test_grade_probe.sh): an
 * honest RK4 step and a wrong one (Euler). Each cheater decides which to
 * run by what it can see of the run. */
#include <stepwise/integrator.h>

static int rk4(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *k1 = work, *k2 = work + n, *k3 = work + 2 * n, *k4 = work + 3 * n, *tmp = work + 4 * n;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < n; i++) tmp[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k2);
    for (int i = 0; i < n; i++) tmp[i] = y[i] + 0.5 * h * k2[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k3);
    for (int i = 0; i < n; i++) tmp[i] = y[i] + h * k3[i];
    sw_ode_eval(ode, t + h, tmp, k4);
    for (int i = 0; i < n; i++) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return 0;
}

static int euler(sw_ode *ode, double t, double *y, double h, double *work)
{
    sw_ode_eval(ode, t, y, work);
    for (int i = 0; i < ode->dim; i++) y[i] += h * work[i];
    return 0;
}

#define CHEATER(NAME, STEP) \
    static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = NAME, .order = 4, .evals = 4, \
                                    .work_vectors = 5, .step = STEP }; \
    const sw_plugin *sw_plugin_info(void); \
    const sw_plugin *sw_plugin_info(void) { return &info; }
