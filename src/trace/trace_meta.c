/* A trace's metadata: "# key: value" lines, checked one by one and then as
 * a whole (required keys, parameters within range, a run within limits).
 * Private to the reader (trace.c), through trace_read.h. */
#include "trace/trace_read.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/num.h"

/* Keys a trace may carry, in the order record writes them. */
static const char *const known_keys =
    "version, scene, param NAME, integrator, dt, steps, until, every, rtol, atol, events, "
    "diverged, student, note";
static const char *const assignment_keys = "tolerance, tolerance COL, ignore, title, points WHAT";

static const char *const key_names[K_COUNT] = { "version", "scene", "integrator", "dt", "steps",
                                                "until", "every", "rtol", "atol", "diverged",
                                                "student", "note", "events" };

static int parse_positive(const sw_trace_reader *r, const char *key, const char *v, double *out,
                          char *err, size_t errlen)
{
    char show[48];
    if (sw_parse_double(v, out) != SW_OK || !(*out > 0))
        return tr_fail(r, err, errlen, "'%s' wants a positive finite number, not '%s'", key,
                       tr_shown(v, strlen(v), show));
    return SW_OK;
}

/* rtol and atol: at least SW_TRACE_TOL_MIN, at most 1, refused up front
 * (a tolerance no run can meet would spend the whole step budget first). */
static int parse_tolerance(const sw_trace_reader *r, const char *key, const char *v, double *out,
                           char *err, size_t errlen)
{
    char show[48];
    if (sw_parse_double(v, out) != SW_OK || !(*out >= SW_TRACE_TOL_MIN && *out <= 1))
        return tr_fail(r, err, errlen, "'%s' wants a tolerance in [%g, 1], not '%s' (below %g "
                       "no double-precision run can meet it)", key, SW_TRACE_TOL_MIN,
                       tr_shown(v, strlen(v), show), SW_TRACE_TOL_MIN);
    return SW_OK;
}

/* Free text (student, note): printable, no control characters. */
static int free_text(const sw_trace_reader *r, const char *key, const char *v, size_t max,
                     char *err, size_t errlen)
{
    if (strlen(v) >= max)
        return tr_fail(r, err, errlen, "'%s' is longer than %zu bytes", key, max - 1);
    return SW_OK;
}

/* An assignment's own key: kept as text for the assignment module. */
static int extra_key(sw_trace_reader *r, const char *key, const char *value, char *err,
                     size_t errlen)
{
    sw_trace_meta *m = &r->meta;
    if (m->nextras == SW_TRACE_EXTRAS)
        return tr_fail(r, err, errlen, "more than %d tolerance, ignore, points and title lines",
                       SW_TRACE_EXTRAS);
    if (strlen(key) >= sizeof m->extras[0].key || strlen(value) >= sizeof m->extras[0].value)
        return tr_fail(r, err, errlen, "'%.40s' has a key or value that is too long", key);
    sw_trace_extra *x = &m->extras[m->nextras++];
    strcpy(x->key, key);
    strcpy(x->value, value);
    x->line = r->line;
    return SW_OK;
}

static int is_assignment_key(const char *key)
{
    return strcmp(key, "tolerance") == 0 || strncmp(key, "tolerance ", 10) == 0 ||
           strcmp(key, "ignore") == 0 || strcmp(key, "title") == 0 || strcmp(key, "kind") == 0 ||
           strcmp(key, "submit") == 0 ||
           strncmp(key, "points ", 7) == 0;
}

