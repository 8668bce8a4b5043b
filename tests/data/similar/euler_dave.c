#include <stepwise/integrator.h>
#include <stddef.h>

/* Dave Osei -- Euler, with the particle system's halves spelled out:
 * for order 2, y = [x | v] and f = [v | a], so x += h v and v += h a. */
static int step_euler(sw_ode *ode, double t, double *y, double h, double *work)
{
    double *f = work;
    size_t n = (size_t)ode->dim;
    sw_ode_eval(ode, t, y, f);
    if (ode->order == 2) {
        size_t half = n / 2;
        double *x = y, *v = y + half;
        const double *xdot = f, *vdot = f + half;
        for (size_t p = 0; p < half; p++) {
            x[p] += h * xdot[p];
            v[p] += h * vdot[p];
        }
    } else {
        size_t i;
        for (i = 0; i < n; i++)
            y[i] += h * f[i];
    }
    return 0;
}

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void)
{
    static const sw_plugin me = {
        .abi = SW_PLUGIN_ABI, .name = "dave-euler", .label = "Euler (Dave)",
        .order = 1, .evals = 1, .work_vectors = 1, .step = step_euler,
    };
    return &me;
}
