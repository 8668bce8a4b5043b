#include <stepwise/integrator.h>

// Eve Lindqvist - RK4, the textbook way
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int i, n = ode->dim;
    double *a = work, *b = work + n, *c = work + 2*n, *d = work + 3*n, *yt = work + 4*n;

    sw_ode_eval(ode, t, y, a);
    for (i = 0; i < n; i++) yt[i] = y[i] + h/2 * a[i];
    sw_ode_eval(ode, t + h/2, yt, b);
    for (i = 0; i < n; i++) yt[i] = y[i] + h/2 * b[i];
    sw_ode_eval(ode, t + h/2, yt, c);
    for (i = 0; i < n; i++) yt[i] = y[i] + h * c[i];
    sw_ode_eval(ode, t + h, yt, d);
    for (i = 0; i < n; i++) y[i] = y[i] + h * (a[i] + 2*b[i] + 2*c[i] + d[i]) / 6;
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "eve-rk4", .label = "RK4 (Eve L.)",
    .order = 4, .evals = 4, .work_vectors = 5, .step = step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
