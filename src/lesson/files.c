/* Lesson files on disk: reading one with a size bound, and listing a
 * directory's *.lesson files in name order (01-..., 02-...: the course
 * order). Invariants: nothing larger than SW_LESSON_MAX_BYTES is ever read,
 * and nothing waits: a FIFO or a device is refused, never opened blocking. */
#include "lesson/lesson.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/infile.h"

int sw_lesson_load(const char *path, sw_lesson *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    struct stat st;
    const char *what;
    int fd = sw_infile_open(path, &st, &what);
    if (fd < 0 && what) {
        snprintf(err, errlen, "%.200s: is %s; expected a lesson file (NAME.lesson)", path, what);
        return SW_EIO;
    }
    if (fd < 0) {
        snprintf(err, errlen, "%.200s: cannot open: %s", path, strerror(errno));
        return SW_EIO;
    }
    if (st.st_size > SW_LESSON_MAX_BYTES) {
        snprintf(err, errlen, "%.200s: file is %lld bytes; expected a lesson of at most %d bytes", path,
                 (long long)st.st_size, SW_LESSON_MAX_BYTES);
        close(fd);
        return SW_EIO;
    }
    char *buf;
    size_t len;
    int got = sw_infile_read(fd, SW_LESSON_MAX_BYTES, &buf, &len);
    int e = errno;
    close(fd);
    if (got > 0) {
        snprintf(err, errlen, "%.200s: file is larger than %d bytes; expected a shorter lesson", path,
                 SW_LESSON_MAX_BYTES);
        return SW_EIO;
    }
    if (got < 0) {
        snprintf(err, errlen, "%.200s: %s: %s", path, e == ENOMEM ? "out of memory" : "cannot read",
                 strerror(e));
        return e == ENOMEM ? SW_ENOMEM : SW_EIO;
    }
    int rc = sw_lesson_parse(path, buf, len, out, err, errlen);
    free(buf);
    return rc;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(((const sw_lesson_entry *)a)->file, ((const sw_lesson_entry *)b)->file);
}

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

void sw_lesson_list_free(sw_lesson_entry *entries, int n)
{
    for (int i = 0; entries && i < n; i++) {
        free(entries[i].path);
        free(entries[i].file);
        free(entries[i].title);
    }
    free(entries);
}

int sw_lesson_list(const char *dir, sw_lesson_entry **out, int *n, char *err, size_t errlen)
{
    *out = NULL;
    *n = 0;
    DIR *d = opendir(dir);
    if (!d) {
        snprintf(err, errlen, "%.200s: cannot list lessons: %s", dir, strerror(errno));
        return SW_EIO;
    }
    sw_lesson_entry *list = calloc(SW_LESSON_MAX_FILES, sizeof *list);
    if (!list) {
        closedir(d);
        snprintf(err, errlen, "%.200s: out of memory", dir);
        return SW_ENOMEM;
    }
    int count = 0, rc = SW_OK;
    struct dirent *de;
    static const char ext[] = ".lesson";
    while (rc == SW_OK && (de = readdir(d)) != NULL) {
        size_t len = strlen(de->d_name);
        if (de->d_name[0] == '.' || len <= sizeof ext - 1 ||
            strcmp(de->d_name + len - (sizeof ext - 1), ext) != 0)
            continue;
        size_t plen = strlen(dir) + 1 + len + 1;
        char *path = malloc(plen);
        if (!path) {
            rc = SW_ENOMEM;
            break;
        }
        snprintf(path, plen, "%s/%s", dir, de->d_name);
        struct stat st;
        if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) {
            free(path);
            continue;
        }
        if (count == SW_LESSON_MAX_FILES) {
            free(path);
            snprintf(err, errlen, "%.200s: more than %d lesson files; expected fewer", dir, SW_LESSON_MAX_FILES);
            rc = SW_EINVAL;
            break;
        }
        list[count].path = path;
        list[count].file = dup_string(de->d_name);
        count++;
        if (!list[count - 1].file)
            rc = SW_ENOMEM;
    }
    closedir(d);
    if (rc == SW_ENOMEM)
        snprintf(err, errlen, "%.200s: out of memory", dir);
    if (rc != SW_OK) {
        sw_lesson_list_free(list, count);
        return rc;
    }
    qsort(list, (size_t)count, sizeof *list, by_name);
    for (int i = 0; i < count; i++) {
        sw_lesson lesson;
        if (sw_lesson_load(list[i].path, &lesson, list[i].error, sizeof list[i].error) == SW_OK) {
            list[i].title = dup_string(lesson.title);
            list[i].npages = lesson.npages;
            sw_lesson_free(&lesson);
            if (!list[i].title) {
                sw_lesson_list_free(list, count);
                snprintf(err, errlen, "%.200s: out of memory", dir);
                return SW_ENOMEM;
            }
        }
    }
    *out = list;
    *n = count;
    return SW_OK;
}
