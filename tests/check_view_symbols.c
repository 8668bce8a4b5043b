/* Every view a student can open, walked on every page at 80×24 (issue 37):
 * each glyph it draws and each mark of its legend explained where it
 * first appears, by the view's own legend on screen or a lesson page read
 * before; the rows are data, tests/support/symbols_views.h. */
#include <check.h>
#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "app/runner.h"
#include "canvas_help.h"
#include "lesson/lesson.h"
#include "render/screen.h"
#include "render/text.h"
#include "symbols_help.h"
#include "util/utf8.h"

/* Every view a student can open, walked on every page at 80×24 as the page
 * shows it (the pane beside the picture): what each view draws (its
 * glyphs, a Braille dot standing for all of them) and every mark of its
 * title, legend and numbers that is not a word (a token with no two
 * letters in a row once its numbers are '#': "V", "<", "#1", "*", "o.")
 * must have a row below, the data of where it is explained: words of the
 * view's own legend, on screen beside it at this size, or a lesson page
 * the student has read. A mark with no row fails, and so does a row whose
 * legend is not on screen or whose page comes later. */
typedef struct view_symbol {
    const char *view;   /* "scene", "graph", "phase", "region", "stages", "compare", "lanes", "plot";
                           "scene:NAME": that scene's picture only */
    const char *mark;   /* a glyph, or a token's form */
    const char *legend; /* words on screen in the view's own text that say what it is; or NULL: */
    const char *file, *page; /* the lesson page that explains it */
} view_symbol;

#include "symbols_views.h"

#define VIEW_COLS 80
#define VIEW_ROWS 24
#define BRAILLE "braille"

/* What one screen of a view holds: its marks, and its text as one string. */
typedef struct view_screen {
    char marks[64][32];
    int nmarks;
    char text[4096];
} view_screen;

static void add_mark(view_screen *v, const char *m)
{
    for (int i = 0; i < v->nmarks; i++)
        if (strcmp(v->marks[i], m) == 0)
            return;
    if (v->nmarks < 64)
        snprintf(v->marks[v->nmarks++], sizeof v->marks[0], "%s", m);
}

/* Whether a token's form is a mark to explain: not a number alone, and no
 * two letters in a row. */
static int is_mark(const char *form)
{
    int run = 0, other = 0;
    for (const unsigned char *p = (const unsigned char *)form; *p;) {
        uint32_t cp = sw_utf8_next(&p);
        int letter = (cp < 128 && isalpha((int)cp)) || (cp >= 0x370 && cp < 0x400);
        run = letter ? run + 1 : 0;
        if (run >= 2)
            return 0;
        other |= !strchr("#.,:;()%/=", (int)(cp < 128 ? cp : '?')) || cp >= 128;
    }
    return other;
}

/* Whether code point c is a letter or digit of a word, a name or a number. */
static int wordish(uint32_t c)
{
    return (c < 128 && isalnum((int)c)) || (c >= 0x370 && c < 0x400);
}

/* The marks of a token (text: from a legend or title; else drawn): its
 * runs of letters and digits, each a mark when it is one ("k1", "V", "o";
 * a word or a number is none), and every other glyph alone (a Braille dot
 * standing for every one; in text, a formula's operators and brackets are
 * none, nor a colon: "h/6*(k1+2*k2)" has the marks h, k#). */
static void token_marks(view_screen *v, const char *tok, int text)
{
    const unsigned char *q = (const unsigned char *)tok;
    while (*q) {
        const unsigned char *at = q;
        uint32_t c = sw_utf8_next(&q);
        if (wordish(c)) {
            const unsigned char *end = q;
            for (const unsigned char *r = q; *r;) {
                uint32_t d = sw_utf8_next(&r);
                /* a number's point, and its exponent's sign */
                int point = d == '.' && isdigit(*r) && isdigit(end[-1]);
                int sign = (d == '-' || d == '+') && end[-1] == 'e' && end - 1 > at && isdigit(end[-2]) &&
                           isdigit(*r);
                if (!wordish(d) && !point && !sign)
                    break;
                end = r;
            }
            char run[200], form[200];
            snprintf(run, sizeof run, "%.*s", (int)(end - at), (const char *)at);
            sym_form_of(run, form, sizeof form);
            if (is_mark(form))
                add_mark(v, form);
            q = end;
            continue;
        }
        if (text && strchr("()=,*/+;:", (int)c))
            continue;
        if ((c == '-' || c == '+') && isdigit(*q))
            continue; /* a number's sign */
        char g[8];
        snprintf(g, sizeof g, "%.*s", (int)(q - at), (const char *)at);
        add_mark(v, c >= 0x2800 && c < 0x2900 ? BRAILLE : g);
    }
}

