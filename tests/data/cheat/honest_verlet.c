/* An honest velocity Verlet (tests/e2e/test_grade_stability_fake.sh). */
#include <stepwise/integrator.h>

static int verlet(sw_ode *o, double t, double *y, double h, double *w)
{
    int n = o->dim, half = n / 2;
    double *f = w, *yt = w + n, *x = y, *v = y + half;
    sw_ode_eval(o, t, y, f);
    for (int i = 0; i < half; i++) {
        double vh = v[i] + 0.5 * h * f[half + i];
        yt[i] = x[i] + h * vh;
        yt[half + i] = v[i] + h * f[half + i];
        x[i] = yt[i];
        v[i] = vh;
    }
    sw_ode_eval(o, t + h, yt, f);
    for (int i = 0; i < half; i++)
        v[i] += 0.5 * h * f[half + i];
    return 0;
}

static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "honest-verlet", .order = 2, .evals = 2,
                                .work_vectors = 2, .step = verlet };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
