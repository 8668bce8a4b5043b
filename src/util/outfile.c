/* Output files written whole or not at all. Invariants: the temporary lives
 * in the target's directory (so rename is atomic), is created with mkstemp
 * (so two writers never share one), gets the mode the target has or would
 * get, and exists only between open and commit or abort; nothing but a
 * regular file or a new name is ever renamed over; what standard output
 * already writes to is written through it (never renamed over under it). */
#include "util/outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/utf8.h"

#ifndef NAME_MAX
#define NAME_MAX 255
#endif

static const char tmp_suffix[] = ".tmp.XXXXXX";

/* Follow symbolic links from path to the file they name (which need not
 * exist yet); out gets the final path. 0, or an errno value. */
static int follow_links(const char *path, char *out, size_t len)
{
    char cur[SW_OUTFILE_PATH_MAX], target[SW_OUTFILE_PATH_MAX];
    if (strlen(path) >= sizeof cur)
        return ENAMETOOLONG;
    strcpy(cur, path);
    for (int hops = 0; hops < 40; hops++) {
        struct stat st;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode)) {
            if (strlen(cur) >= len)
                return ENAMETOOLONG;
            strcpy(out, cur);
            return 0;
        }
        ssize_t n = readlink(cur, target, sizeof target - 1);
        if (n < 0)
            return errno;
        target[n] = '\0';
        if (target[0] == '/') {
            strcpy(cur, target);
        } else {
            /* Relative to the link's own directory. */
            char *slash = strrchr(cur, '/');
            size_t dirlen = slash ? (size_t)(slash - cur) + 1 : 0;
            if (dirlen + (size_t)n >= sizeof cur)
                return ENAMETOOLONG;
            memmove(cur + dirlen, target, (size_t)n + 1);
        }
    }
    return ELOOP;
}

/* The directory part of path ("." when none) into dir. */
static void dir_of(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, len, ".");
    else if (slash == path)
        snprintf(dir, len, "/");
    else
        snprintf(dir, len, "%.*s", (int)(slash - path), path);
}

/* "DIR/NAME.tmp.XXXXXX" with NAME cut (on a character boundary) so the last
 * component fits in NAME_MAX bytes. */
static int temp_name(const char *path, char *out, size_t len)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t dirlen = (size_t)(base - path), baselen = strlen(base);
    size_t room = NAME_MAX - (sizeof tmp_suffix - 1);
    baselen = sw_utf8_clip(base, baselen, room);
    if (dirlen + baselen + sizeof tmp_suffix > len)
        return ENAMETOOLONG;
    memcpy(out, path, dirlen + baselen);
    memcpy(out + dirlen + baselen, tmp_suffix, sizeof tmp_suffix);
    return 0;
}

/* Whether st, an existing file, is the one standard output writes to (a
 * pipe, a FIFO, a regular file or a socket; a terminal or another device is
 * opened on its own, like any device). */
static int is_our_stdout(const struct stat *st)
{
    struct stat out;
    return !S_ISCHR(st->st_mode) && fstat(STDOUT_FILENO, &out) == 0 && out.st_dev == st->st_dev &&
           out.st_ino == st->st_ino;
}

int sw_outfile_resolve(const char *path, sw_outfile_target *t, char *err, size_t errlen)
{
    memset(t, 0, sizeof *t);
    if (!path || strcmp(path, "-") == 0) {
        t->is_stdout = t->direct = 1;
        return SW_OK;
    }
    if (!*path || strlen(path) >= SW_OUTFILE_PATH_MAX) {
        snprintf(err, errlen, "output path is empty or longer than %d bytes", SW_OUTFILE_PATH_MAX - 1);
        return SW_EINVAL;
    }
    struct stat st;
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            snprintf(err, errlen, "'%.200s' is a directory; give a file name to write", path);
            return SW_EINVAL;
        }
        if (is_our_stdout(&st)) {
            /* /dev/stdout, /proc/self/fd/1, or the file stdout was sent to:
             * one stream, so what is written stays in order. */
            t->is_stdout = t->direct = 1;
            return SW_OK;
        }
        if (S_ISBLK(st.st_mode) || S_ISSOCK(st.st_mode)) {
            snprintf(err, errlen, "'%.200s' is a %s; give a file name to write", path,
                     S_ISBLK(st.st_mode) ? "block device" : "socket");
            return SW_EINVAL;
        }
        if (!S_ISREG(st.st_mode)) {
            /* A character device or a FIFO, by the name given: a link such as
             * /dev/stdout to a pipe has no name a temporary could go beside. */
            memcpy(t->path, path, strlen(path) + 1);
            t->direct = t->exists = 1;
            t->st = st;
            return SW_OK;
        }
    }
    int e = follow_links(path, t->path, sizeof t->path);
    if (e) {
        snprintf(err, errlen, "cannot create '%.200s': %s", path, strerror(e));
        return SW_EIO;
    }
    t->exists = stat(t->path, &t->st) == 0;
    char dir[SW_OUTFILE_PATH_MAX];
    dir_of(t->path, dir, sizeof dir);
    struct stat dst;
    errno = 0;
    if (stat(dir, &dst) != 0 || !S_ISDIR(dst.st_mode) || access(dir, W_OK | X_OK) != 0) {
        e = errno ? errno : ENOTDIR;
        snprintf(err, errlen, "cannot create '%.200s': %s", path, strerror(e));
        return SW_EIO;
    }
    return SW_OK;
}

