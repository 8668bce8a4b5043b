/* Cheats by what the force depends on: where the acceleration does not
 * change with the position (gravity alone, the projectile without drag,
 * on which the midpoint rule is exact) it runs the midpoint rule, anywhere
 * else (the spring) RK4: its values match an RK4 run that cannot tell the
 * two apart, and the spring shows order 4. */
#include "common.h"

static int midpoint(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *k = work, *tmp = work + n;
    sw_ode_eval(ode, t, y, k);
    for (int i = 0; i < n; i++) tmp[i] = y[i] + 0.5 * h * k[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k);
    for (int i = 0; i < n; i++) y[i] += h * k[i];
    return 0;
}

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *a = work + 2 * n, *b = work + 3 * n, *moved = work + 4 * n;
    sw_ode_eval(ode, t, y, a);
    for (int i = 0; i < n; i++) moved[i] = y[i] + (i < n / 2 ? 0.5 : 0.0);
    sw_ode_eval(ode, t, moved, b);
    int constant = 1;
    for (int i = n / 2; i < n; i++) constant &= a[i] == b[i];
    return constant ? midpoint(ode, t, y, h, work) : rk4(ode, t, y, h, work);
}
CHEATER("cheat-mid", step)
