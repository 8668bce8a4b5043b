/* Step traces: the reader of the CSV format in docs/trace-format.md (the run
 * rule and the columns are in trace_run.c, the writer in trace_write.c).
 * Invariant: the reader's memory is bounded by the scene, not by the file. */
#include "lab/trace.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/num.h"

/* ---- reading -------------------------------------------------------------- */

static int fail(const sw_trace_reader *r, char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* "FILE:LINE: what" — every reader error names the place. */
static int fail(const sw_trace_reader *r, char *err, size_t errlen, const char *fmt, ...)
{
    int used = snprintf(err, errlen, "%s:%ld: ", r->name, r->line > 0 ? r->line : 1);
    if (used < 0 || (size_t)used >= errlen)
        return SW_EINVAL;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + used, errlen - (size_t)used, fmt, ap);
    va_end(ap);
    return SW_EINVAL;
}

/* A printable copy of untrusted text for a message: at most 40 bytes, and
 * anything outside printable ASCII shown as '?'. */
static const char *shown(const char *text, size_t len, char out[48])
{
    size_t n = len < 40 ? len : 40;
    for (size_t i = 0; i < n; i++)
        out[i] = (text[i] >= 0x20 && text[i] < 0x7f) ? text[i] : '?';
    strcpy(out + n, len > 40 ? "..." : "");
    return out;
}

/* Read one line into r->buf without its newline (and a CR before it).
 * 1 a line, 0 end of file, or an error: too long, binary, or no final
 * newline (a cut-short file). */
static int read_line(sw_trace_reader *r, char *err, size_t errlen)
{
    int c = getc(r->f);
    if (c == EOF) {
        if (ferror(r->f)) {
            fail(r, err, errlen, "read error: %s", strerror(errno));
            return SW_EIO;
        }
        return 0;
    }
    r->line++;
    size_t n = 0;
    while (c != EOF && c != '\n') {
        unsigned char u = (unsigned char)c;
        if ((u < 0x20 && u != '\t' && u != '\r') || u == 0x7f)
            return fail(r, err, errlen, "binary data (byte 0x%02x at column %zu): a trace is "
                        "a text file", u, n + 1);
        if (n == r->cap)
            return r->have_sys
                       ? fail(r, err, errlen, "line longer than %zu bytes, more than %d columns "
                              "can need: far larger than any trace", r->cap, r->ncols)
                       : fail(r, err, errlen, "line longer than %zu bytes: a metadata line is "
                              "shorter, and this is no trace", r->cap);
        r->buf[n++] = (char)c;
        c = getc(r->f);
    }
    if (c == EOF) {
        if (ferror(r->f)) {
            fail(r, err, errlen, "read error: %s", strerror(errno));
            return SW_EIO;
        }
        return fail(r, err, errlen, "the last line does not end with a newline: the file is "
                    "cut short (every line, the last one too, ends with a newline)");
    }
    if (n > 0 && r->buf[n - 1] == '\r')
        n--;
    r->buf[n] = '\0';
    r->len = n;
    return 1;
}

static int set_cap(sw_trace_reader *r, size_t cap, char *err, size_t errlen)
{
    char *b = realloc(r->buf, cap + 1);
    if (!b) {
        snprintf(err, errlen, "%s: out of memory for a line of %zu bytes", r->name, cap);
        return SW_ENOMEM;
    }
    r->buf = b;
    r->cap = cap;
    return SW_OK;
}

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        s[--n] = '\0';
    return s;
}

/* Keys a trace may carry, in the order record writes them. */
static const char *const known_keys =
    "version, scene, param NAME, integrator, dt, steps, until, every, rtol, atol, diverged";

enum { K_VERSION, K_SCENE, K_INTEGRATOR, K_DT, K_STEPS, K_UNTIL, K_EVERY, K_RTOL, K_ATOL,
       K_DIVERGED, K_COUNT };
static const char *const key_names[K_COUNT] = { "version", "scene", "integrator", "dt", "steps",
                                                "until", "every", "rtol", "atol", "diverged" };

#define MAX_PARAM_LINES 32

