/* Explicit Euler - Carol Nguyen */
#include <stepwise/integrator.h>

static int carol_euler(sw_ode *ode, double t, double *y, double h, double *work)
{
    double *slope = work;
    double *end = y + ode->dim;
    sw_ode_eval(ode, t, y, slope);
    /* walk both arrays with pointers */
    for (double *p = y; p != end; ++p, ++slope)
        *p = *p + h * *slope;
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI,
    .name = "carol-euler",
    .label = "Carol's forward Euler",
    .order = 1,
    .evals = 1,
    .work_vectors = 1,
    .step = carol_euler,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
