/* Lesson files: every course lesson parses; every malformed file in
 * tests/data/lessons_bad/ fails with the expected FILE:LINE:COL; hostile
 * bytes give errors, never crashes (goals and answers: check_lesson_goals.c). Tests run from the repository root. */
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
    { "until-empty.lesson", 5, 7, "@until needs a value; expected a stop time in seconds" },
    { "until-range.lesson", 5, 8, "@until '0' is not allowed; expected a number in [1e-09, 1e+06]" },
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
    tc = tcase_create("hostile");
    tcase_add_test(tc, megabyte_line_is_an_error);
    tcase_add_test(tc, nul_bytes_and_binary_are_errors);
    tcase_add_test(tc, fuzz_random_and_mutated);
    tcase_add_test(tc, bounds_are_errors);
    tcase_set_timeout(tc, 30);
    suite_add_tcase(s, tc);
    return s;
}
