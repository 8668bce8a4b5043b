/* CSV fields for gradebooks. Invariant: a field written holds no byte below
 * 0x20, no DEL or C1 control and no invalid UTF-8, never starts with a
 * character a spreadsheet reads as the start of a formula, and reads back
 * (quotes undone) as the escaped text, the neutralising ' first. */
#include "util/csv.h"

#include <string.h>

#include "util/escape.h"

/* OWASP's list ("CSV Injection"): what makes a spreadsheet evaluate a cell. */
static const char formula_starts[] = "=+-@\t\r";

void sw_csv_field(FILE *out, const char *text)
{
    /* At most 4095 bytes, the neutralising ' included: a field read back
     * and written again (a regrade keeps the other rows) comes out as it
     * was, and always within what sw_csv_parse reads. */
    char buf[4096];
    sw_escape_kept(text, SW_CSV_CELL_MAX, buf, sizeof buf);
    int neutralise = buf[0] && strchr(formula_starts, buf[0]);
    if (neutralise && strlen(buf) == sizeof buf - 1)
        sw_escape_kept(text, SW_CSV_CELL_MAX, buf, sizeof buf - 1);
    /* quoted where a ',' or a '"' must be, and where a ';' is: a
     * spreadsheet that splits at ';' (many locales) would start a cell,
     * perhaps a formula, after it */
    int quote = strpbrk(buf, ",\";") != NULL;
    if (quote)
        putc('"', out);
    if (neutralise)
        putc('\'', out);
    for (const char *s = buf; *s; s++) {
        if (*s == '"')
            putc('"', out);
        putc(*s, out);
    }
    if (quote)
        putc('"', out);
}

/* ---- reading a gradebook back ----------------------------------------------- */

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/infile.h"

static int csv_fail(char *err, size_t errlen, const char *name, long line, const char *fmt, ...)
{
    char what[300];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(err, errlen, "%.200s:%ld: %s", name, line, what);
    return SW_EINVAL;
}

void sw_csv_doc_free(sw_csv_doc *d)
{
    for (int r = 0; r < d->nrows; r++) {
        for (int c = 0; c < d->rows[r].n; c++)
            free(d->rows[r].cells[c]);
        free(d->rows[r].cells);
    }
    free(d->rows);
    d->rows = NULL;
    d->nrows = 0;
}

static int add_row(sw_csv_doc *d, int *cap, long line)
{
    if (d->nrows == *cap) {
        int ncap = *cap ? 2 * *cap : 64;
        sw_csv_row *rows = realloc(d->rows, (size_t)ncap * sizeof *rows);
        if (!rows)
            return SW_ENOMEM;
        d->rows = rows;
        *cap = ncap;
    }
    sw_csv_row *row = &d->rows[d->nrows++];
    row->n = 0;
    row->line = line;
    row->cells = calloc(SW_CSV_COLS_MAX, sizeof *row->cells);
    return row->cells ? SW_OK : SW_ENOMEM;
}

