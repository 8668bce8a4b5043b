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
    /* sw_escape_message reads at most 4095 bytes; four bytes out per byte in. */
    char buf[4 * 4096 + 4];
    size_t n = strnlen(text ? text : "", 4095);
    memcpy(buf, text ? text : "", n);
    buf[n] = '\0';
    sw_escape_message(buf, sizeof buf);
    int neutralise = buf[0] && strchr(formula_starts, buf[0]);
    int quote = strpbrk(buf, ",\"") != NULL;
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
