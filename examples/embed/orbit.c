/* A planet's orbit stepped by an adaptive method (dop853) from frame to
 * frame: each call takes one step of at most the time left to the next
 * frame, so every frame (30 a second of simulated time) is reached exactly,
 * whatever steps the method chooses between them. After one period of the
 * ellipse (semi-major axis 1, e = 0.5, mu = 1: T = 2 pi) the planet is back
 * where it started; prints how far off, and the steps and frames taken.
 *
 *     cc -std=c11 orbit.c $(pkg-config --cflags --libs stepwise) -o orbit */
#include <math.h>
#include <stdio.h>
#include <stepwise/stepwise.h>

static void deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)ctx;
    (void)t;
    double r = hypot(y[0], y[1]), r3 = r * r * r;
    dydt[0] = y[2];
    dydt[1] = y[3];
    dydt[2] = -y[0] / r3;
    dydt[3] = -y[1] / r3;
}

int main(void)
{
    const double pi = 3.14159265358979323846, period = 2 * pi, e = 0.5;
    /* at perihelion: r = 1 - e, speed sqrt((1 + e) / (1 - e)) */
    double y[4] = { 1 - e, 0, 0, sqrt((1 + e) / (1 - e)) };
    sw_ode ode = { .dim = 4, .order = 2, .deriv = deriv };
    char err[SW_ERRLEN];
    sw_stepper *st = sw_stepper_new(sw_integrator_find("dop853"), &ode, err, sizeof err);
    if (!st) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    double t = 0;
    long steps = 0, frames = 0;
    int nframes = (int)ceil(period * 30);
    for (int f = 1; f <= nframes; f++) {
        double frame = f < nframes ? f / 30.0 : period;
        while (t < frame) {
            if (sw_stepper_step(st, &ode, &t, y, frame - t) != SW_OK)
                return 1;
            steps++;
        }
        frames++;
    }
    sw_stepper_delete(st);
    printf("dop853: %ld frames, %ld steps; back at the start within %.2g (t = %.15g)\n", frames, steps,
           hypot(y[0] - (1 - e), y[1]), t);
    return 0;
}