/* The picture's rectangle on a screen composed with the page's pane: the
 * rows above the status block, the columns left of the pane. */
static void picture_box(sw_app *a, const sw_side *side, int *rows, int *cols)
{
    char msg[4][SW_TEXT_LINE];
    int nmsg = a->message[0] ? sw_text_wrap(a->message, VIEW_COLS, msg, 4) : 0;
    nmsg = nmsg > 4 ? 4 : nmsg < 1 ? 1 : nmsg;
    int nstat = a->compare && a->lanes && a->view == SW_VIEW_SCENE ? 1 : a->nsims;
    *rows = VIEW_ROWS - (nstat + 1 + nmsg + 1);
    *cols = VIEW_COLS;
    if (side && side->nlines > 0) {
        int w = side->width > 0 ? side->width : VIEW_COLS / 2;
        if (VIEW_COLS - w - 1 < 30)
            w = VIEW_COLS - 31;
        *cols = VIEW_COLS - w - 1;
    }
}

/* The energy graph's rows at the picture's foot (render/compose.c's rule:
 * up to 8 rows, the scene keeping 10, none under 5). */
static int graph_rows(const sw_app *a, int pic_rows)
{
    if (!a->graph)
        return 0;
    int h = pic_rows >= 20 ? 8 : pic_rows / 3;
    if (pic_rows - h < 10)
        h = pic_rows - 10;
    return h < 5 ? 0 : h;
}

/* Compose the page's screen and read the marks and text of the picture's
 * rows from..to (to <= 0: to the picture's foot less to). */
static void read_view(sw_runner *r, sw_app *a, sw_frame *f, view_screen *v, int graph)
{
    char err[SW_ERRLEN];
    sw_screen scr;
    ck_assert_int_eq(sw_screen_init(&scr, VIEW_COLS, VIEW_ROWS, err, sizeof err), SW_OK);
    const sw_side *side = sw_runner_side(r, a, VIEW_COLS);
    sw_frame_compose(f, a, side, &scr);
    int rows, cols;
    picture_box(a, side, &rows, &cols);
    int pic_rows = rows, gh = graph_rows(a, rows), y0 = graph ? rows - gh : 0;
    rows = graph ? rows : rows - gh;
    v->nmarks = 0;
    v->text[0] = '\0';
    size_t n = 0;
    for (int y = 0; y < pic_rows; y++) {
        int marks = y >= y0 && y < rows; /* (the other rows' text may hold a legend: lanes' titles) */
        /* the row's tokens: runs of cells with no space, each from the
         * picture (a canvas's style) or from text */
        char line[4 * VIEW_COLS + 2];
        size_t ln = 0;
        int picture = 0;
        for (int x = 0; x <= cols; x++) {
            uint32_t cp = x < cols ? scr.cp[y * VIEW_COLS + x] : ' ';
            if (cp == SW_SCREEN_WIDE_TAIL)
                continue;
            int cls = x < cols && scr.style[y * VIEW_COLS + x] < SW_STYLE_WARN;
            /* a token ends at a space, and where the picture's cells meet text's */
            if (cp != ' ' && (!ln || cls == picture) && ln + 5 < sizeof line) {
                char u[5];
                u[sw_utf8_encode(cp, u)] = '\0';
                ln += (size_t)snprintf(line + ln, sizeof line - ln, "%s", u);
                picture = cls;
                continue;
            }
            if (cp != ' ')
                x--; /* (this cell starts the next token) */
            line[ln] = '\0';
            n += (size_t)snprintf(v->text + n, sizeof v->text - n, "%s ", line);
            if (!ln)
                continue;
            ln = 0;
            char form[200];
            sym_form_of(line, form, sizeof form);
            if (marks && is_mark(form) && (picture || strcmp(line, "a") != 0)) /* (not a word or a number) */
                token_marks(v, line, !picture);
        }
        n += (size_t)snprintf(v->text + n, sizeof v->text - n, "\n");
    }
    /* the status lines under the picture, each led by its run's glyph ("x vs
     * midpoint"): words a legend may point to (their own marks are
     * every_field_explained_first's) */
    for (int y = pic_rows; y < pic_rows + a->nsims && y < VIEW_ROWS; y++)
        for (int x = 0; x < VIEW_COLS; x++) {
            char u[5];
            uint32_t cp = scr.cp[y * VIEW_COLS + x];
            u[cp == SW_SCREEN_WIDE_TAIL ? 0 : sw_utf8_encode(cp, u)] = '\0';
            n += (size_t)snprintf(v->text + n, sizeof v->text - n, "%s%s", u, x == VIEW_COLS - 1 ? "\n" : "");
        }
    sw_screen_free(&scr);
}

