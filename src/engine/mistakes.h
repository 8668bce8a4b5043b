/* Mistaken versions of the built-in methods, the ones students write: each
 * a step function with the arithmetic a student's program would have, so a
 * trace made that way matches it to rounding. A method's row points at its
 * list (integrator.h: mistakes); the explainer (grade/explain.c) runs them
 * in order and names the first that matches. */
#ifndef SW_ENGINE_MISTAKES_H
#define SW_ENGINE_MISTAKES_H

#include "stepwise/integrator.h"

typedef struct sw_mistake {
    const char *kind;        /* the explanation's kind ("stage-time"); NULL ends a list */
    int time_only;           /* shows only on a time-dependent scene */
    sw_integrator method;    /* the mistaken method, run as the row's method would be */
    const char *hint;        /* what the run does, in words */
    const char *fix;         /* what to change, or NULL */
} sw_mistake;

/* The built-in methods' lists (mistakes.c), named in their rows. */
extern const sw_mistake sw_mistakes_midpoint[], sw_mistakes_heun[], sw_mistakes_rk4[],
    sw_mistakes_verlet[];

#endif
