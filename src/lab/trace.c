/* Step traces: the run rule (which steps a trace records), the writer and the
 * reader of the CSV format in docs/trace-format.md. Invariants: a row reaches
 * the file whole or not at all, the real name only ever holds a finished
 * trace, and the reader's memory is bounded by the scene, not by the file. */
#include "lab/trace.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lab/plugin.h"
#include "stepwise/stepwise.h"

/* ---- the run rule --------------------------------------------------------- */

int sw_trace_spec_check(const sw_trace_spec *spec, double dt, char *err, size_t errlen)
{
    if (spec->steps < 0 || spec->steps > SW_TRACE_MAX_STEPS) {
        snprintf(err, errlen, "steps = %ld is not allowed: a run takes 1 to %ld steps",
                 spec->steps, SW_TRACE_MAX_STEPS);
        return SW_EINVAL;
    }
    if (spec->steps == 0) {
        if (!(isfinite(spec->until) && spec->until > 0)) {
            snprintf(err, errlen, "until = %g is not allowed: it must be a positive finite time",
                     spec->until);
            return SW_EINVAL;
        }
        /* ceil(until/dt) steps, and one more when rounding in t leaves the
         * run short of until: refused at once, not after 10^7 steps. */
        if (!(dt > 0) || ceil(spec->until / dt * (1 - 1e-12)) + 1 > (double)SW_TRACE_MAX_STEPS) {
            snprintf(err, errlen, "until = %g with dt = %g needs %.3g steps (and one more when "
                     "rounding leaves t short of until); a run takes at most %ld (raise dt or "
                     "shorten the run)", spec->until, dt, ceil(spec->until / dt), SW_TRACE_MAX_STEPS);
            return SW_EINVAL;
        }
    }
    if (spec->every < 1 || spec->every > SW_TRACE_MAX_STEPS) {
        snprintf(err, errlen, "every = %ld is not allowed: it takes a whole number in [1, %ld]",
                 spec->every, SW_TRACE_MAX_STEPS);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_trace_done(const sw_sim *s, const sw_trace_spec *spec)
{
    if (s->blown)
        return 1;
    if (spec->steps > 0)
        return s->steps >= spec->steps;
    /* The same test as sw_sim_run_until: within a billionth of a step is there. */
    return !(spec->until - s->t > 1e-9 * s->dt);
}

int sw_trace_due(const sw_sim *s, const sw_trace_spec *spec)
{
    return s->steps == 0 || s->steps % spec->every == 0 || sw_trace_done(s, spec);
}

int sw_trace_step(sw_sim *s, const sw_trace_spec *spec, char *err, size_t errlen)
{
    if (s->steps >= SW_TRACE_MAX_STEPS) {
        snprintf(err, errlen, "the run needs more than %ld steps (at t = %g of %g); raise dt or "
                 "shorten the run", SW_TRACE_MAX_STEPS, s->t, spec->until);
        return SW_EINVAL;
    }
    if (sw_sim_step_until(s, spec->steps > 0 ? 0.0 : spec->until))
        sw_plugin_failed(s); /* a plugin that crashed, looped, ...: say so, not "diverged" */
    return SW_OK;
}

/* ---- columns -------------------------------------------------------------- */

/* Values per particle: position, plus velocity for second-order systems. */
static int per_particle(const sw_system *sys) { return sys->ode->order == 2 ? 4 : 2; }

int sw_trace_ncols(const sw_system *sys)
{
    return 2 + per_particle(sys) * sys->n + (sys->scene->energy ? 1 : 0);
}

void sw_trace_colname(const sw_system *sys, int c, char *buf, size_t len)
{
    static const char *const kinds[] = { "x", "y", "vx", "vy" };
    int pp = per_particle(sys);
    if (c == 0)
        snprintf(buf, len, "step");
    else if (c == 1)
        snprintf(buf, len, "t");
    else if (c - 2 < pp * sys->n)
        snprintf(buf, len, "%s%d", kinds[(c - 2) % pp], (c - 2) / pp);
    else
        snprintf(buf, len, "energy");
}

int sw_trace_colindex(const sw_system *sys, const char *name)
{
    static const char *const kinds[] = { "x", "y", "vx", "vy" };
    int pp = per_particle(sys);
    if (strcmp(name, "step") == 0)
        return 0;
    if (strcmp(name, "t") == 0)
        return 1;
    if (strcmp(name, "energy") == 0)
        return sys->scene->energy ? 2 + pp * sys->n : -1;
    for (int k = pp - 1; k >= 0; k--) {
        size_t len = strlen(kinds[k]);
        const char *digits = name + len;
        if (strncmp(name, kinds[k], len) != 0 || !*digits || strlen(digits) > 9 ||
            (digits[0] == '0' && digits[1]))
            continue;
        long i = 0;
        for (const char *d = digits; *d; d++) {
            if (*d < '0' || *d > '9')
                return -1;
            i = 10 * i + (*d - '0');
        }
        return i < sys->n ? 2 + pp * (int)i + k : -1;
    }
    return -1;
}

void sw_trace_row_values(const sw_sim *s, double *row)
{
    const sw_system *sys = &s->sys;
    int n = sys->n, pp = per_particle(sys);
    const double *y = sys->y;
    row[0] = (double)s->steps;
    row[1] = s->t;
    /* The state is [x(2n) | v(2n)]; the trace groups each particle's values. */
    for (int i = 0; i < n; i++) {
        double *out = row + 2 + pp * i;
        out[0] = y[2 * i];
        out[1] = y[2 * i + 1];
        if (pp == 4) {
            out[2] = y[2 * n + 2 * i];
            out[3] = y[2 * n + 2 * i + 1];
        }
    }
    if (sys->scene->energy)
        row[2 + pp * n] = sw_sim_energy(s);
}

/* ---- writing -------------------------------------------------------------- */

/* Shortest text that reads back as exactly v (metadata: "0.02", not
 * "0.020000000000000000"); rows use %.17g throughout. */
static void fmt_exact(char *buf, size_t len, double v)
{
    if (v == floor(v) && fabs(v) < 1e15) {
        snprintf(buf, len, "%.0f", v);
        return;
    }
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(buf, len, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
}

/* One cell; non-finite values as nan, inf, -inf whatever the sign of a NaN. */
static int fmt_cell(char *out, size_t room, double v)
{
    if (isnan(v))
        return snprintf(out, room, "nan");
    if (isinf(v))
        return snprintf(out, room, v > 0 ? "inf" : "-inf");
    return snprintf(out, room, "%.17g", v);
}

static int write_failed(sw_trace_writer *w, char *err, size_t errlen)
{
    snprintf(err, errlen, "cannot write '%s': %s", w->to_stdout ? "standard output" : w->path,
             errno ? strerror(errno) : "write error");
    return SW_EIO;
}

int sw_trace_open(sw_trace_writer *w, const char *path, char *err, size_t errlen)
{
    memset(w, 0, sizeof *w);
    w->last_step = -1;
    if (!path || strcmp(path, "-") == 0) {
        w->f = stdout;
        w->to_stdout = 1;
        return SW_OK;
    }
    struct stat st;
    if (!*path || strlen(path) >= SW_TRACE_PATH_MAX) {
        snprintf(err, errlen, "output path is empty or longer than %d bytes", SW_TRACE_PATH_MAX - 1);
        return SW_EINVAL;
    }
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "'%.200s' is a directory; give a file name for the trace", path);
        return SW_EINVAL;
    }
    snprintf(w->path, sizeof w->path, "%s", path);
    /* Beside the real name, so that rename() is atomic on the same file system. */
    snprintf(w->tmp, sizeof w->tmp, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(w->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "cannot create '%.200s': %s", path, strerror(errno));
        w->tmp[0] = '\0';
        return SW_EIO;
    }
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || !(w->f = fdopen(fd, "w"))) {
        snprintf(err, errlen, "cannot create '%.200s': %s", path, strerror(errno));
        close(fd);
        unlink(w->tmp);
        w->tmp[0] = '\0';
        return SW_EIO;
    }
    return SW_OK;
}

