/* Every word and mark of the status line and the stability meter is
 * explained where it first appears (issue 37): the course is walked page
 * by page in order, as a student meets it (as each page opens and after a
 * second of play), and every field those two lines show is matched
 * against the list below, the data of what is explained where: the field's
 * form (its words, with each number as #) and the lesson page whose text
 * explains it. A field with no row fails (a new word on screen needs its
 * explanation and its row), and so does one met on a page before the page
 * that explains it. */
#include <check.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "app/runner.h"
#include "canvas_help.h"
#include "lesson/lesson.h"
#include "render/screen.h"
#include "render/text.h"
#include "util/utf8.h"

/* Where a form is explained: a lesson file and a page title; both NULL:
 * the field names itself in words a newcomer reads (a method's name, the
 * state of the run). The course's first page shows both lines before the
 * next two explain them: it says so, in the words FIRST_PAGE_POINTS (the
 * test reads them there), and the two pages' forms may show on it. */
typedef struct symbol {
    const char *form;
    const char *file, *page;
} symbol;

#define L1 "01-flow-fields.lesson"
#define L1_STATUS L1, "The status line"
#define L1_METER L1, "The stability meter"
#define FIRST_PAGE_POINTS "explained field by field on the next two pages"

static const symbol symbols[] = {
    { "dt=#", L1_STATUS },
    { "t=#", L1_STATUS },
    { "steps #", L1_STATUS },
    { "evals #", L1_STATUS },
    { "err # m", L1_STATUS },
    { "v err # m/s", L1_STATUS },
    { "position error # m", L1_STATUS },
    { "velocity error # m/s", L1_STATUS },
    { "drift #", L1_STATUS },
    { "E#%", L1_STATUS },
    { "energy #%", L1_STATUS },
    { "ev step", L1_STATUS },
    { "ev loc", L1_STATUS },
    { "events step", L1_STATUS },
    { "events locate", L1_STATUS },
    { "stop t=#", "02-euler.lesson", "Halve it again" },
    { "acc # rej #", "09-adaptive.lesson", "Let the method choose Δt" },
    { "accepted # rejected #", "09-adaptive.lesson", "Let the method choose Δt" },
    { "stiffness·dt # of limit #", L1_METER },
    { "stability: finding the stiffest mode", L1_METER },
    { "finding the stiffest mode", L1_METER },
    { "stiffness·dt #, no stable dt", L1_METER },
    { "stiffness·dt #, stable at any dt", L1_METER },
    { "(limit with this damping; # undamped)", "05-springs.lesson", "Remedy 3: better integration" },
    { "(# undamped)", "05-springs.lesson", "Remedy 3: better integration" },
    { "[#]", L1_METER },
    { "growth ×# per step: decays", L1_METER },
    { "growth ×# per step: neutral", L1_METER },
    { "growth ×# per step: GROWS", L1_METER },
    { "growth ×# per step: grows slowly", L1_METER },
    { "growth ×# per step: decays slowly", L1_METER },
    { "growth ×#/step decays", L1_METER },
    { "growth ×#/step neutral", L1_METER },
    { "growth ×#/step GROWS", L1_METER },
    { "growth ×#/step grows slowly", L1_METER },
    { "growth ×#/step decays slowly", L1_METER },
    { "(fastest ×#)", L1_METER },
    { "(of the mode |λ| #; the fastest, |λ| #: ×#)", L1_METER },
    { "stops at t=# (u)", "02-euler.lesson", "Halve it again" },
    { "<method> chooses its own steps: no fixed-step limit", NULL, NULL },
    { "BLOWN UP at step #", NULL, NULL },
    { "BLOWN UP", NULL, NULL },
    { "adaptive steps", NULL, NULL },
    { "vs", NULL, NULL },
};

/* s with every number (digits, a point, an exponent; a sign before it)
 * as one '#', and the meter's bar as "[#]". */
