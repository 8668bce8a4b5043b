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
#include "util/wrap.h"

/* The lesson pane grows by at most this many columns for a page's verbatim
 * lines, and leaves the picture at least this many. */
#define PANE_GROW 6
#define PANE_PICTURE_MIN 30
#define READING_COLS 100 /* the reading mode's widest line: longer ones are hard to follow */

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

/* Add m to the work-precision plot's methods, once. */
static void plot_method(sw_app *a, const sw_integrator *m)
{
    int n = (int)(sizeof a->wp_only / sizeof a->wp_only[0]);
    for (int i = 0; i < a->wp_nonly; i++)
        if (a->wp_only[i] == m)
            return;
    if (m && a->wp_nonly < n)
        a->wp_only[a->wp_nonly++] = m;
}

/* The methods the lesson has used up to page: every page's integrator,
 * the ones it compares with and the ones its goals name. On a lesson page
 * the work-precision plot shows these (the methods the text is about),
 * not every method the student has not met yet. */
static void methods_met(const sw_runner *r, sw_app *a, int page)
{
    a->wp_nonly = 0;
    for (int p = 0; p <= page && p < r->lesson.npages; p++) {
        const sw_lesson_page *pg = &r->lesson.pages[p];
        plot_method(a, pg->method);
        for (int k = 0; k < pg->ncompare_with; k++)
            plot_method(a, pg->compare_with[k]);
        for (int g = 0; g < pg->ngoals; g++)
            if (pg->goals[g].var == SW_LV_INTEGRATOR)
                for (int k = 0; k < pg->goals[g].nnames; k++)
                    plot_method(a, sw_integrator_find(pg->goals[g].names[k]));
    }
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
    a->view_gen++; /* a page's pictures are scaled for it (the region view's fixed scale) */
    if (pg->scene != a->scene) {
        /* a new scene starts in its own picture: the scene view, its natural size */
        sw_app_set_view(a, SW_VIEW_SCENE);
        a->zoom = 1;
        a->follow = 0;
        a->have_box = 0;
    }
    if (pg->restart || pg->scene != a->scene || memcmp(pg->p, a->p, sizeof pg->p) != 0) {
        if (sw_app_set_scene(a, pg->scene, pg->p, err, sizeof err) != SW_OK)
            snprintf(a->message, sizeof a->message, "%s", err);
        sw_app_set_method(a, pg->method);
        sw_app_set_dt(a, pg->dt);
        sw_app_reset(a);
        /* a page that starts a run starts it paused and at speed 1, unless
         * it says @pause off or @speed (a slowed page before it no longer
         * slows this one's wait) */
        a->paused = 1;
        a->speed = 1;
        a->nmeas = 0;
        a->error_ratio = NAN;
    }
    /* A page starts clean unless it says otherwise: no run left blown up by
     * the page before, no view or plot of its (the region view, the
     * work-precision plot cover the scene), no trails (the epoch). */
    if (a->sims[0].blown || (a->nsims > 1 && (a->sims[1].blown || (a->nsims > 2 && a->sims[2].blown))))
        sw_app_reset(a);
    if (pg->view < 0 && a->view != SW_VIEW_SCENE)
        sw_app_set_view(a, SW_VIEW_SCENE);
    a->workprec = 0;
    methods_met(r, a, page);
    a->epoch++;
    if (pg->compare >= 0 && pg->ncompare_with > 0)
        sw_app_compare_with(a, pg->compare_with, pg->ncompare_with);
    else if (pg->compare >= 0)
        sw_app_set_compare(a, pg->compare, NULL, NULL);
    if (pg->ghost >= 0)
        sw_app_set_ghost(a, pg->ghost);
    if (pg->events >= 0)
        sw_app_set_events(a, pg->events ? SW_EVENTS_LOCATE : SW_EVENTS_STEP);
    if (pg->paused >= 0)
        a->paused = pg->paused;
    if (pg->speed > 0)
        a->speed = pg->speed;
    if (pg->view >= 0)
        sw_app_set_view(a, pg->view == SW_LESSON_VIEW_PHASE    ? SW_VIEW_PHASE
                           : pg->view == SW_LESSON_VIEW_REGION ? SW_VIEW_REGION
                                                               : SW_VIEW_SCENE);
    /* the camera too: the scene's own view, unless the page sets one (a
     * zoom-out asked for on one page hid the next page's pendulum) */
    if (pg->zoom <= 0)
        a->zoom = 1;
    if (pg->follow < 0)
        a->follow = 0;
    if (!pg->has_box)
        a->have_box = 0;
    if (pg->follow >= 0)
        a->follow = pg->follow;
    if (pg->lanes >= 0)
        a->lanes = pg->lanes;
    if (pg->graph >= 0)
        a->graph = pg->graph;
    if (pg->zoom > 0)
        a->zoom = pg->zoom;
    if (pg->has_box) {
        a->box = (sw_view){ pg->box[0], pg->box[2], pg->box[1], pg->box[3] };
        a->have_box = 1;
    }
    sw_app_set_until(a, pg->until); /* a page's own stop time, or none */
    a->locked = pg->locked;
    a->panel = a->help = 0;
    r->page = page;
    r->feedback = NULL;
    r->hint = 0;
    r->scroll = 0;
    snprintf(a->message, sizeof a->message, "page %d of %d: %s", page + 1, r->lesson.npages, pg->title);
    /* the reading mode carries over, but never hides a run: a page whose
     * run goes on arrival shows the picture; on a paused one, space both
     * runs and brings the picture back (sw_runner_key) */
    size_t said = strlen(a->message);
    if (r->wide && !a->paused) {
        r->wide = 0;
        snprintf(a->message + said, sizeof a->message - said, " (the picture again: the run is going; o: reading "
                 "mode)");
    } else if (r->wide)
        snprintf(a->message + said, sizeof a->message - said, " (reading mode: space runs and brings the picture "
                 "back)");
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
        r->before[i] = 1; /* goals fresh (not ticked from last time); n skips the page */
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
        r->scroll = SW_RUNNER_LINES; /* the pane's end, where the feedback is (a folded question opens) */
        snprintf(a->message, sizeof a->message, "%s", ok == 1 ? "right!" : "not quite: read the feedback and try again");
        return 1;
    }
    const sw_control *c;
    int arg;
    if (!sw_key_lookup(key, sw_key_contexts(a->panel, 1), &c, &arg)) {
        if (pg->question.text && !r->answered[r->page] && key >= 'a' && key < 'a' + pg->question.nanswers) {
            snprintf(a->message, sizeof a->message, "answers take capital letters: %c to %c", SW_ANSWER_FIRST,
                     SW_ANSWER_FIRST + pg->question.nanswers - 1);
            return 1;
        }
        return 0;
    }
    if (c->action >= SW_ACT_PAGE_NEXT && c->action <= SW_ACT_READ)
        a->message[0] = '\0'; /* a message stays until the next key */
    if (c->action == SW_ACT_PAUSE && r->wide && a->paused) {
        /* running in the reading mode would show nothing: the picture comes
         * back (otherwise the app's, as every play action: below) */
        if (!sw_app_apply(a, SW_ACT_PAUSE, 1))
            return 1; /* (locked on this page: the app said so) */
        r->wide = 0;
        snprintf(a->message, sizeof a->message, "running: the picture again (o: reading mode)");
        return 1;
    }
    switch (c->action) {
    case SW_ACT_PAGE_NEXT:
        if (!r->complete[r->page] && !r->before[r->page]) {
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
        r->hint_scroll = r->hint; /* the pane scrolls to it: it may sit below the text shown */
        return 1;
    case SW_ACT_READ:
        r->wide = !r->wide;
        snprintf(a->message, sizeof a->message, "%s", r->wide ? "reading mode: the text full width (o: the picture "
                 "again)" : "the picture and the text side by side (o: the text full width)");
        return 1;
    case SW_ACT_SCROLL_UP:
    case SW_ACT_SCROLL_DOWN:
        r->scroll += (c->action == SW_ACT_SCROLL_DOWN ? 1 : -1) * (r->step > 3 ? r->step : 3);
        if (r->scroll < 0)
            r->scroll = 0;
        return 1;
    case SW_ACT_ANSWER: /* answered above, while the page's question is open */
    SW_PLAY_CASES /* the app's (app.c) */
    SW_PANEL_CASES
    case SW_ACT_NONE:
    case SW_ACT_COUNT:
        return 0;
    }
    return 0;
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

/* A paragraph's or a verbatim line's lines, from util/wrap.c, into the pane
 * (each cut to a pane line's bytes). */
typedef struct pane_out {
    sw_runner *r;
    sw_side_kind kind;
} pane_out;

static void pane_paragraph_line(void *ctx, int lead, const char *text, size_t len)
{
    const pane_out *o = ctx;
    char buf[SW_RUNNER_COLS];
    (void)lead; /* paragraphs have none */
    len = sw_utf8_clip(text, len, sizeof buf - 1);
    memcpy(buf, text, len);
    buf[len] = '\0';
    add_line(o->r, o->kind, buf);
}

static void pane_verbatim_line(void *ctx, int lead, const char *text, size_t len)
{
    const pane_out *o = ctx;
    char buf[SW_RUNNER_COLS];
    snprintf(buf, sizeof buf, "%*s%.*s", lead, "", (int)len, text); /* (a line wider than buf is cut) */
    add_line(o->r, o->kind, buf);
}

static void add_wrapped(sw_runner *r, sw_side_kind kind, const char *text, int width)
{
    pane_out o = { r, kind };
    sw_wrap_paragraph(text, width < 2 ? 2 : width, pane_paragraph_line, &o);
}

static void add_verbatim(sw_runner *r, const char *text, int width)
{
    pane_out o = { r, SW_SIDE_VERBATIM };
    sw_wrap_verbatim(text, width, pane_verbatim_line, &o);
}

/* Where a verbatim line's description starts, in columns: after the first
 * gap of two spaces past its term ("  err … m   position error"), or at its
 * indent when it is all description ("            worst dot's"); 0: none. */
static int description_column(const char *line)
{
    size_t lead = strspn(line, " ");
    const char *gap = strstr(line + lead, "  ");
    if (gap && gap[strspn(gap, " ")])
        return (int)sw_utf8_columns(line, (size_t)(gap - line) + strspn(gap, " "));
    return lead >= 4 && line[lead] ? (int)lead : 0;
}

/* A byte offset of line at column col (col within the line). */
static size_t byte_at_column(const char *line, int col)
{
    size_t b = 0;
    while (line[b] && (int)sw_utf8_columns(line, b) < col)
        b++;
    return b;
}

/* A description's wrapped lines under its column, the first after its term. */
typedef struct hanging {
    sw_runner *r;
    const char *term;
    size_t term_bytes;
    int column, lines;
} hanging;

static void hanging_line(void *ctx, int lead, const char *text, size_t len)
{
    hanging *h = ctx;
    char buf[SW_RUNNER_COLS];
    (void)lead;
    if (h->lines++ == 0)
        snprintf(buf, sizeof buf, "%.*s%.*s", (int)h->term_bytes, h->term, (int)len, text);
    else
        snprintf(buf, sizeof buf, "%*s%.*s", h->column, "", (int)len, text);
    add_line(h->r, SW_SIDE_VERBATIM, buf);
}

/* The reading mode re-flows a definition list written narrow for the pane:
 * lines[0]'s description and the lines under it indented to its column,
 * joined and wrapped to width under that column. Returns how many of the n
 * lines it took (1: the line alone, added as written). */
static int add_definition(sw_runner *r, char (*lines)[SW_RUNNER_COLS], int n, int width)
{
    int d = description_column(lines[0]), k = 1;
    while (d >= 4 && k < n && (int)strspn(lines[k], " ") == d && lines[k][d])
        k++;
    if (k == 1 || width - d < 20) {
        add_verbatim(r, lines[0], width);
        return 1;
    }
    char desc[2048] = "";
    size_t used = 0, at = byte_at_column(lines[0], d);
    used += (size_t)snprintf(desc, sizeof desc, "%s", lines[0] + at);
    for (int i = 1; i < k && used < sizeof desc; i++)
        used += (size_t)snprintf(desc + used, sizeof desc - used, " %s", lines[i] + d);
    hanging h = { r, lines[0], at, d, 0 };
    sw_wrap_paragraph(desc, width - d, hanging_line, &h);
    return k;
}

const sw_side *sw_runner_side(sw_runner *r, sw_app *a, int cols)
{
    const sw_lesson_page *pg = &r->lesson.pages[r->page];
    /* beside the scene at every size: the scene keeps every row above the status lines */
    int width = cols >= 110 ? (cols * 2 / 5 < 64 ? cols * 2 / 5 : 64) : cols / 2;
    /* the reading mode: the whole width, up to a line a reader's eye follows */
    int wide = r->wide ? (cols - 2 < READING_COLS ? cols - 2 : READING_COLS) : 0;
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
    if (wide > width)
        width = wide;
    r->side.full = r->wide;
    char buf[SW_RUNNER_COLS];
    r->side.nlines = 0;
    r->side.lines = r->lines;
    r->side.kinds = r->kinds;
    r->side.width = width;
    r->side.scroll = &r->scroll;
    r->side.step = &r->step;
    r->side.question_open = pg->question.text && !r->answered[r->page] ? pg->question.nanswers : 0;
    r->side.notice = !r->complete[r->page] ? (r->before[r->page] ? "done before: n skips ahead" : NULL)
                     : r->page + 1 < r->lesson.npages ? "page done: n next page" : "lesson complete: q leaves";
    /* the lesson's title and the page: "(page 2/6)" when the line has room,
     * else "(2/6)", which has no space to be broken at */
    snprintf(buf, sizeof buf, "%s  (page %d/%d)", r->lesson.title, r->page + 1, r->lesson.npages);
    if ((int)sw_utf8_columns(buf, strlen(buf)) > width - 1)
        snprintf(buf, sizeof buf, "%s  (%d/%d)", r->lesson.title, r->page + 1, r->lesson.npages);
    add_wrapped(r, SW_SIDE_DIM, buf, width - 1);
    add_wrapped(r, SW_SIDE_TITLE, pg->title, width - 1);
    r->side.head = r->side.nlines;
    add_line(r, SW_SIDE_TEXT, "");
    for (int b = 0; b < pg->nblocks; b++) {
        if (pg->blocks[b].verbatim) {
            /* the block's lines (each indented two), then added: as written,
             * or in the reading mode a definition list re-flowed */
            char (*lines)[SW_RUNNER_COLS] = r->block;
            int n = 0;
            for (const char *s = pg->blocks[b].text; *s && n < SW_RUNNER_LINES;) {
                const char *e = strchr(s, '\n');
                size_t len = e ? (size_t)(e - s) : strlen(s);
                snprintf(lines[n++], SW_RUNNER_COLS, "  %.*s", (int)(len < 300 ? len : 300), s);
                s += len + (e ? 1 : 0);
            }
            for (int i = 0; i < n;)
                i += r->wide ? add_definition(r, lines + i, n - i, width - 1) : (add_verbatim(r, lines[i], width - 1), 1);
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
    int fold_at = -1;
    if (q->text) {
        fold_at = r->side.nlines;
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
        if (r->hint_scroll)
            r->scroll = r->side.nlines; /* the composer clamps it to the pane's end */
        r->hint_scroll = 0;
        snprintf(buf, sizeof buf, "Hint: %s", h ? h : "nothing left to do here: press n");
        add_wrapped(r, SW_SIDE_HINT, buf, width - 1);
    }
    /* (the keys' reminder only where it fits a line: narrower, the key line
     * under the pane says it, and its rows go to the text) */
    int keys_line = width - 1 >= 46;
    if (r->complete[r->page] || r->before[r->page] || keys_line)
        add_line(r, SW_SIDE_TEXT, "");
    if (r->complete[r->page])
        add_wrapped(r, SW_SIDE_OK, r->page + 1 < r->lesson.npages ? "Done: press n for the next page."
                                                                 : "Lesson complete! q leaves the lesson.", width - 1);
    else if (r->before[r->page])
        add_wrapped(r, SW_SIDE_DIM, "Done in an earlier session: the goals start fresh; n skips ahead.",
                    width - 1);
    else if (keys_line)
        add_wrapped(r, SW_SIDE_DIM, "h: hint   n: next page once the goals are met", width - 1);
    r->side.pinned = r->side.nlines - foot;
    r->side.fold = fold_at >= 0 ? r->side.nlines - fold_at : 0;
    return &r->side;
}
