/* The lesson runner: pages drive the app, goals are checked against what
 * the app shows, and a page opens the next one only once its goals are met.
 * Progress is saved through app/progress.c. */
#include "app/runner.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/progress.h"
#include "stepwise/base.h"
#include "util/utf8.h"

/* The lesson pane grows by at most this many columns for a page's verbatim
 * lines, and leaves the picture at least this many. */
#define PANE_GROW 6
#define PANE_PICTURE_MIN 30

void sw_runner_obs(sw_app *a, sw_lesson_obs *obs)
{
    sw_lesson_obs_init(obs);
    sw_lesson_obs_from_sim(obs, &a->sims[0]);
    obs->error = sw_app_error(a, 0);
    obs->error_ratio = a->error_ratio;
    obs->compare = a->compare;
    obs->ghost = a->ghost;
    obs->paused = a->paused;
    obs->speed = a->speed;
    obs->recorded = a->recorded;
    obs->phase = a->view == SW_VIEW_PHASE;
    obs->region = a->view == SW_VIEW_REGION;
}

void sw_runner_enter(sw_runner *r, sw_app *a, int page)
{
    if (page < 0)
        page = 0;
    if (page >= r->lesson.npages)
        page = r->lesson.npages - 1;
    const sw_lesson_page *pg = &r->lesson.pages[page];
    char err[SW_ERRLEN];
    a->locked = 0;
    if (pg->scene != a->scene) {
        /* a new scene starts in its own picture: the scene view, its natural size */
        sw_app_set_view(a, SW_VIEW_SCENE);
        a->zoom = 1;
        a->follow = 0;
    }
    if (pg->restart || pg->scene != a->scene || memcmp(pg->p, a->p, sizeof pg->p) != 0) {
        if (sw_app_set_scene(a, pg->scene, pg->p, err, sizeof err) != SW_OK)
            snprintf(a->message, sizeof a->message, "%s", err);
        sw_app_set_method(a, pg->method);
        sw_app_set_dt(a, pg->dt);
        sw_app_reset(a);
        a->nmeas = 0;
        a->error_ratio = NAN;
    }
    if (pg->compare >= 0 && pg->ncompare_with > 0)
        sw_app_compare_with(a, pg->compare_with, pg->ncompare_with);
    else if (pg->compare >= 0)
        sw_app_set_compare(a, pg->compare, NULL, NULL);
    if (pg->ghost >= 0)
        sw_app_set_ghost(a, pg->ghost);
    if (pg->paused >= 0)
        a->paused = pg->paused;
    if (pg->speed > 0)
        a->speed = pg->speed;
    if (pg->view >= 0)
        sw_app_set_view(a, pg->view == SW_LESSON_VIEW_PHASE    ? SW_VIEW_PHASE
                           : pg->view == SW_LESSON_VIEW_REGION ? SW_VIEW_REGION
                                                               : SW_VIEW_SCENE);
    if (pg->follow >= 0)
        a->follow = pg->follow;
    if (pg->lanes >= 0)
        a->lanes = pg->lanes;
    if (pg->graph >= 0)
        a->graph = pg->graph;
    if (pg->zoom > 0)
        a->zoom = pg->zoom;
    a->locked = pg->locked;
    a->panel = a->help = 0;
    r->page = page;
    r->feedback = NULL;
    r->hint = 0;
    r->scroll = 0;
    snprintf(a->message, sizeof a->message, "page %d of %d: %s", page + 1, r->lesson.npages, pg->title);
}

