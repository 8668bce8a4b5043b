/* The one word wrapper (the lesson pane, the help, the notes, messages):
 * prose wrapped to a width in display cells, never inside a word when a
 * word fits a line, keeping a short bracket together and an operator with
 * what it joins; verbatim lines (formulas, tables) broken where they read
 * best. Lines go to the caller's function: nothing here allocates. */
#include "util/wrap.h"

#include <string.h>

#include "util/utf8.h"

/* How a word changes the bracket depth: ( [ { open, ) ] } close, and a
 * '|' opens at a word's start and closes at its end (|1 + Δt·λ|). */
static int bracket_delta(const char *s, const char *e)
{
    int d = 0;
    for (const char *c = s; c < e; c++)
        d += (*c == '(' || *c == '[' || *c == '{') - (*c == ')' || *c == ']' || *c == '}');
    while (e - s > 1 && strchr(",.;:", e[-1]))
        e--; /* "|x|," closes all the same */
    if (e - s > 1 && *s == '|')
        d++;
    if (e - s > 1 && e[-1] == '|')
        d--;
    return d;
}

/* Whether a word is an operator a formula can be broken before. */
static int is_operator(const char *s, const char *e)
{
    static const char *const ops[] = { "+", "-", "=", "<", ">", "*", "/", "\xc2\xb7", "\xc3\x97", "\xe2\x89\xa4",
                                       "\xe2\x89\xa5", "<=", ">=", "==", "\xe2\x86\x92", "->" };
    for (size_t k = 0; k < sizeof ops / sizeof ops[0]; k++)
        if ((size_t)(e - s) == strlen(ops[k]) && memcmp(s, ops[k], (size_t)(e - s)) == 0)
            return 1;
    return 0;
}

/* Whether a word starts with an operator (a break before it reads well). */
static int starts_operator(const char *s)
{
    static const char *const ops[] = { "+", "-", "=", "<", ">", "*", "/", "\xc2\xb7", "\xc3\x97", "\xe2\x89\xa4",
                                       "\xe2\x89\xa5", "\xe2\x86\x92" };
    for (size_t k = 0; k < sizeof ops / sizeof ops[0]; k++)
        if (strncmp(s, ops[k], strlen(ops[k])) == 0)
            return 1;
    return 0;
}

/* The operands left in s: words that are neither operators nor only
 * closing brackets (a tail of one operand is a poor continuation line);
 * *only_closers says whether every word is a closing bracket. */
