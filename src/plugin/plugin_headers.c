/* The headers built with a student's source: found in its folder by name
 * and type, in a fixed order, never through a link. */
#include "plugin/plugin_headers.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/escape.h"

static int ends_with(const char *name, const char *ext)
{
    size_t n = strlen(name), e = strlen(ext);
    return n > e && strcmp(name + n - e, ext) == 0;
}

/* A header's name as the jail takes it: no dot first, no control byte. */
static int header_name(const char *name)
{
    if (name[0] == '.' || !ends_with(name, ".h"))
        return 0;
    for (const unsigned char *c = (const unsigned char *)name; *c; c++)
        if (*c < 0x20 || *c == 0x7f)
            return 0;
    return 1;
}

/* Whether dir/name is a regular file itself (lstat: a link is not). */
static int regular(const char *dir, const char *name)
{
    char path[PATH_MAX + SW_HEADER_NAME_MAX + 256];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return lstat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(a, b);
}

int sw_headers_find(const char *src, int shared, sw_headers *h, char *err, size_t errlen)
{
    memset(h, 0, sizeof *h);
    const char *slash = strrchr(src, '/');
    if (!slash)
        snprintf(h->dir, sizeof h->dir, ".");
    else if (slash == src)
        snprintf(h->dir, sizeof h->dir, "/");
    else
        snprintf(h->dir, sizeof h->dir, "%.*s", (int)(slash - src), src);
    DIR *d = opendir(h->dir);
    if (!d)
        return 0; /* no folder to read: built alone, as before */
    int found = 0;
    char too_long[SW_HEADER_NAME_MAX] = "";
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] != '.' && ends_with(e->d_name, ".c") && regular(h->dir, e->d_name))
            h->sources++;
        else if (header_name(e->d_name) && regular(h->dir, e->d_name) &&
                 strlen(e->d_name) >= SW_HEADER_NAME_MAX)
            snprintf(too_long, sizeof too_long, "%.40s", e->d_name);
        else if (header_name(e->d_name) && regular(h->dir, e->d_name)) {
            if (found < SW_HEADERS_MAX)
                snprintf(h->name[found], SW_HEADER_NAME_MAX, "%.*s", SW_HEADER_NAME_MAX - 1, e->d_name);
            found++;
        }
    }
    closedir(d);
    if (shared && h->sources > 1) {
        h->withheld = found;
        return 0;
    }
    if (too_long[0]) {
        char shown[200];
        sw_escape(too_long, 40, shown, sizeof shown);
        snprintf(err, errlen, "its folder holds a header whose name ('%s...') is %d bytes or longer; a "
                 "header's name may be at most %d", shown, SW_HEADER_NAME_MAX, SW_HEADER_NAME_MAX - 1);
        return -1;
    }
    if (found > SW_HEADERS_MAX) {
        snprintf(err, errlen, "its folder holds %d headers (.h files); a plugin is built with at most %d",
                 found, SW_HEADERS_MAX);
        return -1;
    }
    h->n = found;
    qsort(h->name, (size_t)h->n, sizeof h->name[0], by_name);
    return 0;
}

int sw_headers_open(const sw_headers *h, int i)
{
    char path[PATH_MAX + SW_HEADER_NAME_MAX + 256];
    snprintf(path, sizeof path, "%s/%s", h->dir, h->name[i]);
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat st;
    if (fd >= 0 && (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
        close(fd);
        errno = EINVAL;
        return -1;
    }
    return fd;
}
