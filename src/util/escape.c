/* Escaping untrusted text for messages. Invariant: the output holds no
 * byte below 0x20, no DEL, no C1 control, no bidirectional or other
 * invisible formatting character and no invalid UTF-8, whatever the
 * input, and is never cut inside a character or an escape. */
#include "util/escape.h"

#include <stdint.h>
#include <string.h>

#include "util/utf8.h"

/* One piece of output: the text at s as it is shown. A printable
 * character stays as it is (shown == take); anything else becomes \xNN per
 * byte. An invisible formatting character is one piece of all its bytes,
 * so that a cut never leaves "\xe2" of a "\xe2\x80\xae" behind; every
 * other escaped byte (a control, a stray byte of invalid UTF-8) is a piece
 * of its own. */
typedef struct piece {
    size_t take;  /* bytes of text it stands for, 1..4 */
    size_t shown; /* bytes it takes in out */
    int escaped;  /* 1: written as \xNN per byte taken */
    size_t cells; /* terminal cells it takes (an escape: one per byte shown) */
} piece;

static piece piece_at(const unsigned char *s, size_t avail, int keep_backslash)
{
    if (s[0] < 0x80) {
        int ok = s[0] >= 0x20 && s[0] != 0x7f && (s[0] != '\\' || keep_backslash);
        return ok ? (piece){ 1, 1, 0, 1 } : (piece){ 1, 4, 1, 4 };
    }
    size_t len;
    uint32_t cp;
    if (sw_utf8_check(s, avail, &len, &cp) != SW_UTF8_OK || (cp >= 0x80 && cp <= 0x9f))
        return (piece){ 1, 4, 1, 4 }; /* C1 controls (U+009B is a CSI) like C0 ones */
    if (sw_utf8_invisible(cp))
        return (piece){ len, 4 * len, 1, 4 * len };
    return (piece){ len, len, 0, (size_t)sw_utf8_width(cp) };
}

/* What escape() may take: outlen bytes and at most cells terminal cells;
 * words: a cut falls after a whole word where one can. */
typedef struct fit {
    size_t cells;
    int words;
} fit;

static const fit any_room = { SIZE_MAX, 0 };

/* A cut after a whole word drops the punctuation left hanging before the
 * mark: "(Operation not permitted)..." rather than "permitted);...". */
static int hangs(char c) { return c == ' ' || c == ',' || c == ';' || c == ':'; }

/* Escape text[0..n) into out; returns 1 when all of it fitted. Text whose
 * escaped form fits (in outlen bytes and r.cells cells) is written whole;
 * only text that does not is cut, with room kept for "...". So escaping
 * text already escaped, which fits, changes nothing (a gradebook's kept
 * cells stay as they are). With r.words, the cut falls after the last
 * whole word that ends in the second half of the room; a name or a path
 * with no space there is cut between characters. */
static int escape(const char *text, size_t n, int keep_backslash, fit r, char *out, size_t outlen)
{
    static const char hex[] = "0123456789abcdef";
    const unsigned char *s = (const unsigned char *)text;
    size_t total = 0, cells = 0;
    for (size_t i = 0; i < n && total < outlen && cells <= r.cells;) {
        piece p = piece_at(s + i, n - i, keep_backslash);
        total += p.shown;
        cells += p.cells;
        i += p.take;
    }
    int cut = total >= outlen || cells > r.cells;
    size_t room = !cut || outlen < 4 ? outlen : outlen - 3; /* "..." when cut */
    size_t cell_room = !cut ? r.cells : r.cells < 3 ? 0 : r.cells - 3;
    size_t used = 0, used_cells = 0, i = 0, word_end = 0;
    while (i < n) {
        piece p = piece_at(s + i, n - i, keep_backslash);
        if (used + p.shown + 1 > room || used_cells + p.cells > cell_room)
            break;
        if (s[i] == ' ' && used > 0 && s[i - 1] != ' ')
            word_end = used; /* out[0..used) ends a word */
        if (!p.escaped)
            memcpy(out + used, s + i, p.take);
        else
            for (size_t b = 0; b < p.take; b++) {
                char *o = out + used + 4 * b;
                o[0] = '\\';
                o[1] = 'x';
                o[2] = hex[s[i + b] >> 4];
                o[3] = hex[s[i + b] & 15];
            }
        used += p.shown;
        used_cells += p.cells;
        i += p.take;
    }
    int whole = i >= n;
    if (!whole && r.words && (s[i] == ' ' || (word_end > 0 && 2 * word_end >= used))) {
        if (s[i] != ' ')
            used = word_end; /* the word under the cut goes, whole, to the mark */
        while (used > 1 && hangs(out[used - 1]))
            used--;
    }
    if (!whole && used + 4 <= outlen) {
        memcpy(out + used, "...", 3);
        used += 3;
    }
    out[used] = '\0';
    return whole;
}

/* n cut back to the start of a character that text[n] (not a NUL) would
 * complete, so that max cutting a character shows "..." and not the
 * escaped bytes of its first half. Only a lead byte with the continuation
 * bytes it wants up to n is cut: invalid text is left to the escapes. */
static size_t clip_to_char(const unsigned char *s, size_t n)
{
    for (size_t back = 1; back <= 3 && back <= n; back++) {
        unsigned char b = s[n - back];
        if ((b & 0xc0) == 0x80)
            continue; /* a continuation byte: its lead is further back */
        size_t want = b >= 0xf0 ? 4 : b >= 0xe0 ? 3 : b >= 0xc0 ? 2 : 1;
        return want > back && (s[n] & 0xc0) == 0x80 ? n - back : n;
    }
    return n;
}

void sw_escape(const char *text, size_t max, char *out, size_t outlen)
{
    if (!out || outlen == 0)
        return;
    if (!text)
        text = "";
    size_t n = strnlen(text, max);
    if (text[n] != '\0')
        n = clip_to_char((const unsigned char *)text, n);
    if (!escape(text, n, 0, any_room, out, outlen) || text[n] == '\0')
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
    escape(copy, n, 1, any_room, msg, len);
}

void sw_escape_kept(const char *text, size_t max, char *out, size_t outlen)
{
    if (!out || outlen == 0)
        return;
    if (!text)
        text = "";
    escape(text, strnlen(text, max), 1, any_room, out, outlen);
}

void sw_escape_fit(const char *text, int keep_backslash, size_t cells, int words, char *out,
                   size_t outlen)
{
    if (!out || outlen == 0)
        return;
    fit r = { cells, words };
    escape(text ? text : "", text ? strlen(text) : 0, keep_backslash, r, out, outlen);
}
