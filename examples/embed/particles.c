/* The lecture's particle system (CS559 "Animation", after Witkin and
 * Baraff), written against libstepwise: particles with position, velocity,
 * mass and a force accumulator; forces as black boxes that add into it; the
 * derivative in the lecture's three steps (clear the forces, apply every
 * force, gather [v | f/m]); and EulerStep, which is the library's "euler".
 *
 *     cc -std=c11 particles.c $(pkg-config --cflags --libs stepwise) -o particles
 *
 * Two balls thrown under gravity and linear drag for one second, stepped
 * by euler and by rk4 with h = 0.01; prints each method's largest error
 * against the closed form. */
#include <math.h>
#include <stdio.h>
#include <stepwise/stepwise.h>

#define N 2

typedef struct particle { double x[2], v[2], f[2], m; } particle;

typedef struct force force;
struct force { void (*apply)(const force *self, particle *p, int n); double k; };

typedef struct system { particle p[N]; const force *forces[4]; int nforces; } system;

static void gravity(const force *self, particle *p, int n)
{
    for (int i = 0; i < n; i++)
        p[i].f[1] -= self->k * p[i].m;
}

static void drag(const force *self, particle *p, int n)
{
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 2; d++)
            p[i].f[d] -= self->k * p[i].m * p[i].v[d];
}

/* The solver's view: y = [x0 y0 x1 y1 | vx0 vy0 vx1 vy1]. */
static void deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)t;
    system *s = ctx;
    for (int i = 0; i < N; i++)
        for (int d = 0; d < 2; d++) {
            s->p[i].x[d] = y[2 * i + d];
            s->p[i].v[d] = y[2 * N + 2 * i + d];
            s->p[i].f[d] = 0; /* 1. clear the forces */
        }
    for (int k = 0; k < s->nforces; k++) /* 2. apply every force */
        s->forces[k]->apply(s->forces[k], s->p, N);
    for (int i = 0; i < N; i++) /* 3. gather */
        for (int d = 0; d < 2; d++) {
            dydt[2 * i + d] = s->p[i].v[d];
            dydt[2 * N + 2 * i + d] = s->p[i].f[d] / s->p[i].m;
        }
}

/* With linear drag k and gravity g: v(t) = (v0 + g/k) e^{-kt} - g/k
 * (vertically; g = 0 across), x(t) = x0 + (v0 + g/k)(1 - e^{-kt})/k - g t/k. */
static double exact(double x0, double v0, double g, double k, double t)
{
    return x0 + (v0 + g / k) * (1 - exp(-k * t)) / k - g * t / k;
}

static double run(const char *method, double h)
{
    static const force g = { gravity, 9.81 }, d = { drag, 0.5 };
    system s = { .forces = { &g, &d }, .nforces = 2 };
    double v0[N][2] = { { 3, 8 }, { -2, 12 } };
    double y[4 * N] = { 0 };
    for (int i = 0; i < N; i++) {
        s.p[i].m = 1 + i;
        y[2 * N + 2 * i] = v0[i][0];
        y[2 * N + 2 * i + 1] = v0[i][1];
    }
    sw_ode ode = { .dim = 4 * N, .order = 2, .deriv = deriv, .ctx = &s };
    char err[SW_ERRLEN];
    sw_stepper *st = sw_stepper_new(sw_integrator_find(method), &ode, err, sizeof err);
    if (!st) {
        fprintf(stderr, "%s\n", err);
        return INFINITY;
    }
    double t = 0;
    while (t < 1 - h / 2)
        if (sw_stepper_step(st, &ode, &t, y, h) != SW_OK)
            return INFINITY;
    sw_stepper_delete(st);
    double worst = 0;
    for (int i = 0; i < N; i++) {
        double ex = exact(0, v0[i][0], 0, 0.5, t), ey = exact(0, v0[i][1], 9.81, 0.5, t);
        worst = fmax(worst, fmax(fabs(y[2 * i] - ex), fabs(y[2 * i + 1] - ey)));
    }
    return worst;
}

int main(void)
{
    printf("euler: largest error at t = 1: %.3g m\n", run("euler", 0.01));
    printf("rk4:   largest error at t = 1: %.3g m\n", run("rk4", 0.01));
    return 0;
}