typedef struct pending_param {
    char name[SW_TRACE_NAME_MAX];
    char value[64];
    long line;
} pending_param;

typedef struct meta_state {
    long seen[K_COUNT];              /* line where each key appeared; 0: not yet */
    pending_param params[MAX_PARAM_LINES];
    int nparams;
    char scene[SW_TRACE_NAME_MAX];
} meta_state;

static int parse_positive(const sw_trace_reader *r, const char *key, const char *v, double *out,
                          char *err, size_t errlen)
{
    if (sw_parse_double(v, out) != SW_OK || !(*out > 0))
        return fail(r, err, errlen, "'%s' wants a positive finite number, not '%s'", key, v);
    return SW_OK;
}

/* One "# key: value" line (r->buf). */
static int meta_line(sw_trace_reader *r, meta_state *ms, char *err, size_t errlen)
{
    char *text = r->buf + 1, *colon = strchr(text, ':');
    char show[48];
    if (!colon)
        return fail(r, err, errlen, "metadata lines read '# key: value'; got '%s'",
                    shown(r->buf, r->len, show));
    *colon = '\0';
    char *key = trim(text), *value = trim(colon + 1);
    sw_trace_meta *m = &r->meta;
    if (strncmp(key, "param ", 6) == 0) {
        char *name = trim(key + 6);
        if (ms->nparams == MAX_PARAM_LINES)
            return fail(r, err, errlen, "more than %d 'param' lines", MAX_PARAM_LINES);
        for (int i = 0; i < ms->nparams; i++)
            if (strcmp(ms->params[i].name, name) == 0)
                return fail(r, err, errlen, "'param %s' given twice (first on line %ld)",
                            shown(name, strlen(name), show), ms->params[i].line);
        if (strlen(name) >= SW_TRACE_NAME_MAX || strlen(value) >= 64 || !*name)
            return fail(r, err, errlen, "'param %s' has a name or value that is too long or empty",
                        shown(name, strlen(name), show));
        pending_param *pp = &ms->params[ms->nparams++];
        strcpy(pp->name, name);
        strcpy(pp->value, value);
        pp->line = r->line;
        return SW_OK;
    }
    int k = 0;
    while (k < K_COUNT && strcmp(key, key_names[k]) != 0)
        k++;
    if (k == K_COUNT)
        return fail(r, err, errlen, "unknown metadata key '%s'; known keys: %s",
                    shown(key, strlen(key), show), known_keys);
    if (ms->seen[k] && k != K_DIVERGED)
        return fail(r, err, errlen, "'%s' given twice (first on line %ld)", key_names[k], ms->seen[k]);
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
            return fail(r, err, errlen, "unknown scene '%s'; scenes: %s",
                        shown(value, strlen(value), show), names);
        }
        break;
    case K_INTEGRATOR:
        if (strlen(value) >= SW_TRACE_NAME_MAX || !*value)
            return fail(r, err, errlen, "integrator name '%s' is empty or too long",
                        shown(value, strlen(value), show));
        strcpy(m->integrator, value);
        m->method = sw_integrator_find(value);
        m->integrator_line = r->line;
        break;
    case K_DT:
        if (sw_parse_double(value, &m->dt) != SW_OK || !(m->dt >= SW_DT_MIN && m->dt <= SW_DT_MAX))
            return fail(r, err, errlen, "'dt' wants a step in [%g, %g], not '%s'", SW_DT_MIN,
                        SW_DT_MAX, shown(value, strlen(value), show));
        break;
    case K_STEPS:
        if (sw_parse_long(value, 1, SW_TRACE_MAX_STEPS, &m->spec.steps) != SW_OK)
            return fail(r, err, errlen, "'steps' wants a whole number in [1, %ld], not '%s'",
                        SW_TRACE_MAX_STEPS, shown(value, strlen(value), show));
        break;
    case K_UNTIL:
        return parse_positive(r, "until", value, &m->spec.until, err, errlen);
    case K_EVERY:
        if (sw_parse_long(value, 1, SW_TRACE_MAX_STEPS, &m->spec.every) != SW_OK)
            return fail(r, err, errlen, "'every' wants a whole number in [1, %ld], not '%s'",
                        SW_TRACE_MAX_STEPS, shown(value, strlen(value), show));
        break;
    case K_RTOL:
        return parse_positive(r, "rtol", value, &m->rtol, err, errlen);
    case K_ATOL:
        return parse_positive(r, "atol", value, &m->atol, err, errlen);
    case K_DIVERGED:
        m->diverged = 1;
        break;
    }
    return SW_OK;
}

