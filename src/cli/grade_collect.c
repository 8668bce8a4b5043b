/* The submissions named on grade's command line: a file as it is, a
 * directory as the submissions in it (sorted by path, the assignment itself
 * left out). */
#include "cli/grade.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"

static int kind_of(const char *name)
{
    size_t len = strlen(name);
    static const char *const traces[] = { ".trace", ".csv" }, *const plugins[] = { ".so", ".c" };
    for (int i = 0; i < 2; i++) {
        size_t n = strlen(traces[i]);
        if (len > n && strcmp(name + len - n, traces[i]) == 0)
            return 1;
        n = strlen(plugins[i]);
        if (len > n && strcmp(name + len - n, plugins[i]) == 0)
            return 2;
    }
    return 0;
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(((const grade_entry *)a)->path, ((const grade_entry *)b)->path);
}

/* Add FILE, or the submissions in DIR (sorted, the assignment itself left out). */
int grade_collect(grade_list *list, const char *arg, const struct stat *assign_st)
{
    struct stat st;
    if (stat(arg, &st) != 0)
        return sw_cli_error("grade: '%.200s': %s", arg, strerror(errno));
    if (!S_ISDIR(st.st_mode)) {
        if (grade_list_add(list, arg, kind_of(arg) == 2) != SW_OK)
            return sw_cli_error("grade: out of memory");
        return SW_EXIT_OK;
    }
    DIR *d = opendir(arg);
    if (!d)
        return sw_cli_error("grade: cannot read the directory '%.200s': %s", arg, strerror(errno));
    int first = list->n;
    for (struct dirent *e; (e = readdir(d));) {
        int kind = e->d_name[0] == '.' ? 0 : kind_of(e->d_name);
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/%s", arg, e->d_name);
        if (!kind || stat(path, &st) != 0 || !S_ISREG(st.st_mode) ||
            (st.st_dev == assign_st->st_dev && st.st_ino == assign_st->st_ino)) {
            list->ignored += e->d_name[0] != '.' && kind == 0;
            continue;
        }
        if (grade_list_add(list, path, kind == 2) != SW_OK) {
            closedir(d);
            return sw_cli_error("grade: out of memory");
        }
    }
    closedir(d);
    if (list->n > first)
        qsort(list->items + first, (size_t)(list->n - first), sizeof list->items[0], cmp_names);
    return SW_EXIT_OK;
}
