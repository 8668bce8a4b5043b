#define _GNU_SOURCE /* strcasestr */
/* Every lesson, driven headless page by page with the keys a student would
 * press (tests/data/lesson_drives/NAME.drive): proves each goal reachable and each
 * page reachable through the same runner and app the terminal uses.
 *
 * A drive file has one line per page, "page N: ACTIONS", ACTIONS being keys
 * (one character each, or space, tab, btab, pgdn, pgup, up, down, left, right)
 * and run:T (let simulated time pass T seconds, as if the student watched). */
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/progress.h"
#include "app/runner.h"
#include "stepwise/stepwise.h"

/* A drive file's key: a character, or a key name (lesson/controls.h). */
static int key_code(const char *tok)
{
    int key = sw_key_find(tok);
    return key == SW_KEY_NONE ? -1 : key;
}

static void press(sw_runner *r, sw_app *a, int key)
{
    if (!sw_runner_key(r, a, key))
        sw_app_key(a, key, 1);
    sw_app_dt_wait(a); /* a Δt key's figures, where they were measured on a worker */
    sw_runner_update(r, a);
}

/* Let simulated time pass in frames of 0.05 s, checking goals each frame. */
static void run_for(sw_runner *r, sw_app *a, double T)
{
    double target = a->sims[0].t + T;
    for (int i = 0; i < 200000 && a->sims[0].t < target - 1e-9 && !a->sims[0].blown && !a->paused; i++) {
        sw_app_advance(a, fmin(0.05, target - a->sims[0].t) / a->speed, 1000000);
        sw_runner_update(r, a);
    }
}

static void unmet_goals(sw_runner *r, sw_app *a, char *buf, size_t len)
{
    const sw_lesson_page *pg = &r->lesson.pages[r->page];
    sw_lesson_obs obs;
    sw_runner_obs(a, &obs);
    size_t used = (size_t)snprintf(buf, len, "t=%g dt=%g %s blown=%d ratio=%g:", obs.t, obs.dt, obs.integrator,
                                   obs.blown, obs.error_ratio);
    for (int g = 0; g < pg->ngoals && used < len; g++)
        if (!sw_lesson_goal_met(&pg->goals[g], &obs)) {
            char t[160];
            sw_lesson_goal_text(&pg->goals[g], t, sizeof t);
            used += (size_t)snprintf(buf + used, len - used, " [%s]", t);
        }
    if (pg->question.text && !r->answered[r->page] && used < len)
        snprintf(buf + used, len - used, " [question not answered]");
}

/* On arriving at a page, no goal on what a run accumulates (time, steps,
 * evaluations, drift, error, a blow-up) may already be met: the page would
 * be done before the student did anything, counting time spent on the
 * pages before (a page whose goals need time to pass restarts the sim). */
static void fresh_on_arrival(sw_runner *r, sw_app *a, const char *lesson_file)
{
    static const sw_lesson_var accumulated[] = { SW_LV_T, SW_LV_STEPS, SW_LV_EVALS, SW_LV_ENERGY_DRIFT,
                                                 SW_LV_ERROR, SW_LV_DRIFT, SW_LV_BLOWN, SW_LV_ACCEPTED,
                                                 SW_LV_REJECTED };
    const sw_lesson_page *pg = &r->lesson.pages[r->page];
    sw_lesson_obs obs, fresh;
    sw_runner_obs(a, &obs);
    fresh = obs; /* the same page at t = 0: a goal met there ("not blown", "|drift| < 1 %") is kept, not reached */
    fresh.t = fresh.energy_drift = fresh.error = fresh.drift = 0;
    fresh.steps = fresh.evals = fresh.accepted = fresh.rejected = 0;
    fresh.blown = 0;
    for (int g = 0; g < pg->ngoals; g++)
        for (size_t k = 0; k < sizeof accumulated / sizeof accumulated[0]; k++)
            if (pg->goals[g].var == accumulated[k] && sw_lesson_goal_met(&pg->goals[g], &obs) &&
                !sw_lesson_goal_met(&pg->goals[g], &fresh)) {
                char t[160];
                sw_lesson_goal_text(&pg->goals[g], t, sizeof t);
                ck_abort_msg("%s page %d '%s': the goal [%s] is met on arrival (t = %g): restart the sim there "
                             "(@reset)", lesson_file, r->page + 1, pg->title, t, obs.t);
            }
}

