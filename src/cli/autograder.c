/* `stepwise autograder --assignment A -o autograder.zip`: Gradescope's
 * autograder bundle. The zip holds setup.sh (installs the build
 * dependencies, builds and installs stepwise from the source carried in the
 * bundle), run_autograder (grades /autograder/submission into
 * /autograder/results/results.json with `grade --gradescope`), the
 * assignment, and stepwise's source tree. Invariants: the assignment is
 * read (and its points checked) before anything is written; the zip is
 * written whole or not at all; the same inputs give the same bytes. */
#include "cli/cli.h"
#include "grade/homework.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade/assignment.h"
#include "plugin/sandbox.h"
#include "util/beside.h"
#include "util/outfile.h"
#include "util/tmpdir.h"
#include "util/zip.h"

static const char autograder_help[] =
    "usage: stepwise autograder --assignment A -o FILE.zip [--points WHAT=N]... [--source DIR]\n"
    "                           [--cpu S] [--memory MB] [--wall S] [--plugin-timeout S]\n"
    "       stepwise autograder --probe\n"
    "\n"
    "Writes Gradescope's autograder bundle for the assignment A: upload FILE.zip as a\n"
    "programming assignment's autograder and every submission is graded on its own,\n"
    "with one test per check of the assignment ('# points' lines, described in\n"
    "docs/trace-format.md). The zip holds setup.sh (apt-get installs the build\n"
    "dependencies; stepwise is built from the source in the bundle and installed),\n"
    "run_autograder (runs 'stepwise grade --gradescope' on /autograder/submission,\n"
    "or $AUTOGRADER_ROOT/submission), assignment.trace and stepwise/ (the source\n"
    "tree).\n"
    "\n"
    "options:\n"
    "  -o, --output FILE.zip  where to write the bundle (required)\n"
    "      --assignment A     the assignment (required)\n"
    "      --points WHAT=N    points for a check, e.g. header=1, 'x* y*=3', energy=1,\n"
    "                         order=1; when given they replace the assignment's '# points'\n"
    "      --source DIR       stepwise's source tree (default: the tree this binary was\n"
    "                         built in)\n"
    "      --cpu S, --memory MB, --wall S, --plugin-timeout S   grade's limits, passed on\n"
    "      --probe            exit 0 when plugins can be jailed here, saying how\n"
    "                         (namespaces, or a user of its own where a container\n"
    "                         refuses them), else 1 saying why\n"
    "  -h, --help             this help\n";

/* ---- the scripts ------------------------------------------------------------- */

static const char setup_sh[] =
    "#!/usr/bin/env bash\n"
    "# Gradescope runs this once, as root, when it builds the autograder's image\n"
    "# (written by 'stepwise autograder'). It installs stepwise's build\n"
    "# dependencies and builds and installs stepwise from the source in this\n"
    "# bundle (stepwise/), so the grader is the version the teacher bundled.\n"
    "set -eu\n"
    "cd \"$(dirname \"$0\")\"\n"
    "export DEBIAN_FRONTEND=noninteractive\n"
    "apt-get update -qq\n"
    "apt-get install -y -qq build-essential pkg-config libncurses-dev libseccomp-dev check tmux unzip\n"
    "make -C stepwise -j\"$(nproc)\" stepwise\n"
    "make -C stepwise install PREFIX=/usr/local\n"
    "stepwise autograder --probe || echo \"setup.sh: plugins cannot be jailed here: they will not be run\"\n";

