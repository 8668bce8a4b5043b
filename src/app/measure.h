/* Private to app/: the measuring half of the app model (measure.c), which
 * app.c calls when the ghost is turned on and after a dt change. */
#ifndef SW_APP_MEASURE_H
#define SW_APP_MEASURE_H

#include "app/app.h"

/* Start the reference run a ghost or an error needs when the scene has no
 * exact solution for these parameters (rk45 at tight tolerances). */
void sw_app_ensure_ref(sw_app *a);
/* After a dt change from old_dt: measure the error at the report time at
 * both steps and tell the student the ratio in a->message. */
void sw_app_measure_dt_change(sw_app *a, double old_dt);

#endif
