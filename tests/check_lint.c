/* Lesson lint: `lesson --check` refuses a goal that can never be met on its
 * page (outside its quantity's range, contradicting another goal, another
 * scene, held by a lock) and accepts every goal a student can meet. The
 * files in tests/data/lessons_bad/ are pinned in check_lesson.c; these
 * cases vary one thing at a time. */
#include <check.h>
#include <stdio.h>
#include <string.h>

#include "lesson/lesson.h"

/* A one-page spring lesson with extra directives and goals (each goal gets a hint). */
static int lint(const char *directives, const char *const *goals, int ngoals, char *err, size_t errlen)
{
    char text[2048];
    int n = snprintf(text, sizeof text, "title: L\n--- P\n@scene spring\n%s\nText.\n", directives);
    for (int i = 0; i < ngoals; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, "@goal %s\n@hint h\n", goals[i]);
    sw_lesson l;
    int rc = sw_lesson_parse("t.lesson", text, strlen(text), &l, err, errlen);
    sw_lesson_free(&l);
    return rc;
}

START_TEST(lint_refuses_goals_never_met)
{
    static const struct {
        const char *directives, *goals[3], *says;
    } cases[] = {
        { "", { "t < 0" }, "t is never below 0" },
        { "", { "evals < 0" }, "evals is never below 0" },
        { "", { "error < 0" }, "error is never below 0" },
        { "", { "|energy_drift| < -1" }, "|energy_drift| is never below 0" },
        { "", { "dt < 1e-10" }, "dt stays in [1e-09, 1000]" },
        { "", { "param m near 1e9 within 1" }, "m stays in" },
        { "", { "t > 5", "t < 4" }, "contradicts goal 't > 5'" },
        { "", { "t >= 2", "t near 1 within 0.5" }, "contradicts goal 't >= 2'" },
        { "", { "t == 1", "t != 1" }, "contradicts goal 't = 1'" },
        { "", { "steps > 5", "steps < 6" }, "no steps meets both" },         /* whole numbers */
        { "", { "t > 1", "t < 3", "t > 4" }, "contradicts goal 't < 3'" },
        { "", { "compare", "compare == off" }, "contradicts goal 'compare is on'" },
        { "", { "scene in orbit, chain" }, "this page shows scene 'spring'" },
        { "", { "scene != spring" }, "this page shows scene 'spring'" },
        { "", { "integrator == rk4", "integrator != rk4" }, "contradicts" },
        { "@pause on\n@lock run", { "steps >= 1" }, "time never moves" },
        { "@pause on\n@lock run", { "blown" }, "time never moves" },
        { "@pause on\n@lock run", { "paused == off" }, "pause is locked" },
        { "@compare off\n@lock compare", { "compare" }, "compare is locked" },
        { "@ghost on\n@lock ghost", { "ghost == off" }, "the ghost is locked" },
        { "@set k=4\n@lock params", { "param k > 5" }, "page sets k = 4" },
        { "@lock record", { "recorded" }, "recording is locked" },
        { "@dt 0.1", { "dt == 0.3" }, "dt is 0.1 x 2^k" },                  /* + and - double and halve */
        { "@dt 0.1", { "dt > 0.3", "dt < 0.35" }, "together with the dt goals above it" },
        { "@lock integrator", { "accepted > 0" }, "takes fixed steps" },
        { "@lock dt", { "error_ratio near 2 within 0.5" }, "needs the error at two step sizes" },
    };
    char err[SW_LESSON_ERRLEN];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int n = 0;
        while (n < 3 && cases[i].goals[n])
            n++;
        ck_assert_msg(lint(cases[i].directives, cases[i].goals, n, err, sizeof err) == SW_EINVAL,
                      "case %zu (%s) passed lint", i, cases[i].goals[0]);
        ck_assert_msg(strstr(err, "can never be met") && strstr(err, cases[i].says), "case %zu: '%s' lacks '%s'", i,
                      err, cases[i].says);
        /* the message names the last goal's line and its expression's column */
        char where[32];
        snprintf(where, sizeof where, "t.lesson:%d:7: ", 6 + 2 * (n - 1) + (strchr(cases[i].directives, '\n') ? 1 : 0));
        ck_assert_msg(strncmp(err, where, strlen(where)) == 0, "case %zu: '%s' does not start '%s'", i, err, where);
    }
}
END_TEST

/* Lint must not refuse a goal a student can meet. */
START_TEST(lint_accepts_goals_that_can_be_met)
{
    static const struct {
        const char *directives, *goals[3];
    } cases[] = {
        { "", { "t <= 0" } },
        { "", { "t > 5", "t >= 5" } },
        { "", { "t > 1", "t < 3" } },
        { "", { "steps > 5", "steps < 7" } },
        { "@dt 62.5", { "dt >= 1000" } },
        { "", { "dt near 1.5e-9 within 5e-10" } }, /* 0.02 / 2^24 */
        { "", { "energy_drift < -1" } },           /* a drift can be negative */
        { "", { "t != 1", "t > 0.5" } },
        { "", { "scene == spring", "integrator in rk4, euler", "integrator != euler" } },
        { "", { "compare", "ghost == off" } },
        { "@pause on", { "t > 1" } },              /* space runs it */
        { "@pause on\n@lock dt", { "t > 1" } },
        { "@lock run", { "t > 1" } },              /* running unless the page pauses it */
        { "@pause on\n@lock run", { "t <= 0", "paused" } },
        { "@compare on\n@lock compare", { "compare" } },
        { "@set k=4\n@lock params", { "param k == 4" } },
        { "@lock all\n@unlock record", { "recorded" } },
        { "@dt 0.1", { "dt == 0.4" } },
        { "@dt 0.1", { "dt == 0.0125" } },
        { "@dt 0.1", { "dt > 0.3", "dt < 0.45" } },
        { "@integrator rk45\n@lock integrator", { "accepted > 10", "rejected >= 1" } },
        { "@lock integrator", { "rejected == 0" } },
        { "@lock dt", { "error < 1" } },
    };
    char err[SW_LESSON_ERRLEN];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int n = 0;
        while (n < 3 && cases[i].goals[n])
            n++;
        ck_assert_msg(lint(cases[i].directives, cases[i].goals, n, err, sizeof err) == SW_OK, "case %zu: %s", i,
                      err);
    }
}
END_TEST

Suite *make_lint_suite(void);
Suite *make_lint_suite(void)
{
    Suite *s = suite_create("lint");
    TCase *tc = tcase_create("lint");
    tcase_add_test(tc, lint_refuses_goals_never_met);
    tcase_add_test(tc, lint_accepts_goals_that_can_be_met);
    suite_add_tcase(s, tc);
    return s;
}
