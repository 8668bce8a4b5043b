/* Private to particles_deriv.c and particles_small.c: the particle
 * system's forces compiled by kind into flat arrays (see
 * swp_model_compile for the layout and the order of summation). */
#ifndef SW_ENGINE_PARTICLES_MODEL_H
#define SW_ENGINE_PARTICLES_MODEL_H

#include "stepwise/particles.h"

/* Springs are evaluated BLOCK at a time: gather the differences, compute the
 * forces in a loop without indices (which the compiler vectorises: square
 * root and divisions two or more at a time), scatter them. */
#define BLOCK 128

/* The small-system derivative chosen at compile time (particles_small.c). */
typedef void swp_small_fn(const sw_particles *p, const double *y, double *dydt);

struct sw_particles_model {
    int compiled;             /* the arrays below match the description */
    int cap;                  /* room for springs */
    /* springs: [0, npair) join particles a and b; [npair, npair + nanchor)
     * tie particle a to the fixed point (ax, ay); a and b hold 2a and 2b,
     * the offsets of the particles' x in the state. Only what the passes
     * read is written (a row never written is never resident: a million
     * beads' chain keeps its model to the forces and `first`): ax, ay of
     * the anchored springs alone; a, b of the paired ones only when they
     * do not follow the stride below; k, c, rest only when the springs do
     * not all share them (uniform). */
    int npair, nanchor;
    int *a, *b;
    double *k, *c, *rest, *ax, *ay;
    int uniform;              /* every spring has these k, c, rest (same bits) */
    double k0, c0, rest0;
    double *shared;           /* uniform: k0, c0, rest0 repeated, BLOCK each, read by every block (a
                                 loop over rows vectorises better than one over constants) */
    int full;                 /* a, b, k, c, rest of every spring written too: the small path
                                 (particles_small.c) reads them */
    int damped;               /* some spring has c != 0 */
    double *scratch;          /* d and dv = v_a - v_b of a block of springs, (x, y) pairs, and
                                 |d|²: 5 BLOCK */
    double *force;            /* each spring's force on its particle a, (x, y) pairs: 2 cap */
    /* each particle's springs, in the order above: entries first[i] ..
     * first[i + 1] - 1 of spring (2j, the offset of spring j's force) and
     * sign (+1: the particle is a, -1: it is b) */
    int *first, *spring;
    double *sign;
    int degree;               /* every particle has this many springs (entries 2i, 2i + 1 when 2); else 0 */
    int skip_run;             /* the lists of the run's particles (below) are not written: no pass
                                 reads them (no extra pass, not small) */
    /* Regular layouts, found by swp_model_compile, that let the loops read
     * neighbours contiguously instead of through the index lists (chains,
     * ropes, rows of cloth): the paired springs' a and b advance by one
     * particle a spring (a = a0 + 2j, b = b0 + 2j; stride 0: not so), and
     * the particles [run_lo, run_hi), all of degree 2, find their springs at
     * fixed distances with fixed signs (spring[2i + e] = 2i + run_c[e],
     * sign run_s[e]). Either gives the same numbers as the lists. */
    int stride, a0, b0;
    int run_lo, run_hi, run_c[2];
    double run_s[2];
    /* one gravity and one drag, fused into the last pass */
    int gravity, drag;
    double gx, gy, kdrag;
    /* every other per-particle force (central fields, a second gravity or
     * drag): a pass each, in the order added, before the last pass */
    int nextra;
    int extra[SW_MAX_FORCES]; /* indices into p->forces */
    /* the springs are a chain between two anchors (swp_chain_shaped):
     * rk4 takes its fused step; tile: that step's workspace (allocated
     * with the springs, swp_chain_work_size doubles), or NULL */
    int chain;
    double *tile;
    const struct sw_ode_fast *fast; /* the system's two rows (swp_model_init) */
    /* NULL, or the small-system path (particles_small.c) that gives these
     * numbers without the blocks and passes above: chosen when compiled */
    swp_small_fn *small;
    /* NULL, or the small chain's fused derivative (particles_chain.c),
     * taken where there is no small path: chosen when compiled; 0 where
     * it leaves the evaluation to the generic passes */
    int (*line)(const sw_particles *p, const double *y, double *dydt);
};

#endif