static int operands(const char *s, const char *end, int *only_closers)
{
    int n = 0;
    *only_closers = 1;
    while (s < end) {
        while (s < end && *s == ' ')
            s++;
        const char *w = s;
        while (s < end && *s != ' ')
            s++;
        if (s == w)
            break;
        int closers = (int)strspn(w, ")]}|") == (int)(s - w), operand = 0;
        *only_closers &= closers;
        /* an operand has a letter or a digit ("-[" and "(" have none) */
        for (const char *c = w; c < s && !operand;) {
            unsigned char b = (unsigned char)*c;
            if (b < 0x80) {
                operand = (b >= '0' && b <= '9') || (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z');
                c++;
            } else {
                const unsigned char *u = (const unsigned char *)c;
                sw_utf8_next(&u);
                operand = !is_operator(c, (const char *)u); /* Δ, λ, ω: letters; ·, ×, ≤: operators */
                c = (const char *)u;
            }
        }
        n += operand;
    }
    return n;
}

/* Word-wrap a paragraph to width display cells (a CJK character takes
 * two), counting the line as written, its runs of spaces included; a word
 * wider than a line (a path; CJK text has no spaces) is broken between
 * characters, never inside one. */
void sw_wrap_paragraph(const char *text, int width, sw_wrap_line_fn *emit, void *ctx)
{
    const char *p = text;
    if (width < 1)
        width = 1;
    while (*p) {
        while (*p == ' ')
            p++;
        if (!*p)
            break;
        /* the starts and ends of the last two words placed on this line */
        const char *line = p, *cut = NULL, *ws[2] = { NULL, NULL }, *we[2] = { NULL, NULL };
        const char *prev_end = NULL; /* the end of the word before those two */
        int used = 0, words = 0;
        while (*p && *p != '\n') {
            const char *w = p;
            while (*p && *p != ' ' && *p != '\n')
                p++;
            /* a bracket opened in this word and closed a few words on
             * ("f = -k(x - r)", "|1 + Δt·λ|") goes on one line when it fits one */
            if (bracket_delta(w, p) > 0) {
                const char *q = p;
                int depth = bracket_delta(w, p);
                while (depth > 0 && *q && *q != '\n') {
                    while (*q == ' ')
                        q++;
                    const char *w2 = q;
                    while (*q && *q != ' ' && *q != '\n')
                        q++;
                    depth += bracket_delta(w2, q);
                }
                if (depth <= 0 && (int)sw_utf8_columns(w, (size_t)(q - w)) <= width)
                    p = q;
            }
            /* the line as written so far, its spaces included */
            int upto = (int)sw_utf8_columns(line, (size_t)(p - line));
            if (used && upto > width) {
                p = w;
                /* an operator goes on with what it joins, and so does its
                 * left operand when more is left on the line ("f =" /
                 * "-k(x - r)" reads badly: "f = -k(x - r)" goes on whole) */
                if (words >= 2 && is_operator(ws[1], we[1])) {
                    int back = words >= 3 ? 2 : 1;
                    p = ws[2 - back];
                    cut = back == 2 ? prev_end : we[0];
                }
                break;
            }
            if (!used && upto > width) {
                p = w + sw_utf8_fit(w, (size_t)(p - w), (size_t)width, NULL);
                if (p == w) { /* a wide character in a one-cell line: take it all the same */
                    const unsigned char *q = (const unsigned char *)w;
                    sw_utf8_next(&q);
                    p = (const char *)q;
                }
                cut = p;
                break;
            }
            used = upto;
            prev_end = we[0];
            ws[0] = ws[1], we[0] = we[1];
            ws[1] = w, we[1] = p;
            words++;
            cut = p;
            while (*p == ' ')
                p++;
            if (used >= width)
                break;
        }
        if (!cut)
            cut = p;
        emit(ctx, 0, line, (size_t)(cut - line));
        if (*p == '\n')
            p++;
    }
}

/* A verbatim line (a formula, a table row) as written; too wide for the
 * pane, it goes on on the next lines, indented under itself. Where it
 * breaks is chosen among its spaces: outside brackets before inside them,
 * before an operator rather than after one, never leaving a lone closing
 * bracket or a single operand for the next line when a better break
 * exists, and the first line as full as that allows. */
void sw_wrap_verbatim(const char *text, int width, sw_wrap_line_fn *emit, void *ctx)
{
    int indent = 0;
    while (text[indent] == ' ')
        indent++;
    if ((int)sw_utf8_columns(text, strlen(text)) <= width || width < indent + 12) {
        emit(ctx, 0, text, strlen(text));
        return;
    }
    const char *p = text;
    int first = 1, depth = 0, next_room = width - (indent + 4);
    while (*p) {
        int lead = first ? 0 : indent + 4, room = width - lead;
        if ((int)sw_utf8_columns(p, strlen(p)) <= room) {
            emit(ctx, lead, p, strlen(p));
            break;
        }
        const char *cut = NULL, *next = NULL, *q = p;
        int best = 0, best_depth = depth, d = depth;
        while (*q == ' ')
            q++;
        while (*q) {
            const char *w = q;
            while (*q && *q != ' ')
                q++;
            d += bracket_delta(w, q);
            const char *ns = q;
            while (*ns == ' ')
                ns++;
            int cells = (int)sw_utf8_columns(p, (size_t)(q - p));
            if (cells > room)
                break;
            if (!*ns)
                break;
            int only_closers, tail = operands(ns, ns + strlen(ns), &only_closers), head_closers;
            const char *head = p + (first ? indent : 0); /* the line so far: p .. q */
            int score = -30 * (d > 0 ? d : 0) + cells / 8;
            if (head >= q || !memchr(head, ' ', (size_t)(q - head)))
                score -= 60; /* "f" or "=" alone on a line */
            else if (operands(p, q, &head_closers) <= 1 && is_operator(w, q))
                score -= 25; /* "f =" */
            if (starts_operator(ns))
                score += 10;
            if (is_operator(w, q))
                score -= 10;
            if (strchr("([{", q[-1]))
                score -= 20; /* a line that ends by opening a bracket */
            if ((int)sw_utf8_columns(ns, strlen(ns)) <= next_room) {
                if (only_closers)
                    score -= 100;
                else if (tail <= 1 && !strchr(ns, ' '))
                    score -= 40; /* one token: "k4)" */
                else if (tail <= 1)
                    score -= 15; /* one operand: "- r)" */
            } else
                score -= 20;
            if (!cut || score >= best) {
                cut = q;
                next = ns;
                best = score;
                best_depth = d;
            }
            q = ns;
        }
        if (!cut) { /* no space to break at: as much as fits, then the rest */
            cut = p + sw_utf8_fit(p, strlen(p), (size_t)room, NULL);
            if (cut == p) { /* nothing fits: one character, progress all the same */
                const unsigned char *c1 = (const unsigned char *)p;
                sw_utf8_next(&c1);
                cut = (const char *)c1;
            }
            next = cut;
            best_depth = depth + bracket_delta(p, cut);
        }
        emit(ctx, lead, p, (size_t)(cut - p));
        p = next;
        while (*p == ' ')
            p++;
        depth = best_depth;
        first = 0;
    }
}
