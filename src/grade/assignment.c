/* Assignments: read with the trace reader's metadata parser (so a reference
 * trace's header is an assignment), then the assignment's own keys. The
 * differences from a trace's header are computed on effective values: a
 * parameter a trace leaves out has the scene's default. */
#include "grade/assignment.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "util/escape.h"
#include "util/num.h"


static int parse_rel_abs(const char *text, double *rel, double *abs_tol)
{
    char copy[128], *comma;
    snprintf(copy, sizeof copy, "%s", text);
    comma = strchr(copy, ',');
    if (comma)
        *comma = '\0';
    if (sw_parse_double(copy, rel) != SW_OK || !(*rel >= 0))
        return SW_EINVAL;
    *abs_tol = *rel;
    if (comma && (sw_parse_double(comma + 1, abs_tol) != SW_OK || !(*abs_tol >= 0)))
        return SW_EINVAL;
    return *rel > 0 || *abs_tol > 0 ? SW_OK : SW_EINVAL;
}

int sw_coltol_parse(sw_coltols *t, const char *text, int ignore, const char *where, char *err,
                    size_t errlen)
{
    if (t->n == SW_COLTOL_MAX) {
        snprintf(err, errlen, "%s: more than %d column tolerances and exclusions", where,
                 SW_COLTOL_MAX);
        return SW_EINVAL;
    }
    sw_coltol *c = &t->cols[t->n];
    memset(c, 0, sizeof *c);
    snprintf(c->where, sizeof c->where, "%s", where);
    c->ignore = ignore;
    const char *eq = ignore ? NULL : strchr(text, '=');
    size_t name_len = ignore ? strlen(text) : eq ? (size_t)(eq - text) : 0;
    if (name_len == 0 || name_len >= sizeof c->column) {
        snprintf(err, errlen, "%s: '%.60s' is not allowed: give %s", where, text,
                 ignore ? "a column name, e.g. energy" : "COL=REL[,ABS], e.g. energy=1e-6");
        return SW_EINVAL;
    }
    memcpy(c->column, text, name_len);
    c->column[name_len] = '\0';
    if (strcmp(c->column, "step") == 0) {
        snprintf(err, errlen, "%s: the step column always matches exactly: it says which rows "
                 "line up", where);
        return SW_EINVAL;
    }
    if (!ignore && parse_rel_abs(eq + 1, &c->rtol, &c->atol) != SW_OK) {
        snprintf(err, errlen, "%s: '%.60s' is not allowed: give COL=REL[,ABS] with non-negative "
                 "numbers, not both zero (e.g. energy=1e-6 or x0=1e-9,1e-12)", where, text);
        return SW_EINVAL;
    }
    t->n++;
    return SW_OK;
}

static int column_matches(const char *pattern, const char *name)
{
    size_t len = strlen(pattern);
    if (len > 0 && pattern[len - 1] == '*')
        return strncmp(pattern, name, len - 1) == 0;
    return strcmp(pattern, name) == 0;
}

int sw_coltol_resolve(const sw_coltols *t, const sw_system *sys, double rtol, double atol,
                      double *col_rtol, double *col_atol, unsigned char *ignore, char *err,
                      size_t errlen)
{
    int ncols = sw_trace_ncols(sys);
    for (int c = 0; c < ncols; c++) {
        col_rtol[c] = rtol;
        col_atol[c] = atol;
        ignore[c] = 0;
    }
    char name[32];
    for (int i = 0; i < t->n; i++) {
        const sw_coltol *ct = &t->cols[i];
        int hits = 0;
        for (int c = 1; c < ncols; c++) {
            sw_trace_colname(sys, c, name, sizeof name);
            if (!column_matches(ct->column, name))
                continue;
            hits++;
            if (ct->ignore)
                ignore[c] = 1;
            else {
                col_rtol[c] = ct->rtol;
                col_atol[c] = ct->atol;
            }
        }
        if (hits == 0) {
            snprintf(err, errlen, "%s: no column '%s' in a %s trace (columns: t, x<i>, y<i>%s%s; "
                     "a prefix ending in '*' names several)", ct->where, ct->column,
                     sys->scene->name, sys->ode->order == 2 ? ", vx<i>, vy<i>" : "",
                     sys->scene->energy ? ", energy" : "");
            return SW_EINVAL;
        }
    }
    return SW_OK;
}

