/* Cheats by the time: RK4 while t < 0.64 (the measuring runs' first 64
 * steps of a dt of 0.01), Euler after: its values fail after step 64, and
 * an order read on those 64 steps alone would be RK4's. */
#include "common.h"

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    return t < 0.64 ? rk4(ode, t, y, h, work) : euler(ode, t, y, h, work);
}
CHEATER("cheat-late", step)
