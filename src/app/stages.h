/* The stage view's model: which step is shown, how far through it, and
 * each drawn method's script (its update formula in the lecture's
 * EulerStep style, and per key press the line lit and what is drawn). */
#ifndef SW_APP_STAGES_H
#define SW_APP_STAGES_H

#include "app/app.h"

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
    const char *method;
    const char *lines[SW_STAGE_LINES]; /* the update formula, NULL-ended */
    sw_stage_view views[SW_STAGE_VIEWS];
    int nviews;
} sw_stage_script;

/* The script of method m, or NULL when its stages are not drawn. */
const sw_stage_script *sw_stage_script_of(const sw_integrator *m);
/* The stage key: open the view at the first stage (pausing the run), show
 * the next, or close it after the last; Esc closes it. 1 when anything
 * changed; a->message says what is shown. */
int sw_app_stages_apply(sw_app *a, sw_action act);
/* Close the stage view (space runs on, a new scene). */
void sw_app_stages_close(sw_app *a);
/* The main run's next step recorded (again only when the run, its method
 * or dt changed since), or NULL with a->stages_why saying why. */
const sw_stages *sw_app_stages(sw_app *a);

#endif
