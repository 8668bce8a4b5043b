/* The submissions named on grade's command line: a file as it is, a
 * directory as every entry in it. Invariants: nothing named is dropped
 * without a row (an entry that is not graded gets one with its reason); a
 * symbolic link is never followed to a submission (lstat, then open with
 * O_NOFOLLOW); nothing is opened in a way that could block (O_NONBLOCK, a
 * FIFO refused by the type of the descriptor it gave). */
#include "cli/grade.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "plugin/plugin_headers.h"
#include "util/escape.h"

/* What a name says it is: 1 a trace (.trace, .csv in any case: a
 * spreadsheet's or another system's RING.CSV is one), 2 a plugin (.so,
 * .c: lower case, as the compiler reads them), -2 a plugin's extension in
 * another case (.C is C++ to a compiler), 0 neither. */
static int kind_of(const char *name)
{
    size_t len = strlen(name);
    static const char *const traces[] = { ".trace", ".csv" }, *const plugins[] = { ".so", ".c" };
    for (int i = 0; i < 2; i++) {
        size_t n = strlen(traces[i]);
        if (len > n && strcasecmp(name + len - n, traces[i]) == 0)
            return 1;
        n = strlen(plugins[i]);
        if (len > n && strcasecmp(name + len - n, plugins[i]) == 0)
            return strcmp(name + len - n, plugins[i]) == 0 ? 2 : -2;
    }
    return 0;
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(((const grade_entry *)a)->path, ((const grade_entry *)b)->path);
}

