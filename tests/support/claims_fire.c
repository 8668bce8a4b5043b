/* Claims: the fire and water scenes' figures in docs/scenes.md (issue 40):
 * the truth module's limits on the scene's own spectrum, water's CFL limit
 * measured against it (tests/support/water_cfl.c). */
#include "claims.h"
#include "water_cfl.h"

#define SCENES "docs/scenes.md"

static double euler_fast_cooling(void) { return cl_limit0("fire", "kappa=100", "euler"); }
static double verlet_fast_cooling(void) { return cl_limit0("fire", "kappa=100", "verlet"); }
static double euler_motion_only(void) { return cl_limit0("fire", "kappa=0", "euler"); }

/* The three ratios measured / theory (symplectic-euler, verlet, rk4). */
static void cfl_ratios(double r[3])
{
    r[0] = water_cfl_ratio("symplectic-euler");
    r[1] = water_cfl_ratio("verlet");
    r[2] = water_cfl_ratio("rk4");
}
static double cfl_least(void)
{
    double r[3];
    cfl_ratios(r);
    return fmin(r[0], fmin(r[1], r[2]));
}
static double cfl_most(void)
{
    double r[3];
    cfl_ratios(r);
    return fmax(r[0], fmax(r[1], r[2]));
}
static double sound_speed(void) { return sqrt(cl_param("water", "k")); }
static double dense_particles(void) { return SW_DENSE_MAX / 4; }

const claim sw_claims_f[] = {
    { SCENES, "blows up: between {1.1} and 1.3 times that theory's limit", cfl_least, ATLEAST, 0,
      "the least of the three ratios (bisected to 1 %)", NULL },
    { SCENES, "blows up: between 1.1 and {1.3} times that theory's limit", cfl_most, ATMOST, 0,
      "the largest of the three ratios (bisected to 1 %)", NULL },
    { SCENES, "the sound speed is c = √k = {20} m/s", sound_speed, EXACT, 0, R_COUNT, NULL },
    { SCENES, "Implicit methods are refused above {16} particles", dense_particles, EXACT, 0,
      "the dense fallback's dimension over 4 doubles a particle", NULL },
    { SCENES, "so at kappa = 100 Euler's step limit is {0.02} s", euler_fast_cooling, REL, 1e-9,
      "the theory's limit on the scene's spectrum: 2/kappa, a real root the truth module finds to rounding", NULL },
    { SCENES, "(drag 1) would allow {2} s", euler_motion_only, REL, 1e-9,
      "Euler's limit with the cooling off: the drag's rate alone, 2/drag, to rounding", NULL },
    { SCENES, "velocity Verlet's is half that ({0.01} s", verlet_fast_cooling, REL, 1e-9,
      "the theory's limit from verlet's own one-step map: 1/kappa, to rounding", NULL },
};
const size_t sw_claims_f_n = sizeof sw_claims_f / sizeof sw_claims_f[0];
