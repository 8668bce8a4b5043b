/* The C tokenizer behind source similarity: each identifier, number and
 * string is one token of its class, keywords and operators keep their own,
 * comments, layout and #include lines vanish. Invariant: any bytes at all
 * give a token stream (garbage becomes SW_TOK_OTHER), never a read past len. */
#include "grade/similar.h"

#include <string.h>

#include "util/utf8.h"

/* Token codes: the classes, then these keywords, then the operators. */
static const char *const keywords[] = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else",
    "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long", "register",
    "restrict", "return", "short", "signed", "sizeof", "static", "struct", "switch", "typedef",
    "union", "unsigned", "void", "volatile", "while", "_Bool", "_Complex", "_Alignas",
    "_Alignof", "_Atomic", "_Generic", "_Noreturn", "_Static_assert", "_Thread_local",
};
#define NKEYWORDS (int)(sizeof keywords / sizeof keywords[0])

/* Longest first, so the first that fits is the longest match. */
static const char *const operators[] = {
    "...", "<<=", ">>=",
    "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "*=", "/=", "%=", "+=",
    "-=", "&=", "^=", "|=", "##",
    "[", "]", "(", ")", "{", "}", ".", "&", "*", "+", "-", "~", "!", "/", "%", "<", ">", "^",
    "|", "?", ":", ";", "=", ",", "#",
};
#define NOPERATORS (int)(sizeof operators / sizeof operators[0])

#define FIRST_KEYWORD (SW_TOK_OTHER + 1)
#define FIRST_OPERATOR (FIRST_KEYWORD + NKEYWORDS)
_Static_assert(FIRST_OPERATOR + NOPERATORS <= 255, "token codes fit a byte");

static int is_alpha(unsigned char c) { return (c | 0x20) >= 'a' && (c | 0x20) <= 'z'; }
static int is_digit(unsigned char c) { return c >= '0' && c <= '9'; }

/* Bytes of a valid UTF-8 character at s (an identifier may hold one), or 0. */
static size_t utf8_len(const unsigned char *s, size_t avail)
{
    size_t n;
    uint32_t cp;
    return sw_utf8_check(s, avail, &n, &cp) == SW_UTF8_OK ? n : 0;
}

static size_t ident_end(const unsigned char *s, size_t i, size_t len)
{
    while (i < len) {
        if (is_alpha(s[i]) || is_digit(s[i]) || s[i] == '_' || s[i] == '$') {
            i++;
        } else if (s[i] >= 0x80) {
            size_t n = utf8_len(s + i, len - i);
            if (n == 0)
                break;
            i += n;
        } else {
            break;
        }
    }
    return i;
}

/* Past the end of the line at i, backslash-newlines joined. */
static size_t line_end(const unsigned char *s, size_t i, size_t len)
{
    while (i < len && s[i] != '\n') {
        if (s[i] == '\\' && i + 1 < len && s[i + 1] == '\n')
            i++;
        i++;
    }
    return i;
}

size_t sw_similar_tokenize(const char *src, size_t len, unsigned char *out, size_t max)
{
    const unsigned char *s = (const unsigned char *)src;
    size_t n = 0, i = 0;
    int line_start = 1;
    int prev_other = 0;
#define EMIT(t) do { if (n < max) out[n] = (unsigned char)(t); n++; prev_other = (t) == SW_TOK_OTHER; } while (0)
    while (i < len) {
        unsigned char c = s[i];
        if (c == '\n') {
            line_start = 1;
            i++;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            i++;
            continue;
        }
        if (c == '\\' && i + 1 < len && s[i + 1] == '\n') {
            i += 2;
            continue;
        }
        if (c == '/' && i + 1 < len && s[i + 1] == '/') {
            i = line_end(s, i, len);
            continue;
        }
        if (c == '/' && i + 1 < len && s[i + 1] == '*') {
            for (i += 2; i < len && !(s[i] == '*' && i + 1 < len && s[i + 1] == '/'); i++)
                ;
            i = i < len ? i + 2 : len;
            continue;
        }
        if (c == '#' && line_start) { /* an #include is the handout's, not the student's */
            size_t j = i + 1;
            while (j < len && (s[j] == ' ' || s[j] == '\t'))
                j++;
            if (len - j >= 7 && memcmp(s + j, "include", 7) == 0) {
                i = line_end(s, j, len);
                continue;
            }
        }
        line_start = 0;
        if (is_alpha(c) || c == '_' || c == '$' || (c >= 0x80 && utf8_len(s + i, len - i))) {
            size_t j = ident_end(s, i, len);
            /* L"..", u8"..", U'..': a prefix of the literal that follows */
            if (j < len && (s[j] == '"' || s[j] == '\'') &&
                ((j - i == 1 && (c == 'L' || c == 'u' || c == 'U')) ||
                 (j - i == 2 && c == 'u' && s[i + 1] == '8'))) {
                i = j;
                continue;
            }
            int tok = SW_TOK_ID;
            for (int k = 0; k < NKEYWORDS; k++)
                if (strlen(keywords[k]) == j - i && memcmp(keywords[k], s + i, j - i) == 0)
                    tok = FIRST_KEYWORD + k;
            EMIT(tok);
            i = j;
            continue;
        }
        if (is_digit(c) || (c == '.' && i + 1 < len && is_digit(s[i + 1]))) {
            size_t j = i + 1;
            while (j < len && (is_alpha(s[j]) || is_digit(s[j]) || s[j] == '_' || s[j] == '.' ||
                               ((s[j] == '+' || s[j] == '-') && strchr("eEpP", s[j - 1]))))
                j++;
            EMIT(SW_TOK_NUM);
            i = j;
            continue;
        }
        if (c == '"' || c == '\'') {
            size_t j = i + 1;
            while (j < len && s[j] != c && s[j] != '\n')
                j += s[j] == '\\' && j + 1 < len ? 2 : 1;
            EMIT(c == '"' ? SW_TOK_STR : SW_TOK_NUM);
            i = j < len && s[j] == c ? j + 1 : j;
            continue;
        }
        int tok = SW_TOK_OTHER;
        size_t used = 1;
        for (int k = 0; k < NOPERATORS; k++) {
            size_t ol = strlen(operators[k]);
            if (ol <= len - i && memcmp(operators[k], s + i, ol) == 0) {
                tok = FIRST_OPERATOR + k;
                used = ol;
                break;
            }
        }
        if (tok == SW_TOK_OTHER && c >= 0x80) {
            size_t u = utf8_len(s + i, len - i);
            used = u ? u : 1;
        }
        i += used;
        if (tok == SW_TOK_OTHER && prev_other)
            continue; /* a run of garbage is one token: it carries no structure */
        EMIT(tok);
    }
#undef EMIT
    return n;
}
