/* CSV for gradebooks: fields that are safe to open in a spreadsheet (RFC
 * 4180 quoting, no control character, no cell a spreadsheet would run as a
 * formula), and a bounded reader for reading a gradebook back. */
#ifndef SW_UTIL_CSV_H
#define SW_UTIL_CSV_H

#include <stddef.h>
#include <stdio.h>

#define SW_CSV_FILE_MAX (16u << 20)  /* bytes in a CSV read back */
#define SW_CSV_ROWS_MAX 100000       /* rows */
#define SW_CSV_COLS_MAX 64           /* cells in a row */
#define SW_CSV_CELL_MAX 8192         /* bytes in a cell */

/* Write text as one CSV field: control characters and invalid UTF-8 as
 * \xNN (util/escape.h's rule; backslashes kept), so a field is one line of
 * printable text; a field starting with =, +, -, @, tab or CR gets a
 * leading ' (OWASP's defence against formula injection); quoted, quotes
 * doubled, when it holds a comma or a quote. At most 4095 bytes of text
 * are kept ("..." marks a cut). NULL writes an empty field. */
void sw_csv_field(FILE *out, const char *text);

/* One row read back: its cells (NUL-terminated, quotes undone) and the
 * line it starts on. */
typedef struct sw_csv_row {
    int n;
    char **cells;
    long line;
} sw_csv_row;

typedef struct sw_csv_doc {
    sw_csv_row *rows;
    int nrows;
} sw_csv_doc;

/* Parse comma-separated text (RFC 4180: CRLF or LF line ends, quoted cells
 * with "" for a quote; a BOM allowed) into d, within the bounds above. A
 * NUL byte, a quote inside an unquoted cell, an unterminated quoted cell
 * or a bound passed is refused. 0, or SW_EINVAL / SW_ENOMEM with err
 * "NAME:LINE: what"; d is then empty (still free it). */
int sw_csv_parse(const char *name, const char *text, size_t len, sw_csv_doc *d, char *err,
                 size_t errlen);
/* The same from a file (a regular file only, never waited on). SW_EIO
 * when it cannot be read. */
int sw_csv_read(const char *path, sw_csv_doc *d, char *err, size_t errlen);
void sw_csv_doc_free(sw_csv_doc *d);

#endif
