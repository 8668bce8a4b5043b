/* Lesson progress on disk. Invariants: the file is only ever replaced whole
 * (sw_outfile: temporary and rename), and every read-merge-write runs under
 * an fcntl lock on progress.lock, so concurrent updates are serialised and
 * none is lost; readers need no lock, since a rename is atomic. */
#include "app/progress.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lesson/lesson.h"
#include "stepwise/base.h"
#include "util/outfile.h"

#define DIR_MAX 2048
#define LINE_MAX_BYTES 1100

/* The progress directory; 0 or SW_EIO when neither variable is usable. */
static int state_dir(char *dir, size_t len, char *err, size_t errlen)
{
    const char *state = getenv("XDG_STATE_HOME"), *home = getenv("HOME");
    int n;
    if (state && *state == '/')
        n = snprintf(dir, len, "%s/stepwise", state);
    else if (home && *home)
        n = snprintf(dir, len, "%s/.local/state/stepwise", home);
    else {
        snprintf(err, errlen, "neither XDG_STATE_HOME nor HOME is set, so there is nowhere to save progress");
        return SW_EIO;
    }
    if (n < 0 || (size_t)n >= len) {
        snprintf(err, errlen, "the progress directory's path is longer than %zu bytes", len - 1);
        return SW_EIO;
    }
    return SW_OK;
}

/* mkdir -p dir (mode 0700), naming the component that fails. */
static int make_dirs(char *dir, char *err, size_t errlen)
{
    for (char *p = dir + 1;; p++) {
        if (*p != '/' && *p != '\0')
            continue;
        char saved = *p;
        *p = '\0';
        struct stat st;
        int ok = mkdir(dir, 0700) == 0 || (errno == EEXIST && stat(dir, &st) == 0 && S_ISDIR(st.st_mode));
        if (!ok) {
            int e = errno == EEXIST ? ENOTDIR : errno;
            snprintf(err, errlen, "cannot make the progress directory '%.300s': %s", dir, strerror(e));
            *p = saved;
            return SW_EIO;
        }
        *p = saved;
        if (!saved)
            return SW_OK;
    }
}

int sw_progress_check(char *err, size_t errlen)
{
    char dir[DIR_MAX];
    if (state_dir(dir, sizeof dir, err, errlen) != SW_OK)
        return SW_EIO;
    return make_dirs(dir, err, errlen);
}

/* Split "NAME PAGES" at its last space; 1 with *name_len and *pages. */
static int parse_line(const char *line, size_t *name_len, int *pages)
{
    size_t len = strcspn(line, "\n");
    const char *sp = NULL;
    for (size_t i = 0; i < len; i++)
        if (line[i] == ' ')
            sp = line + i;
    if (!sp || sp == line)
        return 0;
    char *end;
    long d = strtol(sp + 1, &end, 10);
    if (end == sp + 1 || end != line + len || d < 0 || d > SW_LESSON_MAX_PAGES)
        return 0;
    *name_len = (size_t)(sp - line);
    *pages = (int)d;
    return 1;
}

static int same_name(const char *line, size_t name_len, const char *file)
{
    return strlen(file) == name_len && memcmp(line, file, name_len) == 0;
}

static int get_from(const char *path, const char *file)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    char line[LINE_MAX_BYTES];
    int done = 0, d;
    size_t nlen;
    while (fgets(line, sizeof line, f))
        if (parse_line(line, &nlen, &d) && same_name(line, nlen, file))
            done = d;
    fclose(f);
    return done;
}

int sw_progress_get(const char *file)
{
    char dir[DIR_MAX], path[DIR_MAX + 16], err[SW_ERRLEN];
    if (state_dir(dir, sizeof dir, err, sizeof err) != SW_OK)
        return 0;
    snprintf(path, sizeof path, "%s/progress", dir);
    return get_from(path, file);
}

/* Rewrite path with file's entry set to done, keeping every other entry. */
static int rewrite(const char *path, const char *file, int done, char *err, size_t errlen)
{
    sw_outfile out;
    int rc = sw_outfile_open(&out, path, err, errlen);
    if (rc != SW_OK)
        return rc;
    FILE *in = fopen(path, "r");
    char line[LINE_MAX_BYTES];
    int d;
    size_t nlen;
    while (in && fgets(line, sizeof line, in))
        if (parse_line(line, &nlen, &d) && !same_name(line, nlen, file))
            fputs(line, out.f);
    if (in)
        fclose(in);
    fprintf(out.f, "%s %d\n", file, done);
    return sw_outfile_commit(&out, err, errlen);
}

int sw_progress_set(const char *file, int done, char *err, size_t errlen)
{
    if (!*file || strlen(file) > 255 || strpbrk(file, "\n\r")) {
        snprintf(err, errlen, "a lesson file name must be 1 to 255 bytes without line breaks");
        return SW_EINVAL;
    }
    char dir[DIR_MAX], path[DIR_MAX + 16], lock[DIR_MAX + 16];
    if (state_dir(dir, sizeof dir, err, errlen) != SW_OK || make_dirs(dir, err, errlen) != SW_OK)
        return SW_EIO;
    snprintf(path, sizeof path, "%s/progress", dir);
    snprintf(lock, sizeof lock, "%s/progress.lock", dir);
    int fd = open(lock, O_RDWR | O_CREAT, 0600);
    if (fd < 0) {
        snprintf(err, errlen, "cannot open '%.300s': %s", lock, strerror(errno));
        return SW_EIO;
    }
    struct flock fl = { .l_type = F_WRLCK, .l_whence = SEEK_SET };
    int rc;
    while ((rc = fcntl(fd, F_SETLKW, &fl)) != 0 && errno == EINTR)
        ;
    if (rc != 0) {
        snprintf(err, errlen, "cannot lock '%.300s': %s", lock, strerror(errno));
        close(fd);
        return SW_EIO;
    }
    rc = done <= get_from(path, file) ? SW_OK : rewrite(path, file, done, err, errlen);
    close(fd); /* releases the lock */
    return rc;
}