/* The rows for a mark in view (its own or any scene's, "scene:NAME" for
 * the scene on screen), and whether one is explained now. */
static void check_marks(const view_screen *v, const char *view, sw_app *a,
                        const sw_lesson_entry *e, int n, int li, int pi)
{
    char scene_view[96];
    snprintf(scene_view, sizeof scene_view, "scene:%s", a->scene->name);
    char joined[4100];
    snprintf(joined, sizeof joined, " %s", v->text);
    /* one space between words, rows joined (a legend may wrap) */
    char *w = joined;
    for (const char *c = joined; *c; c++)
        if (!((*c == ' ' || *c == '\n') && w > joined && w[-1] == ' '))
            *w++ = *c == '\n' ? ' ' : *c;
    *w = '\0';
    for (int k = 0; k < v->nmarks; k++) {
        const char *m = v->marks[k];
        int known = 0, ok = 0;
        const char *why = NULL;
        for (size_t j = 0; j < sizeof view_symbols / sizeof view_symbols[0]; j++) {
            const view_symbol *s = &view_symbols[j];
            /* compare overlaid and in lanes draw the scene: its rows hold there */
            int scene_like = strcmp(s->view, "scene") == 0 && (!strcmp(view, "compare") || !strcmp(view, "lanes"));
            if (strcmp(s->mark, m) != 0 ||
                (strcmp(s->view, view) != 0 && strcmp(s->view, "any") != 0 && strcmp(s->view, scene_view) != 0 &&
                 !scene_like))
                continue;
            known = 1;
            if (s->legend) {
                /* the legend's words where a token starts */
                char at[200];
                snprintf(at, sizeof at, " %s", s->legend);
                ok |= strstr(joined, at) != NULL;
                why = s->legend;
            } else {
                int sp, sl = sym_place_of(e, n, s->file, s->page, m, &sp);
                /* (the course's first page points to the next two for the status line's words) */
                ok |= sl < li || (sl == li && sp <= pi) || (li == 0 && sl == 0 && sp <= 2 && sym_first_page_points());
                why = s->page;
            }
        }
        if (getenv("SW_SYMBOLS_SURVEY")) {
            static char seen[400][48];
            static int nseen;
            char key[48];
            snprintf(key, sizeof key, "%s|%s", view, m);
            int fresh = 1;
            for (int i = 0; i < nseen; i++)
                fresh &= strcmp(seen[i], key) != 0;
            if ((!known || !ok) && fresh && nseen < 400)
                snprintf(seen[nseen++], sizeof seen[0], "%s", key);
            if (!known || !ok)
                printf("%s p%d %s %s: '%s' %s\n%s", e[li].file, pi + 1, view, a->scene->name, m,
                       known ? "not explained here" : "no row", fresh ? v->text : "");
            continue;
        }
        ck_assert_msg(known, "%s page %d, %s view of %s: '%s' is drawn and no row of the view symbols says "
                      "where it is explained\n%s", e[li].file, pi + 1, view, a->scene->name, m, v->text);
        ck_assert_msg(ok, "%s page %d, %s view of %s: '%s' is drawn, and its explanation ('%s') is not on "
                      "screen or not read yet\n%s", e[li].file, pi + 1, view, a->scene->name, m, why, v->text);
    }
}

