/* The lesson directives: settings (@scene @set @integrator @dt @compare
 * @ghost @pause @reset @speed @view @lock @unlock), text (@hint @question @answer
 * @correct) and prose paragraphs, each checked as it is read. */
#include "lesson/parse.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "util/kv.h"
#include "util/names.h"
#include "util/num.h"

static int d_scene(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    if (sw_lp_once(ps, &ps->at_scene, "@scene") != SW_OK)
        return ps->status;
    const char *later = ps->at_set.line ? "@set" : ps->at_integrator.line ? "@integrator"
                      : ps->at_dt.line ? "@dt" : ps->at_compare.line ? "@compare"
                      : pg->ngoals ? "@goal" : NULL;
    if (later)
        return FAIL(ps, 0, "@scene comes after %s on this page; expected @scene first, since it "
                    "resets parameters, integrator and dt to the scene's defaults", later);
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (sw_lp_one_word(ps, pos, "@scene", "a scene name", word, &at) != SW_OK)
        return ps->status;
    const sw_scene *sc = sw_scene_find(word);
    if (!sc) {
        char names[300], near[80];
        sw_scene_names(names, sizeof names);
        return FAIL(ps, at, "unknown scene '%s'%s; expected one of %s", word,
                    sw_lp_suggest("", word, sw_lp_scene_at, NULL, sw_scene_count(), near, sizeof near), names);
    }
    ps->at_scene.col = sw_lp_col(ps, at);
    ps->scene = sc;
    /* Entries past the scene's parameters stay 0, so two setups of one
     * scene compare equal as whole arrays. */
    memset(ps->p, 0, sizeof ps->p);
    sw_scene_defaults(sc, ps->p);
    ps->method = sw_integrator_find(sc->integrator);
    ps->dt = sc->dt;
    ps->rebuild = 1;
    pg->restart = 1;
    if (!ps->method)
        return FAIL(ps, at, "scene '%s' names a default integrator '%s' that does not exist", sc->name,
                    sc->integrator);
    return SW_OK;
}
/* @set NAME=VALUE [NAME=VALUE ...], spaces around '=' allowed. */
static int d_set(sw_lp_parser *ps, size_t pos)
{
    if (sw_lp_need_scene(ps, "@set") != SW_OK)
        return ps->status;
    const sw_scene *sc = ps->scene;
    if (!ps->at_set.line) {
        ps->at_set.line = ps->line;
        ps->at_set.col = 1;
    }
    int count = 0;
    sw_kv kv;
    for (int got; (got = sw_kv_next(ps->ln, ps->lnlen, pos, &kv)) != 0;) {
        size_t name_at = kv.name_at, val_at = kv.value_at;
        char name[SW_LESSON_NAME_MAX];
        if (sw_lp_field_word(ps, name_at, kv.name_len, name) != SW_OK)
            return ps->status;
        if (got < 0 || name[0] == '\0')
            return FAIL(ps, name[0] ? kv.eq_at : name_at, "@set wants NAME=VALUE; expected '=' after '%s'",
                        name[0] ? name : "the parameter name");
        char val[SW_LESSON_NAME_MAX];
        if (sw_lp_field_word(ps, val_at, kv.value_len, val) != SW_OK)
            return ps->status;
        int idx = sw_scene_param_index(sc, name);
        if (idx < 0) {
            char names[200];
            sw_scene_param_names(sc, names, sizeof names);
            return FAIL(ps, name_at, "scene '%s' has no parameter '%s'; expected one of %s", sc->name,
                        name, names);
        }
        double v;
        if (sw_parse_double(val, &v) != SW_OK)
            return FAIL(ps, val_at, "'%s' is not a number; expected %s = a number in [%g, %g]",
                        val[0] ? val : "(nothing)", name, sc->params[idx].min, sc->params[idx].max);
        char why[SW_ERRLEN];
        if (sw_scene_check_value(sc, idx, v, why, sizeof why) != SW_OK)
            return FAIL(ps, val_at, "%s", why);
        if (ps->set_line[idx])
            return FAIL(ps, name_at, "'%s' is set twice on this page (also on line %d); expected "
                        "each parameter once", name, ps->set_line[idx]);
        ps->set_line[idx] = ps->line;
        ps->p[idx] = v;
        ps->rebuild = 1;
        sw_lp_page(ps)->restart = 1;
        pos = kv.end;
        count++;
    }
    if (!count)
        return FAIL(ps, ps->lnlen, "@set needs NAME=VALUE; expected e.g. '@set %s=%g'",
                    sc->nparams ? sc->params[0].name : "k", sc->nparams ? sc->params[0].def : 1.0);
    return SW_OK;
}

