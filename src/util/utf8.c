/* UTF-8 in one place. Invariant: the strict check accepts exactly the
 * well-formed sequences of RFC 3629; the lenient decoder never reads past a
 * byte that is not a continuation byte, so it cannot run off a string. */
#include "util/utf8.h"

int sw_utf8_encode(uint32_t cp, char out[4])
{
    if (cp < 0x80) {
        out[0] = (char)cp;
        return 1;
    }
    if (cp < 0x800) {
        out[0] = (char)(0xC0 | (cp >> 6));
        out[1] = (char)(0x80 | (cp & 0x3F));
        return 2;
    }
    if ((cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) {
        out[0] = '?';
        return 1;
    }
    if (cp < 0x10000) {
        out[0] = (char)(0xE0 | (cp >> 12));
        out[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        out[2] = (char)(0x80 | (cp & 0x3F));
        return 3;
    }
    out[0] = (char)(0xF0 | (cp >> 18));
    out[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
    out[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
    out[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}

uint32_t sw_utf8_next(const unsigned char **p)
{
    const unsigned char *s = *p;
    uint32_t c = s[0];
    int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (len == 0) {
        *p = s + 1;
        return '?';
    }
    if (len == 1) {
        *p = s + 1;
        return c;
    }
    c &= 0x3Fu >> (len - 1);
    for (int i = 1; i < len; i++) {
        if ((s[i] & 0xC0) != 0x80) {
            *p = s + 1;
            return '?';
        }
        c = (c << 6) | (s[i] & 0x3F);
    }
    *p = s + len;
    return c;
}

int sw_utf8_check(const unsigned char *s, size_t avail, size_t *len, uint32_t *cp)
{
    unsigned char c = s[0];
    if (c < 0x80) {
        *len = 1;
        *cp = c;
        return SW_UTF8_OK;
    }
    /* Lead byte, continuation count, smallest code point of that length. */
    size_t more;
    uint32_t v, min;
    if (c >= 0xC2 && c <= 0xDF) {
        more = 1; v = c & 0x1F; min = 0x80;
    } else if (c >= 0xE0 && c <= 0xEF) {
        more = 2; v = c & 0x0F; min = 0x800;
    } else if (c >= 0xF0 && c <= 0xF4) {
        more = 3; v = c & 0x07; min = 0x10000;
    } else {
        return SW_UTF8_BAD_LEAD;
    }
    for (size_t k = 1; k <= more; k++) {
        if (k >= avail || (s[k] & 0xC0) != 0x80)
            return SW_UTF8_CUT;
        v = (v << 6) | (s[k] & 0x3F);
    }
    if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF))
        return SW_UTF8_BAD_RANGE;
    *len = more + 1;
    *cp = v;
    return SW_UTF8_OK;
}

size_t sw_utf8_count(const char *s, size_t len)
{
    size_t n = 0;
    for (size_t i = 0; i < len; i++)
        n += ((unsigned char)s[i] & 0xC0) != 0x80;
    return n;
}

size_t sw_utf8_clip(const char *s, size_t len, size_t max)
{
    if (len <= max)
        return len;
    size_t n = max;
    while (n > 0 && ((unsigned char)s[n] & 0xC0) == 0x80)
        n--;
    return n;
}
