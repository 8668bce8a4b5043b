/* Cheats by the particle count: one particle in the plane (dim 4, the
 * old order probe's spring) gets RK4, anything else Euler. */
#include "common.h"

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    return ode->dim == 4 ? rk4(ode, t, y, h, work) : euler(ode, t, y, h, work);
}
CHEATER("cheat-dim", step)
