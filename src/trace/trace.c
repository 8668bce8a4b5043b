/* Step traces: the reader of the CSV format in docs/trace-format.md (the run
 * rule and the columns are in trace_run.c, the writer in trace_write.c, the
 * metadata parser in trace_meta.c, the messages both write in trace_msg.c). Invariant: the reader's memory is
 * bounded by the scene, not by the file; every error names file and line. */
#include "trace/trace_read.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/decimal.h"
#include "util/infile.h"

/* The file is read in blocks of IN_BLOCK bytes into r->in, and lines are
 * cut from the block: no call per byte (a trace of 2 MB is read in 32
 * read() calls). */
#define IN_BLOCK 65536

/* A byte a text file does not hold: a control character other than tab
 * and CR, or DEL (1 or 0, branch-free so that the check vectorises). */
#define IS_BINARY(u) ((unsigned)(((u) < 0x20) & ((u) != '\t') & ((u) != '\r')) | ((u) == 0x7f))

/* Bytes available in r->in after at most one read(): 0 at the end of the
 * file or on a read error (r->in_errno). */
static size_t in_fill(sw_trace_reader *r)
{
    if (r->in_pos < r->in_len)
        return r->in_len - r->in_pos;
    r->in_pos = r->in_len = 0;
    while (!r->in_eof && !r->in_errno) {
        ssize_t got = read(r->fd, r->in, IN_BLOCK);
        if (got > 0) {
            r->in_len = (size_t)got;
            break;
        }
        if (got == 0)
            r->in_eof = 1;
        else if (errno != EINTR)
            r->in_errno = errno ? errno : EIO;
    }
    return r->in_len;
}

/* The next byte without taking it, or EOF. */
static int in_peek(sw_trace_reader *r)
{
    return in_fill(r) ? (unsigned char)r->in[r->in_pos] : EOF;
}

static int in_getc(sw_trace_reader *r)
{
    return in_fill(r) ? (unsigned char)r->in[r->in_pos++] : EOF;
}

static int read_error(sw_trace_reader *r, char *err, size_t errlen)
{
    tr_fail(r, err, errlen, "read error: %s", strerror(r->in_errno));
    return SW_EIO;
}

/* Read one line into r->buf without its newline (and a CR before it).
 * 1 a line, 0 end of file, or an error: too long, binary, or no final
 * newline (a cut-short file). */
static int read_line(sw_trace_reader *r, char *err, size_t errlen)
{
    if (!in_fill(r))
        return r->in_errno ? read_error(r, err, errlen) : 0;
    r->line++;
    size_t n = 0;
    for (;;) {
        size_t avail = in_fill(r);
        if (!avail) {
            if (r->in_errno)
                return read_error(r, err, errlen);
            return tr_fail(r, err, errlen, "the last line does not end with a newline: the file is "
                        "cut short (every line, the last one too, ends with a newline)");
        }
        const unsigned char *s = (const unsigned char *)r->in + r->in_pos;
        const unsigned char *nl = memchr(s, '\n', avail);
        size_t take = nl ? (size_t)(nl - s) : avail, room = r->cap - n;
        /* Bytes are checked in order, as far as one past the room left:
         * binary data is named before a line too long. */
        size_t scan = take <= room ? take : room + 1;
        unsigned bad = 0;
        for (size_t i = 0; i < scan; i++)
            bad |= IS_BINARY(s[i]);
        if (bad)
            for (size_t i = 0; i < scan; i++)
                if (IS_BINARY(s[i]))
                    return tr_fail(r, err, errlen, "binary data (byte 0x%02x at column %zu): a "
                                "trace is a text file", s[i], n + i + 1);
        if (take > room)
            return r->have_sys
                       ? tr_fail(r, err, errlen, "line longer than %zu bytes, more than %d columns "
                              "can need: far larger than any trace", r->cap, r->ncols)
                       : tr_fail(r, err, errlen, "line longer than %zu bytes: a metadata line is "
                              "shorter, and this is no trace", r->cap);
        memcpy(r->buf + n, s, take);
        n += take;
        r->in_pos += take;
        if (nl) {
            r->in_pos++; /* the newline */
            break;
        }
    }
    if (n > 0 && r->buf[n - 1] == '\r')
        n--;
    r->buf[n] = '\0';
    memset(r->buf + n + 1, 0, 7); /* sw_decimal_parse_padded may read 7 bytes past the end */
    r->len = n;
    return 1;
}

