/* Lesson files: every course lesson parses; every malformed file in
 * tests/data/lessons_bad/ fails with the expected FILE:LINE:COL; goals, answers
 * and observations behave as documented; hostile bytes give errors, never
 * crashes. Tests run from the repository root. */
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lesson/lesson.h"

#define LESSONS_DIR "lessons"
#define BAD_DIR "tests/data/lessons_bad"

/* Parse text as a lesson named "t.lesson"; returns the status. */
static int parse(const char *text, sw_lesson *l, char *err, size_t errlen)
{
    return sw_lesson_parse("t.lesson", text, strlen(text), l, err, errlen);
}

/* ---- the course ------------------------------------------------------------- */

START_TEST(course_lessons_all_parse)
{
    sw_lesson_entry *list;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list(LESSONS_DIR, &list, &n, err, sizeof err), SW_OK);
    /* The course is at least ten lessons, numbered in lecture order. */
    ck_assert_int_ge(n, 10);
    for (int i = 0; i < n; i++) {
        ck_assert_msg(list[i].title != NULL, "%s does not parse: %s", list[i].path, list[i].error);
        ck_assert_int_ge(list[i].npages, 3);
        if (i < 10) {
            char prefix[16];
            snprintf(prefix, sizeof prefix, "%02d-", i + 1);
            ck_assert_msg(strncmp(list[i].file, prefix, 3) == 0, "lesson %d is %s", i + 1, list[i].file);
        }
        if (i > 0)
            ck_assert_int_lt(strcmp(list[i - 1].file, list[i].file), 0);
    }
    sw_lesson_list_free(list, n);
}
END_TEST

/* Each page of the course gives the student something to do, and every goal
 * it asks for is one the page's scene can measure (the parser checks that). */
START_TEST(course_pages_have_text_and_hints)
{
    sw_lesson_entry *list;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list(LESSONS_DIR, &list, &n, err, sizeof err), SW_OK);
    int goals = 0, questions = 0;
    for (int i = 0; i < n; i++) {
        sw_lesson l;
        ck_assert_int_eq(sw_lesson_load(list[i].path, &l, err, sizeof err), SW_OK);
        ck_assert_ptr_nonnull(l.pages[0].scene);
        for (int p = 0; p < l.npages; p++) {
            const sw_lesson_page *pg = &l.pages[p];
            ck_assert_int_ge(pg->nblocks, 1);
            for (int g = 0; g < pg->ngoals; g++)
                ck_assert_msg(pg->goals[g].hint && *pg->goals[g].hint, "%s page %d goal %d", list[i].file, p + 1, g);
            goals += pg->ngoals;
            questions += pg->question.text != NULL;
        }
        sw_lesson_free(&l);
    }
    ck_assert_int_ge(goals, 30);
    ck_assert_int_ge(questions, 10);
    sw_lesson_list_free(list, n);
}
END_TEST

/* The authoring guide's example is a valid lesson. */
START_TEST(readme_example_parses)
{
    FILE *f = fopen(LESSONS_DIR "/README.md", "r");
    ck_assert_ptr_nonnull(f);
    static char buf[65536];
    size_t len = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[len] = '\0';
    const char *start = strstr(buf, "```\n# Lines starting with # are comments.");
    ck_assert_ptr_nonnull(start);
    start += 4;
    const char *end = strstr(start, "```");
    ck_assert_ptr_nonnull(end);
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(sw_lesson_parse("README.md", start, (size_t)(end - start), &l, err, sizeof err) == SW_OK,
                  "%s", err);
    ck_assert_int_eq(l.npages, 2);
    sw_lesson_free(&l);
}
END_TEST

/* ---- malformed files ------------------------------------------------------------ */