static int d_integrator(sw_lp_parser *ps, size_t pos)
{
    if (sw_lp_need_scene(ps, "@integrator") != SW_OK || sw_lp_once(ps, &ps->at_integrator, "@integrator") != SW_OK)
        return ps->status;
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (sw_lp_one_word(ps, pos, "@integrator", "an integrator name", word, &at) != SW_OK)
        return ps->status;
    if (sw_lp_find_integrator(ps, word, at, &ps->method) != SW_OK)
        return ps->status;
    ps->at_integrator.col = sw_lp_col(ps, at);
    sw_lp_page(ps)->restart = 1;
    return SW_OK;
}

/* The directive's one word as a number in [lo, hi], into *out. */
static int one_number(sw_lp_parser *ps, size_t pos, const char *dir, const char *what, double lo, double hi,
                      double *out)
{
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (sw_lp_one_word(ps, pos, dir, what, word, &at) != SW_OK)
        return ps->status;
    double v;
    if (sw_parse_double(word, &v) != SW_OK || !(v >= lo && v <= hi))
        return FAIL(ps, at, "%s '%s' is not allowed; expected a number in [%g, %g]", dir, word, lo, hi);
    *out = v;
    return SW_OK;
}

static int d_dt(sw_lp_parser *ps, size_t pos)
{
    if (sw_lp_need_scene(ps, "@dt") != SW_OK || sw_lp_once(ps, &ps->at_dt, "@dt") != SW_OK)
        return ps->status;
    if (one_number(ps, pos, "@dt", "a step size in seconds", SW_DT_MIN, SW_DT_MAX, &ps->dt) != SW_OK)
        return ps->status;
    sw_lp_page(ps)->restart = 1;
    return SW_OK;
}

static int d_compare(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    if (sw_lp_need_scene(ps, "@compare") != SW_OK || sw_lp_once(ps, &ps->at_compare, "@compare") != SW_OK)
        return ps->status;
    size_t start, len;
    int n = 0;
    while (sw_lp_next_field(ps, &pos, &start, &len)) {
        char word[SW_LESSON_NAME_MAX];
        if (sw_lp_field_word(ps, start, len, word) != SW_OK)
            return ps->status;
        if (n == 0 && (strcmp(word, "on") == 0 || strcmp(word, "off") == 0)) {
            pg->compare = word[1] == 'n';
            size_t extra, elen;
            if (sw_lp_next_field(ps, &pos, &extra, &elen))
                return FAIL(ps, extra, "unexpected '%.*s' after @compare %s; expected nothing more",
                            sw_lp_clip(ps->ln + extra, elen, 40), ps->ln + extra, word);
            return SW_OK;
        }
        if (n == SW_LESSON_MAX_COMPARE)
            return FAIL(ps, start, "too many methods in @compare; expected at most %d",
                        SW_LESSON_MAX_COMPARE);
        const sw_integrator *m;
        if (sw_lp_find_integrator(ps, word, start, &m) != SW_OK)
            return ps->status;
        for (int k = 0; k < n; k++)
            if (pg->compare_with[k] == m)
                return FAIL(ps, start, "'%s' is named twice in @compare; expected distinct methods", word);
        if (n == 0)
            ps->at_compare.col = sw_lp_col(ps, start);
        pg->compare_with[n++] = m;
    }
    if (!n)
        return FAIL(ps, ps->lnlen, "@compare needs a value; expected on, off, or the methods to run "
                    "beside the main one (e.g. '@compare rk4')");
    pg->ncompare_with = n;
    pg->compare = 1;
    return SW_OK;
}

/* Lock names for suggestions: the groups, then "all". */
static const char *lock_name_at(const void *ctx, int i)
{
    (void)ctx;
    return i < SW_LOCK_NGROUPS ? sw_lock_name((sw_lock_mask)1 << i) : "all";
}

/* @lock / @unlock: lock groups by name ("integrator"), "all", or a key
 * ("+", "space"), all resolved through the one list of controls. */
