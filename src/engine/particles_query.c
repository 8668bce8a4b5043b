/* Read-only questions about a particle system's forces: its springs
 * (numbered across spring forces) and its central body. The
 * implicit solve, the truth and the views ask them; this file calls
 * nothing else of the engine, so particles.c may call the solve. */
#include "stepwise/particles.h"

#include <string.h>

#include "engine/spring_line.h"

int sw_particles_spring_count(const sw_particles *p) { return p->nsprings_total; }

void sw_particles_spring(const sw_particles *p, int j, sw_spring *out)
{
    for (int k = 0; k < p->nforces; k++) {
        const sw_force *fo = &p->forces[k];
        if (fo->kind != SW_FORCE_SPRINGS)
            continue;
        if (j < fo->nsprings) {
            *out = swp_spring_at(fo, j);
            return;
        }
        j -= fo->nsprings;
    }
    memset(out, 0, sizeof *out);
    out->a = -1;
}

int sw_particles_central(const sw_particles *p, double *cx, double *cy, double *mu)
{
    for (int k = 0; k < p->nforces; k++)
        if (p->forces[k].kind == SW_FORCE_CENTRAL) {
            *cx = p->forces[k].cx;
            *cy = p->forces[k].cy;
            *mu = p->forces[k].mu;
            return 1;
        }
    return 0;
}