static int set_cap(sw_trace_reader *r, size_t cap, char *err, size_t errlen)
{
    char *b = realloc(r->buf, cap + 8); /* the line, its NUL, 7 zeros */
    if (!b) {
        snprintf(err, errlen, "%s: out of memory for a line of %zu bytes", r->name, cap);
        return SW_ENOMEM;
    }
    r->buf = b;
    r->cap = cap;
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
        return tr_fail(r, err, errlen, "empty file; a trace starts with the line '%s'", SW_TRACE_MAGIC);
    }
    /* A byte-order mark (Windows editors) and trailing blanks are no error. */
    char *first = r->buf;
    if (strncmp(first, "\xef\xbb\xbf", 3) == 0)
        first += 3;
    first = tr_trim(first);
    if (strcmp(first, SW_TRACE_MAGIC) == 0 ||
        (r->meta.assignment && strcmp(first, SW_ASSIGNMENT_MAGIC) == 0))
        return SW_OK;
    /* Not a trace. Random or binary bytes may happen to open with a short
     * clean line: look a little further so such a file is called binary. */
    for (int i = 0, c; i < 512 && (c = in_getc(r)) != EOF; i++)
        if ((c < 0x20 && c != '\t' && c != '\r' && c != '\n') || c == 0x7f)
            return tr_fail(r, err, errlen, "binary data (byte 0x%02x within the first 512 bytes "
                        "after line 1): a trace is a text file", (unsigned)c);
    char show[48], tail;
    int version;
    if (sscanf(r->buf, "# stepwise trace %d%c", &version, &tail) == 1)
        return tr_fail(r, err, errlen, "trace format %d; this stepwise reads format %d", version,
                    SW_TRACE_FORMAT);
    return tr_fail(r, err, errlen, "not a stepwise trace: the first line must be '%s', not '%s'",
                SW_TRACE_MAGIC, tr_shown(r->buf, r->len, show));
}

/* Metadata: every line that starts with '#', up to the header row. */
static int read_meta(sw_trace_reader *r, char *err, size_t errlen)
{
    meta_state ms;
    memset(&ms, 0, sizeof ms);
    for (;;) {
        int c = in_peek(r);
        if (c == EOF)
            break;
        if (c != '#')
            break;
        int rc = read_line(r, err, errlen);
        if (rc < 0)
            return rc;
        if (r->filter && r->filter(r->filter_ctx, r->line, r->buf, &r->len, r->cap))
            continue;
        rc = tr_meta_line(r, &ms, err, errlen);
        if (rc != SW_OK)
            return rc;
    }
    /* Messages about what is missing name the line after the metadata. */
    r->line++;
    int rc = tr_meta_finish(r, &ms, err, errlen);
    r->line--;
    return rc;
}

/* Open for reading without ever blocking (util/infile.h): only a regular
 * file is read; a FIFO, a device or a directory is refused at once. */
static int open_regular(sw_trace_reader *r, const char *path, char *err, size_t errlen)
{
    struct stat st;
    const char *what = NULL;
    int fd = sw_infile_open(path, &st, &what);
    if (fd < 0 && !what) {
        snprintf(err, errlen, "%.200s:1: cannot open: %s", path, strerror(errno));
        return SW_EIO;
    }
    if (fd < 0) {
        if (S_ISDIR(st.st_mode))
            snprintf(err, errlen, "%.200s:1: is a directory, not a trace", path);
        else
            snprintf(err, errlen, "%.200s:1: is %s, not a regular file; give a trace file", path,
                     S_ISFIFO(st.st_mode) ? "a FIFO (a named pipe)" : what);
        return SW_EINVAL;
    }
    if (!(r->in = malloc(IN_BLOCK))) {
        snprintf(err, errlen, "%.200s:1: out of memory for reading", path);
        close(fd);
        return SW_ENOMEM;
    }
    r->fd = fd;
    r->have_fd = 1;
    return SW_OK;
}

int sw_trace_read_open(sw_trace_reader *r, const char *path, char *err, size_t errlen)
{
    return sw_trace_read_open_as(r, path, 0, err, errlen);
}

