/* The trace writer. Invariants: a row reaches the file whole or not at all
 * (one write(2) per row), and the real name only ever holds a finished
 * trace (util/outfile: a temporary renamed on commit; standard output,
 * devices and FIFOs are streamed). */
#include "trace/trace.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stepwise/base.h"

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
    snprintf(err, errlen, "cannot write '%.200s': %s", sw_outfile_name(&w->out),
             errno ? strerror(errno) : "write error");
    return SW_EIO;
}

int sw_trace_open(sw_trace_writer *w, const char *path, char *err, size_t errlen)
{
    memset(w, 0, sizeof *w);
    w->last_step = -1;
    int rc = sw_outfile_open(&w->out, path, err, errlen);
    w->f = w->out.f;
    w->to_stdout = w->out.is_stdout;
    return rc;
}

/* Write the sim's current row, whole, and flush it. 0 or SW_EIO. */
static int sw_trace_write_row(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen);

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
    if (s->events == SW_EVENTS_LOCATE) /* only then: step-mode traces keep their bytes */
        fprintf(f, "# events: %s\n", sw_events_mode_name(s->events));
    for (int c = 0; c < ncols; c++) {
        sw_trace_colname(sys, c, num, sizeof num);
        fprintf(f, "%s%s", c ? "," : "", num);
    }
    fputc('\n', f);
    if (fflush(f) != 0 || ferror(f))
        return write_failed(w, err, errlen);
    return sw_trace_write_row(w, s, err, errlen);
}

static int sw_trace_write_row(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen)
{
    const sw_system *sys = &s->sys;
    double cell[4];
    size_t used = 0;
    /* The state is [x(2n) | v(2n)]; a row groups each particle's values. */
    int pp = sw_trace_per_particle(sys);
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
    if (rc == SW_OK)
        rc = sw_outfile_commit(&w->out, err, errlen);
    else
        sw_outfile_abort(&w->out);
    w->f = NULL;
    free(w->row);
    w->row = NULL;
    return rc;
}

void sw_trace_abort(sw_trace_writer *w)
{
    sw_outfile_abort(&w->out);
    w->f = NULL;
    free(w->row);
    w->row = NULL;
}
