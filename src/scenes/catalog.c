/* The scene catalog and what every scene shares: parameter lookup, parsing
 * and range checks, and building a system. The table below is the one place
 * that lists scenes; each family lives in its own file. */
#include "stepwise/scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"
#include "scenes/scenes.h"
#include "util/kv.h"
#include "util/names.h"
#include "util/num.h"

static const sw_scene *const catalog[] = {
    &sw_scene_vortex, &sw_scene_river, &sw_scene_gyre,
    &sw_scene_projectile, &sw_scene_bounce, &sw_scene_fireworks,
    &sw_scene_spring, &sw_scene_stiff_spring, &sw_scene_chain,
    &sw_scene_orbit, &sw_scene_galaxy, &sw_scene_fire, &sw_scene_explosion,
    &sw_scene_water,
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

double sw_scene_dt(const sw_scene *sc, const double *p)
{
    if (!sc->step)
        return sc->dt;
    double full[SW_MAX_PARAMS];
    sw_scene_fill(sc, p, full); /* NULL: the defaults, as sw_scene_fill reads it */
    return fmin(sc->dt, sc->step(full));
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

/* A value for a message: a whole-number parameter's in full (n = 1000001
 * must not read as 1e+06, its limit), others as %g. */
static const char *shown(char *buf, size_t len, double v, int integer)
{
    if (integer && v == floor(v) && fabs(v) < 1e15)
        snprintf(buf, len, "%.0f", v);
    else
        snprintf(buf, len, "%g", v);
    return buf;
}

int sw_scene_check_value(const sw_scene *sc, int index, double value, char *err, size_t errlen)
{
    const sw_param *pd = &sc->params[index];
    if (!(value >= pd->min && value <= pd->max)) {
        char v[40], lo[40], hi[40];
        snprintf(err, errlen, "%s: parameter '%s' = %s is outside its range [%s, %s]%s%s", sc->name, pd->name,
                 shown(v, sizeof v, value, pd->integer), shown(lo, sizeof lo, pd->min, pd->integer),
                 shown(hi, sizeof hi, pd->max, pd->integer), *pd->unit ? " " : "", pd->unit);
        return SW_EINVAL;
    }
    if (pd->integer && value != floor(value)) {
        snprintf(err, errlen, "%s: parameter '%s' must be a whole number in [%g, %g] (got %g)",
                 sc->name, pd->name, pd->min, pd->max, value);
        return SW_EINVAL;
    }
    return SW_OK;
}

static const char *scene_name_at(const void *ctx, int i)
{
    (void)ctx;
    return catalog[i]->name;
}

size_t sw_scene_names(char *buf, size_t len)
{
    return sw_names_join(buf, len, scene_name_at, NULL, NSCENES);
}

static const char *param_name_at(const void *ctx, int i)
{
    return ((const sw_scene *)ctx)->params[i].name;
}

size_t sw_scene_param_names(const sw_scene *sc, char *buf, size_t len)
{
    return sw_names_join(buf, len, param_name_at, sc, sc->nparams);
}

int sw_scene_set(const sw_scene *sc, double *p, const char *assignment, char *err, size_t errlen)
{
    char names[160];
    size_t len = strlen(assignment);
    sw_kv kv;
    int got = sw_kv_next(assignment, len, 0, &kv);
    if (got <= 0 || kv.name_len == 0) {
        sw_scene_param_names(sc, names, sizeof names);
        snprintf(err, errlen, "--set wants PARAM=VALUE (got '%.40s'); %s parameters: %s",
                 assignment, sc->name, names);
        return SW_EINVAL;
    }
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)(kv.name_len < sizeof name ? kv.name_len : sizeof name - 1),
             assignment + kv.name_at);
    int idx = sw_scene_param_index(sc, name);
    if (idx < 0) {
        sw_scene_param_names(sc, names, sizeof names);
        snprintf(err, errlen, "%s has no parameter '%.40s'; its parameters are: %s", sc->name, name, names);
        return SW_EINVAL;
    }
    /* The value is the rest of the text: "k=1 2" is not a number. */
    char value[64];
    const char *rest = assignment + kv.value_at;
    size_t rlen = len - kv.value_at;
    while (rlen && (rest[rlen - 1] == ' ' || rest[rlen - 1] == '\t'))
        rlen--;
    double v;
    if (rlen >= sizeof value ||
        (snprintf(value, sizeof value, "%.*s", (int)rlen, rest), sw_parse_double(value, &v) != SW_OK)) {
        const sw_param *pd = &sc->params[idx];
        snprintf(err, errlen, "%s: '%.40s' is not a finite number; %s takes a value in [%g, %g]",
                 sc->name, rest, pd->name, pd->min, pd->max);
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
    if (rc != SW_OK) {
        sw_system_free(sys);
        return rc;
    }
    /* what a plugin's host needs to build it again: this scene, sys->p, sys->extra */
    sys->ode->maker_kind = SW_MAKER_SCENE;
    sys->ode->maker = sys;
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

int sw_system_event_count(const sw_system *sys)
{
    const sw_scene_events *ev = sys->scene->events;
    return ev ? ev->count(sys) : 0;
}

const char *sw_system_events_break(const sw_system *sys)
{
    const sw_scene_events *ev = sys->scene->events;
    return ev && ev->breaks && ev->count(sys) > 0 ? ev->breaks(sys) : NULL;
}
