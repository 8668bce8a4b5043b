/* Private to the engine: spring j of a spring force, stored or generated.
 * A force from sw_particles_add_spring_line keeps no array (springs is
 * NULL): its springs are line[0], then line[1] with a and b advanced by
 * one particle a spring, then line[2] (a chain of a million beads keeps
 * three springs, not a million). Every reader of a force's springs reads
 * them here. */
#ifndef SW_ENGINE_SPRING_LINE_H
#define SW_ENGINE_SPRING_LINE_H

#include "stepwise/particles.h"

static inline sw_spring swp_spring_at(const sw_force *fo, int j)
{
    if (fo->springs)
        return fo->springs[j];
    if (j == 0)
        return fo->line[0];
    if (j == fo->nsprings - 1)
        return fo->line[2];
    sw_spring sp = fo->line[1];
    sp.a += j - 1;
    sp.b += j - 1;
    return sp;
}

#endif
