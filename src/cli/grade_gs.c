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

static void test(FILE *f, int *first, const char *name, double score, double max, const char *output,
                 int visibility)
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
    fprintf(f, ",\n      \"visibility\": \"%s\"\n    }", sw_visibility_name((sw_visibility)visibility));
}

static const char *verdict_of(int status)
{
    return status == 0 ? "pass" : status == 1 ? "fail" : status == GRADE_LIMIT ? "limit"
           : status == GRADE_SKIPPED ? "skipped" : "error";
}

int grade_write_gradescope(const grade_list *l, const sw_homework *h, const char *path,
                           double seconds, int jailed)
{
    /* The submission's score is its counted files' (grade_count.c): a
     * student who uploads a draft beside the answer is not marked down for
     * it, and only the kind the homework asks for is ever counted. */
    const sw_assignment *a = &h->parts[0].a;
    int *all = calloc((size_t)l->n + 1, sizeof *all);
    if (!all)
        return sw_cli_error("grade: out of memory");
    for (int i = 0; i < l->n; i++)
        all[i] = i;
    grade_counted c;
    grade_count(l, all, l->n, &c);
    free(all);
    int counted = c.status != GRADE_MISSING;
    char why[300];
    snprintf(why, sizeof why, "no submission to grade: upload %s%s", sw_assignment_wanted(a),
             l->n > 0 ? "; the files uploaded are not what this homework asks for"
             : l->ignored ? "; the files uploaded are listed in the output" : "");
    sw_score none;
    grade_zero_score(&none, h, h->kind == SW_KIND_PLUGIN, why);

    sw_outfile o;
    char err[SW_ERRLEN + 256], other[200];
    if (sw_outfile_open(&o, path, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    FILE *f = o.f;
    char *text = NULL;
    size_t text_len = 0;
    FILE *t = open_memstream(&text, &text_len);
    if (t) {
        fprintf(t, "stepwise %s, assignment %s%s%s%s: ", SW_VERSION, base_name(a->path),
                a->title[0] ? " (" : "", a->title, a->title[0] ? ")" : "");
        /* With parts not shown yet, nothing here tells how those went:
         * the points and verdicts of the visible parts only. */
        int hidden = sw_homework_hidden_parts(h);
        int one = c.entry[0]; /* the one file counted for every part, or -1 */
        for (int p = 1; p < h->nparts; p++)
            if (c.entry[p] != one)
                one = -1;
        double shown_pts = 0, shown_max = 0;
        for (int p = 0; p < h->nparts; p++) {
            const sw_score *s = c.entry[p] >= 0 ? &l->items[c.entry[p]].score : &none;
            for (int k = 0; k < s->n; k++)
                if (s->checks[k].part == p && h->parts[p].visibility == SW_VIS_VISIBLE) {
                    shown_pts += s->checks[k].score;
                    shown_max += s->checks[k].max;
                }
        }
        if (hidden)
            fprintf(t, "%g of %g points on the parts shown now; %d of the %d parts %s graded now "
                    "and shown later (or never): their tests say when", counted ? shown_pts : 0, shown_max,
                    hidden, h->nparts, hidden == 1 ? "is" : "are");
        else if (counted && one >= 0)
            fprintf(t, "%g of %g points for %s (%s)", c.score, c.max, base_name(l->items[one].path),
                    verdict_of(c.status));
        else if (counted)
            fprintf(t, "%g of %g points (%s)", c.score, c.max, verdict_of(c.status));
        else
            fprintf(t, "0 of %g points: %s", h->max, why);
        fprintf(t, ".\n");
        if (hidden && !counted)
            fprintf(t, "%s.\n", why);
        int ran_plugin = 0;
        for (int i = 0; i < l->n; i++)
            ran_plugin |= l->items[i].plugin && sw_assignment_kind_ok(a, 1, l->items[i].path, other, sizeof other);
        if (ran_plugin) /* said only where a plugin ran */
            fprintf(t, "Plugins run %s.\n", !jailed ? "without the jail (--no-sandbox, the teacher's choice: the "
                                                   "CPU, memory and time limits still hold)"
                : sw_jail_kind_now() == SW_JAIL_UID ? "in stepwise's jail (a user of its own, seccomp, Landlock, limits)"
                : sw_jail_landlock_abi()            ? "in stepwise's jail (namespaces, seccomp, Landlock, limits)"
                                                    : "in stepwise's jail (namespaces, seccomp, limits)");
        for (int i = 0; i < l->n; i++) {
            int is = 0;
            for (int p = 0; p < h->nparts; p++)
                is |= c.entry[p] == i;
            const grade_entry *e = &l->items[i];
            if (is && h->nparts > 1 && e->part >= 0)
                fprintf(t, "Counted for part %s: %s\n", h->parts[e->part].name, base_name(e->path));
            else if (is && (hidden || one < 0))
                fprintf(t, "Counted: %s\n", base_name(e->path));
            else if (is)
                ; /* named on the first line */
            else {
                const char *rule = h->rule == SW_COUNT_LATEST ? "the latest counts" : "the best counts";
                /* a file that ran no part (it did not build or load): its
                 * message tells nothing of the parts not shown, and is why
                 * it lost; its report is never written */
                const char *lost = !e->report && e->status == SW_VERDICT_ERROR ? e->message : "";
                if (hidden)
                    fprintf(t, "Also graded, not counted (%s): %s%s%s%s\n", rule, base_name(e->path),
                            lost[0] ? " (error: " : "", lost, lost[0] ? ")" : "");
                else
                    fprintf(t, "Also graded, not counted (%s): %s, %g of %g points (%s%s%s)\n", rule,
                            base_name(e->path), e->score.score, e->score.max, verdict_of(e->status),
                            lost[0] ? ": " : "", lost);
            }
        }
        for (int i = 0; i < l->ignored; i++) /* files left out; a roster's missing rows are no file */
            if (l->refused[i].status != GRADE_MISSING)
                fprintf(t, "Not graded: %s: %s\n", base_name(l->refused[i].path), l->refused[i].message);
        for (int p = 0; p < h->nparts; p++) {
            int i = c.entry[p];
            if (i < 0 || (p > 0 && c.entry[p - 1] == i))
                continue; /* a plugin's report covers every part */
            const grade_entry *e = &l->items[i];
            if (e->status == 0 && e->message[0] && h->nparts == 1)
                fprintf(t, "Note: %s\n", e->message); /* a pass's warning */
            if (e->report)
                fprintf(t, "\n%s", e->report);
            else if (h->parts[p].visibility == SW_VIS_VISIBLE)
                fprintf(t, "\n%s\n", e->message);
        }
        fclose(t);
        char *shown = text ? grade_text_shown(text) : NULL;
        free(text);
        text = shown;
    }
    fputs("{\n  \"score\": ", f);
    sw_json_num(f, counted ? c.score : 0);
    fputs(",\n  \"execution_time\": ", f);
    sw_json_num(f, ceil(seconds));
    fputs(",\n  \"output\": ", f);
    sw_json_str(f, text ? text : "(no output: out of memory)");
    fputs(",\n  \"output_format\": \"text\",\n  \"stdout_visibility\": \"hidden\",\n  \"tests\": [", f);
    int first = 1;
    /* Each part's checks from the file counted for it; a part with
     * nothing counted gets its checks at 0, saying why. */
    for (int p = 0; p < h->nparts; p++) {
        const sw_score *s = c.entry[p] >= 0 ? &l->items[c.entry[p]].score : &none;
        for (int k = 0; k < s->n; k++)
            if (s->checks[k].part == p)
                test(f, &first, s->checks[k].name, s->checks[k].score, s->checks[k].max,
                     s->checks[k].output, (int)h->parts[p].visibility);
    }
    fputs(first ? "]\n}\n" : "\n  ]\n}\n", f);
    free(text);
    if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    return SW_EXIT_OK;
}
