/* Private to the engine: a particle's (x, y) as one value, so a pair of
 * components moves and subtracts as one (a GNU C vector, which gcc and clang
 * support; each operation is the elementwise IEEE operation, so the bits are
 * those of two scalar ones), and two particles' as one wider value. */
#ifndef SW_ENGINE_LANES_H
#define SW_ENGINE_LANES_H

#include <string.h>

typedef double v2d __attribute__((vector_size(2 * sizeof(double))));

static inline v2d load2(const double *p)
{
    v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void store2(double *p, v2d v) { memcpy(p, &v, sizeof v); }

/* Two particles' (x, y) as one value, for loops that read neighbours in order. */
typedef double v4d __attribute__((vector_size(4 * sizeof(double))));
/* (no functions that take or return one: without AVX that changes the ABI) */

#endif