static const struct bad_case {
    const char *file;
    int line, col;
    const char *says;  /* a phrase the message must contain */
} bad_cases[] = {
    { "answer-no-feedback.lesson", 7, 20, "' | FEEDBACK'" },
    { "answer-order.lesson", 7, 9, "expected 'a)'" },
    { "build-refuses.lesson", 5, 1, "rest + stretch must be positive" },
    { "compare-flow.lesson", 5, 10, "needs a system with masses" },
    { "control-char.lesson", 5, 14, "control character 0x1B" },
    { "correct-missing-answer.lesson", 10, 10, "names no answer" },
    { "cr-inside.lesson", 5, 5, "carriage return (CR) without a line feed" },
    { "cr-only.lesson", 1, 18, "CR alone (classic Mac line endings)" },
    { "dt-range.lesson", 5, 5, "[1e-09, 1000]" },
    { "duplicate-dt.lesson", 7, 1, "second @dt" },
    { "empty.lesson", 1, 1, "empty file" },
    { "first-page-no-scene.lesson", 3, 1, "chooses no scene" },
    { "goal-bad-op.lesson", 6, 10, "'=>' is not an operator" },
    { "goal-contradicts.lesson", 8, 7, "contradicts goal 't > 5' (line 6)" },
    { "goal-dt-beyond-max.lesson", 6, 7, "dt stays in [1e-09, 1000]" },
    { "goal-dt-unreachable.lesson", 7, 7, "dt is 0.1 x 2^k" },
    { "goal-empty-range.lesson", 6, 7, "goal 't < 0' can never be met: t is never below 0" },
    { "goal-energy-vortex.lesson", 6, 8, "has no energy" },
    { "goal-energy-zero.lesson", 7, 7, "starts with zero energy" },
    { "goal-error-no-exact.lesson", 7, 7, "no exact solution with these parameters" },
    { "goal-integrators-clash.lesson", 8, 7, "contradicts goal 'integrator is rk4'" },
    { "goal-locked.lesson", 8, 7, "can never be met" },
    { "goal-no-hint.lesson", 8, 7, "has no hint" },
    { "goal-other-scene.lesson", 6, 7, "this page shows scene 'spring'" },
    { "goal-param-range.lesson", 6, 7, "k stays in [0.001, 1e+07]" },
    { "goal-paused-locked.lesson", 8, 7, "starts paused at t = 0 and pause and single step are locked" },
    { "goal-record-locked.lesson", 7, 7, "recording is locked on this page" },
    { "goal-steps-negative.lesson", 6, 7, "steps is never below 0" },
    { "goal-trailing.lesson", 6, 14, "unexpected 'and'" },
    { "goal-unknown-var.lesson", 6, 7, "unknown goal variable 'energy'" },
    { "hint-without-goal.lesson", 5, 1, "@hint must follow" },
    { "invalid-utf8.lesson", 5, 4, "invalid UTF-8" },
    { "lock-unknown.lesson", 5, 10, "did you mean 'speed'" },
    { "long-line.lesson", 5, 1001, "longer than 1000 bytes" },
    { "method-flow.lesson", 5, 13, "verlet cannot run scene 'vortex'" },
    { "near-without-within.lesson", 6, 25, "'within TOLERANCE'" },
    { "no-pages.lesson", 3, 1, "no pages" },
    { "no-title.lesson", 2, 1, "before the lesson's title" },
    { "nul-byte.lesson", 5, 3, "NUL byte" },
    { "page-no-text.lesson", 3, 1, "has no text" },
    { "param-goal-unknown.lesson", 6, 13, "(k, m, c, rest, stretch, g)" },
    { "param-range.lesson", 5, 8, "outside its range" },
    { "percent-misuse.lesson", 6, 13, "only goes with energy_drift" },
    { "question-no-correct.lesson", 6, 1, "no @correct" },
    { "scene-after-set.lesson", 8, 1, "@scene comes after @set" },
    { "second-title.lesson", 2, 1, "second title" },
    { "text-before-page.lesson", 2, 1, "text before the first page" },
    { "title-too-long.lesson", 1, 8, "longer than 80 characters" },
    { "too-many-goals.lesson", 22, 1, "at most 8" },
    { "unknown-directive.lesson", 6, 1, "did you mean '@integrator'" },
    { "unknown-integrator.lesson", 6, 13, "unknown integrator 'rk5'" },
    { "unknown-param.lesson", 5, 10, "no parameter 'omega'" },
    { "unknown-scene.lesson", 4, 8, "did you mean 'vortex'" },
    { "utf8-column.lesson", 6, 12, "expected a number" },
};

#define NBAD ((int)(sizeof bad_cases / sizeof bad_cases[0]))

START_TEST(bad_file_reports_line_and_column)
{
    const struct bad_case *c = &bad_cases[_i];
    char path[256], want[300], err[SW_LESSON_ERRLEN];
    snprintf(path, sizeof path, BAD_DIR "/%s", c->file);
    snprintf(want, sizeof want, "%s:%d:%d: ", path, c->line, c->col);
    sw_lesson l;
    int rc = sw_lesson_load(path, &l, err, sizeof err);
    ck_assert_int_eq(rc, SW_EINVAL);
    ck_assert_msg(strncmp(err, want, strlen(want)) == 0, "%s: got '%s', want prefix '%s'", c->file, err, want);
    ck_assert_msg(strstr(err, c->says) != NULL, "%s: '%s' lacks '%s'", c->file, err, c->says);
    /* A failed parse leaves nothing to free, and freeing it is safe. */
    ck_assert_int_eq(l.npages, 0);
    ck_assert_ptr_null(l.pages);
    sw_lesson_free(&l);
}
END_TEST

/* No malformed file goes untested: the table covers the directory. */
START_TEST(bad_dir_fully_covered)
{
    DIR *d = opendir(BAD_DIR);
    ck_assert_ptr_nonnull(d);
    struct dirent *de;
    int files = 0;
    while ((de = readdir(d)) != NULL) {
        if (de->d_name[0] == '.')
            continue;
        files++;
        int found = 0;
        for (int i = 0; i < NBAD; i++)
            found |= strcmp(bad_cases[i].file, de->d_name) == 0;
        ck_assert_msg(found, "%s/%s has no expected error in check_lesson.c", BAD_DIR, de->d_name);
    }
    closedir(d);
    ck_assert_int_eq(files, NBAD);
}
END_TEST

/* ---- files ---------------------------------------------------------------------- */

START_TEST(load_refuses_missing_directory_and_huge)
{
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_load(BAD_DIR "/no-such-file.lesson", &l, err, sizeof err), SW_EIO);
    ck_assert_ptr_nonnull(strstr(err, "no-such-file.lesson: cannot open"));
    ck_assert_int_eq(sw_lesson_load(BAD_DIR, &l, err, sizeof err), SW_EIO);
    ck_assert_ptr_nonnull(strstr(err, "is a directory"));

    char path[] = "/tmp/sw_lesson_big_XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    FILE *f = fdopen(fd, "w");
    ck_assert_ptr_nonnull(f);
    for (int i = 0; i <= SW_LESSON_MAX_BYTES / 64; i++)
        fputs("# a comment line that makes this file larger than the bound ....\n", f);
    fclose(f);
    ck_assert_int_eq(sw_lesson_load(path, &l, err, sizeof err), SW_EIO);
    ck_assert_ptr_nonnull(strstr(err, "at most 262144 bytes"));
    unlink(path);
}
END_TEST

