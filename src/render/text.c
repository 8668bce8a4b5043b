/* Fitting and wrapping text in cells. Invariant: nothing here cuts inside a
 * word or a number; what does not fit is shortened, moved to the next line
 * or left out whole. */
#include "render/text.h"

#include <string.h>

#include "util/utf8.h"
#include "util/wrap.h"

int sw_text_cells(const char *s) { return (int)sw_utf8_columns(s, strlen(s)); }

/* Whether the fields in use[] pack, in order, into at most rows lines of
 * width cells (a field never split); the lines into out when it is given. */
static int pack(char (*out)[SW_TEXT_LINE], int rows, int width, const sw_field *f, const int *use, int n,
                const char *sep)
{
    int row = 0, cells = 0, seplen = sw_text_cells(sep);
    size_t used = 0;
    if (out)
        out[0][0] = '\0';
    for (int k = 0; k < n; k++) {
        if (!use[k])
            continue;
        const char *t = use[k] == 2 ? f[k].brief : f[k].full;
        int tc = sw_text_cells(t);
        size_t tl = strlen(t), sl = strlen(sep);
        if (cells > 0 && (cells + seplen + tc > width || used + sl + tl + 1 > SW_TEXT_LINE)) {
            if (++row >= rows)
                return 0;
            cells = 0;
            used = 0;
            if (out)
                out[row][0] = '\0';
        }
        if (tc > width || tl + 1 > SW_TEXT_LINE)
            return 0;
        if (out) {
            if (cells > 0)
                memcpy(out[row] + used, sep, sl);
            memcpy(out[row] + used + (cells > 0 ? sl : 0), t, tl);
            out[row][used + (cells > 0 ? sl : 0) + tl] = '\0';
        }
        used += (cells > 0 ? sl : 0) + tl;
        cells += (cells > 0 ? seplen : 0) + tc;
    }
    return row + 1;
}

int sw_text_fit_rows(char (*out)[SW_TEXT_LINE], int rows, int width, const sw_field *f, int n, const char *sep,
                     int *dropped)
{
    int use[64] = { 0 }, gone = 0;
    if (n > 64)
        n = 64;
    for (int k = 0; k < n; k++)
        use[k] = f[k].full[0] ? 1 : 0;
    while (!pack(NULL, rows, width, f, use, n, sep)) {
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
        else {
            use[pick] = 0;
            gone++;
        }
    }
    if (dropped)
        *dropped = gone;
    int any = 0;
    for (int k = 0; k < n; k++)
        any |= use[k];
    if (!any) {
        out[0][0] = '\0';
        return 0;
    }
    return pack(out, rows, width, f, use, n, sep);
}

int sw_text_fit(char *out, size_t len, int width, const sw_field *f, int n, const char *sep)
{
    char line[1][SW_TEXT_LINE];
    if (len)
        out[0] = '\0';
    if (!sw_text_fit_rows(line, 1, width, f, n, sep, NULL))
        return 0;
    size_t l = strlen(line[0]);
    if (l + 1 > len)
        return 0;
    memcpy(out, line[0], l + 1);
    return sw_text_cells(out);
}

typedef struct wrap_out {
    char (*lines)[SW_TEXT_LINE];
    int max, count;
} wrap_out;

static void wrap_line(void *ctx, int lead, const char *text, size_t len)
{
    wrap_out *o = ctx;
    (void)lead; /* paragraphs have none */
    if (o->count < o->max) {
        len = sw_utf8_clip(text, len, SW_TEXT_LINE - 1);
        memcpy(o->lines[o->count], text, len);
        o->lines[o->count][len] = '\0';
    }
    o->count++;
}

int sw_text_wrap(const char *text, int width, char (*lines)[SW_TEXT_LINE], int max)
{
    wrap_out o = { lines, max, 0 };
    if (width < 1)
        return 0;
    sw_wrap_paragraph(text, width, wrap_line, &o);
    return o.count;
}

/* A method's name in brief for a legend: every part but the last cut to
 * four letters ("symplectic-euler" -> "symp-euler"); "" when that is no shorter. */
void sw_text_brief_name(const char *name, char *out, size_t len)
{
    size_t o = 0;
    const char *last = strrchr(name, '-');
    for (const char *p = name; *p && o + 1 < len;) {
        const char *e = strchr(p, '-');
        size_t part = e && p < last ? (size_t)(e - p) : strlen(p);
        size_t keep = e && p < last && part > 4 ? 4 : part;
        if (o + keep + 2 > len)
            break;
        memcpy(out + o, p, keep);
        o += keep;
        if (!(e && p < last))
            break;
        out[o++] = '-';
        p = e + 1;
    }
    out[o] = '\0';
    if (strcmp(out, name) == 0)
        out[0] = '\0';
}