int sw_outfile_check(const char *path, char *err, size_t errlen)
{
    sw_outfile_target t;
    return sw_outfile_resolve(path, &t, err, errlen);
}

int sw_outfile_open(sw_outfile *o, const char *path, char *err, size_t errlen)
{
    memset(o, 0, sizeof *o);
    sw_outfile_target t;
    int rc = sw_outfile_resolve(path, &t, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (t.is_stdout) {
        o->f = stdout;
        o->is_stdout = o->direct = 1;
        return SW_OK;
    }
    memcpy(o->path, t.path, sizeof o->path);
    snprintf(o->shown, sizeof o->shown, "%s", path);
    if (t.direct) {
        /* A device, a FIFO, a terminal: write to it as `cat > it` would. */
        int fd = open(o->path, O_WRONLY | O_NOCTTY);
        if (fd < 0 || !(o->f = fdopen(fd, "w"))) {
            snprintf(err, errlen, "cannot open '%.200s' for writing: %s", path, strerror(errno));
            if (fd >= 0)
                close(fd);
            return SW_EIO;
        }
        o->direct = 1;
        return SW_OK;
    }
    int e = temp_name(o->path, o->tmp, sizeof o->tmp);
    int fd = e ? -1 : mkstemp(o->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "cannot create '%.200s': %s", path, strerror(e ? e : errno));
        o->tmp[0] = '\0';
        return SW_EIO;
    }
    mode_t mode;
    if (t.exists) {
        mode = t.st.st_mode & 07777;
        if (fchown(fd, t.st.st_uid, t.st.st_gid) != 0)
            mode &= 0777; /* not ours to give away: no set-id bits either */
    } else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    if (fchmod(fd, mode) != 0 || !(o->f = fdopen(fd, "w"))) {
        snprintf(err, errlen, "cannot create '%.200s': %s", path, strerror(errno));
        close(fd);
        unlink(o->tmp);
        o->tmp[0] = '\0';
        return SW_EIO;
    }
    return SW_OK;
}

const char *sw_outfile_name(const sw_outfile *o)
{
    return o->is_stdout ? "standard output" : o->shown;
}

int sw_outfile_commit(sw_outfile *o, char *err, size_t errlen)
{
    int e = 0;
    if (!o->f) {
        snprintf(err, errlen, "cannot write '%.200s': not open", sw_outfile_name(o));
        return SW_EIO;
    }
    errno = 0;
    if (fflush(o->f) != 0 || ferror(o->f))
        e = errno ? errno : EIO;
    if (!e && !o->direct && fsync(fileno(o->f)) != 0 && errno != EINVAL)
        e = errno;
    if (!o->is_stdout && fclose(o->f) != 0 && !e)
        e = errno ? errno : EIO;
    o->f = NULL;
    if (!e && o->tmp[0] && rename(o->tmp, o->path) != 0)
        e = errno;
    if (e) {
        snprintf(err, errlen, "cannot write '%.200s': %s", sw_outfile_name(o), strerror(e));
        sw_outfile_abort(o);
        return SW_EIO;
    }
    o->tmp[0] = '\0';
    return SW_OK;
}

void sw_outfile_abort(sw_outfile *o)
{
    if (o->f) {
        if (o->is_stdout)
            fflush(o->f);
        else
            fclose(o->f);
    }
    o->f = NULL;
    if (o->tmp[0])
        unlink(o->tmp);
    o->tmp[0] = '\0';
}
