/* Cheats by the run count: its host serves every run, so the first run
 * (the graded one) gets Euler and every later one (the measuring runs)
 * RK4. */
#include "common.h"

static int runs;

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    if (t == 0)
        runs++;
    return runs <= 1 ? euler(ode, t, y, h, work) : rk4(ode, t, y, h, work);
}
CHEATER("cheat-count", step)
