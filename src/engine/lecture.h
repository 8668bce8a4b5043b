/* Each explicit method's step as the lecture writes it (Witkin and Baraff's
 * EulerStep style: the statements of one step, y the state, f its
 * derivative), and per press of the stage view's key the line lit and the
 * shape drawn. A method's row points at its script (integrator.h:
 * lecture) or says why it has none (no_lecture). Pure data: the stage view
 * (app/stages.c, render/stages.c) reads it; the engine never does. */
#ifndef SW_ENGINE_LECTURE_H
#define SW_ENGINE_LECTURE_H

#include "stepwise/integrator.h"

/* What one press of the stage key adds to the picture. */
typedef enum sw_stage_shape {
    SW_STAGE_SLOPE,  /* a recorded stage: its point and h·k from it */
    SW_STAGE_SUM,    /* the step's result: y0 to y1 (the weighted sum) */
    SW_STAGE_KICK,   /* a velocity kick at x0: h·v before (dim) and x0 to x1 (h·v after) */
    SW_STAGE_DRIFT,  /* the particle moved to x1 */
    SW_STAGE_KICK_END /* the last kick at x1: h·v1 from x1 */
} sw_stage_shape;

typedef struct sw_stage_view {
    int line;               /* the formula line lit */
    int stage;              /* SLOPE: the recorded stage it draws */
    sw_stage_shape shape;
    const char *label;      /* at the arrow's tip: "k1", "y1", "v1" */
    const char *caption;    /* one sentence: what this stage is */
} sw_stage_view;

#define SW_STAGE_LINES 6
#define SW_STAGE_VIEWS 5

typedef struct sw_stage_script {
    const char *lines[SW_STAGE_LINES]; /* the update formula, NULL-ended */
    sw_stage_view views[SW_STAGE_VIEWS];
    int nviews;
} sw_stage_script;

/* The built-in methods' scripts (lecture.c), named in their rows. */
extern const sw_stage_script sw_lecture_euler, sw_lecture_symplectic_euler, sw_lecture_midpoint,
    sw_lecture_heun, sw_lecture_rk4, sw_lecture_verlet;

#endif
