/* JSON output helpers (see json.h). */
#include "cli/json.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "grade/assignment.h"
#include "util/utf8.h"

void sw_json_str(FILE *out, const char *s)
{
    if (!s) {
        fputs("null", out);
        return;
    }
    const unsigned char *p = (const unsigned char *)s;
    putc('"', out);
    while (*p) {
        unsigned char c = *p;
        if (c == '"' || c == '\\') {
            fprintf(out, "\\%c", c);
            p++;
        } else if (c < 0x20 || c == 0x7f) {
            fprintf(out, "\\u%04x", c);
            p++;
        } else if (c < 0x80) {
            putc(c, out);
            p++;
        } else {
            /* strictly valid UTF-8 passes through (util/utf8: no overlong
             * form, no surrogate); C1 controls and U+2028/U+2029 (line breaks
             * to JavaScript) are escaped; any other byte becomes U+FFFD */
            size_t len;
            uint32_t cp;
            if (sw_utf8_check(p, strnlen((const char *)p, 4), &len, &cp) != SW_UTF8_OK) {
                fputs("\\ufffd", out);
                p++;
            } else if ((cp >= 0x80 && cp <= 0x9f) || cp == 0x2028 || cp == 0x2029) {
                fprintf(out, "\\u%04x", (unsigned)cp);
                p += len;
            } else {
                fwrite(p, 1, len, out);
                p += len;
            }
        }
    }
    putc('"', out);
}

void sw_json_num(FILE *out, double v)
{
    char buf[40];
    sw_fmt_shortest(buf, sizeof buf, v);
    if (isfinite(v))
        fputs(buf, out);
    else
        fprintf(out, "\"%s\"", buf);
}

void sw_json_long(FILE *out, long v, int null_negative)
{
    if (v < 0 && null_negative)
        fputs("null", out);
    else
        fprintf(out, "%ld", v);
}

void sw_json_key(FILE *out, int indent, const char *key, int first)
{
    fprintf(out, "%s\n%*s", first ? "" : ",", indent, "");
    sw_json_str(out, key);
    fputs(": ", out);
}