static void form_of(const char *s, char *out, size_t len)
{
    size_t n = 0;
    while (*s && n + 2 < len) {
        if (*s == '[' && (s[1] == '#' || s[1] == '.')) {
            while (*s && *s != ']')
                s++;
            s += *s == ']';
            n += (size_t)snprintf(out + n, len - n, "[#]");
            continue;
        }
        int sign = (*s == '-' || *s == '+') && isdigit((unsigned char)s[1]);
        if (isdigit((unsigned char)*s) || sign) {
            s += sign;
            while (isdigit((unsigned char)*s) || *s == '.' ||
                   ((*s == 'e' || *s == 'E') && (isdigit((unsigned char)s[1]) || s[1] == '-' || s[1] == '+')))
                s += (*s == 'e' || *s == 'E') && (s[1] == '-' || s[1] == '+') ? 2 : 1;
            out[n++] = '#';
            continue;
        }
        out[n++] = *s++;
    }
    out[n] = '\0';
}

static int first_page_points; /* the course's first page says where its lines are explained */

/* The place in the course (lesson index, page index) of page `page` of
 * `file`, from the lesson list, whose text must hold key (the form's first
 * word: the page that explains a field names it). */
static int place_of(const sw_lesson_entry *e, int n, const char *file, const char *title, const char *key,
                    int *page)
{
    for (int i = 0; i < n; i++) {
        if (strcmp(e[i].file, file) != 0)
            continue;
        char err[SW_LESSON_ERRLEN];
        sw_lesson lesson;
        ck_assert_msg(sw_lesson_load(e[i].path, &lesson, err, sizeof err) == SW_OK, "%s", err);
        int found = -1;
        int named = 0;
        for (int p = 0; p < lesson.npages; p++)
            if (strcmp(lesson.pages[p].title, title) == 0) {
                found = p;
                for (int b = 0; b < lesson.pages[p].nblocks; b++)
                    named |= strstr(lesson.pages[p].blocks[b].text, key) != NULL;
            }
        sw_lesson_free(&lesson);
        ck_assert_msg(found < 0 || named, "%s's page '%s' is said to explain '%s' but does not name it", file, title,
                      key);
        ck_assert_msg(found >= 0, "the symbol list names page '%s' of %s, which it does not have", title, file);
        *page = found;
        return i;
    }
    ck_abort_msg("the symbol list names %s, which is not a lesson", file);
    return -1;
}

/* Every field of the status lines and the meter now: known, and explained
 * at or before lesson li's page pi. */
static void check_fields(sw_app *a, const sw_lesson_entry *e, int n, int li, int pi, const char *when)
{
    sw_field f[SW_STATUS_FIELDS];
    for (int line = 0; line <= a->nsims; line++) {
        int nf, warn;
        if (line < a->nsims)
            nf = sw_app_status_fields(a, line, f, SW_STATUS_FIELDS);
        else
            nf = sw_app_meter_fields(a, f, SW_STATUS_FIELDS, &warn);
        for (int k = 0; k < nf; k++)
            for (int form_kind = 0; form_kind < 2; form_kind++) {
                const char *text = form_kind ? f[k].brief : f[k].full;
                /* the scene's and the methods' own names (lesson 1's status page names both) */
                int own = strcmp(text, a->scene->name) == 0;
                for (int m = 0; m < a->nsims; m++)
                    own |= strcmp(text, a->sims[m].method->name) == 0;
                if (!text[0] || own)
                    continue;
                /* a method's name leading a field is <method> (its digits are no number) */
                char named[200];
                snprintf(named, sizeof named, "%s", text);
                for (int m = 0; m < a->nsims; m++) {
                    size_t ml = strlen(a->sims[m].method->name);
                    if (strncmp(text, a->sims[m].method->name, ml) == 0 && text[ml] == ' ')
                        snprintf(named, sizeof named, "<method>%s", text + ml);
                }
                char form[200];
                form_of(named, form, sizeof form);
                const symbol *s = NULL;
                for (size_t j = 0; j < sizeof symbols / sizeof symbols[0]; j++)
                    if (strcmp(symbols[j].form, form) == 0)
                        s = &symbols[j];
                if (!s && a->scene->drift_name) {
                    /* the scene's own name for its drift ("radius drift #") */
                    char drift[200];
                    snprintf(drift, sizeof drift, "%s #", a->scene->drift_name);
                    if (strcmp(form, drift) == 0)
                        continue;
                }
                ck_assert_msg(s != NULL, "%s page %d (%s): '%s' (form '%s') is on screen, and no row of the symbol "
                              "list says where it is explained", e[li].file, pi + 1, when, text, form);
                if (!s->file)
                    continue;
                char key[64];
                size_t kl = strcspn(s->form, " #=");
                snprintf(key, sizeof key, "%.*s", (int)kl, s->form);
                if (strcmp(key, "[") == 0)
                    snprintf(key, sizeof key, "[###");
                int sp, sl = place_of(e, n, s->file, s->page, key, &sp);
                int pointed = li == 0 && sl == 0 && pi < sp && sp <= 2 && first_page_points;
                ck_assert_msg(sl < li || (sl == li && sp <= pi) || pointed, "%s page %d (%s): '%s' is on screen "
                              "before %s's page '%s' explains it", e[li].file, pi + 1, when, text, s->file, s->page);
            }
    }
}

