/* The Jacobian block of an inverse-square attraction, shared by central
 * attraction and mutual gravity (below the table, so neither calls back
 * into it). */
#include "engine/forces.h"

#include <math.h>

void swp_inverse_square_block(double s, double dx, double dy, double soft2, double blk[4])
{
    double q2 = dx * dx + dy * dy + soft2, q = sqrt(q2), q3 = q2 * q, q5 = q3 * q2;
    if (!(q > 0)) {
        blk[0] = blk[1] = blk[2] = blk[3] = 0;
        return;
    }
    blk[0] = -s * (1 / q3 - 3 * dx * dx / q5);
    blk[1] = blk[2] = -s * (-3 * dx * dy / q5);
    blk[3] = -s * (1 / q3 - 3 * dy * dy / q5);
}