int sw_runner_start(sw_runner *r, sw_app *a, const char *path, int page, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    int rc = sw_lesson_load(path, &r->lesson, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (r->lesson.npages < 1) {
        snprintf(err, errlen, "%s: the lesson has no pages", path);
        sw_lesson_free(&r->lesson);
        return SW_EINVAL;
    }
    const char *slash = strrchr(path, '/');
    snprintf(r->file, sizeof r->file, "%s", slash ? slash + 1 : path);
    r->done = sw_progress_get(r->file);
    if (r->done > r->lesson.npages)
        r->done = r->lesson.npages;
    for (int i = 0; i < r->done; i++)
        r->complete[i] = 1;
    if (page < 0)
        page = r->done < r->lesson.npages ? r->done : 0;
    const sw_lesson_page *first = &r->lesson.pages[page < r->lesson.npages ? page : 0];
    rc = sw_app_init(a, first->scene, first->p, first->method, first->dt, err, errlen);
    if (rc != SW_OK) {
        sw_lesson_free(&r->lesson);
        return rc;
    }
    sw_runner_enter(r, a, page);
    return SW_OK;
}

void sw_runner_free(sw_runner *r) { sw_lesson_free(&r->lesson); }

int sw_runner_update(sw_runner *r, sw_app *a)
{
    if (r->complete[r->page])
        return 0;
    sw_lesson_obs obs;
    sw_runner_obs(a, &obs);
    if (!sw_lesson_page_complete(&r->lesson.pages[r->page], &obs, r->answered[r->page]))
        return 0;
    r->complete[r->page] = 1;
    if (r->page + 1 > r->done) {
        r->done = r->page + 1;
        char err[SW_ERRLEN];
        if (sw_progress_set(r->file, r->done, err, sizeof err) != SW_OK)
            snprintf(r->save_error, sizeof r->save_error, "progress not saved: %s", err);
    }
    /* The key line and the pane say so; the message line keeps what the
     * student just measured until the next key. */
    if (r->page + 1 == r->lesson.npages)
        r->finished = 1;
    if (r->save_error[0])
        snprintf(a->message, sizeof a->message, "%s", r->save_error);
    return 1;
}

int sw_runner_key(sw_runner *r, sw_app *a, int key)
{
    const sw_lesson_page *pg = &r->lesson.pages[r->page];
    if (pg->question.text && !r->answered[r->page] && key >= SW_ANSWER_FIRST &&
        key < SW_ANSWER_FIRST + pg->question.nanswers) {
        a->message[0] = '\0';
        int ok = sw_lesson_answer(pg, key - SW_ANSWER_FIRST + 'a', &r->feedback);
        r->feedback_ok = ok == 1;
        if (ok == 1)
            r->answered[r->page] = 1;
        snprintf(a->message, sizeof a->message, "%s", ok == 1 ? "right!" : "not quite: read the feedback and try again");
        return 1;
    }
    const sw_control *c;
    int arg;
    if (!sw_key_lookup(key, SW_CTX_PLAY | SW_CTX_LESSON | (a->panel ? SW_CTX_PANEL : 0u), &c, &arg)) {
        if (pg->question.text && !r->answered[r->page] && key >= 'a' && key < 'a' + pg->question.nanswers) {
            snprintf(a->message, sizeof a->message, "answers take capital letters: %c to %c", SW_ANSWER_FIRST,
                     SW_ANSWER_FIRST + pg->question.nanswers - 1);
            return 1;
        }
        return 0;
    }
    if (c->action >= SW_ACT_PAGE_NEXT && c->action <= SW_ACT_SCROLL_DOWN)
        a->message[0] = '\0'; /* a message stays until the next key */
    switch (c->action) {
    case SW_ACT_PAGE_NEXT:
        if (!r->complete[r->page]) {
            snprintf(a->message, sizeof a->message, "this page's goals are not met yet (h shows a hint)");
        } else if (r->page + 1 < r->lesson.npages) {
            sw_runner_enter(r, a, r->page + 1);
        } else {
            snprintf(a->message, sizeof a->message, "that was the last page: q leaves the lesson");
        }
        return 1;
    case SW_ACT_PAGE_PREV:
        if (r->page > 0)
            sw_runner_enter(r, a, r->page - 1);
        return 1;
    case SW_ACT_HINT:
        r->hint = !r->hint;
        return 1;
    case SW_ACT_SCROLL_UP:
    case SW_ACT_SCROLL_DOWN:
        r->scroll += c->action == SW_ACT_SCROLL_DOWN ? 3 : -3;
        if (r->scroll < 0)
            r->scroll = 0;
        return 1;
    default:
        return 0;
    }
}

/* ---- the text pane ---------------------------------------------------------- */

static void add_line(sw_runner *r, sw_side_kind kind, const char *text)
{
    int n = r->side.nlines;
    if (n >= SW_RUNNER_LINES)
        return;
    snprintf(r->text[n], SW_RUNNER_COLS, "%s", text);
    r->lines[n] = r->text[n];
    r->kinds[n] = kind;
    r->side.nlines++;
}

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
static int operands(const char *s, int *only_closers)
{
    int n = 0;
    *only_closers = 1;
    while (*s) {
        while (*s == ' ')
            s++;
        const char *w = s;
        while (*s && *s != ' ')
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
static void add_wrapped(sw_runner *r, sw_side_kind kind, const char *text, int width)
{
    const char *p = text;
    if (width < 2)
        width = 2;
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
                if (p == w) { /* cannot happen with width >= 2; progress all the same */
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
        char buf[SW_RUNNER_COLS];
        size_t len = sw_utf8_clip(line, (size_t)(cut - line), sizeof buf - 1);
        memcpy(buf, line, len);
        buf[len] = '\0';
        add_line(r, kind, buf);
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
static void add_verbatim(sw_runner *r, const char *text, int width)
{
    int indent = 0;
    while (text[indent] == ' ')
        indent++;
    if ((int)sw_utf8_columns(text, strlen(text)) <= width || width < indent + 12) {
        add_line(r, SW_SIDE_VERBATIM, text);
        return;
    }
    char buf[SW_RUNNER_COLS];
    const char *p = text;
    int first = 1, depth = 0, next_room = width - (indent + 4);
    while (*p) {
        int lead = first ? 0 : indent + 4, room = width - lead;
        if ((int)sw_utf8_columns(p, strlen(p)) <= room) {
            if (snprintf(buf, sizeof buf, "%*s%s", lead, "", p) >= 0) /* (a line wider than buf is cut) */
                add_line(r, SW_SIDE_VERBATIM, buf);
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
            int only_closers, tail = operands(ns, &only_closers), head_closers;
            char head[SW_RUNNER_COLS];
            snprintf(head, sizeof head, "%.*s", (int)(q - p), p);
            int score = -30 * (d > 0 ? d : 0) + cells / 8;
            if (!strchr(head + (first ? indent : 0), ' '))
                score -= 60; /* "f" or "=" alone on a line */
            else if (operands(head, &head_closers) <= 1 && is_operator(w, q))
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
        snprintf(buf, sizeof buf, "%*s%.*s", lead, "", (int)(cut - p), p);
        add_line(r, SW_SIDE_VERBATIM, buf);
        p = next;
        while (*p == ' ')
            p++;
        depth = best_depth;
        first = 0;
    }
}

const sw_side *sw_runner_side(sw_runner *r, sw_app *a, int cols)
{
    const sw_lesson_page *pg = &r->lesson.pages[r->page];
    /* beside the scene at every size: the scene keeps every row above the status lines */
    int width = cols >= 110 ? (cols * 2 / 5 < 64 ? cols * 2 / 5 : 64) : cols / 2;
    /* A page with verbatim lines (a table, a formula) gets a pane up to
     * PANE_GROW columns wider, so that they show whole (a table row split
     * in two no longer reads as a row); the picture keeps PANE_PICTURE_MIN
     * columns, and the one between them. */
    int need = 0;
    for (int b = 0; b < pg->nblocks; b++)
        for (const char *s = pg->blocks[b].verbatim ? pg->blocks[b].text : ""; *s;) {
            const char *e = strchr(s, '\n');
            size_t len = e ? (size_t)(e - s) : strlen(s);
            int cells = 2 + (int)sw_utf8_columns(s, len) + 1; /* the indent, the line, the margin */
            need = cells > need ? cells : need;
            s += len + (e ? 1 : 0);
        }
    if (need > width)
        width = need < width + PANE_GROW ? need : width + PANE_GROW;
    if (width > cols - PANE_PICTURE_MIN - 1)
        width = cols - PANE_PICTURE_MIN - 1;
    char buf[SW_RUNNER_COLS];
    r->side.nlines = 0;
    r->side.lines = r->lines;
    r->side.kinds = r->kinds;
    r->side.width = width;
    r->side.scroll = &r->scroll;
    r->side.question_open = pg->question.text && !r->answered[r->page];
    r->side.notice = !r->complete[r->page] ? NULL
                     : r->page + 1 < r->lesson.npages ? "page done: n next page" : "lesson complete: q leaves";
    /* the lesson's title and the page: "(page 2/6)" when the line has room,
     * else "(2/6)", which has no space to be broken at */
    snprintf(buf, sizeof buf, "%s  (page %d/%d)", r->lesson.title, r->page + 1, r->lesson.npages);
    if ((int)sw_utf8_columns(buf, strlen(buf)) > width - 1)
        snprintf(buf, sizeof buf, "%s  (%d/%d)", r->lesson.title, r->page + 1, r->lesson.npages);
    add_wrapped(r, SW_SIDE_DIM, buf, width - 1);
    add_wrapped(r, SW_SIDE_TITLE, pg->title, width - 1);
    add_line(r, SW_SIDE_TEXT, "");
    for (int b = 0; b < pg->nblocks; b++) {
        if (pg->blocks[b].verbatim) {
            const char *s = pg->blocks[b].text;
            while (*s) {
                const char *e = strchr(s, '\n');
                size_t len = e ? (size_t)(e - s) : strlen(s);
                snprintf(buf, sizeof buf, "  %.*s", (int)(len < 300 ? len : 300), s);
                add_verbatim(r, buf, width - 1);
                s += len + (e ? 1 : 0);
            }
        } else {
            add_wrapped(r, SW_SIDE_TEXT, pg->blocks[b].text, width - 1);
        }
        add_line(r, SW_SIDE_TEXT, "");
    }
    sw_lesson_obs obs;
    sw_runner_obs(a, &obs);
    const sw_lesson_goal *unmet = NULL;
    int foot = r->side.nlines; /* from here on: what the page asks, kept in sight */
    if (pg->ngoals > 0)
        add_line(r, SW_SIDE_TITLE, "Goals:");
    for (int g = 0; g < pg->ngoals; g++) {
        char text[160];
        int met = r->complete[r->page] || sw_lesson_goal_met(&pg->goals[g], &obs);
        if (!met && !unmet)
            unmet = &pg->goals[g];
        sw_lesson_goal_text(&pg->goals[g], text, sizeof text);
        snprintf(buf, sizeof buf, " %s %s", met ? "\xe2\x9c\x93" : "\xe2\x9c\x97", text);
        add_line(r, met ? SW_SIDE_OK : SW_SIDE_BAD, buf);
    }
    const sw_lesson_question *q = &pg->question;
    if (q->text) {
        add_line(r, SW_SIDE_TEXT, "");
        add_wrapped(r, SW_SIDE_TITLE, q->text, width - 1);
        for (int i = 0; i < q->nanswers; i++) {
            snprintf(buf, sizeof buf, "%c) %s", SW_ANSWER_FIRST + i, q->answers[i].text);
            add_wrapped(r, r->answered[r->page] && i == q->correct ? SW_SIDE_OK : SW_SIDE_TEXT, buf, width - 1);
        }
        if (!r->answered[r->page]) {
            snprintf(buf, sizeof buf, "(answer with a capital letter, %c to %c)", SW_ANSWER_FIRST,
                     SW_ANSWER_FIRST + q->nanswers - 1);
            add_wrapped(r, SW_SIDE_DIM, buf, width - 1);
        }
        if (r->feedback)
            add_wrapped(r, r->feedback_ok ? SW_SIDE_OK : SW_SIDE_BAD, r->feedback, width - 1);
    }
    if (r->hint) {
        const char *h = unmet ? unmet->hint : (q->text && !r->answered[r->page]) ? q->hint : NULL;
        add_line(r, SW_SIDE_TEXT, "");
        snprintf(buf, sizeof buf, "Hint: %s", h ? h : "nothing left to do here: press n");
        add_wrapped(r, SW_SIDE_HINT, buf, width - 1);
    }
    add_line(r, SW_SIDE_TEXT, "");
    if (r->complete[r->page])
        add_wrapped(r, SW_SIDE_OK, r->page + 1 < r->lesson.npages ? "Done: press n for the next page."
                                                                 : "Lesson complete! q leaves the lesson.", width - 1);
    else
        add_wrapped(r, SW_SIDE_DIM, "h: hint   n: next page once the goals are met", width - 1);
    r->side.pinned = r->side.nlines - foot;
    return &r->side;
}
