/* A cheater of red team 3 (tests/e2e/test_grade_stability_fake.sh): on a
 * verlet homework it runs the midpoint rule (order 2, as verlet's) on
 * every run, but velocity Verlet on the stability probe's system (one
 * particle whose force moves with its position, or the 2x2 test system),
 * so its measured limit is verlet's 2 where midpoint has none. */
#include <stepwise/integrator.h>
static int midpoint(sw_ode *o, double t, double *y, double h, double *w)
{
    int n = o->dim; double *k = w, *tmp = w + n;
    sw_ode_eval(o, t, y, k);
    for (int i = 0; i < n; i++) tmp[i] = y[i] + 0.5 * h * k[i];
    sw_ode_eval(o, t + 0.5 * h, tmp, k);
    for (int i = 0; i < n; i++) y[i] += h * k[i];
    return 0;
}
static int verlet(sw_ode *o, double t, double *y, double h, double *w)
{
    int n = o->dim, half = n / 2;
    double *f = w, *yt = w + n, *x = y, *v = y + half;
    sw_ode_eval(o, t, y, f);
    for (int i = 0; i < half; i++) {
        double vh = v[i] + 0.5 * h * f[half + i];
        yt[i] = x[i] + h * vh; yt[half + i] = v[i] + h * f[half + i];
        x[i] = yt[i]; v[i] = vh;
    }
    sw_ode_eval(o, t + h, yt, f);
    for (int i = 0; i < half; i++) v[i] += 0.5 * h * f[half + i];
    return 0;
}
static int spring;
static int st(sw_ode *o, double t, double *y, double h, double *w)
{
    if (t == 0) {
        spring = o->dim == 2;
        if (o->dim == 4) { /* one particle: a spring (force moves with x) or the projectile (no) */
            double *a = w, *b = w + 4, *moved = w + 8;
            sw_ode_eval(o, t, y, a);
            for (int i = 0; i < 4; i++) moved[i] = y[i] + (i < 2 ? 0.25 : 0.0);
            sw_ode_eval(o, t, moved, b);
            spring = a[2] != b[2] || a[3] != b[3];
        }
    }
    return spring ? verlet(o, t, y, h, w) : midpoint(o, t, y, h, w);
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "stabfake", .label="x", .order = 2, .evals = 2, .work_vectors = 3, .step = st };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
