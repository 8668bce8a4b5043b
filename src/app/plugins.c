/* Plugins in the live app: a plugin that failed (crashed, exited, looped,
 * overran its vectors, wrote to the ode) is disabled with a message, and
 * its sim goes on under the scene's own method, so the UI keeps running.
 * This file decides and switches; app.c restarts the sims (it calls down
 * here, never the other way). */
#include "app/app.h"

#include <stdio.h>
#include <string.h>

#include "plugin/plugin.h"
#include "stepwise/stepwise.h"

int sw_app_plugins_disable_failed(sw_app *a, char *msg, size_t len)
{
    int switched = 0;
    for (int i = 0; i < a->nsims; i++) {
        sw_sim *s = &a->sims[i];
        if (!s->blown || !(s->method->flags & SW_PLUGIN))
            continue;
        sw_plugin_fault f = sw_plugin_failed(s);
        if (f == SW_PF_NONE || f == SW_PF_CANCELLED)
            continue; /* a numerical blow-up is a result; an interrupt ends the UI anyway */
        const sw_integrator *bad = s->method, *now = sw_integrator_find(a->scene->integrator);
        char why[SW_ERRLEN], err[SW_ERRLEN];
        snprintf(why, sizeof why, "%s", s->blow_reason);
        sw_plugin_disable(bad, why);
        if (!now || sw_sim_set_method(s, now, err, sizeof err) != SW_OK)
            continue;
        if (i > 0)
            a->compare_methods[i - 1] = now;
        switched++;
        snprintf(msg, len, "plugin %s disabled: %.200s; now %s from t = 0", bad->name, why, now->name);
    }
    return switched;
}