/* A page whose prose tells the student to press space to run must start
 * paused (space toggles: on a running sim it pauses). */
static void space_runs(sw_runner *r, sw_app *a, const char *lesson_file)
{
    static const char *const asks[] = { "(space)", "press space", "then space", "with space", "space to run",
                                        "space runs", "space to set it running", "space, and", "r, space" };
    const sw_lesson_page *pg = &r->lesson.pages[r->page];
    for (int b = 0; b < pg->nblocks + pg->ngoals; b++) {
        const char *text = b < pg->nblocks ? (pg->blocks[b].verbatim ? "" : pg->blocks[b].text)
                                           : pg->goals[b - pg->nblocks].hint;
        for (size_t k = 0; k < sizeof asks / sizeof asks[0]; k++)
            if (text && strcasestr(text, asks[k]) && !strcasestr(text, "paused")) /* "space if paused" */
                ck_assert_msg(a->paused, "%s page %d '%s' says \"%s\" but the sim is already running on "
                              "arrival (@pause on): \"%s\"", lesson_file, r->page + 1, pg->title, asks[k], text);
    }
}

static char repo[512];

static void drive(const char *lesson_file)
{
    char lesson_path[1024], drive_path[1024], err[SW_LESSON_ERRLEN], line[2048];
    snprintf(lesson_path, sizeof lesson_path, "%s/lessons/%s", repo, lesson_file);
    snprintf(drive_path, sizeof drive_path, "%s/tests/data/lesson_drives/%.*s.drive", repo,
             (int)(strlen(lesson_file) - strlen(".lesson")), lesson_file);
    FILE *f = fopen(drive_path, "r");
    ck_assert_msg(f != NULL, "no drive script %s for lesson %s", drive_path, lesson_file);
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    ck_assert_msg(sw_runner_start(r, &a, lesson_path, 0, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(r->page, 0);
    int pages = 0, lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        int n, off;
        ck_assert_msg(sscanf(line, "page %d:%n", &n, &off) == 1, "%s:%d: expected 'page N: ACTIONS'", drive_path, lineno);
        ck_assert_msg(n == pages + 1, "%s:%d: page %d out of order", drive_path, lineno, n);
        ck_assert_msg(r->page == pages, "%s: on page %d, expected %d", lesson_file, r->page + 1, pages + 1);
        fresh_on_arrival(r, &a, lesson_file);
        space_runs(r, &a, lesson_file);
        for (char *tok = strtok(line + off, " \t\n"); tok; tok = strtok(NULL, " \t\n")) {
            if (strncmp(tok, "run:", 4) == 0) {
                run_for(r, &a, atof(tok + 4));
            } else {
                int key = key_code(tok);
                ck_assert_msg(key >= 0, "%s:%d: unknown action '%s'", drive_path, lineno, tok);
                press(r, &a, key);
            }
        }
        sw_runner_update(r, &a);
        char why[1024];
        unmet_goals(r, &a, why, sizeof why);
        ck_assert_msg(r->complete[r->page], "%s page %d '%s' not complete after its actions: %s", lesson_file,
                      pages + 1, r->lesson.pages[r->page].title, why);
        pages++;
        if (pages < r->lesson.npages) {
            press(r, &a, 'n');
            ck_assert_msg(r->page == pages, "%s: n did not open page %d", lesson_file, pages + 1);
        }
    }
    fclose(f);
    ck_assert_msg(pages == r->lesson.npages, "%s: the drive covers %d of %d pages", lesson_file, pages,
                  r->lesson.npages);
    ck_assert(r->finished);
    sw_app_free(&a);
    sw_runner_free(r);
    free(r);
}

START_TEST(drive_every_lesson)
{
    /* progress and recorded traces go to a scratch directory */
    char state[] = "/tmp/sw-drive-XXXXXX", dir[600];
    ck_assert_ptr_nonnull(mkdtemp(state));
    setenv("XDG_STATE_HOME", state, 1);
    ck_assert_ptr_nonnull(getcwd(repo, sizeof repo));
    snprintf(dir, sizeof dir, "%s/lessons", repo);
    ck_assert_int_eq(chdir(state), 0);
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list(dir, &e, &n, err, sizeof err), SW_OK);
    ck_assert_int_ge(n, 10);
    for (int i = 0; i < n; i++)
        drive(e[i].file);
    /* progress was saved: every lesson complete */
    for (int i = 0; i < n; i++)
        ck_assert_int_eq(sw_progress_get(e[i].file), e[i].npages);
    sw_lesson_list_free(e, n);
    ck_assert_int_eq(chdir(repo), 0);
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", state);
    ck_assert_int_eq(system(cmd), 0);
}
END_TEST