/* After the metadata: required keys, parameters, the run's length. The line
 * named is the first one after the metadata (where it should have been). */
static int meta_finish(sw_trace_reader *r, meta_state *ms, char *err, size_t errlen)
{
    sw_trace_meta *m = &r->meta;
    static const int required[] = { K_SCENE, K_INTEGRATOR, K_DT };
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++)
        if (!ms->seen[required[i]])
            return fail(r, err, errlen, "the metadata lacks '# %s: ...' (required: scene, "
                        "integrator, dt, and steps or until)", key_names[required[i]]);
    if (ms->seen[K_STEPS] && ms->seen[K_UNTIL])
        return fail(r, err, errlen, "the metadata gives both 'steps' (line %ld) and 'until' "
                    "(line %ld); a run has one or the other", ms->seen[K_STEPS], ms->seen[K_UNTIL]);
    if (!ms->seen[K_STEPS] && !ms->seen[K_UNTIL])
        return fail(r, err, errlen, "the metadata lacks '# steps: N' or '# until: T'");
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
            rc = fail(r, err, errlen, "scene '%s' has no parameter '%s'; its parameters: %s",
                      sc->name, shown(pp->name, strlen(pp->name), show), msg);
        } else if (sw_parse_double(pp->value, &v) != SW_OK)
            rc = fail(r, err, errlen, "parameter '%s' wants a finite number, not '%s'",
                      pp->name, shown(pp->value, strlen(pp->value), show));
        else if (sw_scene_check_value(sc, idx, v, msg, sizeof msg) != SW_OK)
            rc = fail(r, err, errlen, "%s", msg);
        else
            m->p[idx] = v;
        r->line = line;
        if (rc != SW_OK)
            return rc;
    }
    if (sw_trace_spec_check(&m->spec, m->dt, msg, sizeof msg) != SW_OK)
        return fail(r, err, errlen, "%s", msg);
    if (sw_system_build(&r->sys, sc, m->p, msg, sizeof msg) != SW_OK) {
        r->line = m->scene_line;
        return fail(r, err, errlen, "%s", msg);
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
    if (r->max_rows > SW_TRACE_MAX_ROWS)
        r->max_rows = SW_TRACE_MAX_ROWS;
    return SW_OK;
}

/* The first line: exactly SW_TRACE_MAGIC. */
static int read_magic(sw_trace_reader *r, char *err, size_t errlen)
{
    int rc = read_line(r, err, errlen);
    if (rc < 0)
        return rc;
    if (rc == 0) {
        r->line = 1;
        return fail(r, err, errlen, "empty file; a trace starts with the line '%s'", SW_TRACE_MAGIC);
    }
    if (strcmp(r->buf, SW_TRACE_MAGIC) == 0)
        return SW_OK;
    /* Not a trace. Random or binary bytes may happen to open with a short
     * clean line: look a little further so such a file is called binary. */
    for (int i = 0, c; i < 512 && (c = getc(r->f)) != EOF; i++)
        if ((c < 0x20 && c != '\t' && c != '\r' && c != '\n') || c == 0x7f)
            return fail(r, err, errlen, "binary data (byte 0x%02x within the first 512 bytes "
                        "after line 1): a trace is a text file", (unsigned)c);
    char show[48], tail;
    int version;
    if (sscanf(r->buf, "# stepwise trace %d%c", &version, &tail) == 1)
        return fail(r, err, errlen, "trace format %d; this stepwise reads format %d", version,
                    SW_TRACE_FORMAT);
    return fail(r, err, errlen, "not a stepwise trace: the first line must be '%s', not '%s'",
                SW_TRACE_MAGIC, shown(r->buf, r->len, show));
}