/* "FILE:LINE" for messages about an assignment line. */
static void where(const sw_assignment *a, long line, char *buf, size_t len)
{
    snprintf(buf, len, "%.40s:%ld", a->path, line);
}

static int read_methods(sw_assignment *a, char *err, size_t errlen)
{
    char list[SW_TRACE_NAME_MAX], *save = NULL;
    snprintf(list, sizeof list, "%s", a->meta.integrator);
    for (char *name = strtok_r(list, ",", &save); name; name = strtok_r(NULL, ",", &save)) {
        while (*name == ' ')
            name++;
        size_t len = strlen(name);
        while (len > 0 && name[len - 1] == ' ')
            name[--len] = '\0';
        const sw_integrator *m = sw_integrator_find(name);
        if (!m || a->nmethods == SW_ASSIGN_METHODS) {
            snprintf(err, errlen, "%.200s:%ld: %s '%.40s' (an assignment names built-in methods, "
                     "'stepwise list integrators', at most %d)", a->path, a->meta.integrator_line,
                     m ? "too many integrators at" : "unknown integrator", name, SW_ASSIGN_METHODS);
            return SW_EINVAL;
        }
        a->methods[a->nmethods++] = m;
    }
    if (a->nmethods == 0) {
        snprintf(err, errlen, "%.200s:%ld: no integrator named", a->path, a->meta.integrator_line);
        return SW_EINVAL;
    }
    return SW_OK;
}

const char *sw_assignment_wanted(const sw_assignment *a)
{
    switch (a->kind) {
    case SW_KIND_TRACE:
        return "a trace (.trace, .csv)";
    case SW_KIND_PLUGIN:
        return a->source_only ? "a plugin's C source (.c)" : "a plugin (.c, .so)";
    case SW_KIND_ANY:
        break;
    }
    return a->source_only ? "a trace (.trace, .csv) or a plugin's C source (.c)"
                          : "a trace (.trace, .csv) or a plugin (.c, .so)";
}

int sw_assignment_kind_ok(const sw_assignment *a, int is_plugin, const char *path, char *why, size_t whylen)
{
    size_t len = path ? strlen(path) : 0;
    int compiled = is_plugin && len >= 3 && strcmp(path + len - 3, ".so") == 0;
    if (compiled && a->source_only) {
        snprintf(why, whylen, "this homework asks for %s, not a compiled plugin (.so): hand in the .c it "
                 "was built from", sw_assignment_wanted(a));
        return 0;
    }
    if (a->kind == SW_KIND_ANY || (a->kind == SW_KIND_PLUGIN) == (is_plugin != 0))
        return 1;
    snprintf(why, whylen, "this homework asks for %s, not %s", sw_assignment_wanted(a),
             is_plugin ? "a plugin" : "a trace");
    return 0;
}

int sw_assignment_read(sw_assignment *a, const char *path, char *err, size_t errlen)
{
    return sw_assignment_read_filtered(a, path, NULL, NULL, err, errlen);
}