static int d_lock(sw_lp_parser *ps, size_t pos, int lock)
{
    const char *directive = lock ? "@lock" : "@unlock";
    sw_lesson_page *pg = sw_lp_page(ps);
    size_t start, len;
    int n = 0;
    while (sw_lp_next_field(ps, &pos, &start, &len)) {
        char word[SW_LESSON_NAME_MAX];
        if (sw_lp_field_word(ps, start, len, word) != SW_OK)
            return ps->status;
        sw_lock_mask bit = sw_lock_find(word);
        if (!bit) {
            char near[80], allowed[300];
            sw_lock_describe(allowed, sizeof allowed);
            return FAIL(ps, start, "%s: '%s' is not a control%s; expected %s", directive, word,
                        sw_lp_suggest("", word, lock_name_at, NULL, SW_LOCK_NGROUPS + 1, near, sizeof near),
                        allowed);
        }
        if (lock)
            ps->locked |= bit;
        else
            ps->locked &= ~bit;
        n++;
    }
    if (!n) {
        if (lock)
            return FAIL(ps, ps->lnlen, "@lock needs the controls to lock; expected e.g. '@lock integrator dt'");
        ps->locked = 0;
    }
    pg->locked = ps->locked;
    return SW_OK;
}
/* ---- text directives ---------------------------------------------------------------------- */

/* The rest of the line after the directive name, trimmed; fails when empty. */
static int rest_text(sw_lp_parser *ps, size_t pos, const char *directive, const char *expected, const char **text,
                     size_t *len, size_t *at)
{
    while (pos < ps->lnlen && sw_lp_blank(ps->ln[pos]))
        pos++;
    if (pos >= ps->lnlen)
        return FAIL(ps, pos, "%s needs text; expected %s", directive, expected);
    *text = ps->ln + pos;
    *len = ps->lnlen - pos;
    *at = pos;
    return SW_OK;
}

static int d_hint(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    const char **slot = NULL;
    if (ps->hint_to == HINT_GOAL)
        slot = &pg->goals[pg->ngoals - 1].hint;
    else if (ps->hint_to == HINT_QUESTION)
        slot = &pg->question.hint;
    if (!slot)
        return FAIL(ps, 0, "@hint must follow the @goal (or @question) it helps with");
    if (*slot)
        return FAIL(ps, 0, "this %s already has a hint; expected one @hint per goal",
                    ps->hint_to == HINT_GOAL ? "goal" : "question");
    const char *text;
    size_t len, at;
    if (rest_text(ps, pos, "@hint", "what to press or try, e.g. '@hint Press i until the status "
                  "line says rk4.'", &text, &len, &at) != SW_OK)
        return ps->status;
    *slot = sw_lp_strdup(ps->out, text, len);
    return *slot ? SW_OK : sw_lp_oom(ps);
}

static int d_question(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    if (pg->question.text)
        return FAIL(ps, 0, "second @question on this page (the first is on line %d); expected one "
                    "question per page", pg->question.line);
    const char *text;
    size_t len, at;
    if (rest_text(ps, pos, "@question", "the question, then @answer lines and @correct", &text, &len,
                  &at) != SW_OK)
        return ps->status;
    pg->question.text = sw_lp_strdup(ps->out, text, len);
    if (!pg->question.text)
        return sw_lp_oom(ps);
    pg->question.line = ps->line;
    ps->at_question = (sw_lp_where){ ps->line, 1 };
    ps->hint_to = HINT_QUESTION;
    return SW_OK;
}