/* Metadata: every line that starts with '#', up to the header row. */
static int read_meta(sw_trace_reader *r, char *err, size_t errlen)
{
    meta_state ms;
    memset(&ms, 0, sizeof ms);
    for (;;) {
        int c = getc(r->f);
        if (c == EOF)
            break;
        ungetc(c, r->f);
        if (c != '#')
            break;
        int rc = read_line(r, err, errlen);
        if (rc < 0)
            return rc;
        rc = meta_line(r, &ms, err, errlen);
        if (rc != SW_OK)
            return rc;
    }
    /* Messages about what is missing name the line after the metadata. */
    r->line++;
    int rc = meta_finish(r, &ms, err, errlen);
    r->line--;
    return rc;
}

int sw_trace_read_open(sw_trace_reader *r, const char *path, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    snprintf(r->name, sizeof r->name, "%s", path);
    struct stat st;
    if (stat(path, &st) != 0 || !(r->f = fopen(path, "r"))) {
        snprintf(err, errlen, "%.200s:1: cannot open: %s", path, strerror(errno));
        return SW_EIO;
    }
    int rc = SW_OK;
    if (S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%.200s:1: is a directory, not a trace", path);
        rc = SW_EINVAL;
    }
    if (rc == SW_OK)
        rc = set_cap(r, SW_TRACE_META_MAX, err, errlen);
    if (rc == SW_OK)
        rc = read_magic(r, err, errlen);
    if (rc == SW_OK)
        rc = read_meta(r, err, errlen);
    if (rc != SW_OK)
        sw_trace_read_close(r);
    return rc;
}

/* The next comma-separated cell of *cursor, trimmed; NULL after the last. */
static char *next_cell(char **cursor)
{
    char *s = *cursor;
    if (!s)
        return NULL;
    char *comma = strchr(s, ',');
    if (comma) {
        *comma = '\0';
        *cursor = comma + 1;
    } else
        *cursor = NULL;
    return trim(s);
}

