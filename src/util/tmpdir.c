/* Temporary directories that never outlive their maker. Invariant: while a
 * directory exists, its maker holds the write end of a pipe (close-on-exec,
 * and closed in every sandboxed child) whose read end a watcher process
 * blocks on; the read ends only when every holder has gone, however it
 * ended, and the watcher then removes the directory. The watcher is a
 * grandchild in its own session, so it is no child anybody waits for and a
 * Ctrl-C or a signal to the maker's process group does not reach it. */
#include "util/tmpdir.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/fds.h"

#define MADE_MAX 8
/* Directories below this depth are not descended into (nothing of ours nests). */
#define DEPTH_MAX 16

static struct made_dir {
    char path[PATH_MAX];
    pid_t owner;
    int hold;               /* our end of the watcher's pipe, or -1 */
} made[MADE_MAX];
static int atexit_done;

/* Empty the directory open at fd (which this takes over and closes). */
static int empty_dir(int fd, int depth)
{
    DIR *d = fdopendir(fd);
    if (!d) {
        close(fd);
        return -1;
    }
    int rc = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (unlinkat(dirfd(d), e->d_name, 0) == 0 || errno == ENOENT)
            continue;
        if (errno != EISDIR && errno != EPERM) {
            rc = -1;
            continue;
        }
        int sub = openat(dirfd(d), e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (sub >= 0 && depth < DEPTH_MAX)
            rc |= empty_dir(sub, depth + 1);
        else if (sub >= 0)
            close(sub);
        if (unlinkat(dirfd(d), e->d_name, AT_REMOVEDIR) != 0 && errno != ENOENT)
            rc = -1;
    }
    closedir(d);
    return rc;
}

int sw_tmpdir_remove(const char *dir)
{
    if (!dir || !*dir)
        return 0;
    for (int i = 0; i < MADE_MAX; i++)
        if (made[i].path[0] && strcmp(made[i].path, dir) == 0 && made[i].owner == getpid()) {
            made[i].path[0] = '\0';
            if (made[i].hold >= 0)
                close(made[i].hold); /* the watcher finds nothing left and ends */
            made[i].hold = -1;
        }
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT ? 0 : -1;
    int rc = empty_dir(fd, 0);
    if (rmdir(dir) != 0 && errno != ENOENT)
        rc = -1;
    return rc;
}

static void remove_all(void)
{
    for (int i = 0; i < MADE_MAX; i++)
        if (made[i].path[0] && made[i].owner == getpid()) {
            char path[PATH_MAX];
            memcpy(path, made[i].path, sizeof path);
            sw_tmpdir_remove(path);
        }
}

/* The watcher: no descriptor but the pipe, no terminal signals, no working
 * directory to keep busy; waits for the end of file, then removes dir
 * (again a few times: a compiler killed with its maker may still be
 * finishing a write). Never returns. */
static void watch(int fd, const char *dir)
{
    setsid();
    static const int ignored[] = { SIGINT, SIGQUIT, SIGHUP, SIGTSTP, SIGTTIN, SIGTTOU, SIGPIPE };
    for (size_t i = 0; i < sizeof ignored / sizeof ignored[0]; i++)
        signal(ignored[i], SIG_IGN);
    sw_close_fds(0, &fd, 1);
    if (chdir("/") != 0)
        _exit(1);
    char c;
    while (read(fd, &c, 1) < 0 && errno == EINTR)
        ;
    for (int tries = 0; tries < 20; tries++) {
        if (sw_tmpdir_remove(dir) == 0 && access(dir, F_OK) != 0)
            break;
        struct timespec pause = { 0, 50000000 };
        nanosleep(&pause, NULL);
    }
    _exit(0);
}

/* Start the watcher of dir; our end of its pipe, or -1. */
static int start_watcher(const char *dir)
{
    int p[2];
    if (pipe(p) != 0)
        return -1;
    fcntl(p[0], F_SETFD, FD_CLOEXEC);
    fcntl(p[1], F_SETFD, FD_CLOEXEC);
    pid_t pid = fork();
    if (pid == 0) {
        close(p[1]);
        pid_t watcher = fork();
        if (watcher == 0)
            watch(p[0], dir);
        _exit(watcher < 0);
    }
    close(p[0]);
    int status = 1;
    if (pid > 0)
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            ;
    if (pid < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        close(p[1]);
        return -1;
    }
    return p[1];
}

int sw_tmpdir_make(const char *kind, char *dir, size_t len, char *err, size_t errlen)
{
    int slot = -1;
    for (int i = 0; i < MADE_MAX && slot < 0; i++)
        if (!made[i].path[0])
            slot = i;
    if (slot < 0) {
        snprintf(err, errlen, "cannot make a temporary directory: %d are in use already", MADE_MAX);
        return SW_EIO;
    }
    const char *tmp = getenv("TMPDIR");
    char path[PATH_MAX], real[PATH_MAX];
    int n = snprintf(path, sizeof path, "%s/stepwise-%s-XXXXXX", tmp && *tmp ? tmp : "/tmp", kind);
    if (n < 0 || (size_t)n >= sizeof path) {
        snprintf(err, errlen, "cannot make a temporary directory: TMPDIR is too long");
        return SW_EIO;
    }
    if (!mkdtemp(path)) {
        snprintf(err, errlen, "cannot make a temporary directory in '%.200s': %s",
                 tmp && *tmp ? tmp : "/tmp", strerror(errno));
        return SW_EIO;
    }
    /* Absolute, so the watcher (working in /) and compilers find it. */
    int resolved = realpath(path, real) != NULL, e = errno;
    if (!resolved || strlen(real) >= len) {
        rmdir(path);
        snprintf(err, errlen, "cannot make a temporary directory: %s",
                 resolved ? "its path is too long" : strerror(e));
        return SW_EIO;
    }
    memcpy(made[slot].path, real, strlen(real) + 1);
    made[slot].owner = getpid();
    made[slot].hold = start_watcher(real);
    if (!atexit_done && atexit(remove_all) == 0)
        atexit_done = 1;
    snprintf(dir, len, "%s", real);
    return SW_OK;
}
