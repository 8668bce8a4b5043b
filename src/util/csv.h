/* CSV fields that are safe to open in a spreadsheet: RFC 4180 quoting, no
 * control character, and no cell a spreadsheet would run as a formula. */
#ifndef SW_UTIL_CSV_H
#define SW_UTIL_CSV_H

#include <stdio.h>

/* Write text as one CSV field: control characters and invalid UTF-8 as
 * \xNN (util/escape.h's rule; backslashes kept), so a field is one line of
 * printable text; a field starting with =, +, -, @, tab or CR gets a
 * leading ' (OWASP's defence against formula injection); quoted, quotes
 * doubled, when it holds a comma or a quote. At most 4095 bytes of text
 * are kept ("..." marks a cut). NULL writes an empty field. */
void sw_csv_field(FILE *out, const char *text);

#endif