/* @answer X) TEXT | FEEDBACK — split at the first " | ". */
static int d_answer(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_question *q = &sw_lp_page(ps)->question;
    if (!q->text)
        return FAIL(ps, 0, "@answer before any @question; expected '@question TEXT' first");
    if (q->nanswers == SW_LESSON_MAX_ANSWERS)
        return FAIL(ps, 0, "too many answers; expected at most %d (a) to %c))", SW_LESSON_MAX_ANSWERS,
                    'a' + SW_LESSON_MAX_ANSWERS - 1);
    char want = (char)('a' + q->nanswers);
    while (pos < ps->lnlen && sw_lp_blank(ps->ln[pos]))
        pos++;
    size_t at = pos;
    char c = pos < ps->lnlen ? ps->ln[pos] : '\0';
    if (c >= 'A' && c <= 'Z')
        c = (char)(c - 'A' + 'a');
    if (c != want || pos + 1 >= ps->lnlen || ps->ln[pos + 1] != ')')
        return FAIL(ps, at, "expected '%c)' to start this answer (answers go a), b), c), ... in order)", want);
    pos += 2;
    const char *text;
    size_t len, text_at;
    if (rest_text(ps, pos, "@answer", "'X) ANSWER | FEEDBACK'", &text, &len, &text_at) != SW_OK)
        return ps->status;
    if (text[0] == '|')
        return FAIL(ps, text_at, "the answer text is empty; expected '%c) ANSWER | FEEDBACK'", want);
    size_t bar = 0;
    while (bar + 2 < len && !(sw_lp_blank(text[bar]) && text[bar + 1] == '|' && sw_lp_blank(text[bar + 2])))
        bar++;
    if (bar + 2 >= len) {
        if (len >= 2 && text[len - 1] == '|')
            return FAIL(ps, ps->lnlen, "the feedback after '|' is empty; expected what the student is "
                        "told on choosing %c)", want);
        return FAIL(ps, ps->lnlen, "expected ' | FEEDBACK' after the answer: what the student is told "
                    "on choosing it");
    }
    size_t tlen = bar, fb = bar + 3;
    while (fb < len && sw_lp_blank(text[fb]))
        fb++;
    while (tlen && sw_lp_blank(text[tlen - 1]))
        tlen--;
    sw_lesson_choice *a = &q->answers[q->nanswers];
    a->letter = want;
    a->text = sw_lp_strdup(ps->out, text, tlen);
    a->feedback = sw_lp_strdup(ps->out, text + fb, len - fb);
    if (!a->text || !a->feedback)
        return sw_lp_oom(ps);
    q->nanswers++;
    ps->hint_to = HINT_QUESTION;
    return SW_OK;
}

static int d_correct(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_question *q = &sw_lp_page(ps)->question;
    if (!q->text)
        return FAIL(ps, 0, "@correct before any @question; expected '@question TEXT' first");
    if (sw_lp_once(ps, &ps->at_correct, "@correct") != SW_OK)
        return ps->status;
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (sw_lp_one_word(ps, pos, "@correct", "the letter of the right answer", word, &at) != SW_OK)
        return ps->status;
    char c = word[0];
    if (c >= 'A' && c <= 'Z')
        c = (char)(c - 'A' + 'a');
    if (word[1] == ')' && word[2] == '\0')
        word[1] = '\0';
    if (word[1] != '\0' || c < 'a' || c >= 'a' + SW_LESSON_MAX_ANSWERS)
        return FAIL(ps, at, "@correct takes one letter (a, b, ...), not '%s'", word);
    ps->correct = c - 'a';
    ps->at_correct.col = sw_lp_col(ps, at);
    return SW_OK;
}

/* ---- lines ------------------------------------------------------------------------------------------ */

static int d_ghost(sw_lp_parser *ps, size_t pos) { return sw_lp_on_off(ps, pos, "@ghost", &sw_lp_page(ps)->ghost); }
static void i_ghost(sw_lesson_page *pg) { pg->ghost = -1; }

static int d_pause(sw_lp_parser *ps, size_t pos) { return sw_lp_on_off(ps, pos, "@pause", &sw_lp_page(ps)->paused); }
static void i_pause(sw_lesson_page *pg) { pg->paused = -1; }

/* @events locate|step: how the page's sims meet contacts and crossings. */
static int d_events(sw_lp_parser *ps, size_t pos)
{
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (sw_lp_one_word(ps, pos, "@events", "locate or step", word, &at) != SW_OK)
        return ps->status;
    if (strcmp(word, "locate") == 0)
        sw_lp_page(ps)->events = 1;
    else if (strcmp(word, "step") == 0)
        sw_lp_page(ps)->events = 0;
    else
        return FAIL(ps, at, "@events takes locate or step, not '%s'", word);
    return SW_OK;
}
static void i_events(sw_lesson_page *pg) { pg->events = -1; }

static int d_reset(sw_lp_parser *ps, size_t pos)
{
    size_t start, len;
    if (sw_lp_next_field(ps, &pos, &start, &len))
        return FAIL(ps, start, "@reset takes nothing after it");
    sw_lp_page(ps)->restart = 1;
    return SW_OK;
}

/* @speed X: simulated seconds per wall second on entering the page. */
static int d_speed(sw_lp_parser *ps, size_t pos)
{
    if (one_number(ps, pos, "@speed", "simulated seconds per wall second", SW_LESSON_SPEED_MIN,
                   SW_LESSON_SPEED_MAX, &sw_lp_page(ps)->speed) != SW_OK)
        return ps->status;
    return SW_OK;
}