/* The grading options are filled in where @OPTIONS@ stands. */
static const char run_autograder_head[] =
    "#!/bin/sh\n"
    "# Gradescope runs this for each submission, in a fresh container (written\n"
    "# by 'stepwise autograder'). It grades the files in $AUTOGRADER_ROOT/submission\n"
    "# (default /autograder) against the bundled assignment into\n"
    "# $AUTOGRADER_ROOT/results/results.json. Plugins run in stepwise's jail:\n"
    "# namespaces where the container allows them, else (as root) a user of the\n"
    "# jail's own, to which this folder is closed; never without a jail. Whatever\n"
    "# happens, a results.json is written, by the grader: one that fails scores 0\n"
    "# and says why.\n"
    "root=${AUTOGRADER_ROOT:-/autograder}\n"
    "sw=${STEPWISE:-stepwise}\n"
    "here=$(cd \"$(dirname \"$0\")\" && pwd)\n"
    "assignment=$root/source/assignment.trace\n"
    "[ -f \"$assignment\" ] || assignment=$here/assignment.trace\n"
    "results=$root/results/results.json\n"
    "mkdir -p \"$root/results\" \"$root/submission\"\n"
    "rm -f \"$results\"\n"
    "# A submission uploaded as a folder: its files are graded too (one level).\n"
    "set -- \"$root/submission\"\n"
    "for d in \"$root/submission\"/*/; do\n"
    "    [ -d \"$d\" ] && [ ! -L \"${d%/}\" ] && set -- \"$@\" \"${d%/}\"\n"
    "done\n"
    "# Whose submission it is: for parameters drawn per student (their e-mail).\n"
    "[ -f \"$root/submission_metadata.json\" ] && set -- --submission-metadata \"$root/submission_metadata.json\" \"$@\"\n"
    "# The bundle, the submission and the results are root's alone: a plugin,\n"
    "# run as another user, can read or write none of them.\n"
    "chmod go-rwx \"$root\" \"$root/source\" \"$root/results\" \"$root/submission\" \"$here\" 2>/dev/null\n"
    "if why=$(\"$sw\" autograder --probe 2>&1); then\n"
    "    echo \"run_autograder: $why\"\n"
    "else\n"
    "    echo \"run_autograder: plugins cannot be jailed in this container ($why); they are not run\"\n"
    "fi\n";

static const char run_autograder_tail[] =
    "rc=$?\n"
    "if [ \"$rc\" -gt 1 ] || [ ! -s \"$results\" ]; then\n"
    "    # The grader itself failed (not the submission's verdict): never leave\n"
    "    # Gradescope without a results.json, nor with one a plugin wrote.\n"
    "    printf '{\\n  \"score\": 0,\\n  \"output\": \"%s\",\\n  \"tests\": []\\n}\\n' \\\n"
    "        \"The autograder could not grade this submission (stepwise exit status $rc). Please tell your teacher.\" \\\n"
    "        > \"$results\"\n"
    "fi\n"
    "exit 0\n";

/* ---- the source tree ---------------------------------------------------------- */

static int src_dir_ok(const char *dir)
{
    char path[PATH_MAX + 64];
    struct stat st;
    snprintf(path, sizeof path, "%s/main.c", dir);
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Whether a file of the source tree goes into the bundle: sources, headers,
 * lessons, scripts, the man page; never build products or hidden files. */
static int wanted(const char *name)
{
    static const char *const ends[] = { ".c", ".h", ".lesson", ".md", ".sh", ".1" };
    if (name[0] == '.')
        return 0;
    size_t len = strlen(name);
    for (size_t i = 0; i < sizeof ends / sizeof ends[0]; i++) {
        size_t n = strlen(ends[i]);
        if (len > n && strcmp(name + len - n, ends[i]) == 0)
            return 1;
    }
    return 0;
}

static int read_all(const char *path, char **data, size_t *len, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    *data = NULL;
    *len = 0;
    if (!f) {
        snprintf(err, errlen, "%.300s: %s", path, strerror(errno));
        return SW_EIO;
    }
    size_t cap = 0;
    char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) {
        if (*len + n > cap) {
            size_t ncap = cap ? 2 * cap : 65536;
            while (ncap < *len + n)
                ncap *= 2;
            char *p = realloc(*data, ncap);
            if (!p) {
                fclose(f);
                snprintf(err, errlen, "%.300s: out of memory", path);
                return SW_ENOMEM;
            }
            *data = p;
            cap = ncap;
        }
        memcpy(*data + *len, buf, n);
        *len += n;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) {
        snprintf(err, errlen, "%.300s: read error", path);
        return SW_EIO;
    }
    return SW_OK;
}

static int add_file(sw_zip *z, const char *path, const char *name, char *err, size_t errlen)
{
    char *data;
    size_t len;
    struct stat st;
    int rc = read_all(path, &data, &len, err, errlen);
    if (rc == SW_OK)
        rc = sw_zip_add(z, name, data, len, stat(path, &st) == 0 && (st.st_mode & 0111) ? 0755 : 0644,
                        err, errlen);
    free(data);
    return rc;
}

/* Every wanted regular file under dir/rel (sorted, links not followed) as
 * stepwise/rel/... */