START_TEST(list_sorts_and_reports_broken_files)
{
    char dir[] = "/tmp/sw_lesson_dir_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    const char *names[] = { "b.lesson", "a.lesson", ".hidden.lesson", "notes.txt" };
    const char *texts[] = { "title: B\n--- p\n@scene spring\nText.\n", "title: A\n--- p\nno scene\n",
                            "title: H\n--- p\n@scene spring\nx\n", "not a lesson" };
    char path[512];
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        FILE *f = fopen(path, "w");
        ck_assert_ptr_nonnull(f);
        fputs(texts[i], f);
        fclose(f);
    }
    sw_lesson_entry *list;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list(dir, &list, &n, err, sizeof err), SW_OK);
    ck_assert_int_eq(n, 2);
    ck_assert_str_eq(list[0].file, "a.lesson");
    ck_assert_ptr_null(list[0].title);
    ck_assert_ptr_nonnull(strstr(list[0].error, "a.lesson:2:1: the first page chooses no scene"));
    ck_assert_str_eq(list[1].file, "b.lesson");
    ck_assert_str_eq(list[1].title, "B");
    ck_assert_int_eq(list[1].npages, 1);
    sw_lesson_list_free(list, n);
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        unlink(path);
    }
    rmdir(dir);
    ck_assert_int_eq(sw_lesson_list("/nonexistent/lessons", &list, &n, err, sizeof err), SW_EIO);
}
END_TEST

/* ---- the format ----------------------------------------------------------------- */

START_TEST(prose_paragraphs_verbatim_escapes_crlf_bom)
{
    const char *text = "\xEF\xBB\xBFtitle: T\r\n--- First page ---\r\n@scene vortex\r\n"
                       "One line\r\nand the next.\r\n\r\n    x' = g(x)\r\n\tindented\r\n"
                       "\\@not a directive\r\n\\# not a comment\r\n# a comment\r\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_str_eq(l.title, "T");
    ck_assert_int_eq(l.npages, 1);
    const sw_lesson_page *pg = &l.pages[0];
    ck_assert_str_eq(pg->title, "First page");
    ck_assert_int_eq(pg->nblocks, 3);
    ck_assert_int_eq(pg->blocks[0].verbatim, 0);
    ck_assert_str_eq(pg->blocks[0].text, "One line and the next.");
    ck_assert_int_eq(pg->blocks[1].verbatim, 1);
    ck_assert_str_eq(pg->blocks[1].text, "    x' = g(x)\n        indented");
    ck_assert_str_eq(pg->blocks[2].text, "@not a directive # not a comment");
    ck_assert_int_eq(pg->blocks[2].line, 9);
    sw_lesson_free(&l);
}
END_TEST

START_TEST(settings_inherit_and_restart)
{
    const char *text = "title: T\n"
                       "--- One\n@scene spring\n@set k=100 c = 0\n@integrator rk4\n@dt 0.01\n"
                       "@compare euler verlet\n@ghost on\n@pause on\n@lock integrator +\nText.\n"
                       "--- Two\nNo settings: the sim goes on.\n@unlock dt\n"
                       "--- Three\n@dt 0.02\n@compare off\n@unlock\nText.\n"
                       "--- Four\n@scene orbit\nText.\n"
                       "--- Five\n@reset\nText.\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(l.npages, 5);
    const sw_lesson_page *p = l.pages;
    const sw_scene *spring = sw_scene_find("spring");
    ck_assert_ptr_eq(p[0].scene, spring);
    ck_assert_int_eq(p[0].restart, 1);
    ck_assert_double_eq(p[0].p[sw_scene_param_index(spring, "k")], 100);
    ck_assert_double_eq(p[0].p[sw_scene_param_index(spring, "c")], 0);
    ck_assert_double_eq(p[0].p[sw_scene_param_index(spring, "m")], 1);
    ck_assert_str_eq(p[0].method->name, "rk4");
    ck_assert_double_eq(p[0].dt, 0.01);
    ck_assert_int_eq(p[0].compare, 1);
    ck_assert_int_eq(p[0].ncompare_with, 2);
    ck_assert_str_eq(p[0].compare_with[1]->name, "verlet");
    ck_assert_int_eq(p[0].ghost, 1);
    ck_assert_int_eq(p[0].paused, 1);
    ck_assert_uint_eq(p[0].locked, SW_LOCK_INTEGRATOR | SW_LOCK_DT);
    /* Page two changes nothing but a lock, and carries the setup along. */
    ck_assert_int_eq(p[1].restart, 0);
    ck_assert_ptr_eq(p[1].scene, spring);
    ck_assert_str_eq(p[1].method->name, "rk4");
    ck_assert_int_eq(p[1].compare, -1);
    ck_assert_int_eq(p[1].ghost, -1);
    ck_assert_uint_eq(p[1].locked, SW_LOCK_INTEGRATOR);
    ck_assert_int_eq(p[2].restart, 1);
    ck_assert_double_eq(p[2].dt, 0.02);
    ck_assert_double_eq(p[2].p[sw_scene_param_index(spring, "k")], 100);
    ck_assert_int_eq(p[2].compare, 0);
    ck_assert_uint_eq(p[2].locked, 0);
    /* A new scene brings its own defaults. */
    const sw_scene *orbit = sw_scene_find("orbit");
    ck_assert_ptr_eq(p[3].scene, orbit);
    ck_assert_str_eq(p[3].method->name, orbit->integrator);
    ck_assert_double_eq(p[3].dt, orbit->dt);
    ck_assert_double_eq(p[3].p[0], orbit->params[0].def);
    for (int k = orbit->nparams; k < SW_MAX_PARAMS; k++)
        ck_assert_double_eq(p[3].p[k], 0);  /* nothing left over from the spring */
    ck_assert_int_eq(p[4].restart, 1);
    ck_assert_ptr_eq(p[4].scene, orbit);
    sw_lesson_free(&l);
}
END_TEST

