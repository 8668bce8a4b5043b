/* The stage view's model: which step is shown and how far through it; each
 * drawn method's script (its update formula in the lecture's EulerStep
 * style, and per key press the line lit and what is drawn) is its row's
 * (engine/lecture.h). */
#ifndef SW_APP_STAGES_H
#define SW_APP_STAGES_H

#include "app/app.h"
#include "engine/lecture.h"

/* The script of method m (its row's lecture), or NULL when its stages are
 * not drawn. */
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