/* The view on screen, by what the app shows. */
static const char *view_now(const sw_app *a)
{
    if (a->workprec && a->bench)
        return "plot";
    if (a->stages_open && a->view == SW_VIEW_SCENE)
        return "stages";
    if (a->view == SW_VIEW_PHASE)
        return "phase";
    if (a->view == SW_VIEW_REGION)
        return "region";
    return a->compare && a->nsims > 1 ? (a->lanes ? "lanes" : "compare") : "scene";
}

/* The view on screen, and the energy graph under it when it is open. */
static void check_view(sw_runner *r, sw_app *a, sw_frame *f, const sw_lesson_entry *e, int n, int li, int pi)
{
    view_screen v;
    sw_app_meter_settle(a, 100000);
    read_view(r, a, f, &v, 0);
    check_marks(&v, view_now(a), a, e, n, li, pi);
    if (a->graph) {
        read_view(r, a, f, &v, 1);
        check_marks(&v, "graph", a, e, n, li, pi);
    }
}

/* The keys that open a view, and the key that closes each again. */
static const struct {
    int open, close;
} view_keys[] = {
    { 'e', 'e' }, { 'v', 'v' }, { 's', 's' }, { 'k', SW_KEY_ESC }, { 'c', 'c' },
};

static void page_views(sw_runner *r, sw_app *a, const sw_lesson_entry *e, int n, int lesson, int page, void *ctx)
{
    sw_frame *f = ctx;
    sym_read_first_page(r, lesson, page);
    r->wide = 0;
    sw_frame_forget(f);
    /* the page as it opens, and after a second of play */
    check_view(r, a, f, e, n, lesson, page);
    int paused = a->paused;
    a->paused = 0;
    for (int k = 0; k < 20; k++) { /* as frames do: the graph, the phase paths and the trails fill */
        sw_app_advance(a, 0.05, 5000);
        sw_app_sample(a);
        sw_frame_push_trails(f, a);
    }
    a->paused = paused;
    check_view(r, a, f, e, n, lesson, page);
    /* each view a key opens (where the page lets it), then closed again */
    for (size_t i = 0; i < sizeof view_keys / sizeof view_keys[0]; i++) {
        const char *before = view_now(a);
        int graph = a->graph;
        if (!sw_app_key(a, view_keys[i].open, 1))
            continue;
        if (strcmp(view_now(a), before) == 0 && a->graph == graph)
            continue;
        check_view(r, a, f, e, n, lesson, page);
        if (a->compare && !a->lanes && sw_app_key(a, 'l', 1)) {
            check_view(r, a, f, e, n, lesson, page);
            sw_app_key(a, 'l', 1);
        }
        sw_app_key(a, view_keys[i].close, 1);
    }
    /* the work-precision plot, where a page first asks for it (its sweep
     * takes seconds: not on every page) */
    char text[8192] = "";
    const sw_lesson_page *pg = &r->lesson.pages[page];
    for (int b = 0; b < pg->nblocks; b++)
        strncat(text, pg->blocks[b].text, sizeof text - strlen(text) - 1);
    if (strstr(text, "Press w") && sw_app_key(a, 'w', 1)) {
        sw_app_sweep_wait(a);
        if (a->workprec && a->bench)
            check_view(r, a, f, e, n, lesson, page);
        while (a->workprec)
            sw_app_key(a, 'w', 1);
    }
}

START_TEST(every_view_symbol_explained)
{
    char err[SW_ERRLEN];
    sw_frame f;
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    f.unicode = 1;
    ct_each_page(page_views, &f);
    sw_frame_free(&f);
}
END_TEST

Suite *make_view_symbols_suite(void);
Suite *make_view_symbols_suite(void)
{
    Suite *s = suite_create("view_symbols");
    TCase *tc = tcase_create("view_symbols");
    tcase_set_timeout(tc, 240);
    tcase_add_test(tc, every_view_symbol_explained);
    suite_add_tcase(s, tc);
    return s;
}