START_TEST(lock_names_and_keys)
{
    ck_assert_uint_eq(sw_lock_of_key('i'), SW_LOCK_INTEGRATOR);
    ck_assert_uint_eq(sw_lock_of_key('7'), SW_LOCK_INTEGRATOR);
    ck_assert_uint_eq(sw_lock_of_key(SW_KEY_TAB), SW_LOCK_INTEGRATOR);
    ck_assert_uint_eq(sw_lock_of_key('='), SW_LOCK_DT);
    ck_assert_uint_eq(sw_lock_of_key(' '), SW_LOCK_RUN);
    ck_assert_uint_eq(sw_lock_of_key('R'), SW_LOCK_RECORD);
    ck_assert_uint_eq(sw_lock_of_key('p'), SW_LOCK_PARAMS);
    /* Navigation, hints, help and quit are never locked. */
    ck_assert_uint_eq(sw_lock_of_key('n'), 0);
    ck_assert_uint_eq(sw_lock_of_key('N'), 0);
    ck_assert_uint_eq(sw_lock_of_key('h'), 0);
    ck_assert_uint_eq(sw_lock_of_key('q'), 0);
    ck_assert_uint_eq(sw_lock_of_key('?'), 0);
    ck_assert_str_eq(sw_lock_name(SW_LOCK_GRAPH), "graph");
    ck_assert_ptr_null(sw_lock_name(3));

    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(parse("title: T\n--- p\n@scene spring\n@lock all\n@unlock space r\nx\n", &l, err, sizeof err) == SW_OK,
                  "%s", err);
    ck_assert_uint_eq(l.pages[0].locked, SW_LOCK_ALL & ~(SW_LOCK_RUN | SW_LOCK_RESET));
    sw_lesson_free(&l);
}
END_TEST

/* ---- goals ---------------------------------------------------------------------- */

/* Which observation field a case sets before evaluating. */
enum field { F_NONE, F_SCENE, F_INTEGRATOR, F_DT, F_T, F_STEPS, F_EVALS, F_SPEED, F_ENERGY, F_ERROR,
             F_DRIFT, F_RATIO, F_ACCEPTED, F_REJECTED, F_PARAM_C, F_BLOWN, F_COMPARE, F_GHOST,
             F_PAUSED, F_RECORDED, F_PHASE, F_REGION };

static const struct goal_case {
    const char *scene;  /* the page's scene, and any settings after it (goals are checked against them) */
    const char *goal;
    enum field field;
    double value;
    const char *name;   /* for F_SCENE / F_INTEGRATOR */
    int met;
} goal_cases[] = {
    { "spring", "integrator == rk4", F_INTEGRATOR, 0, "rk4", 1 },
    { "spring", "integrator == rk4", F_INTEGRATOR, 0, "euler", 0 },
    { "spring", "integrator is rk4", F_INTEGRATOR, 0, "rk4", 1 },
    { "spring", "integrator != rk4", F_INTEGRATOR, 0, "euler", 1 },
    { "spring", "integrator is not rk4", F_INTEGRATOR, 0, "rk4", 0 },
    { "spring", "integrator in verlet, symplectic-euler", F_INTEGRATOR, 0, "symplectic-euler", 1 },
    { "spring", "integrator in verlet symplectic-euler", F_INTEGRATOR, 0, "rk4", 0 },
    { "spring", "integrator == rk4", F_INTEGRATOR, 0, NULL, 0 },
    { "spring", "scene == spring", F_SCENE, 0, "spring", 1 },
    { "orbit", "scene != spring", F_SCENE, 0, "spring", 0 },  /* (on a spring page lint refuses it) */
    { "spring", "dt >= 0.2", F_DT, 0.05 * 4, NULL, 1 },
    { "spring", "Δt ≥ 0.2", F_DT, 0.1, NULL, 0 },
    { "spring", "dt <= 0.0125", F_DT, 0.1 / 8, NULL, 1 },
    { "spring", "dt <= 0.0125", F_DT, 0.013, NULL, 0 },
    /* dt 0.15 on the page: + and - reach 0.3 (lint refuses a dt no doubling reaches) */
    { "spring\n@dt 0.15", "dt == 0.3", F_DT, 0.1 * 3, NULL, 1 },    /* 0.30000000000000004 */
    { "spring\n@dt 0.15", "dt = 0.3", F_DT, 0.31, NULL, 0 },
    { "spring", "dt != 0.3", F_DT, 0.31, NULL, 1 },
    { "spring", "dt ≠ 0.3", F_DT, 0.1 * 3, NULL, 0 },
    { "spring", "t > 10", F_T, 10.5, NULL, 1 },
    { "spring", "t > 10", F_T, 10, NULL, 0 },
    { "spring", "time < 1", F_T, 0.5, NULL, 1 },
    { "spring", "t < 1", F_T, 1, NULL, 0 },
    { "spring", "t ≤ 1", F_T, 1, NULL, 1 },
    { "spring", "steps >= 5", F_STEPS, 5, NULL, 1 },
    { "spring", "steps >= 5", F_STEPS, 4, NULL, 0 },
    { "spring", "evals > 100", F_EVALS, 101, NULL, 1 },
    { "spring", "evals > 100", F_EVALS, 100, NULL, 0 },
    { "spring", "speed >= 2", F_SPEED, 4, NULL, 1 },
    { "spring", "speed >= 2", F_SPEED, 1, NULL, 0 },
    { "spring", "|energy_drift| < 1%", F_ENERGY, -0.5, NULL, 1 },
    { "spring", "|energy_drift| < 1", F_ENERGY, -1.5, NULL, 0 },
    { "spring", "abs(energy_drift) < 1", F_ENERGY, 0.9, NULL, 1 },
    { "spring", "energy_drift < -10", F_ENERGY, -12, NULL, 1 },
    { "spring", "energy_drift < -10", F_ENERGY, 12, NULL, 0 },
    { "spring", "energy_drift > 50", F_ENERGY, INFINITY, NULL, 1 },  /* a blown-up energy */
    { "spring", "energy_drift < 1", F_ENERGY, NAN, NULL, 0 },       /* not measured: not met */
    { "spring", "energy_drift != 1", F_ENERGY, NAN, NULL, 0 },
    { "spring", "energy_drift == 5", F_ENERGY, INFINITY, NULL, 0 },
    { "spring", "error < 0.01", F_ERROR, 0.001, NULL, 1 },
    { "spring", "error < 0.01", F_ERROR, 0.1, NULL, 0 },
    { "vortex", "drift > 0.3", F_DRIFT, 0.36, NULL, 1 },
    { "vortex", "|drift| < 1e-9", F_DRIFT, 1e-6, NULL, 0 },
    { "vortex", "error_ratio near 2 within 0.3", F_RATIO, 2.08, NULL, 1 },
    { "vortex", "error_ratio near 2 within 0.3", F_RATIO, 2.4, NULL, 0 },
    { "vortex", "error_ratio near 2 within 0.3", F_RATIO, 1.7, NULL, 1 },
    { "vortex", "error_ratio near 16 within 2", F_RATIO, NAN, NULL, 0 },
    { "orbit", "accepted >= 100", F_ACCEPTED, 100, NULL, 1 },
    { "orbit", "accepted >= 100", F_ACCEPTED, 99, NULL, 0 },
    { "orbit", "rejected >= 1", F_REJECTED, 3, NULL, 1 },
    { "orbit", "rejected >= 1", F_REJECTED, 0, NULL, 0 },
    { "spring", "param c >= 60", F_PARAM_C, 200, NULL, 1 },
    { "spring", "param c >= 60", F_PARAM_C, 10, NULL, 0 },
    { "spring", "param c >= 60", F_NONE, 0, NULL, 0 },  /* parameter not in obs */
    { "spring", "blown", F_BLOWN, 1, NULL, 1 },
    { "spring", "blown", F_BLOWN, 0, NULL, 0 },
    { "spring", "not blown", F_BLOWN, 0, NULL, 1 },
    { "spring", "!blown", F_BLOWN, 1, NULL, 0 },
    { "spring", "blown == no", F_BLOWN, 0, NULL, 1 },
    { "spring", "compare", F_COMPARE, 1, NULL, 1 },
    { "spring", "compare == off", F_COMPARE, 1, NULL, 0 },
    { "spring", "ghost is on", F_GHOST, 1, NULL, 1 },
    { "spring", "ghost != on", F_GHOST, 1, NULL, 0 },
    { "spring", "paused", F_PAUSED, 1, NULL, 1 },
    { "spring", "paused == false", F_PAUSED, 1, NULL, 0 },
    { "spring", "recorded", F_RECORDED, 1, NULL, 1 },
    { "spring", "recorded", F_RECORDED, 0, NULL, 0 },
    { "spring", "phase", F_PHASE, 1, NULL, 1 },
    { "spring", "phase", F_PHASE, 0, NULL, 0 },
    { "spring", "not region", F_REGION, 0, NULL, 1 },
    { "spring", "region", F_REGION, 0, NULL, 0 },
};