/* On the course's first page: whether its text points to the next two
 * (lines joined with spaces). */
static void read_first_page(const sw_runner *r, int lesson, int page)
{
    if (lesson != 0 || page != 0)
        return;
    char text[4096] = "";
    const sw_lesson_page *pg = &r->lesson.pages[0];
    for (int b = 0; b < pg->nblocks; b++)
        strncat(text, pg->blocks[b].text, sizeof text - strlen(text) - 2);
    for (char *c = text; *c; c++)
        *c = *c == '\n' ? ' ' : *c;
    first_page_points = strstr(text, FIRST_PAGE_POINTS) != NULL;
}

/* The page as it opens and after a second of play. */
static void page_fields(sw_runner *r, sw_app *a, const sw_lesson_entry *e, int n, int lesson, int page, void *ctx)
{
    (void)ctx;
    read_first_page(r, lesson, page);
    check_fields(a, e, n, lesson, page, "as the page opens");
    int paused = a->paused;
    a->paused = 0;
    sw_app_advance(a, 1.0, 100000);
    a->paused = paused;
    check_fields(a, e, n, lesson, page, "after a second of play");
}

START_TEST(every_field_explained_first)
{
    ct_each_page(page_fields, NULL);
}
END_TEST

/* The form of a field: numbers become '#', the bar "[#]". */
START_TEST(forms)
{
    char out[64];
    form_of("stiffness·dt 0.5 of limit 2.83", out, sizeof out);
    ck_assert_str_eq(out, "stiffness·dt # of limit #");
    form_of("E-1.45e+03%", out, sizeof out);
    ck_assert_str_eq(out, "E#%");
    form_of("[###.......]", out, sizeof out);
    ck_assert_str_eq(out, "[#]");
    form_of("err 5.2e-08 m", out, sizeof out);
    ck_assert_str_eq(out, "err # m");
}
END_TEST

/* ---- the views: every glyph of a picture and every mark of its legend ------------ */

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
            form_of(run, form, sizeof form);
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
            form_of(line, form, sizeof form);
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
                int sp, sl = place_of(e, n, s->file, s->page, m, &sp);
                /* (the course's first page points to the next two for the status line's words) */
                ok |= sl < li || (sl == li && sp <= pi) || (li == 0 && sl == 0 && sp <= 2 && first_page_points);
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
    read_first_page(r, lesson, page);
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

Suite *make_symbols_suite(void);
Suite *make_symbols_suite(void)
{
    Suite *s = suite_create("symbols");
    TCase *tc = tcase_create("symbols");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, forms);
    tcase_add_test(tc, every_field_explained_first);
    tcase_add_test(tc, every_view_symbol_explained);
    suite_add_tcase(s, tc);
    return s;
}