/* @until T: the run stops at t = T (its last step cut to land there) and
 * pauses; u runs there at once. */
static int d_until(sw_lp_parser *ps, size_t pos)
{
    return one_number(ps, pos, "@until", "a stop time in seconds", SW_DT_MIN, SW_LESSON_UNTIL_MAX,
                      &sw_lp_page(ps)->until);
}

/* box=X0,Y0,X1,Y1: four numbers, X0 < X1 and Y0 < Y1, each within
 * ±SW_LESSON_BOX_MAX. */
static int view_box(sw_lp_parser *ps, size_t start, const char *word, double box[4])
{
    const char *p = word + 4;
    int n = 0;
    for (; n < 4; n++) {
        const char *end = strchr(p, ',');
        char field[SW_LESSON_NAME_MAX];
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if ((n < 3) != (end != NULL) || len == 0 || len >= sizeof field)
            break;
        memcpy(field, p, len);
        field[len] = '\0';
        if (sw_parse_double(field, &box[n]) != SW_OK || !(fabs(box[n]) <= SW_LESSON_BOX_MAX))
            break;
        p = end ? end + 1 : p + len;
    }
    if (n != 4)
        return FAIL(ps, start, "@view %s: expected box=X0,Y0,X1,Y1 (four numbers in [-1e6, 1e6], no spaces)", word);
    if (!(box[0] < box[2] && box[1] < box[3]))
        return FAIL(ps, start, "@view %s: expected X0 < X1 and Y0 < Y1 (the lower left corner first)", word);
    return SW_OK;
}

/* @view WORD...: scene, phase or region (what the picture shows); fixed or
 * follow (the camera); overlay or lanes (compare's layout); graph or
 * nograph (the energy/error graph); zoom=X; box=X0,Y0,X1,Y1 (the part of
 * the world the camera shows: what the page is about). */
static int d_view(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    size_t start, len;
    int n = 0;
    while (sw_lp_next_field(ps, &pos, &start, &len)) {
        char word[SW_LESSON_NAME_MAX];
        if (sw_lp_field_word(ps, start, len, word) != SW_OK)
            return ps->status;
        double z;
        if (strcmp(word, "scene") == 0 || strcmp(word, "phase") == 0 || strcmp(word, "region") == 0)
            pg->view = word[0] == 's' ? SW_LESSON_VIEW_SCENE : word[0] == 'p' ? SW_LESSON_VIEW_PHASE
                                                                            : SW_LESSON_VIEW_REGION;
        else if (strcmp(word, "fixed") == 0 || strcmp(word, "follow") == 0)
            pg->follow = word[1] == 'o';
        else if (strcmp(word, "overlay") == 0 || strcmp(word, "lanes") == 0)
            pg->lanes = word[0] == 'l';
        else if (strcmp(word, "graph") == 0 || strcmp(word, "nograph") == 0)
            pg->graph = word[0] == 'g';
        else if (strncmp(word, "zoom=", 5) == 0) {
            if (sw_parse_double(word + 5, &z) != SW_OK || !(z >= 1.0 / 64 && z <= 4096))
                return FAIL(ps, start, "@view %s: expected zoom=X with X in [1/64, 4096]", word);
            pg->zoom = z;
        } else if (strncmp(word, "box=", 4) == 0) {
            if (view_box(ps, start, word, pg->box) != SW_OK)
                return ps->status;
            pg->has_box = 1;
        } else
            return FAIL(ps, start, "@view: '%s' is not a view; expected scene, phase, region, fixed, follow, "
                        "overlay, lanes, graph, nograph, zoom=X or box=X0,Y0,X1,Y1", word);
        n++;
    }
    if (!n)
        return FAIL(ps, ps->lnlen, "@view needs a view; expected e.g. '@view phase' or '@view region zoom=2'");
    return SW_OK;
}

static int d_lock_on(sw_lp_parser *ps, size_t pos) { return d_lock(ps, pos, 1); }
static int d_lock_off(sw_lp_parser *ps, size_t pos) { return d_lock(ps, pos, 0); }

static void i_view(sw_lesson_page *pg) { pg->view = pg->follow = pg->lanes = pg->graph = -1; }
static void i_compare(sw_lesson_page *pg) { pg->compare = -1; }

