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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "app/runner.h"
#include "canvas_help.h"
#include "lesson/lesson.h"
#include "symbols_help.h"

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
                sym_form_of(named, form, sizeof form);
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
                int sp, sl = sym_place_of(e, n, s->file, s->page, key, &sp);
                int pointed = li == 0 && sl == 0 && pi < sp && sp <= 2 && sym_first_page_points();
                ck_assert_msg(sl < li || (sl == li && sp <= pi) || pointed, "%s page %d (%s): '%s' is on screen "
                              "before %s's page '%s' explains it", e[li].file, pi + 1, when, text, s->file, s->page);
            }
    }
}

/* The page as it opens and after a second of play. */
static void page_fields(sw_runner *r, sw_app *a, const sw_lesson_entry *e, int n, int lesson, int page, void *ctx)
{
    (void)ctx;
    sym_read_first_page(r, lesson, page);
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
    sym_form_of("stiffness·dt 0.5 of limit 2.83", out, sizeof out);
    ck_assert_str_eq(out, "stiffness·dt # of limit #");
    sym_form_of("E-1.45e+03%", out, sizeof out);
    ck_assert_str_eq(out, "E#%");
    sym_form_of("[###.......]", out, sizeof out);
    ck_assert_str_eq(out, "[#]");
    sym_form_of("err 5.2e-08 m", out, sizeof out);
    ck_assert_str_eq(out, "err # m");
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
    suite_add_tcase(s, tc);
    return s;
}