int sw_assignment_read_filtered(sw_assignment *a, const char *path, sw_trace_meta_filter filter,
                                void *ctx, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    snprintf(a->path, sizeof a->path, "%s", path);
    sw_trace_reader r;
    int rc = sw_trace_read_open_filtered(&r, path, filter, ctx, err, errlen);
    if (rc != SW_OK)
        return rc;
    a->meta = r.meta;
    const sw_system *sys = &r.sys; /* the reader stays open to resolve column names */
    a->rtol = SW_CHECK_RTOL;
    a->atol = SW_CHECK_ATOL;
    rc = read_methods(a, err, errlen);
    char at[64];
    for (int i = 0; rc == SW_OK && i < a->meta.nextras; i++) {
        const sw_trace_extra *x = &a->meta.extras[i];
        where(a, x->line, at, sizeof at);
        if (strcmp(x->key, "title") == 0)
            snprintf(a->title, sizeof a->title, "%.*s", (int)sizeof a->title - 1, x->value);
        else if (strcmp(x->key, "kind") == 0) {
            if (strcmp(x->value, "trace") == 0)
                a->kind = SW_KIND_TRACE;
            else if (strcmp(x->value, "plugin") == 0)
                a->kind = SW_KIND_PLUGIN;
            else {
                char shown[64];
                sw_escape(x->value, 40, shown, sizeof shown);
                snprintf(err, errlen, "%s: 'kind' is trace or plugin (what students hand in), not '%s'", at,
                         shown);
                rc = SW_EINVAL;
            }
        }
        else if (strcmp(x->key, "submit") == 0) {
            if (strcmp(x->value, "source") == 0 || strcmp(x->value, "source or compiled") == 0)
                a->source_only = strcmp(x->value, "source") == 0;
            else {
                char shown[64];
                sw_escape(x->value, 40, shown, sizeof shown);
                snprintf(err, errlen, "%s: 'submit' is source (a plugin's .c only) or source or compiled "
                         "(.c or .so), not '%s'", at, shown);
                rc = SW_EINVAL;
            }
        }
        else if (strcmp(x->key, "tolerance") == 0) {
            if (parse_rel_abs(x->value, &a->rtol, &a->atol) != SW_OK) {
                snprintf(err, errlen, "%s: 'tolerance' wants REL[,ABS], e.g. 1e-9 or 1e-9,1e-12, "
                         "not '%.60s'", at, x->value);
                rc = SW_EINVAL;
            }
        } else if (strcmp(x->key, "ignore") == 0) {
            char list[256], *save = NULL;
            snprintf(list, sizeof list, "%s", x->value);
            for (char *c = strtok_r(list, ", ", &save); c && rc == SW_OK; c = strtok_r(NULL, ", ", &save))
                rc = sw_coltol_parse(&a->coltols, c, 1, at, err, errlen);
        } else if (strncmp(x->key, "points ", 7) == 0) {
            rc = sw_points_parse(&a->points, x->key + 7, x->value, x->line, at, err, errlen);
        } else { /* "tolerance COL" */
            char text[320];
            const char *col = x->key + 10;
            while (*col == ' ')
                col++;
            snprintf(text, sizeof text, "%s=%s", col, x->value);
            rc = sw_coltol_parse(&a->coltols, text, 0, at, err, errlen);
        }
    }
    if (rc == SW_OK) {
        int n = sw_trace_ncols(sys);
        double *buf = malloc((size_t)n * (2 * sizeof(double) + 1));
        if (!buf) {
            snprintf(err, errlen, "out of memory");
            rc = SW_ENOMEM;
        } else {
            rc = sw_coltol_resolve(&a->coltols, sys, a->rtol, a->atol, buf, buf + n,
                                   (unsigned char *)(buf + 2 * n), err, errlen);
            free(buf);
            if (rc == SW_OK)
                rc = sw_points_resolve(&a->points, sys, a->path, err, errlen);
        }
    }
    sw_trace_read_close(&r);
    return rc;
}

const sw_integrator *sw_assignment_method(const sw_assignment *a, const sw_trace_meta *m)
{
    for (int i = 0; i < a->nmethods; i++)
        if (m && strcmp(a->methods[i]->name, m->integrator) == 0)
            return a->methods[i];
    return a->methods[0];
}

int sw_assignment_sim(const sw_assignment *a, const sw_integrator *mth, sw_sim *s, char *err,
                      size_t errlen)
{
    char msg[SW_ERRLEN];
    int rc = sw_sim_init(s, a->meta.scene, a->meta.p, mth, a->meta.dt, msg, sizeof msg);
    if (rc != SW_OK) {
        snprintf(err, errlen, "%.200s:%ld: %s", a->path, a->meta.integrator_line, msg);
        return rc;
    }
    sw_sim_set_tolerances(s, a->meta.rtol, a->meta.atol);
    rc = sw_sim_set_events(s, a->meta.events, msg, sizeof msg);
    if (rc != SW_OK) {
        sw_sim_free(s);
        snprintf(err, errlen, "%s", msg);
    }
    return rc;
}

static void add_diff(sw_header_diff *out, int max, int *n, const char *what, const char *got,
                     const char *want, long line)
{
    if (*n < max) {
        sw_header_diff *d = &out[*n];
        snprintf(d->what, sizeof d->what, "%s", what);
        snprintf(d->got, sizeof d->got, "%s", got);
        snprintf(d->want, sizeof d->want, "%s", want);
        d->line = line;
    }
    (*n)++;
}

