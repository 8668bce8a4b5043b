/* Fitting and wrapping text in cells. Invariant: nothing here cuts inside a
 * word or a number; what does not fit is shortened, moved to the next line
 * or left out whole. */
#include "render/text.h"

#include <string.h>

#include "util/utf8.h"

int sw_text_cells(const char *s) { return (int)sw_utf8_columns(s, strlen(s)); }

/* The line with fields marked in use[] (1 full, 2 brief, 0 dropped). */
static int join(char *out, size_t len, const sw_field *f, const int *use, int n, const char *sep)
{
    size_t used = 0;
    int cells = 0, first = 1, seplen = sw_text_cells(sep);
    if (len)
        out[0] = '\0';
    for (int k = 0; k < n; k++) {
        if (!use[k])
            continue;
        const char *t = use[k] == 2 ? f[k].brief : f[k].full;
        size_t tl = strlen(t), sl = first ? 0 : strlen(sep);
        if (used + sl + tl + 1 > len)
            break;
        if (!first)
            memcpy(out + used, sep, sl);
        memcpy(out + used + sl, t, tl);
        used += sl + tl;
        out[used] = '\0';
        cells += (first ? 0 : seplen) + sw_text_cells(t);
        first = 0;
    }
    return cells;
}

int sw_text_fit(char *out, size_t len, int width, const sw_field *f, int n, const char *sep)
{
    int use[64] = { 0 };
    if (n > 64)
        n = 64;
    for (int k = 0; k < n; k++)
        use[k] = f[k].full[0] ? 1 : 0;
    int cells = join(out, len, f, use, n, sep);
    while (cells > width) {
        /* the least important field still shown: shorten it if it can be, else drop it */
        int pick = -1;
        for (int k = 0; k < n; k++)
            if (use[k] && (pick < 0 || f[k].prio < f[pick].prio ||
                           (f[k].prio == f[pick].prio && use[k] == 1 && use[pick] == 2)))
                pick = k;
        if (pick < 0)
            break;
        /* brief forms go first, from the least important up, before any field is dropped */
        int brief = -1;
        for (int k = 0; k < n; k++)
            if (use[k] == 1 && f[k].brief[0] && (brief < 0 || f[k].prio < f[brief].prio))
                brief = k;
        if (brief >= 0)
            use[brief] = 2;
        else
            use[pick] = 0;
        cells = join(out, len, f, use, n, sep);
    }
    if (cells > width) {
        if (len)
            out[0] = '\0';
        return 0;
    }
    return cells;
}

int sw_text_wrap(const char *text, int width, char (*lines)[SW_TEXT_LINE], int max)
{
    int count = 0;
    if (width < 1)
        return 0;
    const char *p = text;
    while (*p) {
        char line[SW_TEXT_LINE];
        size_t used = 0;
        int cells = 0;
        while (*p == ' ')
            p++;
        while (*p && *p != '\n') {
            const char *w = p;
            while (*p && *p != ' ' && *p != '\n')
                p++;
            size_t wl = (size_t)(p - w);
            int wc = (int)sw_utf8_columns(w, wl);
            if (cells > 0 && cells + 1 + wc > width) {
                p = w; /* the word starts the next line */
                break;
            }
            if (wc > width) {
                /* a word longer than a whole line (a path): split it */
                size_t fit_cells = 0;
                wl = sw_utf8_fit(w, wl, (size_t)width, &fit_cells);
                if (wl == 0) { /* a wide character in a one-cell line: take it, it is clipped */
                    const unsigned char *q = (const unsigned char *)w;
                    sw_utf8_next(&q);
                    wl = (size_t)((const char *)q - w);
                    fit_cells = (size_t)width;
                }
                wc = (int)fit_cells;
                p = w + wl;
            }
            if (used + (cells ? 1 : 0) + wl + 1 > sizeof line)
                break;
            if (cells)
                line[used++] = ' ', cells++;
            memcpy(line + used, w, wl);
            used += wl;
            cells += wc;
            while (*p == ' ')
                p++;
            if (cells >= width)
                break;
        }
        line[used] = '\0';
        if (count < max)
            memcpy(lines[count], line, used + 1);
        count++;
        if (*p == '\n')
            p++;
        if (count > 1000)
            break;
    }
    return count;
}