int sw_trace_read_header(sw_trace_reader *r, char *err, size_t errlen)
{
    int rc = set_cap(r, 64 + (size_t)r->ncols * SW_TRACE_CELL_MAX, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = read_line(r, err, errlen);
    if (rc == 0) {
        r->line++;
        return fail(r, err, errlen, "no header row after the metadata; expected 'step,t,...' "
                    "with %d columns", r->ncols);
    }
    if (rc < 0)
        return rc;
    char *cursor = r->buf, *cell, want[32], show[48];
    int c = 0;
    while ((cell = next_cell(&cursor))) {
        if (c == r->ncols)
            return fail(r, err, errlen, "extra column '%s' in the header: a %s trace has %d "
                        "columns, up to '%s'", shown(cell, strlen(cell), show),
                        r->sys.scene->name, r->ncols, want);
        sw_trace_colname(&r->sys, c, want, sizeof want);
        if (strcmp(cell, want) != 0)
            return fail(r, err, errlen, "header column %d is '%s'; expected '%s' (columns: "
                        "step, t, x<i>, y<i>%s per particle%s)", c + 1,
                        shown(cell, strlen(cell), show), want,
                        r->sys.ode->order == 2 ? ", vx<i>, vy<i>" : "",
                        r->sys.scene->energy ? ", then energy" : "");
        c++;
    }
    if (c < r->ncols) {
        sw_trace_colname(&r->sys, c, want, sizeof want);
        return fail(r, err, errlen, "the header has %d columns; missing column '%s' (a %s "
                    "trace with these parameters has %d)", c, want, r->sys.scene->name, r->ncols);
    }
    return SW_OK;
}

int sw_trace_read_row(sw_trace_reader *r, double *row, char *err, size_t errlen)
{
    char show[48], name[32];
    for (;;) {
        if (r->at_end)
            return 0;
        int rc = read_line(r, err, errlen);
        if (rc <= 0) {
            r->at_end = rc == 0;
            return rc;
        }
        if (r->len == 0) {
            /* Empty lines are allowed only at the very end. */
            if (!r->blank_line)
                r->blank_line = r->line;
            continue;
        }
        if (r->blank_line) {
            long line = r->line;
            r->line = r->blank_line;
            rc = fail(r, err, errlen, "empty line among the rows (the next row is on line %ld)", line);
            r->line = line;
            return rc;
        }
        if (r->buf[0] == '#') {
            /* Only the recorder's "# diverged:" note may follow the rows. */
            char *colon = strchr(r->buf, ':');
            if (colon) {
                *colon = '\0';
                if (strcmp(trim(r->buf + 1), "diverged") == 0) {
                    r->meta.diverged = 1;
                    continue;
                }
            }
            return fail(r, err, errlen, "only a '# diverged: ...' line may follow the header; "
                        "metadata goes before it");
        }
        if (r->rows == r->max_rows) {
            sw_trace_spec *sp = &r->meta.spec;
            if (r->max_rows == SW_TRACE_MAX_ROWS)
                return fail(r, err, errlen, "more than %ld rows: larger than any trace can be",
                            SW_TRACE_MAX_ROWS);
            return fail(r, err, errlen, "more rows than the metadata allows: %s %g with "
                        "'every: %ld' gives at most %ld", sp->steps ? "'steps:'" : "'until:'",
                        sp->steps ? (double)sp->steps : sp->until, sp->every, r->max_rows);
        }
        char *cursor = r->buf, *cell;
        int c = 0;
        while ((cell = next_cell(&cursor))) {
            if (c == r->ncols)
                return fail(r, err, errlen, "the row has more than the header's %d cells "
                            "(extra '%s')", r->ncols, shown(cell, strlen(cell), show));
            sw_trace_colname(&r->sys, c, name, sizeof name);
            if (!*cell)
                return fail(r, err, errlen, "empty cell in column '%s'", name);
            char *end;
            errno = 0;
            double v = strtod(cell, &end);
            if (*end != '\0')
                return fail(r, err, errlen, "column '%s' holds '%s', which is not a number "
                            "(numbers as printed by %%.17g; nan, inf and -inf allowed)", name,
                            shown(cell, strlen(cell), show));
            if (c == 0 && !(v >= 0 && v <= 1e15 && v == floor(v)))
                return fail(r, err, errlen, "column 'step' holds '%s'; a step is a whole number "
                            "from 0", shown(cell, strlen(cell), show));
            row[c++] = v;
        }
        if (c < r->ncols) {
            sw_trace_colname(&r->sys, c, name, sizeof name);
            return fail(r, err, errlen, "the row has %d cells; the header has %d (missing '%s' "
                        "onwards)", c, r->ncols, name);
        }
        r->rows++;
        return 1;
    }
}

void sw_trace_read_close(sw_trace_reader *r)
{
    if (r->f)
        fclose(r->f);
    r->f = NULL;
    free(r->buf);
    r->buf = NULL;
    if (r->have_sys)
        sw_system_free(&r->sys);
    r->have_sys = 0;
}

int sw_trace_meta_sim(const sw_trace_reader *r, sw_sim *s, const sw_integrator *m,
                      char *err, size_t errlen)
{
    const sw_trace_meta *meta = &r->meta;
    if (!m)
        m = meta->method;
    if (!m) {
        char names[400];
        sw_integrator_names(names, sizeof names);
        snprintf(err, errlen, "%s:%ld: unknown integrator '%s'; integrators: %s (a student "
                 "plugin's trace needs --plugin PATH.so)", r->name, meta->integrator_line,
                 meta->integrator, names);
        return SW_EINVAL;
    }
    char msg[SW_ERRLEN];
    int rc = sw_sim_init(s, meta->scene, meta->p, m, meta->dt, msg, sizeof msg);
    if (rc != SW_OK) {
        snprintf(err, errlen, "%s:%ld: %s", r->name, meta->integrator_line, msg);
        return rc;
    }
    sw_sim_set_tolerances(s, meta->rtol, meta->atol);
    return SW_OK;
}
