/* Cheats by the initial state: a run that starts where the old order
 * probe's spring does (x = 1.5, at rest) gets RK4, any other Euler. */
#include "common.h"

static int probe;

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    if (t == 0)
        probe = ode->dim == 4 && y[0] == 1.5 && y[1] == 0 && y[2] == 0 && y[3] == 0;
    return probe ? rk4(ode, t, y, h, work) : euler(ode, t, y, h, work);
}
CHEATER("cheat-start", step)