int sw_trace_begin(sw_trace_writer *w, const sw_sim *s, const sw_trace_spec *spec,
                   char *err, size_t errlen)
{
    int rc = sw_trace_spec_check(spec, s->dt, err, errlen);
    if (rc != SW_OK)
        return rc;
    const sw_system *sys = &s->sys;
    const sw_scene *sc = sys->scene;
    int ncols = sw_trace_ncols(sys);
    w->spec = *spec;
    w->row_cap = (size_t)ncols * 32 + 64;
    free(w->row);
    w->row = malloc(w->row_cap);
    if (!w->row) {
        snprintf(err, errlen, "out of memory for a trace row of %d columns", ncols);
        return SW_ENOMEM;
    }
    char num[40];
    errno = 0;
    FILE *f = w->f;
    fprintf(f, "%s\n# version: %s\n# scene: %s\n", SW_TRACE_MAGIC, SW_VERSION, sc->name);
    for (int i = 0; i < sc->nparams; i++) {
        fmt_exact(num, sizeof num, sys->p[i]);
        fprintf(f, "# param %s: %s\n", sc->params[i].name, num);
    }
    fprintf(f, "# integrator: %s\n", s->method->name);
    fmt_exact(num, sizeof num, s->dt);
    fprintf(f, "# dt: %s\n", num);
    if (spec->steps > 0)
        fprintf(f, "# steps: %ld\n", spec->steps);
    else {
        fmt_exact(num, sizeof num, spec->until);
        fprintf(f, "# until: %s\n", num);
    }
    fprintf(f, "# every: %ld\n", spec->every);
    fmt_exact(num, sizeof num, s->rtol);
    fprintf(f, "# rtol: %s\n", num);
    fmt_exact(num, sizeof num, s->atol);
    fprintf(f, "# atol: %s\n", num);
    for (int c = 0; c < ncols; c++) {
        sw_trace_colname(sys, c, num, sizeof num);
        fprintf(f, "%s%s", c ? "," : "", num);
    }
    fputc('\n', f);
    if (fflush(f) != 0 || ferror(f))
        return write_failed(w, err, errlen);
    return sw_trace_write_row(w, s, err, errlen);
}