#define NGOALS ((int)(sizeof goal_cases / sizeof goal_cases[0]))

static void obs_base(sw_lesson_obs *obs, const char *scene)
{
    sw_lesson_obs_init(obs);
    obs->scene = scene;
    obs->integrator = "euler";
    obs->dt = 0.1;
    obs->t = 5;
    obs->speed = 1;
}

START_TEST(goal_cases_evaluate)
{
    const struct goal_case *c = &goal_cases[_i];
    char text[256], err[SW_LESSON_ERRLEN];
    snprintf(text, sizeof text, "title: T\n--- p\n@scene %s\nx\n@goal %s\n@hint h\n", c->scene, c->goal);
    sw_lesson l;
    ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s: %s", c->goal, err);
    const sw_lesson_goal *g = &l.pages[0].goals[0];
    sw_lesson_obs obs;
    obs_base(&obs, c->scene);
    switch (c->field) {
    case F_SCENE: obs.scene = c->name; break;
    case F_INTEGRATOR: obs.integrator = c->name; break;
    case F_DT: obs.dt = c->value; break;
    case F_T: obs.t = c->value; break;
    case F_STEPS: obs.steps = (long)c->value; break;
    case F_EVALS: obs.evals = (long)c->value; break;
    case F_SPEED: obs.speed = c->value; break;
    case F_ENERGY: obs.energy_drift = c->value; break;
    case F_ERROR: obs.error = c->value; break;
    case F_DRIFT: obs.drift = c->value; break;
    case F_RATIO: obs.error_ratio = c->value; break;
    case F_ACCEPTED: obs.accepted = (long)c->value; break;
    case F_REJECTED: obs.rejected = (long)c->value; break;
    case F_PARAM_C:
        obs.nparams = 2;
        obs.param_name[0] = "k";
        obs.param_value[0] = 1e4;
        obs.param_name[1] = "c";
        obs.param_value[1] = c->value;
        break;
    case F_BLOWN: obs.blown = (int)c->value; break;
    case F_COMPARE: obs.compare = (int)c->value; break;
    case F_GHOST: obs.ghost = (int)c->value; break;
    case F_PAUSED: obs.paused = (int)c->value; break;
    case F_RECORDED: obs.recorded = (int)c->value; break;
    case F_PHASE: obs.phase = (int)c->value; break;
    case F_REGION: obs.region = (int)c->value; break;
    case F_NONE: break;
    }
    ck_assert_msg(sw_lesson_goal_met(g, &obs) == c->met, "goal '%s' (case %d) should %sbe met", c->goal, _i,
                  c->met ? "" : "not ");
    sw_lesson_free(&l);
}
END_TEST

