/* An honest RK4. */
#include "common.h"

CHEATER("honest-rk4", rk4)
