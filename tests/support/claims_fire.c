/* Claims: the fire scene's figures in docs/scenes.md (issue 40), from the
 * truth module's limits on the scene's own spectrum. */
#include "claims.h"

#define SCENES "docs/scenes.md"

static double euler_fast_cooling(void) { return cl_limit0("fire", "kappa=100", "euler"); }
static double verlet_fast_cooling(void) { return cl_limit0("fire", "kappa=100", "verlet"); }
static double euler_motion_only(void) { return cl_limit0("fire", "kappa=0", "euler"); }

const claim sw_claims_f[] = {
    { SCENES, "so at kappa = 100 Euler's step limit is {0.02} s", euler_fast_cooling, REL, 1e-9,
      "the theory's limit on the scene's spectrum: 2/kappa, a real root the truth module finds to rounding", NULL },
    { SCENES, "(drag 1) would allow {2} s", euler_motion_only, REL, 1e-9,
      "Euler's limit with the cooling off: the drag's rate alone, 2/drag, to rounding", NULL },
    { SCENES, "velocity Verlet's is half that ({0.01} s", verlet_fast_cooling, REL, 1e-9,
      "the theory's limit from verlet's own one-step map: 1/kappa, to rounding", NULL },
};
const size_t sw_claims_f_n = sizeof sw_claims_f / sizeof sw_claims_f[0];
