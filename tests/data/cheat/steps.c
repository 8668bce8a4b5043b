/* Cheats by the step count: the graded run takes 100 steps, so a run's
 * first 100 steps get Euler and any step after them RK4 (a sweep's finer
 * runs take more). */
#include "common.h"

static long n;

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    n = t == 0 ? 1 : n + 1;
    return n <= 100 ? euler(ode, t, y, h, work) : rk4(ode, t, y, h, work);
}
CHEATER("cheat-steps", step)
