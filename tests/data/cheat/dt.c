/* Cheats by the step: the graded dt (0.01) gets Euler, every other step
 * (the order probe's halvings) RK4. */
#include "common.h"

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    return h == 0.01 ? euler(ode, t, y, h, work) : rk4(ode, t, y, h, work);
}
CHEATER("cheat-dt", step)