static int same_file(const struct stat *a, const struct stat *b)
{
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

static int add_place(grade_list *l, const struct stat *st, const char *real)
{
    if (l->nplaces == l->places_cap) {
        int cap = l->places_cap ? 2 * l->places_cap : 32;
        grade_place *p = realloc(l->places, (size_t)cap * sizeof *p);
        if (!p)
            return SW_ENOMEM;
        l->places = p;
        l->places_cap = cap;
    }
    grade_place *p = &l->places[l->nplaces];
    p->dev = st->st_dev;
    p->ino = st->st_ino;
    p->real = NULL;
    if (real && !(p->real = strdup(real)))
        return SW_ENOMEM;
    l->nplaces++;
    return SW_OK;
}

/* A row for an entry that is not graded, with its reason. */
static int refuse(grade_list *l, const char *path, const char *why)
{
    if (l->ignored == l->refused_cap) {
        int cap = l->refused_cap ? 2 * l->refused_cap : 16;
        grade_entry *r = realloc(l->refused, (size_t)cap * sizeof *r);
        if (!r)
            return SW_ENOMEM;
        l->refused = r;
        l->refused_cap = cap;
    }
    grade_entry *e = &l->refused[l->ignored];
    memset(e, 0, sizeof *e);
    if (!(e->path = strdup(path)))
        return SW_ENOMEM;
    e->status = GRADE_SKIPPED;
    e->failing_step = -1;
    e->part = -1; /* of no part (a .md beside the plugin is not its chain part) */
    snprintf(e->kind, sizeof e->kind, "not-graded");
    snprintf(e->message, sizeof e->message, "%s", why);
    l->ignored++;
    return SW_OK;
}

/* The kind of a file that is not a regular one, in words. */
static const char *type_words(mode_t mode)
{
    return S_ISDIR(mode) ? "a directory" : S_ISFIFO(mode) ? "a FIFO (named pipe)"
         : S_ISSOCK(mode) ? "a socket" : S_ISCHR(mode) || S_ISBLK(mode) ? "a device"
         : "not a regular file";
}

/* Whether the resolved path lies in (or is) the resolved directory dir. */
static int lies_in(const char *path, const char *dir)
{
    size_t n = strlen(dir);
    return strncmp(path, dir, n) == 0 && (path[n] == '/' || path[n] == '\0' || n == 1);
}

/* Why the symbolic link at path is not graded. dir: the resolved
 * submissions directory it sits in, or NULL when it was named itself. */
static void link_reason(const char *path, const char *dir, const struct stat *assign_st,
                        char *why, size_t len)
{
    char target[PATH_MAX], shown[200], real[PATH_MAX];
    ssize_t n = readlink(path, target, sizeof target - 1);
    target[n > 0 ? n : 0] = '\0';
    sw_escape(target, 120, shown, sizeof shown);
    struct stat st;
    if (stat(path, &st) == 0 && same_file(&st, assign_st))
        snprintf(why, len, "not graded: a symbolic link to the assignment");
    else if (dir && (!realpath(path, real) || !lies_in(real, dir)))
        snprintf(why, len, "not graded: a symbolic link to '%s', outside the submissions "
                 "directory; links are never followed", shown);
    else
        snprintf(why, len, "not graded: a symbolic link to '%s'; links are never followed "
                 "(copy the file itself in)", shown);
}

/* Whether path (named name, in the resolved submissions directory dir, or
 * named itself when dir is NULL) is to be graded: 1, or 0 with why filled.
 * *st gets what lstat said (its mode 0 when it failed). */
static int judge(const char *path, const char *name, const char *dir, const struct stat *assign_st,
                 struct stat *st, char *why, size_t len)
{
    memset(st, 0, sizeof *st);
    if (lstat(path, st) != 0) {
        snprintf(why, len, "not graded: cannot be read: %s", strerror(errno));
        return 0;
    }
    if (S_ISLNK(st->st_mode)) {
        link_reason(path, dir, assign_st, why, len);
        return 0;
    }
    if (S_ISDIR(st->st_mode)) {
        snprintf(why, len, "not a submission: a directory; only the files directly in the "
                 "submissions directory are graded");
        return 0;
    }
    if (!S_ISREG(st->st_mode)) {
        snprintf(why, len, "not a submission: %s, not a regular file", type_words(st->st_mode));
        return 0;
    }
    if (same_file(st, assign_st)) {
        snprintf(why, len, "not graded: the assignment itself");
        return 0;
    }
    if (dir && name[0] == '.') {
        snprintf(why, len, "not graded: a hidden file (its name starts with a dot)");
        return 0;
    }
    sw_headers hd;
    char unused[SW_ERRLEN];
    size_t nlen = strlen(name), plen = strlen(path);
    if (kind_of(name) == 0 && nlen > 2 && strcmp(name + nlen - 2, ".h") == 0 &&
        sw_headers_find(path, 1, &hd, unused, sizeof unused) == 0 && hd.sources > 0) {
        if (hd.sources == 1)
            snprintf(why, len, GRADE_HEADER_BUILT);
        else
            snprintf(why, len, GRADE_HEADER_SHARED "%d of them, and a folder's headers go with its one .c "
                     "only, unless every .c in it is one student's", hd.sources);
        return 0;
    }
    if (kind_of(name) <= 0) {
        const char *dot = strrchr(name, '.');
        char ext[80];
        if (kind_of(name) < 0) {
            sw_escape(dot, 24, ext, sizeof ext);
            snprintf(why, len, "not graded: a %s file; a plugin ends in lower-case .c or .so (rename it)", ext);
        } else if (dot && dot != name) {
            sw_escape(dot, 24, ext, sizeof ext);
            snprintf(why, len, "not a submission: a %s file; traces end in .trace or .csv, plugins "
                     "in .so or .c", ext);
        } else
            snprintf(why, len, "not a submission: a file without an extension; traces end in "
                     ".trace or .csv, plugins in .so or .c");
        return 0;
    }
    /* In a folder, x.so beside x.c is its build (an upload often holds
     * both, the .so built on another machine): the source is graded. */
    if (dir && nlen > 3 && strcmp(name + nlen - 3, ".so") == 0 && plen < PATH_MAX) {
        char source[PATH_MAX + 1], shown[200];
        struct stat cs;
        memcpy(source, path, plen - 2);
        memcpy(source + plen - 2, "c", 2);
        if (lstat(source, &cs) == 0 && S_ISREG(cs.st_mode)) {
            sw_escape(strrchr(source, '/') ? strrchr(source, '/') + 1 : source, 80, shown, sizeof shown);
            snprintf(why, len, "not graded: a build of '%s' beside it, which is graded (a source "
                     "and its build are one submission)", shown);
            return 0;
        }
    }
    /* Opened as it will be read: never through a link, never waiting on a
     * FIFO; the descriptor's own type and identity decide. */
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat fst;
    if (fd < 0) {
        snprintf(why, len, "not graded: cannot be opened: %s", errno == ELOOP ? "it is now a "
                 "symbolic link" : strerror(errno));
        return 0;
    }
    int ok = fstat(fd, &fst) == 0;
    close(fd);
    if (!ok || !S_ISREG(fst.st_mode) || !same_file(&fst, st)) {
        snprintf(why, len, "not graded: it changed while it was being read");
        return 0;
    }
    return 1;
}

/* The last row added (to the submissions or to the refused). */
static grade_entry *last_row(grade_list *l, int graded)
{
    return graded ? &l->items[l->n - 1] : &l->refused[l->ignored - 1];
}

static int grade_list_add(grade_list *l, const char *path, int plugin);

/* Judge one entry and add it to the submissions or to the refused; rel is
 * what the roster matches. */
static int take(grade_list *list, const char *path, const char *name, const char *rel,
                const char *dir, const struct stat *assign_st)
{
    struct stat st;
    char why[400];
    int graded = judge(path, name, dir, assign_st, &st, why, sizeof why);
    int rc = graded ? grade_list_add(list, path, kind_of(name) == 2) : refuse(list, path, why);
    if (rc == SW_OK && !(last_row(list, graded)->rel = strdup(rel)))
        rc = SW_ENOMEM;
    if (rc == SW_OK && st.st_mode)
        rc = add_place(list, &st, NULL);
    return rc;
}

/* Whether the resolved path real is, or is inside, one submission's folder
 * of a Gradescope export: a component named submission_ and digits whose
 * parent holds the export's submission_metadata.yml (into meta). The
 * files there, its folders' included, are the student's upload. */
static int upload_in_export(const char *real, char *meta, size_t metalen)
{
    for (const char *c = real; *c;) {
        const char *end = strchr(c, '/');
        size_t n = end ? (size_t)(end - c) : strlen(c);
        int digits = n > 11 && strncmp(c, "submission_", 11) == 0;
        for (size_t i = 11; digits && i < n; i++)
            digits = c[i] >= '0' && c[i] <= '9';
        struct stat st;
        if (digits && snprintf(meta, metalen, "%.*ssubmission_metadata.yml", (int)(c - real), real) > 0 &&
            lstat(meta, &st) == 0 && S_ISREG(st.st_mode))
            return 1;
        c += n;
        while (*c == '/')
            c++;
    }
    return 0;
}

static int a_submission_folder(const char *real)
{
    char meta[PATH_MAX + 32];
    return upload_in_export(real, meta, sizeof meta);
}

/* How deep folders are walked with a roster: Moodle's and Gradescope's
 * one level, a student's own folder inside them, and one more. */
#define WALK_DEPTH 4

/* How many entries a folder inside the directory named may bring, its
 * own folders' included: a student's upload, whose every file would be a
 * row (and a worker), cannot swell the gradebook past what it reads back. */
#define FOLDER_ENTRIES 64
/* And the directory named itself: every submission in it is graded (no
 * entry may push a classmate's out), and at most this many others are
 * listed, the rest counted in one row. */
#define DIR_REFUSED 1000

/* What is left of a folder's entries, and whether its row saying so is in. */
typedef struct walk_budget {
    int left, said, dropped;
    const char *folder, *rel; /* its path, and the path the roster matches */
} walk_budget;

/* The directory named: the entries refused since *before count against
 * its budget; past it, their rows are dropped and counted. */
static void trim_refused(grade_list *list, int *before, walk_budget *b)
{
    int added = list->ignored - *before, keep = added < b->left ? added : b->left;
    b->left -= keep;
    while (list->ignored > *before + keep) {
        grade_entry *e = &list->refused[--list->ignored];
        free(e->path);
        free(e->rel);
        b->dropped++;
    }
    *before = list->ignored;
}

/* Every entry of the directory path (rel below the directory named,
 * top: that directory resolved), its folders walked with a roster; b:
 * what is left of the entries of the directory named (depth 0) or of its
 * folder that path is in. */
static int collect_dir(grade_list *list, const char *path, const char *rel, const char *top,
                       const struct stat *assign_st, int depth, walk_budget *b)
{
    DIR *d = opendir(path);
    if (!d)
        return refuse(list, path, "not graded: a directory that cannot be read");
    int rc = SW_OK, before = list->ignored;
    for (struct dirent *e; rc == SW_OK && (e = readdir(d));) {
        if (depth == 0)
            trim_refused(list, &before, b);
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (depth > 0 && b->left-- <= 0) {
            if (!b->said++) {
                rc = refuse(list, b->folder, "not graded beyond its first 64 entries: a folder of a "
                            "class holds at most 64 files and folders, its folders' included");
                if (rc == SW_OK && !(last_row(list, 0)->rel = strdup(b->rel)))
                    rc = SW_ENOMEM;
            }
            break;
        }
        char sub[PATH_MAX], subrel[PATH_MAX];
        /* Joined once: "class/" or "class//" as given names "class/a.trace". */
        size_t plen = strlen(path);
        while (plen > 1 && path[plen - 1] == '/')
            plen--;
        int root = plen == 1 && path[0] == '/';
        int n = snprintf(sub, sizeof sub, "%.*s%s%s", (int)plen, path, root ? "" : "/", e->d_name);
        int m = snprintf(subrel, sizeof subrel, "%s%s%s", rel, rel[0] ? "/" : "", e->d_name);
        struct stat st;
        if (n < 0 || (size_t)n >= sizeof sub || m < 0 || (size_t)m >= sizeof subrel) {
            rc = refuse(list, e->d_name, "not graded: its path is too long");
            continue;
        }
        int is_dir = lstat(sub, &st) == 0 && S_ISDIR(st.st_mode);
        if (list->roster && is_dir && e->d_name[0] != '.' && depth < WALK_DEPTH) {
            /* A download's folder: walked, never through a link (lstat said
             * a directory), and remembered so no output goes into it. */
            rc = add_place(list, &st, NULL);
            walk_budget own = { FOLDER_ENTRIES, 0, 0, sub, subrel };
            if (rc == SW_OK)
                rc = collect_dir(list, sub, subrel, top, assign_st, depth + 1, depth ? b : &own);
            before = list->ignored; /* the folder's rows are its own budget's */
            continue;
        }
        if (list->roster && depth == 0 && strcmp(e->d_name, "submission_metadata.yml") == 0 &&
            lstat(sub, &st) == 0 && S_ISREG(st.st_mode) && a_submission_folder(top)) {
            /* in a student's folder: a file of the upload, never who submitted it */
            rc = refuse(list, sub, "not graded: a submission_metadata.yml inside a submission's folder "
                        "is the student's upload; only the export's (the folder above) is read");
            if (rc == SW_OK && !(last_row(list, 0)->rel = strdup(subrel)))
                rc = SW_ENOMEM;
            continue;
        }
        if (list->roster && depth == 0 && strcmp(e->d_name, "submission_metadata.yml") == 0 &&
            lstat(sub, &st) == 0 && S_ISREG(st.st_mode)) {
            /* Gradescope's export: who submitted each submission_ID folder
             * (the export's own, rather than one found above it) */
            free(list->gs_metadata);
            if (!(list->gs_metadata = strdup(sub)))
                rc = SW_ENOMEM;
            /* read, never a row of the gradebook */
            if (rc == SW_OK)
                rc = add_place(list, &st, NULL);
            continue;
        }
        rc = take(list, sub, e->d_name, subrel, top, assign_st);
    }
    closedir(d);
    if (depth == 0) {
        trim_refused(list, &before, b);
        if (rc == SW_OK && b->dropped) {
            char why[200];
            snprintf(why, sizeof why, "and %d more entries not graded (none of them a submission): at most %d "
                     "are listed", b->dropped, DIR_REFUSED);
            rc = refuse(list, b->folder, why);
            if (rc == SW_OK && !(last_row(list, 0)->rel = strdup(b->rel)))
                rc = SW_ENOMEM;
        }
    }
    return rc;
}

static void sort_from(grade_entry *items, int first, int n)
{
    if (n > first)
        qsort(items + first, (size_t)(n - first), sizeof items[0], cmp_names);
}

/* A regrade names one student's folder or file of a Gradescope export:
 * the metadata is then in the folder above it, or the one above that;
 * never in a submission's own folder, which holds what the student
 * uploaded. */
static int metadata_above(grade_list *list, const char *real)
{
    char dir[PATH_MAX], meta[PATH_MAX + 32];
    if (upload_in_export(real, meta, sizeof meta)) /* the export's, however deep the file */
        return (list->gs_metadata = strdup(meta)) ? SW_OK : SW_ENOMEM;
    snprintf(dir, sizeof dir, "%s", real);
    for (int up = 0; up < 2 && !list->gs_metadata; up++) {
        char *slash = strrchr(dir, '/');
        if (!slash || slash == dir)
            break;
        *slash = '\0';
        if (a_submission_folder(dir))
            continue;
        struct stat st;
        snprintf(meta, sizeof meta, "%s/submission_metadata.yml", dir);
        if (lstat(meta, &st) == 0 && S_ISREG(st.st_mode) && !(list->gs_metadata = strdup(meta)))
            return SW_ENOMEM;
    }
    return SW_OK;
}

int grade_collect(grade_list *list, const char *arg, const struct stat *assign_st)
{
    struct stat st;
    int first = list->n, first_refused = list->ignored;
    char real_arg[PATH_MAX];
    if (list->roster && realpath(arg, real_arg) && metadata_above(list, real_arg) != SW_OK)
        return sw_cli_error("grade: out of memory");
    if (stat(arg, &st) != 0 || !S_ISDIR(st.st_mode)) {
        /* A file named itself: no directory listing, the same rules. */
        struct stat lst;
        if (lstat(arg, &lst) != 0)
            return sw_cli_error("grade: '%.200s': %s", arg, strerror(errno));
        const char *slash = strrchr(arg, '/');
        /* The roster reads the path as named, without "./" and "../". */
        const char *rel = arg;
        while (rel[0] == '.' && (rel[1] == '/' || (rel[1] == '.' && rel[2] == '/')))
            rel += rel[1] == '/' ? 2 : 3;
        while (*rel == '/')
            rel++;
        if (take(list, arg, slash ? slash + 1 : arg, rel, NULL, assign_st) != SW_OK)
            return sw_cli_error("grade: out of memory");
        return SW_EXIT_OK;
    }
    char real[PATH_MAX];
    if (!realpath(arg, real))
        return sw_cli_error("grade: cannot resolve the directory '%.200s': %s", arg,
                            strerror(errno));
    /* The roster sees the directory's own name first: a student's folder
     * or a submission_ID named alone is matched as in the whole export. */
    const char *own = strrchr(real, '/');
    own = own && own[1] ? own + 1 : "";
    int rc = add_place(list, &st, real);
    walk_budget whole = { DIR_REFUSED, 0, 0, arg, list->roster ? own : "" };
    if (rc == SW_OK)
        rc = collect_dir(list, arg, whole.rel, real, assign_st, 0, &whole);
    if (rc != SW_OK)
        return sw_cli_error("grade: out of memory");
    sort_from(list->items, first, list->n);
    sort_from(list->refused, first_refused, list->ignored);
    return SW_EXIT_OK;
}


/* The submissions directory that the resolved directory real is in or
 * under, by identity (each directory up to /) and by resolved path; NULL. */
const char *grade_inside_submissions(const grade_list *l, const char *real)
{
    char cur[PATH_MAX];
    snprintf(cur, sizeof cur, "%s", real);
    for (;;) {
        struct stat st;
        int known = stat(cur, &st) == 0;
        for (int i = 0; i < l->nplaces; i++) {
            const grade_place *p = &l->places[i];
            if (p->real && ((known && st.st_dev == p->dev && st.st_ino == p->ino) || lies_in(real, p->real)))
                return p->real;
        }
        char *slash = strrchr(cur, '/');
        if (!slash || slash == cur)
            break;
        *slash = '\0';
    }
    return NULL;
}

static int grade_list_add(grade_list *l, const char *path, int plugin)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 32;
        grade_entry *items = realloc(l->items, (size_t)cap * sizeof *items);
        if (!items)
            return SW_ENOMEM;
        l->items = items;
        l->cap = cap;
    }
    grade_entry *e = &l->items[l->n];
    memset(e, 0, sizeof *e);
    e->path = strdup(path);
    if (!e->path)
        return SW_ENOMEM;
    e->plugin = plugin;
    e->who = SW_ROSTER_NONE;
    e->part = -1;
    struct stat st;
    if (lstat(path, &st) == 0)
        e->mtime = (long long)st.st_mtime;
    l->n++;
    return SW_OK;
}