/* A page's goals gate the next page; answers give their feedback. */
START_TEST(gating_and_answers)
{
    char state[] = "/tmp/sw-gate-XXXXXX", path[128];
    ck_assert_ptr_nonnull(mkdtemp(state));
    setenv("XDG_STATE_HOME", state, 1);
    snprintf(path, sizeof path, "%s/gate.lesson", state);
    FILE *f = fopen(path, "w");
    fputs("title: Gate\n--- First\n@scene spring\n@integrator euler\nPick RK4.\n@goal integrator == rk4\n"
          "@hint press 5\n--- Second\nWhich is implicit?\n@question Which method solves a linear system?\n"
          "@answer a) euler | No: one evaluation, no solve.\n@answer b) implicit-euler | Yes.\n@correct b\n",
          f);
    fclose(f);
    sw_runner r;
    sw_app a;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(sw_runner_start(&r, &a, path, 0, err, sizeof err) == SW_OK, "%s", err);
    press(&r, &a, 'n');
    ck_assert_int_eq(r.page, 0);
    ck_assert_ptr_nonnull(strstr(a.message, "not met"));
    press(&r, &a, 'h');
    const sw_side *side = sw_runner_side(&r, &a, 120);
    int found = 0;
    for (int i = 0; i < side->nlines; i++)
        found |= strstr(side->lines[i], "Hint: press 5") != NULL;
    ck_assert(found);
    press(&r, &a, '5');
    ck_assert(r.complete[0]);
    ck_assert_int_eq(sw_progress_get("gate.lesson"), 1);
    sw_app_free(&a);
    sw_runner_free(&r);
    /* resuming opens the first page not yet done */
    ck_assert_int_eq(sw_runner_start(&r, &a, path, -1, err, sizeof err), SW_OK);
    ck_assert_int_eq(r.page, 1);
    ck_assert(r.before[0] && !r.complete[0]); /* done before: not ticked again */
    press(&r, &a, 'A');
    ck_assert(!r.answered[1]);
    ck_assert_ptr_nonnull(strstr(r.feedback, "No: one evaluation"));
    press(&r, &a, 'B');
    ck_assert(r.answered[1] && r.complete[1] && r.finished);
    ck_assert_int_eq(sw_progress_get("gate.lesson"), 2);
    press(&r, &a, 'N');
    ck_assert_int_eq(r.page, 0);
    /* a page done in an earlier session shows its goal fresh, says so, and n skips it */
    side = sw_runner_side(&r, &a, 120);
    int fresh = 0, said = 0;
    for (int i = 0; i < side->nlines; i++) {
        fresh |= strstr(side->lines[i], "\xe2\x9c\x97") != NULL; /* the goal's ✗ */
        said |= strstr(side->lines[i], "earlier session") != NULL;
    }
    ck_assert(fresh && said);
    press(&r, &a, 'n');
    ck_assert_int_eq(r.page, 1);
    sw_app_free(&a);
    sw_runner_free(&r);
    /* a finished lesson reopens at its first page, every goal fresh */
    ck_assert_int_eq(sw_runner_start(&r, &a, path, -1, err, sizeof err), SW_OK);
    ck_assert_int_eq(r.page, 0);
    ck_assert(r.before[0] && r.before[1] && !r.complete[0] && !r.answered[1]);
    sw_app_free(&a);
    sw_runner_free(&r);
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", state);
    ck_assert_int_eq(system(cmd), 0);
}
END_TEST


/* The menu's next lesson: the first not finished from a place on, wrapping
 * round; an unreadable lesson skipped; -1 when all are done. */