/* The directives: one line each. once: at most one per page (the
 * dispatcher checks); init: the page's "leave as is" values before any
 * directive (NULL: zero). A new directive is its function(s) here, a line
 * below, its page field in lesson.h and what the runner does with it
 * (docs/architecture.md). */
static const struct directive {
    const char *name;
    int (*run)(sw_lp_parser *ps, size_t pos);
    int once;
    void (*init)(sw_lesson_page *pg);
} directives[] = {
    { .name = "scene", .run = d_scene },
    { .name = "set", .run = d_set },
    { .name = "integrator", .run = d_integrator },
    { .name = "dt", .run = d_dt },
    { .name = "compare", .run = d_compare, .init = i_compare },
    { .name = "ghost", .run = d_ghost, .once = 1, .init = i_ghost },
    { .name = "pause", .run = d_pause, .once = 1, .init = i_pause },
    { .name = "reset", .run = d_reset, .once = 1 },
    { .name = "speed", .run = d_speed, .once = 1 },
    { .name = "until", .run = d_until, .once = 1 },
    { .name = "view", .run = d_view, .once = 1, .init = i_view },
    { .name = "events", .run = d_events, .once = 1, .init = i_events },
    { .name = "lock", .run = d_lock_on },
    { .name = "unlock", .run = d_lock_off },
    { .name = "goal", .run = sw_lp_goal },
    { .name = "hint", .run = d_hint },
    { .name = "question", .run = d_question },
    { .name = "answer", .run = d_answer },
    { .name = "correct", .run = d_correct },
};

#define NDIRECTIVES ((int)(sizeof directives / sizeof directives[0]))
_Static_assert(NDIRECTIVES <= SW_LP_DIRECTIVES_MAX, "parse.h's SW_LP_DIRECTIVES_MAX: room for every directive");

void sw_lp_page_defaults(sw_lesson_page *pg)
{
    for (int k = 0; k < NDIRECTIVES; k++)
        if (directives[k].init)
            directives[k].init(pg);
}

static const char *directive_name_at(const void *ctx, int i)
{
    (void)ctx;
    return directives[i].name;
}

const char *sw_lp_directive_name(int i)
{
    return i >= 0 && i < NDIRECTIVES ? directives[i].name : NULL;
}

int sw_lp_directive(sw_lp_parser *ps, size_t at)
{
    if (!sw_lp_page(ps))
        return FAIL(ps, at, "directive before the first page; expected '--- PAGE TITLE' first");
    size_t i = at + 1;
    while (i < ps->lnlen && ((ps->ln[i] >= 'a' && ps->ln[i] <= 'z') || (ps->ln[i] >= 'A' && ps->ln[i] <= 'Z')))
        i++;
    char name[SW_LESSON_NAME_MAX];
    size_t nlen = i - at - 1;
    if (nlen >= sizeof name)
        nlen = sizeof name - 1;
    memcpy(name, ps->ln + at + 1, nlen);
    name[nlen] = '\0';
    if (i < ps->lnlen && !sw_lp_blank(ps->ln[i]))
        return FAIL(ps, i, "expected a space after '@%s'", name);
    if (ps->hint_to == HINT_QUESTION && strcmp(name, "hint") != 0 && strcmp(name, "answer") != 0 &&
        strcmp(name, "correct") != 0)
        ps->hint_to = HINT_NONE;
    if (ps->hint_to == HINT_GOAL && strcmp(name, "hint") != 0)
        ps->hint_to = HINT_NONE;
    for (int k = 0; k < NDIRECTIVES; k++)
        if (strcmp(name, directives[k].name) == 0) {
            char what[SW_LESSON_NAME_MAX + 1];
            snprintf(what, sizeof what, "@%s", name);
            if (directives[k].once && sw_lp_once(ps, &ps->seen[k], what) != SW_OK)
                return ps->status;
            return directives[k].run(ps, i);
        }
    char near[80], known[16 * NDIRECTIVES] = "";
    for (int k = 0, used = 0; k < NDIRECTIVES && used < (int)sizeof known; k++) /* from the table */
        used += snprintf(known + used, sizeof known - (size_t)used, "%s@%s", k ? " " : "", directives[k].name);
    return FAIL(ps, at, "unknown directive '@%s'%s; expected one of %s", name,
                sw_lp_suggest("@", name, directive_name_at, NULL, NDIRECTIVES, near, sizeof near), known);
}
