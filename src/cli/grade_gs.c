/* Gradescope's results.json for one submission, as its autograder contract
 * asks (gradescope-autograders.readthedocs.io, "Autograder Specifications"):
 * score, execution_time, output, and one test per check of the assignment
 * with name, score, max_score, status, output and visibility. Invariant:
 * the file is written whole or not at all (util/outfile.h), every string
 * through cli/json.h, and a submission with nothing gradable still gets
 * every check, at 0, saying why. */
#include "cli/grade.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/json.h"
#include "plugin/jail.h"
#include "stepwise/stepwise.h"
#include "util/outfile.h"
#include "util/escape.h"

/* A file's name as the output shows it: escaped (it may hold a newline
 * and a forged line after it), in one of four rotating buffers. */
static const char *base_name(const char *path)
{
    static char shown[4][300];
    static int next;
    const char *slash = strrchr(path, '/');
    char *out = shown[next++ & 3];
    sw_escape(slash ? slash + 1 : path, 200, out, sizeof shown[0]);
    return out;
}

static void test(FILE *f, int *first, const char *name, double score, double max, const char *output)
{
    fprintf(f, "%s\n    {\n      \"name\": ", *first ? "" : ",");
    *first = 0;
    sw_json_str(f, name);
    fputs(",\n      \"score\": ", f);
    sw_json_num(f, score);
    fputs(",\n      \"max_score\": ", f);
    sw_json_num(f, max);
    fprintf(f, ",\n      \"status\": \"%s\",\n      \"output\": ", score >= max ? "passed" : "failed");
    sw_json_str(f, output);
    fputs(",\n      \"visibility\": \"visible\"\n    }", f);
}

static const char *verdict_of(int status)
{
    return status == 0 ? "pass" : status == 1 ? "fail" : status == GRADE_LIMIT ? "limit"
           : status == GRADE_SKIPPED ? "skipped" : "error";
}

int grade_write_gradescope(const grade_list *l, const sw_assignment *a, const char *path,
                           double seconds, int jailed)
{
    /* The submission's score is its best graded file's: a student who
     * uploads a draft beside the answer is not marked down for it. */
    /* Only the kind the homework asks for is ever counted. */
    int best = -1;
    char other[200];
    for (int i = 0; i < l->n; i++)
        if (sw_assignment_kind_ok(a, l->items[i].plugin, other, sizeof other) &&
            (best < 0 || l->items[i].score.score > l->items[best].score.score))
            best = i;
    sw_score none;
    char why[300];
    snprintf(why, sizeof why, "no submission to grade: upload %s%s", sw_assignment_wanted(a),
             l->n > 0 ? "; the files uploaded are not what this homework asks for"
             : l->ignored ? "; the files uploaded are listed in the output" : "");
    sw_score_facts facts = { .is_plugin = 0, .usable = 0, .error = why };
    sw_points_score(&a->points, &facts, &none);
    const sw_score *s = best >= 0 ? &l->items[best].score : &none;

    sw_outfile o;
    char err[SW_ERRLEN + 256];
    if (sw_outfile_open(&o, path, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    FILE *f = o.f;
    char *text = NULL;
    size_t text_len = 0;
    FILE *t = open_memstream(&text, &text_len);
    if (t) {
        fprintf(t, "stepwise %s, assignment %s%s%s%s: ", SW_VERSION, base_name(a->path),
                a->title[0] ? " (" : "", a->title, a->title[0] ? ")" : "");
        if (best >= 0)
            fprintf(t, "%g of %g points for %s (%s)", s->score, s->max,
                    base_name(l->items[best].path), verdict_of(l->items[best].status));
        else
            fprintf(t, "0 of %g points: %s", s->max, why);
        fprintf(t, ".\n");
        int ran_plugin = 0;
        for (int i = 0; i < l->n; i++)
            ran_plugin |= l->items[i].plugin && sw_assignment_kind_ok(a, 1, other, sizeof other);
        if (ran_plugin) /* said only where a plugin ran */
            fprintf(t, "Plugins run %s.\n", !jailed ? "without the jail (--no-sandbox, the teacher's choice: the "
                                                   "CPU, memory and time limits still hold)"
                : sw_jail_kind_now() == SW_JAIL_UID ? "in stepwise's jail (a user of its own, seccomp, Landlock, limits)"
                                                    : "in stepwise's jail (namespaces, seccomp, Landlock, limits)");
        for (int i = 0; i < l->n; i++)
            if (i != best)
                fprintf(t, "Also graded, not counted: %s, %g of %g points (%s)\n",
                        base_name(l->items[i].path), l->items[i].score.score,
                        l->items[i].score.max, verdict_of(l->items[i].status));
        for (int i = 0; i < l->ignored; i++)
            fprintf(t, "Not graded: %s: %s\n", base_name(l->refused[i].path), l->refused[i].message);
        if (best >= 0 && l->items[best].status == 0 && l->items[best].message[0])
            fprintf(t, "Note: %s\n", l->items[best].message); /* a pass's warning */
        if (best >= 0 && l->items[best].report)
            fprintf(t, "\n%s", l->items[best].report);
        else if (best >= 0)
            fprintf(t, "\n%s\n", l->items[best].message);
        fclose(t);
        char *shown = text ? grade_text_shown(text) : NULL;
        free(text);
        text = shown;
    }
    fputs("{\n  \"score\": ", f);
    sw_json_num(f, s->score);
    fputs(",\n  \"execution_time\": ", f);
    sw_json_num(f, ceil(seconds));
    fputs(",\n  \"output\": ", f);
    sw_json_str(f, text ? text : "(no output: out of memory)");
    fputs(",\n  \"output_format\": \"text\",\n  \"stdout_visibility\": \"hidden\",\n  \"tests\": [", f);
    int first = 1;
    /* The counted file's checks; the others are named in the output. */
    for (int k = 0; k < s->n; k++)
        test(f, &first, s->checks[k].name, s->checks[k].score, s->checks[k].max,
             s->checks[k].output);
    fputs(first ? "]\n}\n" : "\n  ]\n}\n", f);
    free(text);
    if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    return SW_EXIT_OK;
}
