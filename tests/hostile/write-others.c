/* Destroying others' work, before and after it is graded: truncates every
 * classmate's trace (and writes junk in it), overwrites every classmate's .c
 * with one that does not compile, truncates every .so, appends to the
 * assignment, truncates a classmate's trace in the directory beside the
 * class (../outside/), and drops a new file in the submissions directory.
 * Safety without a sandbox: it writes only regular files (never through a
 * link: O_NOFOLLOW, lstat) whose real path lies in this test run's
 * directory (/swrun-RUN-...). Every honest classmate must keep a
 * byte-identical file and a "pass". */
#define EVIL_FAMILY "write-others"
#define EVIL_EXPENSIVE
#include "evil.h"

static int in_test_run(const char *path)
{
    char real[EVIL_PATH], want[32];
    if (!realpath(path, real))
        return 0;
    snprintf(want, sizeof want, "/swrun-%.6s-", EVIL_TOKEN);
    return strstr(real, want) != NULL;
}

static int ends(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a > b && strcmp(s + a - b, suffix) == 0;
}

static void spoil(const char *path, int append)
{
    struct stat st;
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (strncmp(base, "write-others", 12) == 0 || strncmp(base, "swevil-", 7) == 0)
        return;
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode) || !in_test_run(path))
        return;
    const char *junk = ends(path, ".c") ? "#error SWEVIL:write-others was here\n"
                                        : "# SWEVIL:write-others was here\n";
    int flags = O_WRONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | (append ? O_APPEND : O_TRUNC);
    int fd = open(path, flags);
    if (fd < 0)
        return;
    if (!ends(path, ".so")) {
        ssize_t r = write(fd, junk, strlen(junk));
        (void)r;
    }
    close(fd);
}

static void spoil_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    for (struct dirent *e; (e = readdir(d));) {
        char path[EVIL_PATH + 300];
        snprintf(path, sizeof path, "%.4000s/%.255s", dir, e->d_name);
        if (ends(e->d_name, ".trace") || ends(e->d_name, ".csv") || ends(e->d_name, ".c") ||
            ends(e->d_name, ".so"))
            spoil(path, 0);
    }
    closedir(d);
}

static void evil_attack(void)
{
    static evil_grader g;
    if (evil_grader_info(&g) != 0)
        return;
    for (int i = 0; i < g.ndirs; i++) {
        char path[EVIL_PATH + 300];
        spoil_dir(g.dirs[i]);
        snprintf(path, sizeof path, "%.4000s/../outside", g.dirs[i]);
        spoil_dir(path);
        snprintf(path, sizeof path, "%.4000s/swevil-%s-write-others-new.trace", g.dirs[i], EVIL_TOKEN);
        evil_write_file(path, "# stepwise trace 1\n", 19, O_TRUNC);
    }
    if (g.assignment[0])
        spoil(g.assignment, 1);
}