/* One "# key: value" line (r->buf). */
int tr_meta_line(sw_trace_reader *r, meta_state *ms, char *err, size_t errlen)
{
    char *text = r->buf + 1, *colon = strchr(text, ':');
    char show[48];
    if (!colon)
        return tr_fail(r, err, errlen, "metadata lines read '# key: value'; got '%s'",
                    tr_shown(r->buf, r->len, show));
    *colon = '\0';
    char *key = tr_trim(text), *value = tr_trim(colon + 1);
    sw_trace_meta *m = &r->meta;
    if (strncmp(key, "param ", 6) == 0) {
        char *name = tr_trim(key + 6);
        if (ms->nparams == MAX_PARAM_LINES)
            return tr_fail(r, err, errlen, "more than %d 'param' lines", MAX_PARAM_LINES);
        for (int i = 0; i < ms->nparams; i++)
            if (strcmp(ms->params[i].name, name) == 0)
                return tr_fail(r, err, errlen, "'param %s' given twice (first on line %ld)",
                            tr_shown(name, strlen(name), show), ms->params[i].line);
        if (strlen(name) >= SW_TRACE_NAME_MAX || strlen(value) >= 64 || !*name)
            return tr_fail(r, err, errlen, "'param %s' has a name or value that is too long or empty",
                        tr_shown(name, strlen(name), show));
        pending_param *pp = &ms->params[ms->nparams++];
        strcpy(pp->name, name);
        strcpy(pp->value, value);
        pp->line = r->line;
        return SW_OK;
    }
    int k = 0;
    while (k < K_COUNT && strcmp(key, key_names[k]) != 0)
        k++;
    if (k == K_COUNT && m->assignment && is_assignment_key(key))
        return extra_key(r, key, value, err, errlen);
    if (k == K_COUNT)
        return tr_fail(r, err, errlen, "unknown metadata key '%s'; known keys: %s%s%s",
                    tr_shown(key, strlen(key), show), known_keys,
                    m->assignment ? ", " : "", m->assignment ? assignment_keys : "");
    if (ms->seen[k] && k != K_DIVERGED && k != K_NOTE)
        return tr_fail(r, err, errlen, "'%s' given twice (first on line %ld)", key_names[k], ms->seen[k]);
    ms->seen[k] = r->line;
    char names[400];
    switch (k) {
    case K_VERSION:
        snprintf(m->version, sizeof m->version, "%s", value);
        break;
    case K_SCENE:
        m->scene = sw_scene_find(value);
        m->scene_line = r->line;
        if (!m->scene) {
            sw_scene_names(names, sizeof names);
            return tr_fail(r, err, errlen, "unknown scene '%s'; scenes: %s",
                        tr_shown(value, strlen(value), show), names);
        }
        break;
    case K_INTEGRATOR:
        if (strlen(value) >= SW_TRACE_NAME_MAX || !*value)
            return tr_fail(r, err, errlen, "integrator name '%s' is empty or too long",
                        tr_shown(value, strlen(value), show));
        strcpy(m->integrator, value);
        m->method = sw_integrator_find(value);
        m->integrator_line = r->line;
        break;
    case K_DT:
        m->dt_line = r->line;
        if (sw_parse_double(value, &m->dt) != SW_OK || !(m->dt >= SW_DT_MIN && m->dt <= SW_DT_MAX))
            return tr_fail(r, err, errlen, "'dt' wants a step in [%g, %g], not '%s'", SW_DT_MIN,
                        SW_DT_MAX, tr_shown(value, strlen(value), show));
        break;
    case K_STEPS:
        m->steps_line = r->line;
        if (sw_parse_long(value, 1, SW_TRACE_MAX_STEPS, &m->spec.steps) != SW_OK)
            return tr_fail(r, err, errlen, "'steps' wants a whole number in [1, %ld], not '%s'",
                        SW_TRACE_MAX_STEPS, tr_shown(value, strlen(value), show));
        break;
    case K_UNTIL:
        m->steps_line = r->line;
        return parse_positive(r, "until", value, &m->spec.until, err, errlen);
    case K_EVERY:
        m->every_line = r->line;
        if (sw_parse_long(value, 1, SW_TRACE_MAX_STEPS, &m->spec.every) != SW_OK)
            return tr_fail(r, err, errlen, "'every' wants a whole number in [1, %ld], not '%s'",
                        SW_TRACE_MAX_STEPS, tr_shown(value, strlen(value), show));
        break;
    case K_RTOL:
        m->rtol_line = r->line;
        return parse_tolerance(r, "rtol", value, &m->rtol, err, errlen);
    case K_ATOL:
        m->atol_line = r->line;
        return parse_tolerance(r, "atol", value, &m->atol, err, errlen);
    case K_STUDENT:
        if (free_text(r, "student", value, sizeof m->student, err, errlen) != SW_OK)
            return SW_EINVAL;
        strcpy(m->student, value);
        break;
    case K_NOTE: {
        size_t used = strlen(m->notes), len = strlen(value);
        if (used + len + 4 >= sizeof m->notes)
            return tr_fail(r, err, errlen, "the notes are longer than %zu bytes in all",
                           sizeof m->notes - 1);
        snprintf(m->notes + used, sizeof m->notes - used, "%s%s", used ? " / " : "", value);
        break;
    }
    case K_DIVERGED:
        m->diverged = 1;
        break;
    case K_EVENTS: {
        char msg[SW_ERRLEN];
        m->events_line = r->line;
        if (sw_events_mode_parse(value, &m->events, msg, sizeof msg) != SW_OK)
            return tr_fail(r, err, errlen, "'events' wants locate or step, not '%s'",
                           tr_shown(value, strlen(value), show));
        break;
    }
    }
    return SW_OK;
}