/* Each variable is reachable by some true and some false case above. */
START_TEST(goal_cases_cover_every_variable)
{
    int seen_true[SW_LV_COUNT] = { 0 }, seen_false[SW_LV_COUNT] = { 0 };
    char text[256], err[SW_LESSON_ERRLEN];
    for (int i = 0; i < NGOALS; i++) {
        snprintf(text, sizeof text, "title: T\n--- p\n@scene %s\nx\n@goal %s\n@hint h\n", goal_cases[i].scene,
                 goal_cases[i].goal);
        sw_lesson l;
        ck_assert_int_eq(parse(text, &l, err, sizeof err), SW_OK);
        int v = l.pages[0].goals[0].var;
        (goal_cases[i].met ? seen_true : seen_false)[v] = 1;
        sw_lesson_free(&l);
    }
    for (int v = 0; v < SW_LV_COUNT; v++)
        ck_assert_msg(seen_true[v] && seen_false[v], "variable %s lacks a true or a false case",
                      sw_lesson_var_name((sw_lesson_var)v));
}
END_TEST

START_TEST(goal_text_reads_well)
{
    static const struct { const char *scene, *goal, *text; } cases[] = {
        { "spring", "integrator == rk4", "integrator is rk4" },
        { "spring", "integrator != euler", "integrator is not euler" },
        { "spring", "integrator in verlet symplectic-euler rk4", "integrator is verlet, symplectic-euler or rk4" },
        { "spring", "dt >= 0.2", "dt >= 0.2" },
        { "spring", "dt = 0.16", "dt = 0.16" },
        { "spring", "|energy_drift| < 1%", "|energy drift| < 1 %" },
        { "spring", "t > 10", "t > 10" },
        { "vortex", "error_ratio near 4 within 0.5", "error ratio within 0.5 of 4" },
        { "spring", "blown", "the sim has blown up" },
        { "spring", "not blown", "the sim has not blown up" },
        { "spring", "ghost", "ghost is on" },
        { "spring", "compare == off", "compare is off" },
        { "spring", "paused", "the sim is paused" },
        { "spring", "recorded", "a trace has been recorded" },
        { "spring", "param c >= 60", "c >= 60" },
        { "orbit", "rejected >= 1", "rejected steps >= 1" },
    };
    char text[256], err[SW_LESSON_ERRLEN], out[128];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(text, sizeof text, "title: T\n--- p\n@scene %s\nx\n@goal %s\n@hint h\n", cases[i].scene,
                 cases[i].goal);
        sw_lesson l;
        ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s", err);
        sw_lesson_goal_text(&l.pages[0].goals[0], out, sizeof out);
        ck_assert_str_eq(out, cases[i].text);
        /* Truncation keeps the buffer a string. */
        char tiny[5];
        sw_lesson_goal_text(&l.pages[0].goals[0], tiny, sizeof tiny);
        ck_assert_uint_le(strlen(tiny), 4);
        sw_lesson_free(&l);
    }
}
END_TEST

START_TEST(goal_var_lookup)
{
    for (int v = 0; v < SW_LV_COUNT; v++)
        ck_assert_int_eq(sw_lesson_var_find(sw_lesson_var_name((sw_lesson_var)v)), v);
    ck_assert_int_eq(sw_lesson_var_find("Δt"), SW_LV_DT);
    ck_assert_int_eq(sw_lesson_var_find("time"), SW_LV_T);
    ck_assert_int_eq(sw_lesson_var_find("energy"), -1);
    ck_assert_ptr_null(sw_lesson_var_name(SW_LV_COUNT));
}
END_TEST

/* ---- questions and pages ------------------------------------------------------------ */

START_TEST(question_answers_and_completion)
{
    const char *text = "title: T\n--- p\n@scene spring\nx\n@goal t >= 1\n@hint Run.\n"
                       "@question Which?\n@answer a) One | Not one.\n@answer B) Two | Yes, two.\n"
                       "@answer c) Three|four | Bars inside | text are fine.\n@correct b\n@hint Think.\n"
                       "--- q\nNo question here.\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s", err);
    const sw_lesson_page *pg = &l.pages[0];
    ck_assert_int_eq(pg->question.nanswers, 3);
    ck_assert_int_eq(pg->question.correct, 1);
    ck_assert_str_eq(pg->question.hint, "Think.");
    ck_assert_str_eq(pg->question.answers[2].text, "Three|four");
    ck_assert_str_eq(pg->question.answers[2].feedback, "Bars inside | text are fine.");
    const char *fb = NULL;
    ck_assert_int_eq(sw_lesson_answer(pg, 'a', &fb), 0);
    ck_assert_str_eq(fb, "Not one.");
    ck_assert_int_eq(sw_lesson_answer(pg, 'b', &fb), 1);
    ck_assert_str_eq(fb, "Yes, two.");
    ck_assert_int_eq(sw_lesson_answer(pg, 'B', &fb), 1);
    ck_assert_int_eq(sw_lesson_answer(pg, 'd', &fb), SW_EINVAL);
    ck_assert_ptr_nonnull(fb);
    ck_assert_int_eq(sw_lesson_answer(pg, 0x10000, &fb), SW_EINVAL);
    ck_assert_int_eq(sw_lesson_answer(&l.pages[1], 'a', &fb), SW_EINVAL);

    sw_lesson_obs obs;
    obs_base(&obs, "spring");
    obs.t = 2;
    ck_assert_int_eq(sw_lesson_page_complete(pg, &obs, 0), 0);  /* not answered */
    ck_assert_int_eq(sw_lesson_page_complete(pg, &obs, 1), 1);
    obs.t = 0.5;
    ck_assert_int_eq(sw_lesson_page_complete(pg, &obs, 1), 0);  /* goal not met */
    ck_assert_int_eq(sw_lesson_page_complete(&l.pages[1], &obs, 0), 1);  /* nothing asked */
    sw_lesson_free(&l);
}
END_TEST