START_TEST(menu_next_unfinished)
{
    char state[] = "/tmp/sw-next-XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(state));
    setenv("XDG_STATE_HOME", state, 1);
    char f0[] = "a.lesson", f1[] = "b.lesson", f2[] = "c.lesson", title[] = "T";
    sw_lesson_entry e[3] = {
        { .file = f0, .title = title, .npages = 2 },
        { .file = f1, .title = NULL, .npages = 0 },   /* does not load */
        { .file = f2, .title = title, .npages = 3 },
    };
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_progress_next(e, 3, 0), 0);
    ck_assert_int_eq(sw_progress_set("a.lesson", 2, err, sizeof err), SW_OK); /* a finished */
    ck_assert_int_eq(sw_progress_next(e, 3, 0), 2);
    ck_assert_int_eq(sw_progress_next(e, 3, 1), 2);
    ck_assert_int_eq(sw_progress_set("c.lesson", 1, err, sizeof err), SW_OK); /* c begun, not done */
    ck_assert_int_eq(sw_progress_next(e, 3, 0), 2);
    ck_assert_int_eq(sw_progress_set("c.lesson", 3, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_progress_next(e, 3, 0), -1);
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", state);
    ck_assert_int_eq(system(cmd), 0);
}
END_TEST


/* A page that asks the student to watch starts paused (its text says how
 * to run it), so nothing happens before the page has been read; and a
 * page with a time goal cannot meet it on arrival (drive() checks that). */
START_TEST(watch_pages_start_paused)
{
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    ck_assert_int_ge(n, 10);
    int checked = 0;
    for (int i = 0; i < n; i++) {
        sw_lesson les;
        ck_assert_msg(sw_lesson_load(e[i].path, &les, err, sizeof err) == SW_OK, "%s", err);
        for (int p = 0; p < les.npages; p++) {
            const sw_lesson_page *pg = &les.pages[p];
            int watch = 0;
            for (int b = 0; b < pg->nblocks; b++)
                watch |= strcasestr(pg->blocks[b].text, "watch") != NULL;
            if (!watch)
                continue;
            checked++;
            ck_assert_msg(pg->paused == 1, "%s page %d '%s' says watch but does not start paused (@pause on)",
                          e[i].file, p + 1, pg->title);
        }
        sw_lesson_free(&les);
    }
    ck_assert_int_ge(checked, 10);
    sw_lesson_list_free(e, n);
}
END_TEST

/* A page starts with the scene's own camera unless it sets one: a zoom,
 * a camera following the run, a box from the page before are dropped
 * (lesson 7: the zoom-out page 3 asks for hid page 4's pendulum); a page
 * that sets them gets them. */
START_TEST(pages_start_with_the_scene_camera)
{
    char state[] = "/tmp/sw-cam-XXXXXX", path[128];
    ck_assert_ptr_nonnull(mkdtemp(state));
    setenv("XDG_STATE_HOME", state, 1);
    snprintf(path, sizeof path, "%s/cam.lesson", state);
    FILE *f = fopen(path, "w");
    fputs("title: Camera\n--- First\n@scene spring\nZoom out.\n--- Second\nThe spring.\n"
          "--- Third\n@view follow zoom=0.5 box=0,0,1,1\nClose up.\n",
          f);
    fclose(f);
    sw_runner r;
    sw_app a;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(sw_runner_start(&r, &a, path, 0, err, sizeof err) == SW_OK, "%s", err);
    a.zoom = 4;
    a.follow = 1;
    a.have_box = 1;
    sw_runner_enter(&r, &a, 1);
    ck_assert(a.zoom == 1 && a.follow == 0 && a.have_box == 0);
    sw_runner_enter(&r, &a, 2);
    ck_assert(a.zoom == 0.5 && a.follow == 1 && a.have_box == 1);
    sw_app_free(&a);
    sw_runner_free(&r);
    char cmd[160];
    snprintf(cmd, sizeof cmd, "rm -rf %s", state);
    ck_assert_int_eq(system(cmd), 0);
    unsetenv("XDG_STATE_HOME");
}
END_TEST

Suite *make_lesson_drive_suite(void);
Suite *make_lesson_drive_suite(void)
{
    Suite *s = suite_create("lesson_drive");
    TCase *tc = tcase_create("drive");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, gating_and_answers);
    tcase_add_test(tc, menu_next_unfinished);
    tcase_add_test(tc, watch_pages_start_paused);
    tcase_add_test(tc, pages_start_with_the_scene_camera);
    tcase_add_test(tc, drive_every_lesson);
    suite_add_tcase(s, tc);
    return s;
}
