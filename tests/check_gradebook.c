/* The gradebook's ground (issue 21): temporary directories that never
 * outlive their maker, even one killed with SIGKILL. */
#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/clock.h"
#include "util/tmpdir.h"

static char tmpdir[64];

static void make_tmpdir(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/sw_gradebook_XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(tmpdir));
}

static void remove_tmpdir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    ck_assert_int_eq(system(cmd), 0);
}

static void touch(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    ck_assert_int_eq(fclose(f), 0);
}

/* Wait up to `seconds` for path to be gone; 1 when it is. */
static int gone_within(const char *path, double seconds)
{
    double end = sw_clock_now() + seconds;
    while (access(path, F_OK) == 0 && sw_clock_now() < end) {
        struct timespec pause = { 0, 20000000 };
        nanosleep(&pause, NULL);
    }
    return access(path, F_OK) != 0;
}

/* ---- temporary directories ------------------------------------------------- */

/* Removed with what is in it (files, a subdirectory), a link removed but not
 * followed; at exit; and by the watcher when the maker is killed. */
START_TEST(tmpdir_never_outlives_its_maker)
{
    make_tmpdir();
    setenv("TMPDIR", tmpdir, 1);
    char dir[4096], err[SW_ERRLEN], path[4200], outside[128];
    snprintf(outside, sizeof outside, "%s/outside.txt", tmpdir);
    touch(outside, "keep me\n");

    ck_assert_msg(sw_tmpdir_make("test", dir, sizeof dir, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_ptr_nonnull(strstr(dir, "/stepwise-test-"));
    struct stat st;
    ck_assert_int_eq(stat(dir, &st), 0);
    ck_assert_int_eq(st.st_mode & 0777, 0700);
    snprintf(path, sizeof path, "%s/a.so", dir);
    touch(path, "x");
    snprintf(path, sizeof path, "%s/sub", dir);
    ck_assert_int_eq(mkdir(path, 0700), 0);
    snprintf(path, sizeof path, "%s/sub/deeper.log", dir);
    touch(path, "y");
    snprintf(path, sizeof path, "%s/link", dir);
    ck_assert_int_eq(symlink(outside, path), 0);
    ck_assert_int_eq(sw_tmpdir_remove(dir), 0);
    ck_assert_int_ne(access(dir, F_OK), 0);
    ck_assert_int_eq(access(outside, F_OK), 0); /* the link's target stays */
    ck_assert_int_eq(sw_tmpdir_remove(dir), 0); /* twice is harmless */

    /* A maker that exits: atexit. One killed with SIGKILL: the watcher. */
    for (int killed = 0; killed < 2; killed++) {
        int p[2];
        ck_assert_int_eq(pipe(p), 0);
        pid_t pid = fork();
        ck_assert_int_ge(pid, 0);
        if (pid == 0) {
            char d[4096], e[SW_ERRLEN], f[4200];
            if (sw_tmpdir_make("test", d, sizeof d, e, sizeof e) != SW_OK)
                _exit(1);
            snprintf(f, sizeof f, "%s/p0.so", d);
            FILE *out = fopen(f, "w");
            if (out)
                fclose(out);
            if (write(p[1], d, strlen(d) + 1) < 0)
                _exit(1);
            if (killed)
                raise(SIGKILL);
            exit(0);
        }
        close(p[1]);
        char made[4096] = "";
        ck_assert_int_gt(read(p[0], made, sizeof made - 1), 0);
        close(p[0]);
        int status;
        ck_assert_int_eq(waitpid(pid, &status, 0), pid);
        ck_assert_int_eq(killed ? WIFSIGNALED(status) : WIFEXITED(status), 1);
        ck_assert_msg(gone_within(made, 5), "%s is still there after its maker %s", made,
                      killed ? "was killed" : "exited");
    }
    ck_assert_int_eq(access(outside, F_OK), 0);
    unsetenv("TMPDIR");
    remove_tmpdir();
}
END_TEST

Suite *make_gradebook_suite(void);
Suite *make_gradebook_suite(void)
{
    Suite *s = suite_create("gradebook");
    TCase *tc = tcase_create("gradebook");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, tmpdir_never_outlives_its_maker);
    suite_add_tcase(s, tc);
    return s;
}