/* The observation a sim fills: checked against the sim's own fields. */
START_TEST(obs_from_sim_fills_what_a_sim_knows)
{
    sw_sim s;
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("spring");
    ck_assert_int_eq(sw_sim_init(&s, sc, NULL, sw_integrator_find("euler"), 0.02, err, sizeof err), SW_OK);
    sw_sim_run_until(&s, 1.0);
    sw_lesson_obs obs;
    sw_lesson_obs_init(&obs);
    obs.ghost = 1;
    sw_lesson_obs_from_sim(&obs, &s);
    ck_assert_str_eq(obs.scene, "spring");
    ck_assert_str_eq(obs.integrator, "euler");
    ck_assert_double_eq(obs.dt, 0.02);
    ck_assert_double_eq(obs.t, s.t);
    ck_assert_int_eq(obs.steps, 50);
    ck_assert_int_eq(obs.evals, 50);  /* Euler: one evaluation per step */
    ck_assert_int_eq(obs.blown, 0);
    ck_assert_double_eq(obs.energy_drift, sw_sim_energy_drift(&s));
    ck_assert(isnan(obs.drift));      /* the spring has no invariant */
    ck_assert(isnan(obs.error));      /* left to the app */
    ck_assert_int_eq(obs.ghost, 1);   /* app fields untouched */
    ck_assert_int_eq(obs.nparams, sc->nparams);
    ck_assert_str_eq(obs.param_name[0], "k");
    ck_assert_double_eq(obs.param_value[0], 10);
    sw_sim_free(&s);
}
END_TEST

/* ---- hostile input -------------------------------------------------------------------- */

START_TEST(megabyte_line_is_an_error)
{
    size_t n = 1 << 20;
    char *text = malloc(n + 64);
    ck_assert_ptr_nonnull(text);
    strcpy(text, "title: T\n--- p\n@scene vortex\n");
    size_t head = strlen(text);
    memset(text + head, 'x', n);
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    /* Past the file bound first; then as a line, with the file bound lifted by size. */
    ck_assert_int_eq(sw_lesson_parse("big", text, head + n, &l, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "big:1:1: file is"));
    ck_assert_int_eq(sw_lesson_parse("long", text, head + 200000, &l, err, sizeof err), SW_EINVAL);
    ck_assert_str_eq(err, "long:4:1001: line longer than 1000 bytes; expected shorter lines (break the "
                          "paragraph: lines are joined)");
    free(text);
}
END_TEST