/* After the metadata: required keys, parameters, the run's length. The line
 * named is the first one after the metadata (where it should have been). */
int tr_meta_finish(sw_trace_reader *r, meta_state *ms, char *err, size_t errlen)
{
    sw_trace_meta *m = &r->meta;
    static const int required[] = { K_SCENE, K_INTEGRATOR, K_DT };
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++)
        if (!ms->seen[required[i]])
            return tr_fail(r, err, errlen, "the metadata lacks '# %s: ...' (required: scene, "
                        "integrator, dt, and steps or until)", key_names[required[i]]);
    if (ms->seen[K_STEPS] && ms->seen[K_UNTIL])
        return tr_fail(r, err, errlen, "the metadata gives both 'steps' (line %ld) and 'until' "
                    "(line %ld); a run has one or the other", ms->seen[K_STEPS], ms->seen[K_UNTIL]);
    if (!ms->seen[K_STEPS] && !ms->seen[K_UNTIL])
        return tr_fail(r, err, errlen, "the metadata lacks '# steps: N' or '# until: T'");
    if (!ms->seen[K_EVERY])
        m->spec.every = 1;
    if (!ms->seen[K_RTOL])
        m->rtol = SW_RTOL_DEFAULT;
    if (!ms->seen[K_ATOL])
        m->atol = SW_ATOL_DEFAULT;
    const sw_scene *sc = m->scene;
    sw_scene_defaults(sc, m->p);
    char show[48], msg[SW_ERRLEN];
    for (int i = 0; i < ms->nparams; i++) {
        pending_param *pp = &ms->params[i];
        long line = r->line;
        r->line = pp->line;
        int idx = sw_scene_param_index(sc, pp->name);
        double v;
        int rc = SW_OK;
        if (idx < 0) {
            sw_scene_param_names(sc, msg, sizeof msg);
            rc = tr_fail(r, err, errlen, "scene '%s' has no parameter '%s'; its parameters: %s",
                      sc->name, tr_shown(pp->name, strlen(pp->name), show), msg);
        } else if (sw_parse_double(pp->value, &v) != SW_OK)
            rc = tr_fail(r, err, errlen, "parameter '%s' wants a finite number, not '%s'",
                      pp->name, tr_shown(pp->value, strlen(pp->value), show));
        else if (sw_scene_check_value(sc, idx, v, msg, sizeof msg) != SW_OK)
            rc = tr_fail(r, err, errlen, "%s", msg);
        else {
            m->p[idx] = v;
            m->param_line[idx] = pp->line;
        }
        r->line = line;
        if (rc != SW_OK)
            return rc;
    }
    if (sw_trace_spec_check(&m->spec, m->dt, msg, sizeof msg) != SW_OK)
        return tr_fail(r, err, errlen, "%s", msg);
    if (sw_system_build(&r->sys, sc, m->p, msg, sizeof msg) != SW_OK) {
        r->line = m->scene_line;
        return tr_fail(r, err, errlen, "%s", msg);
    }
    r->have_sys = 1;
    r->ncols = sw_trace_ncols(&r->sys);
    /* Rows: step 0, every `every`-th step, and the last. A fixed-step run to
     * `until` takes at most ceil(until/dt) steps (+1 for rounding in t);
     * an adaptive or unknown method is bounded only by the step limit. */
    long every = m->spec.every, steps = m->spec.steps;
    if (steps > 0)
        r->max_rows = steps / every + 1 + (steps % every != 0);
    else if (m->method && !(m->method->flags & SW_ADAPTIVE))
        r->max_rows = ((long)ceil(m->spec.until / m->dt) + 1) / every + 2;
    else
        r->max_rows = SW_TRACE_MAX_ROWS;
    /* A few rows of slack: a duplicated row is a mistake to grade (extra
     * rows), not an unreadable file. */
    r->max_rows += SW_TRACE_ROW_SLACK;
    if (r->max_rows > SW_TRACE_MAX_ROWS)
        r->max_rows = SW_TRACE_MAX_ROWS;
    return SW_OK;
}

