/* A stiff damped spring stepped by rodas4 in the program's own loop:
 * x'' = -k x - c x' with k = 1e6 N/kg, c = 10 /s, from x = 1, stepped with
 * h = 0.01 s, a hundred times the period 2 pi / sqrt(k) = 0.00628 s. rk4
 * is stable only for sqrt(k) h below 2.83 (here 10) and blows up; rodas4,
 * L-stable, stays bounded. It does not follow the spring: a step 1.6
 * periods long cannot, and its damping per step (its stability function
 * at h times the eigenvalue) is not the true e^{-c h / 2}; it only keeps
 * the motion from growing. For the motion itself, take steps well below
 * the period (docs/stability.md).
 *
 *     cc -std=c11 stiff_spring.c $(pkg-config --cflags --libs stepwise) -o stiff_spring */
#include <math.h>
#include <stdio.h>
#include <stepwise/stepwise.h>

static const double k = 1e6, c = 10;

static void deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)ctx;
    (void)t;
    dydt[0] = y[1];
    dydt[1] = -k * y[0] - c * y[1];
}

static double run(const char *method)
{
    sw_ode ode = { .dim = 2, .order = 2, .deriv = deriv }; /* solve NULL: finite differences */
    char err[SW_ERRLEN];
    sw_stepper *st = sw_stepper_new(sw_integrator_find(method), &ode, err, sizeof err);
    if (!st) {
        fprintf(stderr, "%s\n", err);
        return NAN;
    }
    double t = 0, y[2] = { 1, 0 };
    for (int i = 0; i < 100 && isfinite(y[0]) && fabs(y[0]) < 1e100; i++)
        if (sw_stepper_step(st, &ode, &t, y, 0.01) != SW_OK)
            break;
    sw_stepper_delete(st);
    return y[0];
}

int main(void)
{
    double r = run("rodas4"), e = run("rk4");
    printf("rodas4: |x(1)| = %.3g: bounded (the true motion's envelope at t = 1: %.3g)\n", fabs(r), exp(-c / 2));
    printf("rk4:    |x| = %.3g when it stopped: %s\n", fabs(e),
           !isfinite(e) || fabs(e) > 1e10 ? "blown up" : "stable");
    return 0;
}
