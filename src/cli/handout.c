/* `stepwise handout --assignment A --roster R -o DIR`: each student's own
 * assignment sheet, DIR/NAME.txt: the homework with their values drawn in
 * place of each "per student" range (from their e-mail and the course
 * secret, as grade and the autograder draw them), without the secret, and
 * for a plugin homework without the parts that are not shown. Each file is
 * written whole; an index DIR/handout.csv says whose is which. */
#include "cli/cli.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "cli/grade.h"
#include "grade/homework.h"
#include "grade/roster.h"
#include "util/csv.h"
#include "util/escape.h"
#include "util/outfile.h"

static const char handout_help[] =
    "usage: stepwise handout --assignment A --roster R -o DIR\n"
    "\n"
    "Writes each roster student's own assignment sheet to DIR/NAME.txt: the\n"
    "assignment A with that student's values in place of every '# param P: LO..HI\n"
    "per student' or 'one of ...' line, drawn from their e-mail and A's '# secret:'\n"
    "(the same values 'grade' and the Gradescope autograder use), without the\n"
    "secret, and for a plugin homework without the parts not shown at once. A\n"
    "sheet is an assignment: the student checks their work with 'stepwise check\n"
    "... --assignment NAME.txt'. DIR/handout.csv lists name, email and file.\n"
    "Values per student need the roster's email column; a student without an\n"
    "e-mail gets no sheet, and is named.\n"
    "\n"
    "exit status: 0 written, 2 bad usage.\n";

/* Whether path names one of the two inputs (the assignment, the roster):
 * a sheet or the index is never written over them. */
static int is_input(const char *path, const struct stat *in, int n)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return 0;
    for (int i = 0; i < n; i++)
        if (st.st_dev == in[i].st_dev && st.st_ino == in[i].st_ino)
            return 1;
    return 0;
}

int sw_cmd_handout(int argc, char **argv)
{
    const char *assignment = NULL, *roster_path = NULL, *dir = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            fputs(handout_help, stdout);
            return SW_EXIT_OK;
        }
        const char **to = strcmp(a, "--assignment") == 0 ? &assignment
                          : strcmp(a, "--roster") == 0 ? &roster_path
                          : strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0 ? &dir : NULL;
        if (!to)
            return sw_cli_error("handout: unknown argument '%.60s'; see 'stepwise handout --help'", a);
        if (i + 1 >= argc)
            return sw_cli_error("handout: %s needs a value; see 'stepwise handout --help'", a);
        *to = argv[++i];
    }
    if (!assignment || !roster_path || !dir)
        return sw_cli_error("handout needs --assignment A, --roster R and -o DIR; see 'stepwise "
                            "handout --help'");
    static sw_homework h;
    char err[SW_ERRLEN + 512];
    if (sw_homework_read(&h, assignment, NULL, err, sizeof err) != SW_OK) {
        sw_homework_free(&h);
        return sw_cli_error("handout: %s", err);
    }
    if (h.secret_public && h.nvarying > 0)
        sw_cli_warn_public_secret(assignment);
    sw_homework_free(&h);
    sw_roster r;
    if (sw_roster_read(roster_path, &r, err, sizeof err) != SW_OK)
        return sw_cli_error("handout: --roster: %s", err);
    int rc = SW_EXIT_OK, with_email = 0, skipped = 0;
    for (int s = 0; s < r.n; s++)
        with_email += r.students[s].email[0] != 0;
    if (h.nvarying > 0 && with_email == 0)
        rc = sw_cli_error("handout: the roster has no email column, and %.200s draws each student's "
                          "values from their e-mail", assignment);
    if (rc == SW_EXIT_OK && mkdir(dir, 0777) != 0 && errno != EEXIST)
        rc = sw_cli_error("handout: cannot make '%.200s': %s", dir, strerror(errno));
    sw_outfile index;
    char path[PATH_MAX];
    struct stat inputs[2];
    int ninputs = (stat(assignment, &inputs[0]) == 0) + 0;
    if (stat(roster_path, &inputs[ninputs]) == 0)
        ninputs++;
    snprintf(path, sizeof path, "%s/handout.csv", dir);
    if (rc == SW_EXIT_OK && is_input(path, inputs, ninputs))
        rc = sw_cli_error("handout: '%.200s' is the assignment or the roster: give -o another folder", path);
    if (rc == SW_EXIT_OK && sw_outfile_open(&index, path, err, sizeof err) != SW_OK)
        rc = sw_cli_error("handout: %s", err);
    if (rc != SW_EXIT_OK) {
        sw_roster_free(&r);
        return rc;
    }
    fputs("name,email,file\r\n", index.f);
    char (*names)[112] = calloc((size_t)r.n + 1, sizeof *names);
    int written = 0;
    for (int s = 0; names && s < r.n && rc == SW_EXIT_OK; s++) {
        const sw_student *st = &r.students[s];
        if (h.nvarying > 0 && !st->email[0]) {
            char shown[160];
            sw_escape(st->name, 80, shown, sizeof shown);
            sw_cli_note("handout: no sheet for %s (roster line %ld): no e-mail to draw their values from",
                        shown, st->line);
            skipped++;
            continue;
        }
        char base[100];
        grade_safe_name(st->name, base, sizeof base);
        grade_name_unique(names, s, base);
        snprintf(path, sizeof path, "%s/%s.txt", dir, names[s]);
        sw_outfile o;
        if (is_input(path, inputs, ninputs)) {
            rc = sw_cli_error("handout: '%.200s' is the assignment or the roster: give -o another folder", path);
            break;
        }
        if (sw_homework_read(&h, assignment, st->email, err, sizeof err) != SW_OK ||
            sw_outfile_open(&o, path, err, sizeof err) != SW_OK) {
            rc = sw_cli_error("handout: %s", err);
        } else {
            sw_homework_write_sheet(&h, o.f, st->name);
            if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
                rc = sw_cli_error("handout: %s", err);
            written++;
        }
        sw_homework_free(&h);
        char file[128];
        snprintf(file, sizeof file, "%s.txt", names[s]);
        sw_csv_field(index.f, st->name);
        fputc(',', index.f);
        sw_csv_field(index.f, st->email);
        fputc(',', index.f);
        sw_csv_field(index.f, file);
        fputs("\r\n", index.f);
    }
    if (!names)
        rc = sw_cli_error("handout: out of memory");
    if (rc == SW_EXIT_OK && sw_outfile_commit(&index, err, sizeof err) != SW_OK)
        rc = sw_cli_error("handout: %s", err);
    else if (rc != SW_EXIT_OK)
        sw_outfile_abort(&index);
    if (rc == SW_EXIT_OK)
        sw_cli_note("handout: %d sheet%s in %s (and handout.csv)%s", written, written == 1 ? "" : "s", dir,
                    skipped ? "; the students without an e-mail are named above" : "");
    free(names);
    sw_roster_free(&r);
    return rc;
}
