/* Step traces (docs/trace-format.md): a CSV file a student can write from any
 * language. The writer streams whole rows into a temporary file and renames
 * it on commit; the reader streams in memory bounded by the scene's column
 * count, never by the file's size. The recorder in `stepwise record` and the
 * TUI both drive a sim through sw_trace_step, so their traces are identical. */
#ifndef SW_TRACE_TRACE_H
#define SW_TRACE_TRACE_H

#include <stddef.h>
#include <stdio.h>

#include "stepwise/sim.h"
#include "util/outfile.h"

#define SW_TRACE_MAGIC "# stepwise trace 1"
#define SW_ASSIGNMENT_MAGIC "# stepwise assignment 1"
#define SW_TRACE_FORMAT 1
/* At most this many steps per run, and so at most SW_TRACE_MAX_STEPS + 1 rows. */
#define SW_TRACE_MAX_STEPS 10000000L
#define SW_TRACE_MAX_ROWS (SW_TRACE_MAX_STEPS + 1)
/* Longest metadata line, in bytes (the first line and every "# key: value"). */
#define SW_TRACE_META_MAX 4096
/* Row and header lines may hold up to 64 + SW_TRACE_CELL_MAX bytes per column
 * (the scene's columns and SW_TRACE_EXTRA_COLS more). */
#define SW_TRACE_CELL_MAX 48
#define SW_TRACE_PATH_MAX 4096
#define SW_TRACE_NAME_MAX 64
/* Rows beyond the metadata's run that are still read (and graded as extra
 * rows) before the file is refused as longer than its metadata allows. */
#define SW_TRACE_ROW_SLACK 4

/* How long a run lasts and which steps it records. */
typedef struct sw_trace_spec {
    long steps;    /* > 0: stop after this many steps; 0: stop at time `until` */
    double until;  /* used when steps == 0 */
    long every;    /* record step 0, every `every`-th step, and the last step */
} sw_trace_spec;

/* Check a spec for a run with step dt: steps in [1, SW_TRACE_MAX_STEPS], or
 * until > 0 with until/dt at most SW_TRACE_MAX_STEPS; every in [1, same].
 * 0 or SW_EINVAL naming what is allowed. */
int sw_trace_spec_check(const sw_trace_spec *spec, double dt, char *err, size_t errlen);
/* Whether the run is over: blown up, took its steps, or reached `until`. */
int sw_trace_done(const sw_sim *s, const sw_trace_spec *spec);
/* Whether the sim's current step is recorded: step 0, a multiple of every,
 * or the run's last step (including a blow-up). */
int sw_trace_due(const sw_sim *s, const sw_trace_spec *spec);
/* One step of the run (landing exactly on `until`); 0, or SW_EINVAL when the
 * run would exceed SW_TRACE_MAX_STEPS steps. A blow-up is not an error. */
int sw_trace_step(sw_sim *s, const sw_trace_spec *spec, char *err, size_t errlen);

/* Columns of a system's trace: step, t, then x<i>, y<i> (and vx<i>, vy<i>
 * for second-order systems) per particle, then energy when defined. */
int sw_trace_ncols(const sw_system *sys);
/* Values per particle in a row: 4 (x, y, vx, vy) or 2 for a flow. */
int sw_trace_per_particle(const sw_system *sys);
/* Name of column c (0 <= c < ncols) into buf. */
void sw_trace_colname(const sw_system *sys, int c, char *buf, size_t len);
/* Index of the column called name (the inverse of sw_trace_colname), or -1. */
int sw_trace_colindex(const sw_system *sys, const char *name);
/* The sim's current row: ncols values (step, t, state..., energy). */
void sw_trace_row_values(const sw_sim *s, double *row);

/* ---- writing ------------------------------------------------------------ */

typedef struct sw_trace_writer {
    sw_outfile out;                  /* the file (util/outfile.h) */
    FILE *f;                         /* out.f while open */
    int to_stdout;                   /* path "-" or NULL */
    char *row;                       /* one formatted row */
    size_t row_cap;
    sw_trace_spec spec;
    long last_step;                  /* step of the last row written; -1: none */
    long rows;
} sw_trace_writer;

/* Open a trace for writing through sw_outfile: path NULL or "-" is stdout,
 * a device or FIFO is written in place, anything else is a temporary file
 * beside path that only sw_trace_commit renames onto it. 0, SW_EINVAL (path
 * is a directory) or SW_EIO. After any later failure (begin, write_row,
 * observe), call sw_trace_abort. */
int sw_trace_open(sw_trace_writer *w, const char *path, char *err, size_t errlen);
/* Write the first line, the metadata that regenerates s under spec (s at
 * step 0), the header row and row 0. 0, SW_EINVAL or SW_EIO. */
int sw_trace_begin(sw_trace_writer *w, const sw_sim *s, const sw_trace_spec *spec,
                   char *err, size_t errlen);
/* After each step: write the row when the spec records this step. 0 or SW_EIO. */
int sw_trace_observe(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen);
/* Finish: the last row if not yet written, a "# diverged:" line after a
 * blow-up, then close and rename onto the real name. The writer is closed
 * whatever happens; on failure the temporary file is removed. 0 or SW_EIO. */
int sw_trace_commit(sw_trace_writer *w, const sw_sim *s, char *err, size_t errlen);
/* Give up: close and remove the temporary file. Safe after a failed call. */
void sw_trace_abort(sw_trace_writer *w);

/* ---- reading ------------------------------------------------------------ */

