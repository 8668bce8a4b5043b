/* The gradebook's ground (issue 21): temporary directories that never
 * outlive their maker, even one killed with SIGKILL; output paths resolved
 * before anything is written (/dev/stdout on a pipe, devices in place);
 * CSV fields neutralised against formulas and escaped; and the lesson
 * progress file read under the input-file rules (a FIFO, a link to
 * /dev/zero, a 2 GiB sparse file: refused at once, never waited on). */
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

#include "app/progress.h"
#include "stepwise/base.h"
#include "util/clock.h"
#include "util/csv.h"
#include "util/outfile.h"
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

/* ---- output paths ------------------------------------------------------------ */

/* /dev/stdout on a pipe is standard output itself (no temporary, no
 * rename); /dev/null is written in place; a directory is refused; a
 * regular file is resolved through its link. */
START_TEST(outfile_targets)
{
    make_tmpdir();
    char err[SW_ERRLEN], path[128], link[128];
    sw_outfile_target t;
    ck_assert_int_eq(sw_outfile_resolve("/dev/null", &t, err, sizeof err), SW_OK);
    ck_assert(t.direct && !t.is_stdout);
    ck_assert_str_eq(t.path, "/dev/null");
    ck_assert_int_eq(sw_outfile_resolve(tmpdir, &t, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "is a directory"));
    snprintf(path, sizeof path, "%s/grades.csv", tmpdir);
    snprintf(link, sizeof link, "%s/link.csv", tmpdir);
    ck_assert_int_eq(symlink("grades.csv", link), 0);
    ck_assert_int_eq(sw_outfile_resolve(link, &t, err, sizeof err), SW_OK);
    ck_assert(!t.direct && !t.exists);
    ck_assert_str_eq(t.path, path);

    int p[2];
    ck_assert_int_eq(pipe(p), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        close(p[0]);
        dup2(p[1], STDOUT_FILENO);
        close(p[1]);
        sw_outfile o;
        char e[SW_ERRLEN];
        if (sw_outfile_open(&o, "/dev/stdout", e, sizeof e) != SW_OK || !o.is_stdout)
            _exit(1);
        fputs("a,b\r\n", o.f);
        _exit(sw_outfile_commit(&o, e, sizeof e) == SW_OK ? 0 : 2);
    }
    close(p[1]);
    char got[64] = "";
    ssize_t n = read(p[0], got, sizeof got - 1);
    close(p[0]);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    ck_assert_int_eq((int)n, 5);
    ck_assert_str_eq(got, "a,b\r\n");
    remove_tmpdir();
}
END_TEST

/* ---- CSV fields ---------------------------------------------------------------- */

static const char *csv_of(const char *text)
{
    static char buf[512];
    FILE *f = fmemopen(buf, sizeof buf, "w");
    ck_assert_ptr_nonnull(f);
    sw_csv_field(f, text);
    fputc('\0', f);
    fclose(f);
    return buf;
}