int sw_trace_write_row(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen)
{
    const sw_system *sys = &s->sys;
    double cell[4];
    size_t used = 0;
    /* The state is [x(2n) | v(2n)]; a row groups each particle's values. */
    int pp = per_particle(sys);
    used += (size_t)snprintf(w->row, w->row_cap, "%ld,", s->steps);
    used += (size_t)fmt_cell(w->row + used, w->row_cap - used, s->t);
    const double *y = sys->y;
    int n = sys->n;
    for (int i = 0; i < n; i++) {
        cell[0] = y[2 * i];
        cell[1] = y[2 * i + 1];
        if (pp == 4) {
            cell[2] = y[2 * n + 2 * i];
            cell[3] = y[2 * n + 2 * i + 1];
        }
        for (int q = 0; q < pp; q++) {
            w->row[used++] = ',';
            used += (size_t)fmt_cell(w->row + used, w->row_cap - used, cell[q]);
        }
    }
    if (sys->scene->energy) {
        w->row[used++] = ',';
        used += (size_t)fmt_cell(w->row + used, w->row_cap - used, sw_sim_energy(s));
    }
    w->row[used++] = '\n';
    /* Past stdio, in one write(2) (more only if the kernel takes part of it):
     * stdio would cut a row longer than its buffer into several writes, and
     * a process killed between them would leave half a row. */
    errno = 0;
    if (fflush(w->f) != 0)
        return write_failed(w, err, errlen);
    int fd = fileno(w->f);
    for (size_t done = 0; done < used;) {
        ssize_t wrote = write(fd, w->row + done, used - done);
        if (wrote < 0 && errno == EINTR)
            continue;
        if (wrote <= 0)
            return write_failed(w, err, errlen);
        done += (size_t)wrote;
    }
    w->last_step = s->steps;
    w->rows++;
    return SW_OK;
}

int sw_trace_observe(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen)
{
    if (s->steps == w->last_step || !sw_trace_due(s, &w->spec))
        return SW_OK;
    return sw_trace_write_row(w, s, err, errlen);
}

int sw_trace_commit(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen)
{
    int rc = SW_OK;
    if (s->steps != w->last_step)
        rc = sw_trace_write_row(w, s, err, errlen);
    if (rc == SW_OK && s->blown) {
        char t[40];
        fmt_exact(t, sizeof t, s->blow_time);
        errno = 0;
        fprintf(w->f, "# diverged: step %ld, t %s: %s\n", s->blow_step, t, s->blow_reason);
        if (fflush(w->f) != 0 || ferror(w->f))
            rc = write_failed(w, err, errlen);
    }
    if (rc != SW_OK) {
        sw_trace_abort(w);
        return rc;
    }
    if (w->to_stdout) {
        free(w->row);
        w->row = NULL;
        w->f = NULL;
        return SW_OK;
    }
    errno = 0;
    int bad = fsync(fileno(w->f)) != 0 && errno != EINVAL;
    bad |= fclose(w->f) != 0;
    w->f = NULL;
    if (bad || rename(w->tmp, w->path) != 0) {
        snprintf(err, errlen, "cannot write '%.200s': %s", w->path, strerror(errno));
        sw_trace_abort(w);
        return SW_EIO;
    }
    w->tmp[0] = '\0';
    free(w->row);
    w->row = NULL;
    return SW_OK;
}

void sw_trace_abort(sw_trace_writer *w)
{
    if (w->f && !w->to_stdout)
        fclose(w->f);
    else if (w->f)
        fflush(w->f);
    w->f = NULL;
    if (w->tmp[0])
        unlink(w->tmp);
    w->tmp[0] = '\0';
    free(w->row);
    w->row = NULL;
}