/* Longest "# student:" value; all "# note:" values together. */
#define SW_TRACE_STUDENT_MAX 128
#define SW_TRACE_NOTES_MAX 512
/* rtol and atol of a run must lie in [SW_TRACE_TOL_MIN, 1]: below it no
 * double-precision run can meet them (rk45 would shrink its step forever). */
#define SW_TRACE_TOL_MIN 1e-14
/* An assignment's own keys (tolerance, ignore, title), kept as text. */
#define SW_TRACE_EXTRAS 32
/* Columns a header may carry beyond the scene's (ignored, with a warning). */
#define SW_TRACE_EXTRA_COLS 8

typedef struct sw_trace_extra {
    char key[48];
    char value[256];
    long line;
} sw_trace_extra;

/* What the metadata says: enough to rebuild the run. */
typedef struct sw_trace_meta {
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    long param_line[SW_MAX_PARAMS];   /* line that set each parameter; 0: the default */
    char integrator[SW_TRACE_NAME_MAX];
    const sw_integrator *method;      /* NULL when no integrator has that name (or a list) */
    long integrator_line;
    long scene_line;
    double dt, rtol, atol;
    long dt_line, steps_line, every_line, rtol_line, atol_line; /* steps_line: steps or until */
    sw_events_mode events;            /* "# events: locate"; step when absent */
    long events_line;
    sw_trace_spec spec;
    char version[32];
    int diverged;                     /* a "# diverged:" line was seen */
    char student[SW_TRACE_STUDENT_MAX]; /* "# student: NAME" ("" when none) */
    char notes[SW_TRACE_NOTES_MAX];   /* every "# note:", joined by " / " */
    int assignment;                   /* read as an assignment (sw_trace_read_open_as) */
    sw_trace_extra extras[SW_TRACE_EXTRAS];
    int nextras;
} sw_trace_meta;

/* A metadata line's filter (an assignment's parts and per-student values,
 * grade/homework.c): called with each "# ..." line after the first, its
 * number and its text (len bytes, room for cap); returns 1 to skip the
 * line, 0 to read it as it now is (it may be rewritten in place, len
 * updated, within cap). */
typedef int (*sw_trace_meta_filter)(void *ctx, long line, char *buf, size_t *len, size_t cap);

typedef struct sw_trace_reader {
    int fd;                           /* the open file (have_fd) */
    int have_fd;
    char *in;                         /* read-ahead block: in[in_pos, in_len) not yet read */
    size_t in_pos, in_len;
    int in_eof;                       /* read() said end of file */
    int in_errno;                     /* read() failed with this; 0: no error */
    char name[SW_TRACE_PATH_MAX];     /* the path, for messages */
    long line;                        /* number of the line in buf */
    char *buf;                        /* the current line, without its newline */
    size_t cap;                       /* longest line accepted now */
    size_t len;
    sw_trace_meta meta;
    sw_system sys;                    /* built from the metadata: gives the columns */
    int have_sys;
    int ncols;
    int *col_of;                      /* header position -> column (step, t, x0, ...); -1 ignored */
    int nhead;                        /* cells in the header: ncols + the ignored ones */
    char ignored[96];                 /* the extra columns' names, ", "-separated ("" none) */
    long rows;
    long max_rows;                    /* the most rows the metadata's run can give */
    long blank_line;                  /* first empty line since the last row; 0: none */
    int at_end;
    sw_trace_meta_filter filter;      /* sw_trace_read_open_filtered; NULL: none */
    void *filter_ctx;
} sw_trace_reader;

/* Open path and read its first line and metadata, up to (not including) the
 * header row; builds the scene to know the columns. The integrator is looked
 * up but may be unknown (meta.method NULL). A UTF-8 byte-order mark and
 * blanks after the first line are accepted. Only a regular file is read
 * (a FIFO or device is refused without blocking). Errors read "FILE:LINE:
 * what". 0, SW_EINVAL, SW_EIO or SW_ENOMEM; on failure the reader is closed. */
int sw_trace_read_open(sw_trace_reader *r, const char *path, char *err, size_t errlen);
/* The same for an assignment (docs/trace-format.md): the first line may also
 * be "# stepwise assignment 1", the integrator may be a comma-separated list
 * (meta.method NULL), and the keys "tolerance", "tolerance COL", "ignore" and
 * "title" are kept in meta.extras. */
int sw_trace_read_open_as(sw_trace_reader *r, const char *path, int assignment, char *err,
                          size_t errlen);
/* The same as an assignment, each metadata line through filter first. */
int sw_trace_read_open_filtered(sw_trace_reader *r, const char *path, sw_trace_meta_filter filter,
                                void *ctx, char *err, size_t errlen);
/* Read the header row: every column of the scene once, in any order, matched
 * by name (rows are returned in the canonical order). Up to
 * SW_TRACE_EXTRA_COLS other names (e.g. "ke") are ignored, their cells
 * skipped, and listed in r->ignored for a warning. 0 or an error. */
int sw_trace_read_header(sw_trace_reader *r, char *err, size_t errlen);
/* Read the next row into row (ncols values in the canonical column order,
 * step, t, x0, ...; non-finite allowed). 1 a row,
 * 0 the end, or a negative status with "FILE:LINE: what" in err. */
int sw_trace_read_row(sw_trace_reader *r, double *row, char *err, size_t errlen);
void sw_trace_read_close(sw_trace_reader *r);

/* Initialise a sim that regenerates the trace: the metadata's scene,
 * parameters, dt and tolerances under method m (NULL: the metadata's). */
int sw_trace_meta_sim(const sw_trace_reader *r, sw_sim *s, const sw_integrator *m,
                      char *err, size_t errlen);

#endif
