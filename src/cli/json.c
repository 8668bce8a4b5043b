/* JSON output helpers (see json.h). */
#include "cli/json.h"

#include <math.h>
#include <string.h>

#include "grade/assignment.h"

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
            /* valid UTF-8 passes through; any other byte becomes U+FFFD */
            int len = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 && c < 0xf0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
            int ok = len > 0;
            for (int i = 1; ok && i < len; i++)
                ok = (p[i] & 0xc0) == 0x80;
            if (ok && len == 2 && p[0] == 0xc2 && p[1] < 0xa0) {
                fprintf(out, "\\u%04x", p[1]); /* C1 controls: escaped like C0 */
                p += 2;
            } else if (ok) {
                fwrite(p, 1, (size_t)len, out);
                p += len;
            } else {
                fputs("\\ufffd", out);
                p++;
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
