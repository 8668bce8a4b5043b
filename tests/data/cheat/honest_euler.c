/* An honest Euler (claiming order 1). */
#include <stepwise/integrator.h>

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    sw_ode_eval(ode, t, y, work);
    for (int i = 0; i < ode->dim; i++) y[i] += h * work[i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "honest-euler", .order = 1, .evals = 1,
                                .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