START_TEST(csv_fields_are_inert)
{
    /* OWASP's formula starts get a leading quote; the rest is kept. */
    ck_assert_str_eq(csv_of("=HYPERLINK(\"http://x\",\"y\")"),
                     "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
    ck_assert_str_eq(csv_of("+1"), "'+1");
    ck_assert_str_eq(csv_of("-1+2"), "'-1+2");
    ck_assert_str_eq(csv_of("@SUM(A1)"), "'@SUM(A1)");
    /* Tab and CR are escaped as text, and the \ then starts the field. */
    ck_assert_str_eq(csv_of("\t=1"), "\\x09=1");
    ck_assert_str_eq(csv_of("\r=1"), "\\x0d=1");
    /* Control characters and escape sequences never reach the file raw. */
    ck_assert_str_eq(csv_of("a\033[2Jb\nc"), "a\\x1b[2Jb\\x0ac");
    ck_assert_str_eq(csv_of("caf\xc3\xa9 \xff"), "caf\xc3\xa9 \\xff");
    /* Quoting as RFC 4180 has it; backslashes kept; plain text as it is. */
    ck_assert_str_eq(csv_of("a,b"), "\"a,b\"");
    ck_assert_str_eq(csv_of("say \"hi\""), "\"say \"\"hi\"\"\"");
    ck_assert_str_eq(csv_of("C:\\class\\a.trace"), "C:\\class\\a.trace");
    ck_assert_str_eq(csv_of("Ada Lovelace"), "Ada Lovelace");
    ck_assert_str_eq(csv_of(""), "");
    ck_assert_str_eq(csv_of(NULL), "");
    ck_assert_str_eq(csv_of("a = b"), "a = b"); /* only the first character counts */
}
END_TEST


/* Reading a gradebook back (regrading): what sw_csv_field writes reads back
 * as written and writes again byte for byte; hostile files are refused
 * with their line, never overrun. */
static const char *csv_reject(const char *text, size_t len)
{
    static char err[SW_ERRLEN];
    sw_csv_doc d;
    err[0] = '\0';
    ck_assert_int_ne(sw_csv_parse("g.csv", text, len, &d, err, sizeof err), SW_OK);
    ck_assert_int_eq(d.nrows, 0);
    return err;
}

START_TEST(csv_reads_back)
{
    const char *cells[] = { "=cmd|' /C calc'!A0", "a,b", "say \"hi\"", "a\033[2Jb\nc", "",
                            "caf\xc3\xa9 \xff", "Ada Lovelace" };
    int n = (int)(sizeof cells / sizeof cells[0]);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    for (int i = 0; i < n; i++) {
        sw_csv_field(f, cells[i]);
        fputs(i + 1 < n ? "," : "\r\n", f);
    }
    fclose(f);
    sw_csv_doc d;
    char err[SW_ERRLEN] = "";
    ck_assert_int_eq(sw_csv_parse("g.csv", buf, len, &d, err, sizeof err), SW_OK);
    ck_assert_int_eq(d.nrows, 1);
    ck_assert_int_eq(d.rows[0].n, n);
    ck_assert_str_eq(d.rows[0].cells[0], "'=cmd|' /C calc'!A0");
    ck_assert_str_eq(d.rows[0].cells[1], "a,b");
    ck_assert_str_eq(d.rows[0].cells[3], "a\\x1b[2Jb\\x0ac");
    /* Written again, the line is the same bytes: a kept row does not drift. */
    char *again = NULL;
    size_t alen = 0;
    f = open_memstream(&again, &alen);
    for (int i = 0; i < n; i++) {
        sw_csv_field(f, d.rows[0].cells[i]);
        fputs(i + 1 < n ? "," : "\r\n", f);
    }
    fclose(f);
    ck_assert_str_eq(again, buf);
    free(again);
    free(buf);
    sw_csv_doc_free(&d);
    /* LF line ends, a BOM, a quoted line break, a last line without end. */
    const char lf[] = "\xef\xbb\xbf" "a,b\n\"x\ny\",2\nz,3";
    ck_assert_int_eq(sw_csv_parse("g.csv", lf, sizeof lf - 1, &d, err, sizeof err), SW_OK);
    ck_assert_int_eq(d.nrows, 3);
    ck_assert_str_eq(d.rows[0].cells[0], "a");
    ck_assert_str_eq(d.rows[1].cells[0], "x\ny");
    ck_assert_int_eq(d.rows[2].line, 4);
    sw_csv_doc_free(&d);
    /* Hostile: each refused with its line. */
    ck_assert_str_eq(csv_reject("a,\"b\n", 5), "g.csv:1: a quoted cell runs to the end of the file "
                     "(a missing closing quote)");
    ck_assert_str_eq(csv_reject("a\nb\0c\n", 6), "g.csv:2: a NUL byte; not a CSV gradebook");
    ck_assert_str_eq(csv_reject("a\"b\n", 4), "g.csv:1: a quote inside an unquoted cell");
    ck_assert_str_eq(csv_reject("\"a\"b\n", 5), "g.csv:1: text after a closing quote");
    size_t big = SW_CSV_CELL_MAX + 10;
    char *long_cell = malloc(big);
    memset(long_cell, 'x', big);
    ck_assert_ptr_nonnull(strstr(csv_reject(long_cell, big), "a cell longer than"));
    char *many = malloc(2 * (SW_CSV_COLS_MAX + 1));
    for (int i = 0; i < SW_CSV_COLS_MAX + 1; i++)
        many[2 * i] = 'x', many[2 * i + 1] = ',';
    ck_assert_ptr_nonnull(strstr(csv_reject(many, 2 * (SW_CSV_COLS_MAX + 1) - 1), "more than"));
    free(many);
    free(long_cell);
}
END_TEST

/* ---- the progress file ----------------------------------------------------------- */

/* Each hostile progress file: refused at once with what it is, the lesson
 * starts at page 0, and saving leaves the file as it is. */
START_TEST(progress_under_input_rules)
{
    make_tmpdir();
    char state[128], dir[160], path[192], err[SW_ERRLEN + 400];
    snprintf(state, sizeof state, "%s/state", tmpdir);
    snprintf(dir, sizeof dir, "%s/stepwise", state);
    snprintf(path, sizeof path, "%s/progress", dir);
    setenv("XDG_STATE_HOME", state, 1);
    ck_assert_int_eq(sw_progress_check(err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_progress_readable(err, sizeof err), SW_OK); /* none yet */
    static const struct {
        const char *what, *says;
    } cases[] = {
        { "fifo", "is a FIFO" },
        { "zero", "is a device" },
        { "sparse", "is larger than 1024 KiB" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        unlink(path);
        if (strcmp(cases[i].what, "fifo") == 0)
            ck_assert_int_eq(mkfifo(path, 0600), 0);
        else if (strcmp(cases[i].what, "zero") == 0)
            ck_assert_int_eq(symlink("/dev/zero", path), 0);
        else {
            int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
            ck_assert_int_ge(fd, 0);
            ck_assert_int_eq(ftruncate(fd, (off_t)2 << 30), 0);
            close(fd);
        }
        /* Judged without reading: a FIFO opened for reading would block
         * (the case would hang, and fail at Check's timeout), and the
         * sparse file's message is about its size. No clock here: a loaded
         * machine must not fail it. */
        ck_assert_int_eq(sw_progress_readable(err, sizeof err), SW_EIO);
        ck_assert_msg(strstr(err, cases[i].says), "%s: %s", cases[i].what, err);
        ck_assert_int_eq(sw_progress_get("intro.lesson"), 0);
        ck_assert_int_eq(sw_progress_set("intro.lesson", 2, err, sizeof err), SW_EIO);
        struct stat st;
        ck_assert_int_eq(lstat(path, &st), 0);
        if (strcmp(cases[i].what, "fifo") == 0)
            ck_assert(S_ISFIFO(st.st_mode));
        else if (strcmp(cases[i].what, "zero") == 0)
            ck_assert(S_ISLNK(st.st_mode));
        else
            ck_assert(st.st_size == (off_t)2 << 30);
    }
    /* A readable file again: read, merged, kept. */
    unlink(path);
    touch(path, "other.lesson 3\nbroken line\n");
    ck_assert_int_eq(sw_progress_readable(err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_progress_set("intro.lesson", 2, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_progress_get("intro.lesson"), 2);
    ck_assert_int_eq(sw_progress_get("other.lesson"), 3);
    unsetenv("XDG_STATE_HOME");
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
    tcase_add_test(tc, outfile_targets);
    tcase_add_test(tc, csv_fields_are_inert);
    tcase_add_test(tc, csv_reads_back);
    tcase_add_test(tc, progress_under_input_rules);
    suite_add_tcase(s, tc);
    return s;
}