START_TEST(nul_bytes_and_binary_are_errors)
{
    const char text[] = "title: T\n--- p\n@scene vortex\nab\0cd\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_parse("nul", text, sizeof text - 1, &l, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "nul:4:3: NUL byte"));
    static const unsigned char elf[] = { 0x7F, 'E', 'L', 'F', 2, 1, 1, 0, 0, 0 };
    ck_assert_int_eq(sw_lesson_parse("elf", (const char *)elf, sizeof elf, &l, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "elf:1:1: control character 0x7F"));
    /* Overlong, surrogate, truncated and C1-control sequences. */
    static const char *const bad_utf8[] = { "\xC0\xAF", "\xED\xA0\x80", "\xE2\x89", "\xC2\x9B", "\xF5\x80\x80\x80" };
    for (size_t i = 0; i < sizeof bad_utf8 / sizeof bad_utf8[0]; i++) {
        char buf[64];
        snprintf(buf, sizeof buf, "title: T%s\n", bad_utf8[i]);
        ck_assert_int_eq(parse(buf, &l, err, sizeof err), SW_EINVAL);
        ck_assert_msg(strncmp(err, "t.lesson:1:9: ", 14) == 0, "%s", err);
    }
    /* Text ending without a newline or NUL, in a buffer of exactly its size
     * (the parser must not read past len; a sanitizer build checks it). */
    static const char *const endings[] = { "title: Bad lesson\nt", "title: T\n--", "title: T\n--- p\n@",
                                           "title: T\n--- p\n@scene vortex\nx\n@goal |" };
    for (size_t i = 0; i < sizeof endings / sizeof endings[0]; i++) {
        size_t n = strlen(endings[i]);
        char *exact = malloc(n);
        ck_assert_ptr_nonnull(exact);
        memcpy(exact, endings[i], n);
        ck_assert_int_eq(sw_lesson_parse("end", exact, n, &l, err, sizeof err), SW_EINVAL);
        ck_assert_msg(strncmp(err, "end:2:", 6) == 0 || strncmp(err, "end:3:", 6) == 0 ||
                      strncmp(err, "end:5:", 6) == 0, "%s", err);
        free(exact);
    }
    /* NULL text and a zero-length or tiny error buffer are safe. */
    ck_assert_int_eq(sw_lesson_parse("none", NULL, 0, &l, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_lesson_parse("none", NULL, 0, &l, NULL, 0), SW_EINVAL);
    char tiny[8];
    ck_assert_int_eq(sw_lesson_parse("a-long-name.lesson", "x", 1, &l, tiny, sizeof tiny), SW_EINVAL);
    ck_assert_uint_eq(strlen(tiny), 7);
}
END_TEST

/* Deterministic fuzzing: random bytes, and real lessons with bytes changed.
 * Every outcome must be SW_OK or SW_EINVAL with a "NAME:LINE:COL: " message;
 * a crash or a sanitizer report fails the suite. */
static unsigned long long rng_state = 0x9E3779B97F4A7C15ull;

static unsigned rnd(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (unsigned)(rng_state >> 32);
}

static void check_outcome(int rc, const char *err, sw_lesson *l)
{
    ck_assert(rc == SW_OK || rc == SW_EINVAL);
    if (rc == SW_EINVAL) {
        int line, col;
        ck_assert_msg(sscanf(err, "fuzz:%d:%d: ", &line, &col) == 2, "%s", err);
        ck_assert_int_ge(line, 1);
        ck_assert_int_ge(col, 1);
    } else {
        ck_assert_int_ge(l->npages, 1);
        sw_lesson_free(l);
    }
}

START_TEST(fuzz_random_and_mutated)
{
    static const char alphabet[] = "@#-|<>=!%()., \t\nabcdegilnpqrstuvwxyz0123456789\\\r\xce\x94\xe2\x89\xa5\x80\xff";
    char err[SW_LESSON_ERRLEN];
    sw_lesson l;
    for (int iter = 0; iter < 400; iter++) {
        char buf[600];
        size_t n = rnd() % sizeof buf;
        for (size_t i = 0; i < n; i++)
            buf[i] = (iter & 1) ? (char)(rnd() & 0xFF) : alphabet[rnd() % (sizeof alphabet - 1)];
        check_outcome(sw_lesson_parse("fuzz", buf, n, &l, err, sizeof err), err, &l);
    }
    /* Mutations of the course's own files reach deep into the parser. */
    sw_lesson_entry *list;
    int count;
    ck_assert_int_eq(sw_lesson_list(LESSONS_DIR, &list, &count, err, sizeof err), SW_OK);
    static char text[SW_LESSON_MAX_BYTES];
    for (int k = 0; k < count; k++) {
        FILE *f = fopen(list[k].path, "rb");
        ck_assert_ptr_nonnull(f);
        size_t len = fread(text, 1, sizeof text, f);
        fclose(f);
        static char copy[SW_LESSON_MAX_BYTES];
        for (int iter = 0; iter < 60; iter++) {
            memcpy(copy, text, len);
            int edits = 1 + (int)(rnd() % 4);
            for (int e = 0; e < edits; e++)
                copy[rnd() % len] = (rnd() & 1) ? alphabet[rnd() % (sizeof alphabet - 1)] : (char)(rnd() & 0xFF);
            size_t cut = (rnd() % 4 == 0) ? rnd() % len : len;
            check_outcome(sw_lesson_parse("fuzz", copy, cut, &l, err, sizeof err), err, &l);
        }
    }
    sw_lesson_list_free(list, count);
}
END_TEST

/* Bounds: pages, prose, answers. */
START_TEST(bounds_are_errors)
{
    static char text[40000];
    size_t used = (size_t)snprintf(text, sizeof text, "title: T\n");
    for (int i = 0; i <= SW_LESSON_MAX_PAGES; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "--- Page %d\n%sText.\n", i + 1,
                                 i == 0 ? "@scene vortex\n" : "");
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(parse(text, &l, err, sizeof err), SW_EINVAL);
    char want[64];
    snprintf(want, sizeof want, "t.lesson:%d:1: too many pages", 2 + 2 * SW_LESSON_MAX_PAGES + 1);
    ck_assert_msg(strncmp(err, want, strlen(want)) == 0, "%s", err);

    used = (size_t)snprintf(text, sizeof text, "title: T\n--- p\n@scene vortex\n");
    for (int i = 0; i < 80; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "%090d\n", i);
    ck_assert_int_eq(parse(text, &l, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "more than 6000 bytes of text"));

    used = (size_t)snprintf(text, sizeof text, "title: T\n--- p\n@scene vortex\nx\n@question Q?\n");
    for (int i = 0; i <= SW_LESSON_MAX_ANSWERS; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "@answer %c) A | F\n", 'a' + i);
    ck_assert_int_eq(parse(text, &l, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "t.lesson:12:1: too many answers"));
}
END_TEST

Suite *make_lesson_suite(void);
Suite *make_lesson_suite(void)
{
    Suite *s = suite_create("lesson");
    TCase *tc = tcase_create("course");
    tcase_add_test(tc, course_lessons_all_parse);
    tcase_add_test(tc, course_pages_have_text_and_hints);
    tcase_add_test(tc, readme_example_parses);
    suite_add_tcase(s, tc);
    tc = tcase_create("errors");
    tcase_add_loop_test(tc, bad_file_reports_line_and_column, 0, NBAD);
    tcase_add_test(tc, bad_dir_fully_covered);
    tcase_add_test(tc, load_refuses_missing_directory_and_huge);
    tcase_add_test(tc, list_sorts_and_reports_broken_files);
    suite_add_tcase(s, tc);
    tc = tcase_create("format");
    tcase_add_test(tc, prose_paragraphs_verbatim_escapes_crlf_bom);
    tcase_add_test(tc, settings_inherit_and_restart);
    tcase_add_test(tc, lock_names_and_keys);
    suite_add_tcase(s, tc);
    tc = tcase_create("goals");
    tcase_add_loop_test(tc, goal_cases_evaluate, 0, NGOALS);
    tcase_add_test(tc, goal_cases_cover_every_variable);
    tcase_add_test(tc, goal_text_reads_well);
    tcase_add_test(tc, goal_var_lookup);
    tcase_add_test(tc, question_answers_and_completion);
    tcase_add_test(tc, obs_from_sim_fills_what_a_sim_knows);
    suite_add_tcase(s, tc);
    tc = tcase_create("hostile");
    tcase_add_test(tc, megabyte_line_is_an_error);
    tcase_add_test(tc, nul_bytes_and_binary_are_errors);
    tcase_add_test(tc, fuzz_random_and_mutated);
    tcase_add_test(tc, bounds_are_errors);
    tcase_set_timeout(tc, 30);
    suite_add_tcase(s, tc);
    return s;
}
