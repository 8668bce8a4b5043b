/* Folding names and ids for comparison: lower case, Latin accents off,
 * combining marks and punctuation dropped, so "José García-López", its
 * NFD spelling from a Mac and "garcialopezjose" compare equal word by word.
 * Invariant: pure and locale-free; the output is never longer than outlen. */
#include "grade/roster.h"

#include <stdint.h>
#include <string.h>

#include "grade/roster_int.h"
#include "util/utf8.h"

/* U+00C0..U+017F (Latin-1 letters, Latin Extended-A) to ASCII: one letter
 * each, except A = ae, T = th, S = ss, J = ij, O = oe, '-' = nothing (× ÷). */
static const char latin_fold[] =
    "aaaaaaAceeeeiiiidnooooo-ouuuuyTSaaaaaaAceeeeiiiidnooooo-ouuuuyTy"
    "aaaaaaccccccccddddeeeeeeeeeegggggggghhhhiiiiiiiiiiJJjjkkkllllllllll"
    "nnnnnnnnnooooooOOrrrrrrssssssssttttttuuuuuuuuuuuuwwyyyzzzzzzs";
_Static_assert(sizeof latin_fold == 0x180 - 0xC0 + 1, "one entry per code point");

static void put(char *out, size_t outlen, size_t *o, const char *s, size_t n)
{
    if (*o + n < outlen) {
        memcpy(out + *o, s, n);
        *o += n;
    }
}

static void fold_cp(uint32_t cp, char *out, size_t outlen, size_t *o)
{
    if (cp < 0x80) {
        char c = (char)cp;
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))
            put(out, outlen, o, &c, 1);
        return;
    }
    if (cp >= 0xC0 && cp < 0x180) {
        char c = latin_fold[cp - 0xC0];
        switch (c) {
        case 'A': put(out, outlen, o, "ae", 2); break;
        case 'T': put(out, outlen, o, "th", 2); break;
        case 'S': put(out, outlen, o, "ss", 2); break;
        case 'J': put(out, outlen, o, "ij", 2); break;
        case 'O': put(out, outlen, o, "oe", 2); break;
        case '-': break;
        default: put(out, outlen, o, &c, 1); break;
        }
        return;
    }
    if (cp < 0xC0 || (cp >= 0x300 && cp <= 0x36F))  /* Latin-1 symbols, combining marks */
        return;
    if ((cp >= 0x2000 && cp <= 0x206F) || (cp >= 0x3000 && cp <= 0x303F) || cp == 0xFEFF)
        return;                                      /* punctuation, spaces, BOM */
    if (cp >= 0x391 && cp <= 0x3A9)                  /* Greek and Cyrillic capitals */
        cp += 0x20;
    else if (cp >= 0x410 && cp <= 0x42F)
        cp += 0x20;
    else if (cp >= 0x400 && cp <= 0x40F)
        cp += 0x50;
    char enc[4];
    put(out, outlen, o, enc, (size_t)sw_utf8_encode(cp, enc));
}

/* The code point at s (avail bytes); *n its length. A byte that is not
 * UTF-8 is read as Latin-1: a zip made on Windows may hold "Jos\xe9". */
static uint32_t next_cp(const unsigned char *s, size_t avail, size_t *n)
{
    uint32_t cp = s[0];
    *n = 1;
    if (s[0] >= 0x80 && sw_utf8_check(s, avail, n, &cp) != SW_UTF8_OK) {
        cp = s[0];
        *n = 1;
    }
    return cp;
}

size_t sw_roster_fold(const char *text, size_t len, char *out, size_t outlen)
{
    if (!out || outlen == 0)
        return 0;
    size_t o = 0;
    const unsigned char *s = (const unsigned char *)(text ? text : "");
    for (size_t i = 0, n; i < len && s[i]; i += n)
        fold_cp(next_cp(s + i, len - i, &n), out, outlen, &o);
    out[o] = '\0';
    return o;
}

/* Whether a letter of U+00C0..U+017F is a capital: Latin-1's À..Þ but ×,
 * then Latin Extended-A's pairs, capital first: Ā ā .. ķ from an even code
 * point, Ĺ ĺ .. ň (after ĸ) from an odd one, Ŋ ŋ .. ŷ even, Ÿ, Ź ź .. ž odd. */
static int latin_capital(uint32_t cp)
{
    if (cp < 0x100)
        return cp <= 0xDE && cp != 0xD7;
    if (cp <= 0x137)
        return cp % 2 == 0;
    if (cp <= 0x148)
        return cp % 2 == 1;
    if (cp == 0x149)
        return 0;
    if (cp <= 0x177)
        return cp % 2 == 0;
    return cp == 0x178 || (cp <= 0x17E && cp % 2 == 1);
}

size_t sw_roster_fold_latin(const char *text, size_t len, char *out, size_t outlen)
{
    if (!out || outlen == 0)
        return 0;
    size_t o = 0;
    const unsigned char *s = (const unsigned char *)(text ? text : "");
    for (size_t i = 0, n; i < len && s[i]; i += n) {
        uint32_t cp = next_cp(s + i, len - i, &n);
        if (cp >= 0xC0 && cp < 0x180) {
            char folded[3] = "";
            size_t k = 0;
            fold_cp(cp, folded, sizeof folded, &k); /* the roster's letters, lower case */
            if (k > 0 && latin_capital(cp))
                folded[0] = (char)(folded[0] - 'a' + 'A');
            put(out, outlen, &o, folded, k);
        } else if (cp < 0x300 || cp > 0x36F) { /* combining marks go, as in the roster */
            char enc[4];
            put(out, outlen, &o, enc, (size_t)sw_utf8_encode(cp, enc));
        }
    }
    out[o] = '\0';
    return o;
}

static int word_sep(char c) { return c == ' ' || c == '\t' || c == ','; }

size_t rst_fold_words(const char *s, size_t n, char *out, size_t outlen)
{
    size_t o = 0, i = 0;
    if (outlen == 0)
        return 0;
    out[0] = '\0';
    while (i < n) {
        while (i < n && word_sep(s[i]))
            i++;
        size_t start = i;
        while (i < n && !word_sep(s[i]))
            i++;
        char w[RST_KEY_MAX];
        size_t wl = i > start ? sw_roster_fold(s + start, i - start, w, sizeof w) : 0;
        if (wl > 0 && o + (o > 0) + wl < outlen) {
            if (o > 0)
                out[o++] = ' ';
            memcpy(out + o, w, wl);
            o += wl;
            out[o] = '\0';
        }
    }
    return o;
}

size_t rst_norm_id(const char *s, size_t n, char *out, size_t outlen)
{
    size_t o = 0;
    int digits = 1;
    if (outlen == 0)
        return 0;
    for (size_t i = 0; i < n && s[i]; i++) {
        char c = s[i];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')))
            continue;
        if (c > '9')
            digits = 0;
        if (o + 1 < outlen)
            out[o++] = c;
    }
    out[o] = '\0';
    if (digits && o > 1) {  /* "00123" is 123: spreadsheets drop leading zeros */
        size_t z = 0;
        while (z + 1 < o && out[z] == '0')
            z++;
        memmove(out, out + z, o - z + 1);
        o -= z;
    }
    return o;
}