static int add_tree(sw_zip *z, const char *dir, const char *rel, int recurse, char *err,
                    size_t errlen)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    struct dirent **names;
    int n = scandir(path, &names, NULL, alphasort);
    if (n < 0) {
        snprintf(err, errlen, "%.300s: %s", path, strerror(errno));
        return SW_EIO;
    }
    int rc = SW_OK;
    for (int i = 0; i < n; i++) {
        const char *name = names[i]->d_name;
        char sub[PATH_MAX], file[PATH_MAX + 8], zname[PATH_MAX + 16];
        struct stat st;
        snprintf(sub, sizeof sub, "%s/%s", rel, name);
        snprintf(file, sizeof file, "%s/%s", dir, sub);
        if (rc == SW_OK && name[0] != '.' && lstat(file, &st) == 0) {
            if (S_ISDIR(st.st_mode) && recurse)
                rc = add_tree(z, dir, sub, recurse, err, errlen);
            else if (S_ISREG(st.st_mode) && wanted(name)) {
                snprintf(zname, sizeof zname, "stepwise/%s", sub);
                rc = add_file(z, file, zname, err, errlen);
            }
        }
        free(names[i]);
    }
    free(names);
    return rc;
}

static int add_source(sw_zip *z, const char *dir, char *err, size_t errlen)
{
    static const char *const trees[] = { "src", "include", "lessons" };
    char path[PATH_MAX + 32];
    int rc = SW_OK;
    for (size_t i = 0; rc == SW_OK && i < sizeof trees / sizeof trees[0]; i++)
        rc = add_tree(z, dir, trees[i], 1, err, errlen);
    if (rc == SW_OK)
        rc = add_tree(z, dir, "examples", 0, err, errlen);
    static const char *const files[] = { "Makefile", "tests/deps.sh", "docs/stepwise.1" };
    for (size_t i = 0; rc == SW_OK && i < sizeof files / sizeof files[0]; i++) {
        char name[64];
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        snprintf(name, sizeof name, "stepwise/%s", files[i]);
        rc = add_file(z, path, name, err, errlen);
    }
    return rc;
}

/* ---- the assignment ------------------------------------------------------------- */

/* The assignment's text, its "# points" lines replaced by the --points
 * options when there are any. */
