/* Every page names every key its goals ask for, in its own text (not only
 * in a hint): a page that asks for the ghost says g, one that asks for a
 * smaller Δt says -, and so on. No play key is a capital A-F, so answering
 * a question never toggles anything. */
#include <check.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lesson/lesson.h"
#include "stepwise/stepwise.h"

static char *err_buf(void)
{
    static char buf[512];
    return buf;
}

/* Whether text names key as a word of its own: "press g", "(g)", "g:". */
static int names_key(const char *text, const char *key)
{
    size_t k = strlen(key);
    for (const char *p = strstr(text, key); p; p = strstr(p + 1, key)) {
        char before = p == text ? ' ' : p[-1], after = p[k];
        int b = before == ' ' || before == '(' || before == '\n' || before == '\'' || before == '"';
        int a = after == '\0' || after == ' ' || after == ')' || after == ',' || after == '.' || after == ':' ||
                after == ';' || after == '\n' || after == '\'' || after == '"';
        if (b && a)
            return 1;
    }
    return 0;
}

static int page_names(const sw_lesson_page *pg, const char *key)
{
    for (int b = 0; b < pg->nblocks; b++)
        if (names_key(pg->blocks[b].text, key))
            return 1;
    return pg->question.text && names_key(pg->question.text, key);
}

/* The keys a goal needs (any one of them named will do). */
static int keys_for(const sw_lesson_page *pg, const sw_lesson_goal *g, const char **keys)
{
    int n = 0;
    switch (g->var) {
    case SW_LV_GHOST: if (g->value) keys[n++] = "g"; break;
    case SW_LV_COMPARE: if (g->value) keys[n++] = "c"; break;
    case SW_LV_PAUSED: keys[n++] = "space"; break;
    case SW_LV_RECORDED: keys[n++] = "R"; break;
    case SW_LV_PHASE: keys[n++] = "v"; break;
    case SW_LV_REGION: keys[n++] = "s"; break;
    case SW_LV_PARAM: keys[n++] = "p"; break;
    case SW_LV_DT:
        if (!(pg->locked & SW_LOCK_DT))
            keys[n++] = g->op == SW_LOP_GE || g->op == SW_LOP_GT ? "+" : "-";
        break;
    case SW_LV_ERROR_RATIO: keys[n++] = "-", keys[n++] = "+"; break;
    case SW_LV_INTEGRATOR:
        if (!(pg->locked & SW_LOCK_INTEGRATOR) && g->op != SW_LOP_NE) {
            keys[n++] = "i";
            static const char *const digits[] = { "1", "2", "3", "4", "5", "6", "7", "8", "9", "0" };
            for (int d = 0; d < 10; d++)
                keys[n++] = digits[d];
        }
        break;
    case SW_LV_STEPS:
        if (pg->paused == 1)
            keys[n++] = ".";
        break;
    case SW_LV_T:
        if (pg->paused == 1)
            keys[n++] = "space";
        break;
    default:
        break;
    }
    return n;
}

START_TEST(pages_name_their_keys)
{
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN], missing[4096] = "";
    size_t used = 0;
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    ck_assert_int_ge(n, 10);
    for (int i = 0; i < n; i++) {
        sw_lesson l;
        ck_assert_msg(sw_lesson_load(e[i].path, &l, err, sizeof err) == SW_OK, "%s", err);
        for (int p = 0; p < l.npages; p++)
            for (int g = 0; g < l.pages[p].ngoals; g++) {
                const char *keys[16];
                int k = keys_for(&l.pages[p], &l.pages[p].goals[g], keys), named = k == 0;
                for (int j = 0; j < k; j++)
                    named |= page_names(&l.pages[p], keys[j]);
                if (!named && used < sizeof missing)
                    used += (size_t)snprintf(missing + used, sizeof missing - used, "\n  %s page %d '%s': "
                                             "goal on line %d needs key '%s' named in the page's text",
                                             e[i].file, p + 1, l.pages[p].title, l.pages[p].goals[g].line, keys[0]);
            }
        sw_lesson_free(&l);
    }
    sw_lesson_list_free(e, n);
    ck_assert_msg(used == 0, "pages that ask for a key without naming it:%s", missing);
}
END_TEST

START_TEST(answers_never_play)
{
    int count;
    const sw_control *c = sw_controls(&count);
    for (int i = 0; i < count; i++) {
        if (c[i].context == SW_CTX_LESSON && c[i].action == SW_ACT_ANSWER)
            continue;
        for (int k = 0; c[i].keys[k]; k++)
            ck_assert_msg(!(c[i].keys[k] >= SW_ANSWER_FIRST && c[i].keys[k] < SW_ANSWER_FIRST + SW_LESSON_MAX_ANSWERS),
                          "'%s' uses the answer key %c", c[i].name, c[i].keys[k]);
    }
    /* and the check can fail: a page asking for the ghost without naming g */
    sw_lesson l;
    const char *text = "title: T\n--- P\n@scene spring\nTurn on the ghost.\n@goal ghost\n@hint press g\n";
    ck_assert_int_eq(sw_lesson_parse("t", text, strlen(text), &l, err_buf(), 512), SW_OK);
    const char *keys[16];
    ck_assert_int_eq(keys_for(&l.pages[0], &l.pages[0].goals[0], keys), 1);
    ck_assert(!page_names(&l.pages[0], keys[0]));
    sw_lesson_free(&l);
}
END_TEST

Suite *make_lesson_keys_suite(void);
Suite *make_lesson_keys_suite(void)
{
    Suite *s = suite_create("lesson_keys");
    TCase *tc = tcase_create("keys");
    tcase_add_test(tc, pages_name_their_keys);
    tcase_add_test(tc, answers_never_play);
    suite_add_tcase(s, tc);
    return s;
}