int sw_csv_parse(const char *name, const char *text, size_t len, sw_csv_doc *d, char *err,
                 size_t errlen)
{
    d->rows = NULL;
    d->nrows = 0;
    if (len > SW_CSV_FILE_MAX)
        return csv_fail(err, errlen, name, 0, "larger than %u MiB", SW_CSV_FILE_MAX >> 20);
    size_t i = 0;
    if (len >= 3 && memcmp(text, "\357\273\277", 3) == 0)
        i = 3;
    int cap = 0, rc = SW_OK;
    long line = 1;
    char *cell = malloc(SW_CSV_CELL_MAX + 1);
    if (!cell)
        return SW_ENOMEM;
    while (i < len && rc == SW_OK) {
        /* One row: cells up to an unquoted line end. */
        long row_line = line;
        if ((rc = add_row(d, &cap, row_line)) != SW_OK)
            break;
        if (d->nrows > SW_CSV_ROWS_MAX) {
            rc = csv_fail(err, errlen, name, line, "more than %d rows", SW_CSV_ROWS_MAX);
            break;
        }
        sw_csv_row *row = &d->rows[d->nrows - 1];
        for (int end_of_row = 0; !end_of_row && rc == SW_OK;) {
            size_t n = 0;
            int quoted = i < len && text[i] == '"';
            if (quoted)
                i++;
            for (;;) {
                if (i >= len) {
                    if (quoted)
                        rc = csv_fail(err, errlen, name, row_line, "a quoted cell runs to the end "
                                      "of the file (a missing closing quote)");
                    end_of_row = 1;
                    break;
                }
                char ch = text[i];
                if (ch == '\0') {
                    rc = csv_fail(err, errlen, name, line, "a NUL byte; not a CSV gradebook");
                    break;
                }
                if (quoted && ch == '"') {
                    if (i + 1 < len && text[i + 1] == '"') {
                        i += 2;
                        ch = '"';
                    } else {
                        i++;
                        quoted = 0;
                        if (i < len && text[i] != ',' && text[i] != '\r' && text[i] != '\n') {
                            rc = csv_fail(err, errlen, name, line, "text after a closing quote");
                            break;
                        }
                        continue;
                    }
                } else if (!quoted && ch == ',') {
                    i++;
                    break;
                } else if (!quoted && (ch == '\n' || ch == '\r')) {
                    i += ch == '\r' && i + 1 < len && text[i + 1] == '\n' ? 2 : 1;
                    line++;
                    end_of_row = 1;
                    break;
                } else if (!quoted && ch == '"') {
                    rc = csv_fail(err, errlen, name, line, "a quote inside an unquoted cell");
                    break;
                } else {
                    if (ch == '\n')
                        line++;
                    i++;
                }
                if (n == SW_CSV_CELL_MAX) {
                    rc = csv_fail(err, errlen, name, line, "a cell longer than %d bytes",
                                  SW_CSV_CELL_MAX);
                    break;
                }
                cell[n++] = ch;
            }
            if (rc != SW_OK)
                break;
            if (row->n == SW_CSV_COLS_MAX) {
                rc = csv_fail(err, errlen, name, row_line, "more than %d cells in a row",
                              SW_CSV_COLS_MAX);
                break;
            }
            cell[n] = '\0';
            if (!(row->cells[row->n] = strdup(cell)))
                rc = SW_ENOMEM;
            else
                row->n++;
        }
        /* A row keeps only the cells it has (100 000 rows of 64 would be
         * 50 MB of pointers). */
        char **fit = row->n ? realloc(row->cells, (size_t)row->n * sizeof *fit) : NULL;
        if (fit)
            row->cells = fit;
    }
    free(cell);
    if (rc == SW_ENOMEM)
        snprintf(err, errlen, "%.200s: out of memory", name);
    if (rc != SW_OK)
        sw_csv_doc_free(d);
    return rc;
}

int sw_csv_read(const char *path, sw_csv_doc *d, char *err, size_t errlen)
{
    struct stat st;
    const char *what;
    d->rows = NULL;
    d->nrows = 0;
    int fd = sw_infile_open(path, &st, &what);
    if (fd < 0) {
        snprintf(err, errlen, "cannot read '%.200s': %s", path, what ? what : strerror(errno));
        return SW_EIO;
    }
    char *text;
    size_t len;
    int r = sw_infile_read(fd, SW_CSV_FILE_MAX, &text, &len);
    close(fd);
    if (r == 1)
        return csv_fail(err, errlen, path, 0, "larger than %u MiB", SW_CSV_FILE_MAX >> 20);
    if (r != 0) {
        snprintf(err, errlen, "cannot read '%.200s': %s", path, strerror(errno));
        return SW_EIO;
    }
    int rc = sw_csv_parse(path, text, len, d, err, errlen);
    free(text);
    return rc;
}
