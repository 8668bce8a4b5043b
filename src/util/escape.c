/* Escaping untrusted text for messages. Invariant: the output holds no
 * byte below 0x20, no DEL, no C1 control, no bidirectional or other
 * invisible formatting character and no invalid UTF-8, whatever the
 * input, and is never cut inside a character or an escape. */
#include "util/escape.h"

#include <stdint.h>
#include <string.h>

#include "util/utf8.h"

/* Unicode's invisible formatting: the bidirectional controls (which can
 * show "lamrof" as "formal" and move a column), zero-width characters and
 * the line and paragraph separators. Shown, they would let a name look
 * like another or break a row: escaped like controls. */
static int invisible(uint32_t cp)
{
    return cp == 0x061c || (cp >= 0x200b && cp <= 0x200f) || (cp >= 0x2028 && cp <= 0x202e) ||
           (cp >= 0x2060 && cp <= 0x2069) || cp == 0xfeff;
}

/* Length of the printable character at s (avail bytes readable): 1..4, or
 * 0 when it is a control, DEL, a C1 control, invisible formatting or not
 * well-formed UTF-8. */
static size_t printable(const unsigned char *s, size_t avail)
{
    if (s[0] < 0x80)
        return s[0] >= 0x20 && s[0] != 0x7f ? 1 : 0;
    size_t len;
    uint32_t cp;
    if (sw_utf8_check(s, avail, &len, &cp) != SW_UTF8_OK || (cp >= 0x80 && cp <= 0x9f) || invisible(cp))
        return 0;
    return len;
}

/* Length of the piece text at s becomes: the character itself, or 4 for
 * \xNN; *k gets the bytes of text it stands for. */
static size_t piece_len(const unsigned char *s, size_t avail, int keep_backslash, size_t *k)
{
    *k = s[0] == '\\' && !keep_backslash ? 0 : printable(s, avail);
    return *k ? *k : 4;
}

/* Escape text[0..n) into out; returns 1 when all of it fitted. Text whose
 * escaped form fits is written whole; only text that does not is cut, with
 * room kept for "...". So escaping text already escaped, which fits,
 * changes nothing (a gradebook's kept cells stay as they are). */
static int escape(const char *text, size_t n, int keep_backslash, char *out, size_t outlen)
{
    static const char hex[] = "0123456789abcdef";
    const unsigned char *s = (const unsigned char *)text;
    size_t k, total = 0;
    for (size_t i = 0; i < n && total < outlen; i += k ? k : 1)
        total += piece_len(s + i, n - i, keep_backslash, &k);
    size_t room = total < outlen || outlen < 4 ? outlen : outlen - 3; /* "..." when cut */
    size_t used = 0, i = 0;
    while (i < n) {
        size_t plen = piece_len(s + i, n - i, keep_backslash, &k);
        if (used + plen + 1 > room)
            break;
        if (k)
            memcpy(out + used, s + i, k);
        else {
            out[used] = '\\';
            out[used + 1] = 'x';
            out[used + 2] = hex[s[i] >> 4];
            out[used + 3] = hex[s[i] & 15];
        }
        used += plen;
        i += k ? k : 1;
    }
    int whole = i >= n;
    if (!whole && used + 4 <= outlen) {
        memcpy(out + used, "...", 3);
        used += 3;
    }
    out[used] = '\0';
    return whole;
}

void sw_escape(const char *text, size_t max, char *out, size_t outlen)
{
    if (!out || outlen == 0)
        return;
    if (!text)
        text = "";
    size_t n = strnlen(text, max);
    if (!escape(text, n, 0, out, outlen) || text[n] == '\0')
        return;
    /* cut by max: mark it */
    size_t used = strlen(out);
    if (used + 4 <= outlen)
        memcpy(out + used, "...", 4);
}

void sw_escape_message(char *msg, size_t len)
{
    if (!msg || len == 0)
        return;
    char copy[4096];
    size_t n = strnlen(msg, len - 1);
    if (n >= sizeof copy)
        n = sizeof copy - 1;
    memcpy(copy, msg, n);
    escape(copy, n, 1, msg, len);
}

void sw_escape_kept(const char *text, size_t max, char *out, size_t outlen)
{
    if (!out || outlen == 0)
        return;
    if (!text)
        text = "";
    escape(text, strnlen(text, max), 1, out, outlen);
}