static void add_num(sw_header_diff *out, int max, int *n, const char *what, double got,
                    double want, long line)
{
    char g[40], w[40];
    sw_fmt_shortest(g, sizeof g, got);
    sw_fmt_shortest(w, sizeof w, want);
    add_diff(out, max, n, what, g, w, line);
}

static void run_length(const sw_trace_spec *spec, char *buf, size_t len)
{
    char num[40];
    if (spec->steps > 0)
        snprintf(buf, len, "steps %ld", spec->steps);
    else {
        sw_fmt_shortest(num, sizeof num, spec->until);
        snprintf(buf, len, "until %s", num);
    }
}

/* Whether two run lengths are the same run of a method with step dt:
 * equal, or "until T" and "steps N" with T = N dt to a billionth of a step
 * (the until run's last step is then dt to rounding) for a fixed-step
 * method; an adaptive method counts accepted steps, so not for it. */
static int same_length(const sw_trace_spec *a, const sw_trace_spec *b, double dt,
                       const sw_integrator *m)
{
    if (a->steps > 0 && b->steps > 0)
        return a->steps == b->steps;
    if (a->steps == 0 && b->steps == 0)
        return a->until == b->until;
    if (m->flags & SW_ADAPTIVE)
        return 0;
    long n = a->steps > 0 ? a->steps : b->steps;
    double until = a->steps > 0 ? b->until : a->until;
    return fabs(until - (double)n * dt) <= 1e-9 * dt;
}

int sw_assignment_diff(const sw_assignment *a, const sw_trace_meta *m, const sw_system *trace_sys,
                       sw_header_diff *out, int max, int *comparable)
{
    const sw_trace_meta *w = &a->meta;
    int n = 0;
    *comparable = 1;
    if (m->scene != w->scene) {
        add_diff(out, max, &n, "scene", m->scene->name, w->scene->name, m->scene_line);
        *comparable = 0;
        return n;
    }
    const sw_scene *sc = w->scene;
    for (int i = 0; i < sc->nparams; i++)
        if (m->p[i] != w->p[i]) {
            char what[48];
            snprintf(what, sizeof what, "param %s", sc->params[i].name);
            add_num(out, max, &n, what, m->p[i], w->p[i], m->param_line[i]);
        }
    int allowed = 0;
    char list[160] = "";
    for (int i = 0; i < a->nmethods; i++) {
        allowed |= strcmp(a->methods[i]->name, m->integrator) == 0;
        size_t used = strlen(list);
        snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : a->nmethods > 1 ? "any of " : "",
                 a->methods[i]->name);
    }
    if (!allowed)
        add_diff(out, max, &n, "integrator", m->integrator, list, m->integrator_line);
    if (m->dt != w->dt)
        add_num(out, max, &n, "dt", m->dt, w->dt, m->dt_line);
    if (!same_length(&m->spec, &w->spec, w->dt, sw_assignment_method(a, m))) {
        char g[60], wt[60];
        run_length(&m->spec, g, sizeof g);
        run_length(&w->spec, wt, sizeof wt);
        add_diff(out, max, &n, "run length", g, wt, m->steps_line); /* "steps 200" or "until 2" each */
    }
    if (m->spec.every != w->spec.every)
        add_num(out, max, &n, "every", (double)m->spec.every, (double)w->spec.every, m->every_line);
    const sw_integrator *mth = sw_assignment_method(a, m);
    if (mth->flags & (SW_ADAPTIVE | SW_IMPLICIT)) {
        if (m->rtol != w->rtol)
            add_num(out, max, &n, "rtol", m->rtol, w->rtol, m->rtol_line);
        if (m->atol != w->atol)
            add_num(out, max, &n, "atol", m->atol, w->atol, m->atol_line);
    }
    if (m->events != w->events)
        add_diff(out, max, &n, "events", sw_events_mode_name(m->events), sw_events_mode_name(w->events),
                 m->events_line);
    /* The numbers compare only when the columns are the same ones. */
    sw_system want_sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&want_sys, sc, w->p, err, sizeof err) == SW_OK) {
        *comparable = sw_trace_ncols(&want_sys) == sw_trace_ncols(trace_sys) &&
                      want_sys.n == trace_sys->n;
        sw_system_free(&want_sys);
    } else
        *comparable = 0;
    return n;
}
