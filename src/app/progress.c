/* Lesson progress on disk. Invariants: the file is only ever replaced whole
 * (sw_outfile: temporary and rename), and every read-merge-write runs under
 * an fcntl lock on progress.lock, so concurrent updates are serialised and
 * none is lost; readers need no lock, since a rename is atomic. It is read
 * under the input-file rules (util/infile.h): anything but a regular file
 * of sane size is refused at once, never waited on or read to its end. */
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
#include "util/infile.h"
#include "util/outfile.h"

#define DIR_MAX 2048
#define LINE_MAX_BYTES 1100
/* The largest progress file read: thousands of lessons' lines. */
#define PROGRESS_MAX (1024 * 1024)

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

/* Read the progress file whole under the input-file rules (util/infile:
 * a regular file only, opened without blocking, at most PROGRESS_MAX
 * bytes), so a FIFO, a link to /dev/zero or a huge sparse file is refused
 * at once. 0 with *text (NULL when there is no file yet; else free it), or
 * SW_EIO with err saying what the file is. */
static int read_all(const char *path, char **text, char *err, size_t errlen)
{
    *text = NULL;
    struct stat st;
    const char *what;
    int fd = sw_infile_open(path, &st, &what);
    if (fd < 0) {
        if (!what && errno == ENOENT)
            return SW_OK;
        snprintf(err, errlen, "the progress file '%.300s' %s%s", path,
                 what ? "is " : "cannot be read: ", what ? what : strerror(errno));
        return SW_EIO;
    }
    size_t len;
    int rc = st.st_size > PROGRESS_MAX ? 1 : sw_infile_read(fd, PROGRESS_MAX, text, &len);
    int e = errno;
    close(fd);
    if (rc == 1)
        snprintf(err, errlen, "the progress file '%.300s' is larger than %d KiB, which no progress "
                 "file is", path, PROGRESS_MAX >> 10);
    else if (rc != 0)
        snprintf(err, errlen, "the progress file '%.300s' cannot be read: %s", path, strerror(e));
    return rc == 0 ? SW_OK : SW_EIO;
}

/* The next line of text at *at ("NAME PAGES", without its newline): 1 with
 * *line and *len, 0 at the end. */
static int next_line(const char **at, const char **line, size_t *len)
{
    if (!*at || !**at)
        return 0;
    *line = *at;
    *len = strcspn(*at, "\n");
    *at += *len + ((*at)[*len] == '\n');
    return 1;
}

static int get_from(const char *text, const char *file)
{
    const char *at = text, *line;
    size_t len, nlen;
    int done = 0, d;
    while (next_line(&at, &line, &len))
        if (len < LINE_MAX_BYTES && parse_line(line, &nlen, &d) && same_name(line, nlen, file))
            done = d;
    return done;
}

/* The progress file's path into path; 0 or SW_EIO. */
static int progress_path(char *path, size_t len, char *err, size_t errlen)
{
    char dir[DIR_MAX];
    if (state_dir(dir, sizeof dir, err, errlen) != SW_OK)
        return SW_EIO;
    snprintf(path, len, "%s/progress", dir);
    return SW_OK;
}

int sw_progress_readable(char *err, size_t errlen)
{
    char path[DIR_MAX + 16], *text;
    if (progress_path(path, sizeof path, err, errlen) != SW_OK)
        return SW_OK; /* nowhere to keep it: sw_progress_check says so */
    int rc = read_all(path, &text, err, errlen);
    free(text);
    return rc;
}

int sw_progress_get(const char *file)
{
    char path[DIR_MAX + 16], err[SW_ERRLEN + 400], *text;
    if (progress_path(path, sizeof path, err, sizeof err) != SW_OK ||
        read_all(path, &text, err, sizeof err) != SW_OK || !text)
        return 0;
    int done = get_from(text, file);
    free(text);
    return done;
}

/* Rewrite path (whose contents are old, NULL when new) with file's entry
 * set to done, keeping every other entry. */
static int rewrite(const char *path, const char *old, const char *file, int done, char *err,
                   size_t errlen)
{
    sw_outfile out;
    int rc = sw_outfile_open(&out, path, err, errlen);
    if (rc != SW_OK)
        return rc;
    const char *at = old, *line;
    size_t len, nlen;
    int d;
    while (next_line(&at, &line, &len))
        if (len < LINE_MAX_BYTES && parse_line(line, &nlen, &d) && !same_name(line, nlen, file))
            fprintf(out.f, "%.*s\n", (int)len, line);
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
    int fd = open(lock, O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0600);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "cannot open '%.300s': %s", lock,
                 fd < 0 ? strerror(errno) : "not a regular file");
        if (fd >= 0)
            close(fd);
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
    char *text;
    rc = read_all(path, &text, err, errlen);
    if (rc == SW_OK && done > (text ? get_from(text, file) : 0))
        rc = rewrite(path, text, file, done, err, errlen);
    free(text);
    close(fd); /* releases the lock */
    return rc;
}

int sw_progress_next(const sw_lesson_entry *e, int n, int from)
{
    for (int k = 0; k < n; k++) {
        int i = ((from % n) + n + k) % n;
        if (e[i].title && sw_progress_get(e[i].file) < e[i].npages)
            return i;
    }
    return -1;
}