static int open_with(sw_trace_reader *r, const char *path, int assignment,
                     sw_trace_meta_filter filter, void *ctx, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    snprintf(r->name, sizeof r->name, "%s", path);
    r->meta.assignment = assignment;
    r->filter = filter;
    r->filter_ctx = ctx;
    int rc = open_regular(r, path, err, errlen);
    if (rc != SW_OK)
        return rc;
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

int sw_trace_read_open_as(sw_trace_reader *r, const char *path, int assignment, char *err,
                          size_t errlen)
{
    return open_with(r, path, assignment, NULL, NULL, err, errlen);
}

int sw_trace_read_open_filtered(sw_trace_reader *r, const char *path, sw_trace_meta_filter filter,
                                void *ctx, char *err, size_t errlen)
{
    return open_with(r, path, 1, filter, ctx, err, errlen);
}

/* The next comma-separated cell of *cursor, trimmed; NULL after the last. */
static char *next_cell(char **cursor)
{
    char *s = *cursor;
    if (!s)
        return NULL;
    char *e = s;
    while (*e && *e != ',')
        e++;
    *cursor = *e ? e + 1 : NULL;
    *e = '\0';
    while (*s == ' ' || *s == '\t')
        s++;
    while (e > s && (e[-1] == ' ' || e[-1] == '\t'))
        *--e = '\0';
    return s;
}

int sw_trace_read_header(sw_trace_reader *r, char *err, size_t errlen)
{
    int rc = set_cap(r, 64 + (size_t)(r->ncols + SW_TRACE_EXTRA_COLS) * SW_TRACE_CELL_MAX, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = read_line(r, err, errlen);
    if (rc == 0) {
        r->line++;
        return tr_fail(r, err, errlen, "no header row after the metadata; expected 'step,t,...' "
                    "with %d columns", r->ncols);
    }
    if (rc < 0)
        return rc;
    free(r->col_of);
    r->col_of = malloc((size_t)(r->ncols + SW_TRACE_EXTRA_COLS) * sizeof *r->col_of);
    unsigned char *seen = calloc((size_t)r->ncols, 1);
    if (!r->col_of || !seen) {
        free(seen);
        snprintf(err, errlen, "%s: out of memory for %d columns", r->name, r->ncols);
        return SW_ENOMEM;
    }
    /* Columns are matched by name, in any order; each exactly once. A name
     * the scene does not have is an extra column: the same run with more
     * written, so it is skipped (a few of them), and named for a warning. */
    char *cursor = r->buf, *cell, want[32], show[48];
    int c = 0, extra = 0;
    r->ignored[0] = '\0';
    rc = SW_OK;
    while (rc == SW_OK && (cell = next_cell(&cursor))) {
        int idx = sw_trace_colindex(&r->sys, cell);
        if (idx < 0 && extra == SW_TRACE_EXTRA_COLS)
            rc = tr_fail(r, err, errlen, "header column %d is '%s', which a %s trace with these "
                         "parameters does not have (columns: step, t, x<i>, y<i>%s per particle "
                         "for i < %d%s; in any order; at most %d extra columns are ignored)",
                         c + extra + 1, tr_shown(cell, strlen(cell), show), r->sys.scene->name,
                         r->sys.ode->order == 2 ? ", vx<i>, vy<i>" : "", r->sys.n,
                         r->sys.scene->energy ? ", energy" : "", SW_TRACE_EXTRA_COLS);
        else if (idx < 0 && !*cell)
            rc = tr_fail(r, err, errlen, "header column %d has no name", c + extra + 1);
        else if (idx < 0) {
            size_t used = strlen(r->ignored);
            snprintf(r->ignored + used, sizeof r->ignored - used, "%s%s", used ? ", " : "",
                     tr_shown(cell, strlen(cell), show));
            r->col_of[c + extra++] = -1;
        } else if (seen[idx])
            rc = tr_fail(r, err, errlen, "header column %d, '%s', appears twice", c + extra + 1,
                         tr_shown(cell, strlen(cell), show));
        else {
            seen[idx] = 1;
            r->col_of[c + extra] = idx;
            c++;
        }
    }
    r->nhead = c + extra;
    if (rc == SW_OK && c < r->ncols) {
        int missing = 0;
        while (seen[missing])
            missing++;
        sw_trace_colname(&r->sys, missing, want, sizeof want);
        rc = tr_fail(r, err, errlen, "the header has %d columns; missing column '%s' (a %s "
                     "trace with these parameters has %d)", c, want, r->sys.scene->name, r->ncols);
    }
    free(seen);
    return rc;
}

/* A printable copy of the cell at s: up to its comma, without trailing blanks. */
static const char *cell_shown(const char *s, char out[48])
{
    size_t n = 0;
    while (s[n] && s[n] != ',')
        n++;
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        n--;
    return tr_shown(s, n, out);
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
        if (r->len == strspn(r->buf, " \t")) {
            /* Empty (or blank) lines are allowed only at the very end. */
            if (!r->blank_line)
                r->blank_line = r->line;
            continue;
        }
        if (r->blank_line) {
            long line = r->line;
            r->line = r->blank_line;
            rc = tr_fail(r, err, errlen, "empty line among the rows (the next row is on line %ld)", line);
            r->line = line;
            return rc;
        }
        if (r->buf[0] == '#') {
            /* Only the recorder's "# diverged:" note may follow the rows. */
            char *colon = strchr(r->buf, ':');
            if (colon) {
                *colon = '\0';
                if (strcmp(tr_trim(r->buf + 1), "diverged") == 0) {
                    r->meta.diverged = 1;
                    continue;
                }
            }
            return tr_fail(r, err, errlen, "only a '# diverged: ...' line may follow the header; "
                        "metadata goes before it");
        }
        if (r->rows == r->max_rows) {
            sw_trace_spec *sp = &r->meta.spec;
            if (r->max_rows == SW_TRACE_MAX_ROWS)
                return tr_fail(r, err, errlen, "more than %ld rows: larger than any trace can be",
                            SW_TRACE_MAX_ROWS);
            return tr_fail(r, err, errlen, "more rows than the metadata allows: %s %g with "
                        "'every: %ld' gives at most %ld (and %d more are graded as extra rows)",
                        sp->steps ? "'steps:'" : "'until:'",
                        sp->steps ? (double)sp->steps : sp->until, sp->every,
                        r->max_rows - SW_TRACE_ROW_SLACK, SW_TRACE_ROW_SLACK);
        }
        /* Each cell is read where it lies: blanks, a number, blanks, then a
         * comma or the end; its text is cut out only for a message. */
        char *p = r->buf;
        int c = 0;
        for (;;) {
            while (*p == ' ' || *p == '\t')
                p++;
            char *cell = p;
            if (c == r->nhead)
                return tr_fail(r, err, errlen, "the row has more than the header's %d cells "
                            "(extra '%s')", r->nhead, cell_shown(cell, show));
            int col = r->col_of[c];
            if (col < 0) { /* an extra column: not read */
                while (*p && *p != ',')
                    p++;
            } else {
                if (*p == ',' || !*p) {
                    sw_trace_colname(&r->sys, col, name, sizeof name);
                    return tr_fail(r, err, errlen, "empty cell in column '%s'", name);
                }
                char *end;
                double v = sw_decimal_parse_padded(cell, &end);
                for (p = end; *p == ' ' || *p == '\t'; p++)
                    ;
                if ((*p && *p != ',') || end == cell) {
                    sw_trace_colname(&r->sys, col, name, sizeof name);
                    return tr_fail(r, err, errlen, "column '%s' holds '%s', which is not a number "
                                "(numbers as printed by %%.17g; nan, inf and -inf allowed)", name,
                                cell_shown(cell, show));
                }
                if (col == 0 && !(v >= 0 && v <= 1e15 && v == floor(v)))
                    return tr_fail(r, err, errlen, "column 'step' holds '%s'; a step is a whole "
                                "number from 0", cell_shown(cell, show));
                row[col] = v;
            }
            c++;
            if (!*p)
                break;
            p++; /* the comma */
        }
        if (c < r->nhead) {
            int at = c;
            while (r->col_of[at] < 0 && at + 1 < r->nhead)
                at++;
            if (r->col_of[at] < 0)
                snprintf(name, sizeof name, "an extra column");
            else
                sw_trace_colname(&r->sys, r->col_of[at], name, sizeof name);
            return tr_fail(r, err, errlen, "the row has %d cells; the header has %d (missing '%s' "
                        "onwards)", c, r->nhead, name);
        }
        r->rows++;
        return 1;
    }
}

void sw_trace_read_close(sw_trace_reader *r)
{
    if (r->have_fd)
        close(r->fd);
    r->have_fd = 0;
    free(r->in);
    r->in = NULL;
    free(r->buf);
    r->buf = NULL;
    free(r->col_of);
    r->col_of = NULL;
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
    rc = sw_sim_set_events(s, meta->events, msg, sizeof msg);
    if (rc != SW_OK) {
        sw_sim_free(s);
        snprintf(err, errlen, "%s", msg);
    }
    return rc;
}