static char *bundled_assignment(const char *path, const char **points, int npoints, size_t *len,
                                char *err, size_t errlen)
{
    char *text;
    size_t text_len;
    if (read_all(path, &text, &text_len, err, errlen) != SW_OK)
        return NULL;
    char *out = malloc(text_len + (size_t)npoints * 128 + 2);
    if (!out) {
        free(text);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    size_t used = 0;
    int header_done = 0;
    for (size_t at = 0; at < text_len;) {
        char *nl = memchr(text + at, '\n', text_len - at);
        size_t line_len = nl ? (size_t)(nl - (text + at)) + 1 : text_len - at;
        const char *line = text + at;
        const char *k = line + 1;
        while (k < line + line_len && *k == ' ')
            k++;
        int is_points = line[0] == '#' && line_len > 8 && strncmp(k, "points ", 7) == 0;
        int is_meta = line[0] == '#';
        int is_part = is_meta && line_len > 6 && strncmp(k, "part", 4) == 0 && (k[4] == ' ' || k[4] == ':');
        if ((!is_meta || is_part) && !header_done && npoints > 0) {
            /* a reference trace: the points go before its header row; a
             * homework of parts: before the first part, shared by all */
            header_done = 1;
            for (int i = 0; i < npoints; i++) {
                const char *eq = strrchr(points[i], '=');
                used += (size_t)sprintf(out + used, "# points %.*s: %s\n",
                                        (int)(eq - points[i]), points[i], eq + 1);
            }
        }
        if (!(is_points && npoints > 0)) {
            memcpy(out + used, line, line_len);
            used += line_len;
        }
        at += line_len;
    }
    if (!header_done && npoints > 0)
        for (int i = 0; i < npoints; i++) {
            const char *eq = strrchr(points[i], '=');
            used += (size_t)sprintf(out + used, "# points %.*s: %s\n", (int)(eq - points[i]),
                                    points[i], eq + 1);
        }
    free(text);
    *len = used;
    return out;
}

/* Read the bundled text as an assignment, so a mistake shows now, not in
 * Gradescope: 0 or SW_EINVAL with err naming the line. */
static int check_bundled(const char *text, size_t len, double *trace_max, double *plugin_max,
                         char *err, size_t errlen)
{
    char dir[PATH_MAX], path[PATH_MAX + 32];
    if (sw_tmpdir_make("autograder", dir, sizeof dir, err, errlen) != SW_OK)
        return SW_EIO;
    snprintf(path, sizeof path, "%s/assignment.trace", dir);
    FILE *f = fopen(path, "wb");
    int rc = SW_EIO;
    if (f) {
        fwrite(text, 1, len, f);
        rc = fclose(f) == 0 ? SW_OK : SW_EIO;
    }
    static sw_homework h;
    char msg[SW_ERRLEN + 600];
    if (rc == SW_OK && sw_homework_read(&h, path, NULL, msg, sizeof msg) != SW_OK) {
        /* The message names the temporary: give the option's view. */
        const char *colon = strstr(msg, "assignment.trace:");
        char *rest = NULL;
        long line = colon ? strtol(colon + 17, &rest, 10) : 0;
        if (colon && rest && rest[0] == ':')
            snprintf(err, errlen, "the assignment with the --points lines, line %ld:%.400s", line,
                     rest + 1);
        else
            snprintf(err, errlen, "the assignment with the --points lines: %.400s", msg);
        rc = SW_EINVAL;
    } else if (rc != SW_OK)
        snprintf(err, errlen, "cannot write %.300s", path);
    *trace_max = *plugin_max = 0;
    for (int p = 0; rc == SW_OK && p < h.nparts; p++) {
        const sw_points_set *set = &h.parts[p].a.points;
        for (int i = 0; i < set->n; i++) {
            sw_points_kind k = set->items[i].kind;
            if (k != SW_POINTS_ORDER && k != SW_POINTS_STABILITY)
                *trace_max += set->items[i].points;
            if (k != SW_POINTS_HEADER)
                *plugin_max += set->items[i].points;
        }
    }
    sw_homework_free(&h);
    sw_tmpdir_remove(dir);
    return rc;
}

/* ---- the command ----------------------------------------------------------------- */

int sw_cmd_autograder(int argc, char **argv)
{
    const char *assignment = NULL, *output = NULL, *source = NULL;
    const char *points[SW_POINTS_MAX];
    const char *limits[8];
    int npoints = 0, nlimits = 0, probe = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(autograder_help, stdout);
            return SW_EXIT_OK;
        }
        if (strcmp(a, "--probe") == 0) {
            probe = 1;
            continue;
        }
        if (i + 1 >= argc)
            return sw_cli_error("autograder: %.40s needs a value; see 'stepwise autograder --help'", a);
        const char *val = argv[++i];
        double d;
        if (strcmp(a, "--assignment") == 0)
            assignment = val;
        else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0)
            output = val;
        else if (strcmp(a, "--source") == 0)
            source = val;
        else if (strcmp(a, "--points") == 0) {
            const char *eq = strrchr(val, '=');
            if (!eq || eq == val || strlen(val) > 100 || strchr(val, '\n'))
                return sw_cli_error("autograder: --points wants WHAT=N (header=1, 'x* y*=3', "
                                    "energy=1, order=1), not '%.60s'", val);
            if (npoints == SW_POINTS_MAX)
                return sw_cli_error("autograder: at most %d --points", SW_POINTS_MAX);
            points[npoints++] = val;
        } else if (strcmp(a, "--cpu") == 0 || strcmp(a, "--wall") == 0 ||
                   strcmp(a, "--memory") == 0 || strcmp(a, "--plugin-timeout") == 0) {
            int rc = a[2] == 'c'   ? sw_cli_range(a, val, 0.1, 3600, "seconds", &d)
                     : a[2] == 'w' ? sw_cli_range(a, val, 0.1, 86400, "seconds", &d)
                     : a[2] == 'm' ? sw_cli_range(a, val, 64, 65536, "MiB", &d)
                                   : sw_cli_range(a, val, 0.01, 3600, "seconds", &d);
            if (rc != SW_EXIT_OK)
                return rc;
            for (int k = 0; k < nlimits; k += 2)
                if (strcmp(limits[k], a) == 0)
                    return sw_cli_error("autograder: %s is given twice", a);
            limits[nlimits++] = a;
            limits[nlimits++] = val;
        } else
            return sw_cli_error("autograder: unknown option '%.40s'; see 'stepwise autograder --help'", a);
    }
    char err[SW_ERRLEN + 700];
    if (probe) {
        if (sw_sandbox_probe(err, sizeof err) != SW_OK) {
            fprintf(stderr, "%s\n", err);
            return SW_EXIT_FAIL;
        }
        const char *forced = getenv("STEPWISE_JAIL");
        printf("the jail can be built here: plugins are graded in it (%s, seccomp, %s, limits)\n",
               sw_jail_kind_now() != SW_JAIL_UID           ? "namespaces"
               : forced && strcmp(forced, "uid") == 0 ? "a user of its own, as STEPWISE_JAIL=uid asks"
                                                      : "a user of its own: this system refuses user namespaces",
               sw_jail_landlock_abi() ? "Landlock" : "no Landlock: this kernel does not enable it");
        return SW_EXIT_OK;
    }
    if (!assignment || !output)
        return sw_cli_error("autograder needs --assignment A and -o FILE.zip; see 'stepwise "
                            "autograder --help'");
    static sw_homework asg;
    int read = sw_homework_read(&asg, assignment, NULL, err, sizeof err);
    sw_homework_free(&asg);
    if (read != SW_OK)
        return sw_cli_error("%s", err);
    char srcdir[PATH_MAX];
    if (source)
        snprintf(srcdir, sizeof srcdir, "%s", source);
    else if (!sw_beside_binary("src", src_dir_ok, srcdir, sizeof srcdir))
        return sw_cli_error("autograder: no stepwise source tree beside this binary; give "
                            "--source DIR (a checkout of stepwise: the bundle builds it in "
                            "Gradescope's container)");
    else {
        char *slash = strrchr(srcdir, '/'); /* DIR/src -> DIR */
        if (slash)
            *slash = '\0';
    }
    char probe_path[PATH_MAX + 16];
    snprintf(probe_path, sizeof probe_path, "%s/src", srcdir);
    if (!src_dir_ok(probe_path))
        return sw_cli_error("autograder: --source '%.200s' is not a stepwise source tree (no "
                            "src/main.c)", srcdir);
    size_t text_len;
    char *text = bundled_assignment(assignment, points, npoints, &text_len, err, sizeof err);
    if (!text)
        return sw_cli_error("autograder: %s", err);
    double trace_max, plugin_max;
    if (check_bundled(text, text_len, &trace_max, &plugin_max, err, sizeof err) != SW_OK) {
        free(text);
        return sw_cli_error("autograder: %s", err);
    }
    /* run_autograder, with the limits. */
    char opts[512] = "";
    for (int i = 0; i < nlimits; i++) {
        size_t used = strlen(opts);
        snprintf(opts + used, sizeof opts - used, " %s", limits[i]);
    }
    char run[sizeof run_autograder_head + sizeof run_autograder_tail + 700];
    snprintf(run, sizeof run, "%s\"$sw\" grade --assignment \"$assignment\" --gradescope "
             "\"$results\"%s \"$@\"\n%s", run_autograder_head, opts, run_autograder_tail);

    sw_outfile o;
    if (sw_outfile_open(&o, output, err, sizeof err) != SW_OK) {
        free(text);
        return sw_cli_error("autograder: %s", err);
    }
    sw_zip z;
    sw_zip_begin(&z, o.f);
    int rc = sw_zip_add(&z, "setup.sh", setup_sh, sizeof setup_sh - 1, 0755, err, sizeof err);
    if (rc == SW_OK)
        rc = sw_zip_add(&z, "run_autograder", run, strlen(run), 0755, err, sizeof err);
    if (rc == SW_OK)
        rc = sw_zip_add(&z, "assignment.trace", text, text_len, 0644, err, sizeof err);
    if (rc == SW_OK)
        rc = add_source(&z, srcdir, err, sizeof err);
    int files = z.n;
    if (rc == SW_OK)
        rc = sw_zip_end(&z, err, sizeof err);
    else
        sw_zip_free(&z);
    free(text);
    if (rc != SW_OK) {
        sw_outfile_abort(&o);
        return sw_cli_error("autograder: %s", err);
    }
    if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
        return sw_cli_error("autograder: %s", err);
    char scores[120];
    if (asg.kind == SW_KIND_TRACE)
        snprintf(scores, sizeof scores, "a trace scores up to %g points", trace_max);
    else if (asg.kind == SW_KIND_PLUGIN)
        snprintf(scores, sizeof scores, "a plugin scores up to %g points", plugin_max);
    else
        snprintf(scores, sizeof scores, "a trace scores up to %g points, a plugin up to %g", trace_max,
                 plugin_max);
    if (!o.is_stdout)
        sw_cli_note("wrote %s: setup.sh, run_autograder, assignment.trace (%s) and stepwise's source "
                    "(%d files)", output, scores, files - 3);
    return SW_EXIT_OK;
}
