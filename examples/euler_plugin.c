/* A student integrator for stepwise: explicit (forward) Euler as a plugin.
 *
 * Copy this file, rename the method, change the step function, then build
 * and grade it (docs/plugins.md has the whole story):
 *
 *     make plugin-example          # or:
 *     cc -std=c11 -O2 -shared -fPIC -Iinclude -o my_euler.so examples/euler_plugin.c
 *     ./stepwise record spring --plugin ./examples/euler_plugin.so -o mine.csv
 *     ./stepwise check --plugin ./examples/euler_plugin.so --reference euler --scene spring
 *
 * The solver sees only the lecture's interface: a dimension (ode->dim), a
 * flat state y and its derivative dy/dt = f(t, y), evaluated by
 * sw_ode_eval. For a particle system y = [x | v] (ode->order == 2); for a
 * flow field y = x (order 1). A step must not allocate: `work` holds
 * work_vectors vectors of ode->dim doubles, given to every call. */

#include <stepwise/integrator.h>

/* y(t + h) = y(t) + h·f(t, y(t)), in place. Return 0; a non-zero return
 * tells stepwise the step failed (it stops the run). */
static int euler_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    double *dydt = work; /* work vector 0 */
    sw_ode_eval(ode, t, y, dydt);
    for (int i = 0; i < ode->dim; i++)
        y[i] += h * dydt[i];
    return 0;
}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI,         /* the interface version this file was built for */
    .name = "student-euler",      /* the name for --integrator; must differ from built-ins */
    .label = "explicit Euler (student plugin)",
    .order = 1,                   /* what you claim; stepwise reports it, the check tests it */
    .evals = 1,                   /* derivative evaluations per step, for reports */
    .work_vectors = 1,            /* how many dim-long vectors euler_step uses in `work` */
    .step = euler_step,
};

/* The one symbol stepwise looks up after loading the shared object. */
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
