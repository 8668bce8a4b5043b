/* A planet around a fixed sun under μ/r² attraction (Kepler). Only the
 * central force: no springs, no drag. The exact solution comes from Kepler's
 * equation; energy (-μ/2) and angular momentum are conserved exactly. */
#include <math.h>
#include <stdio.h>

#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/num.h"


enum { OR_E, OR_MU };
static const sw_param orbit_params[] = {
    { "e", 0.5, 0.0, 0.97, 0, "", "eccentricity of the orbit" },
    { "mu", 1.0, 0.01, 100.0, 0, "m^3/s^2", "gravitational parameter of the sun" },
};

static int orbit_build(sw_system *sys, char *err, size_t errlen)
{
    double e = sys->p[OR_E], mu = sys->p[OR_MU];
    int rc = sw_scene_particles(sys, 1, 1.0, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_particles_add_central(&sys->particles, 0.0, 0.0, mu);
    sys->y[0] = 1.0 - e;
    sys->y[3] = sqrt(mu * (1.0 + e) / (1.0 - e));
    return SW_OK;
}

/* Semi-major axis 1, mean motion n = √μ: solve E - e sin E = n t by Newton,
 * then x = cos E - e, y = b sin E, ẋ = -n sin E / (1 - e cos E),
 * ẏ = b n cos E / (1 - e cos E), b = √(1 - e²). */
static int orbit_exact(const sw_system *sys, double t, double *y)
{
    double e = sys->p[OR_E], n = sqrt(sys->p[OR_MU]), b = sqrt(1 - e * e);
    double M = fmod(n * t, 2 * SW_PI);
    double E = e < 0.8 ? M : SW_PI;
    for (int i = 0; i < 60; i++) {
        double dE = (E - e * sin(E) - M) / (1 - e * cos(E));
        E -= dE;
        if (fabs(dE) < 1e-16)
            break;
    }
    double den = 1 - e * cos(E);
    y[0] = cos(E) - e;
    y[1] = b * sin(E);
    y[2] = -n * sin(E) / den;
    y[3] = b * n * cos(E) / den;
    return 0;
}

/* |L - L0| with L = x vy - y vx and L0 = √(μ(1 - e²)). */
static double orbit_drift(const sw_system *sys, const double *y)
{
    double e = sys->p[OR_E];
    return fabs(y[0] * y[3] - y[1] * y[2] - sqrt(sys->p[OR_MU] * (1 - e * e)));
}

static sw_view orbit_view(const sw_system *sys)
{
    double e = sys->p[OR_E], b = sqrt(1 - e * e);
    return (sw_view){ -1.0 - e - 0.15, 1.0 - e + 0.15, -b - 0.15, b + 0.15 };
}

const sw_scene sw_scene_orbit = {
    .name = "orbit",
    .kind = SW_SYS_PARTICLES,
    .summary = "a planet around a fixed sun; Kepler's exact ellipse, period 2 pi / sqrt(mu)",
    .teaches = "RK4's energy drifts away; Verlet's stays bounded, and its ellipse slowly turns instead.",
    .params = orbit_params,
    .nparams = SW_NPARAMS(orbit_params),
    .dt = 0.01,
    .integrator = "verlet",
    .duration = 4 * SW_PI,
    .build = orbit_build,
    .exact = orbit_exact,
    .energy = sw_scene_particle_energy,
    .drift = orbit_drift,
    .drift_name = "angular-momentum drift",
    .reference = 1,
    .view = orbit_view,
};
