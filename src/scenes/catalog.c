/* The scene catalog and what every scene shares: parameter lookup, parsing
 * and range checks, and building a system. The table below is the one place
 * that lists scenes; each family lives in its own file. */
#include "stepwise/scene.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "scenes/scenes.h"

static const sw_scene *const catalog[] = {
    &sw_scene_vortex, &sw_scene_river, &sw_scene_gyre,
    &sw_scene_projectile, &sw_scene_bounce, &sw_scene_fireworks,
    &sw_scene_spring, &sw_scene_stiff_spring, &sw_scene_chain,
    &sw_scene_orbit,
};

#define NSCENES ((int)(sizeof catalog / sizeof catalog[0]))

int sw_scene_count(void) { return NSCENES; }

const sw_scene *sw_scene_at(int index)
{
    return index >= 0 && index < NSCENES ? catalog[index] : NULL;
}

const sw_scene *sw_scene_find(const char *name)
{
    for (int i = 0; i < NSCENES; i++)
        if (strcmp(catalog[i]->name, name) == 0)
            return catalog[i];
    return NULL;
}

int sw_scene_param_index(const sw_scene *sc, const char *name)
{
    for (int i = 0; i < sc->nparams; i++)
        if (strcmp(sc->params[i].name, name) == 0)
            return i;
    return -1;
}

void sw_scene_defaults(const sw_scene *sc, double *p)
{
    for (int i = 0; i < sc->nparams; i++)
        p[i] = sc->params[i].def;
}

void sw_scene_fill(const sw_scene *sc, const double *p, double *out)
{
    if (p)
        memcpy(out, p, (size_t)sc->nparams * sizeof *p);
    else
        sw_scene_defaults(sc, out);
    for (int i = sc->nparams; i < SW_MAX_PARAMS; i++)
        out[i] = 0;
}

int sw_parse_double(const char *text, double *out)
{
    if (!text || !*text)
        return SW_EINVAL;
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (*end != '\0' || end == text || errno == ERANGE || !isfinite(v))
        return SW_EINVAL;
    *out = v;
    return SW_OK;
}

int sw_parse_long(const char *text, long min, long max, long *out)
{
    if (!text || !*text)
        return SW_EINVAL;
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (*end != '\0' || end == text || errno == ERANGE || v < min || v > max)
        return SW_EINVAL;
    *out = v;
    return SW_OK;
}

int sw_scene_check_value(const sw_scene *sc, int index, double value, char *err, size_t errlen)
{
    const sw_param *pd = &sc->params[index];
    if (!(value >= pd->min && value <= pd->max)) {
        snprintf(err, errlen, "%s: parameter '%s' = %g is outside its range [%g, %g]%s%s",
                 sc->name, pd->name, value, pd->min, pd->max, *pd->unit ? " " : "", pd->unit);
        return SW_EINVAL;
    }
    if (pd->integer && value != floor(value)) {
        snprintf(err, errlen, "%s: parameter '%s' must be a whole number in [%g, %g] (got %g)",
                 sc->name, pd->name, pd->min, pd->max, value);
        return SW_EINVAL;
    }
    return SW_OK;
}

/* Names of all parameters, for "allowed" lists in messages. */
static void param_names(const sw_scene *sc, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < sc->nparams && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", i ? ", " : "", sc->params[i].name);
}

int sw_scene_set(const sw_scene *sc, double *p, const char *assignment, char *err, size_t errlen)
{
    char names[160];
    const char *eq = strchr(assignment, '=');
    if (!eq || eq == assignment) {
        param_names(sc, names, sizeof names);
        snprintf(err, errlen, "--set wants PARAM=VALUE (got '%.40s'); %s parameters: %s",
                 assignment, sc->name, names);
        return SW_EINVAL;
    }
    char name[64];
    size_t len = (size_t)(eq - assignment);
    if (len >= sizeof name)
        len = sizeof name - 1;
    memcpy(name, assignment, len);
    name[len] = '\0';
    int idx = sw_scene_param_index(sc, name);
    if (idx < 0) {
        param_names(sc, names, sizeof names);
        snprintf(err, errlen, "%s has no parameter '%.40s'; its parameters are: %s", sc->name, name, names);
        return SW_EINVAL;
    }
    double v;
    if (sw_parse_double(eq + 1, &v) != SW_OK) {
        const sw_param *pd = &sc->params[idx];
        snprintf(err, errlen, "%s: '%.40s' is not a finite number; %s takes a value in [%g, %g]",
                 sc->name, eq + 1, pd->name, pd->min, pd->max);
        return SW_EINVAL;
    }
    int rc = sw_scene_check_value(sc, idx, v, err, errlen);
    if (rc == SW_OK)
        p[idx] = v;
    return rc;
}

int sw_system_build(sw_system *sys, const sw_scene *sc, const double *p, char *err, size_t errlen)
{
    memset(sys, 0, sizeof *sys);
    sys->scene = sc;
    sw_scene_fill(sc, p, sys->p);
    for (int i = 0; i < sc->nparams; i++) {
        int rc = sw_scene_check_value(sc, i, sys->p[i], err, errlen);
        if (rc != SW_OK)
            return rc;
    }
    int rc = sc->build(sys, err, errlen);
    if (rc == SW_OK && sys->kind == SW_SYS_PARTICLES)
        rc = sw_particles_finish(&sys->particles, err, errlen);
    if (rc != SW_OK)
        sw_system_free(sys);
    return rc;
}

void sw_system_free(sw_system *sys)
{
    if (sys->kind == SW_SYS_FLOW)
        sw_flow_free(&sys->flow);
    else if (sys->kind == SW_SYS_PARTICLES)
        sw_particles_free(&sys->particles);
    free(sys->extra);
    sys->extra = NULL;
    sys->kind = 0;
    sys->ode = NULL;
    sys->y = NULL;
}

int sw_system_reset(sw_system *sys, char *err, size_t errlen)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = sys->scene;
    memcpy(p, sys->p, sizeof p);
    sw_system_free(sys);
    return sw_system_build(sys, sc, p, err, errlen);
}
