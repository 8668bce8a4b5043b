/* Which of a student's submissions counts, by the homework's rule (best or
 * latest): a plugin counts as a whole, on every part; traces count part by
 * part, one per part. Only the kind the homework asks for is ever counted.
 * The score is the counted checks' sum, out of the homework's points. */
#include "cli/grade.h"

#include <string.h>

/* An entry's points on part p (its checks of that part). */
static double part_score(const grade_entry *e, int p)
{
    double s = 0;
    for (int i = 0; i < e->score.n; i++)
        if (e->score.checks[i].part == p)
            s += e->score.checks[i].score;
    return s;
}

/* Whether a beats b under rule: the higher score (then the later file),
 * or the later file (then the later in the list). */
static int better(const grade_entry *a, double sa, int ia, const grade_entry *b, double sb, int ib,
                  sw_count_rule rule)
{
    if (rule == SW_COUNT_BEST && sa != sb)
        return sa > sb;
    if (a->mtime != b->mtime)
        return a->mtime > b->mtime;
    if (rule == SW_COUNT_LATEST && sa != sb)
        return sa > sb;
    return ia > ib;
}

/* count: latest: whether a file that competed with the counted one w (the
 * same kind, and for a trace the same part) and scored otherwise was
 * modified so close to it that which came later is not to be believed. */
static int close_times(const grade_list *l, const int *entries, int n, int w, int p)
{
    const grade_entry *win = &l->items[w];
    for (int k = 0; k < n; k++) {
        const grade_entry *e = &l->items[entries[k]];
        long long dt = e->mtime - win->mtime;
        if (entries[k] == w || e->plugin != win->plugin || e->status == GRADE_SKIPPED ||
            e->status == GRADE_MISSING || (!e->plugin && e->part != win->part))
            continue;
        double se = e->plugin ? e->score.score : part_score(e, p), sw = win->plugin ? win->score.score
                                                                                  : part_score(win, p);
        if (se != sw && dt <= GRADE_CLOSE_SECONDS && dt >= -GRADE_CLOSE_SECONDS)
            return 1;
    }
    return 0;
}

void grade_count(const grade_list *l, const int *entries, int n, grade_counted *out)
{
    const sw_homework *h = l->hw;
    char why[200];
    memset(out, 0, sizeof *out);
    for (int p = 0; p < SW_PARTS_MAX; p++)
        out->entry[p] = -1;
    out->max = h->max; /* a trace's, when the homework takes either */
    out->status = GRADE_MISSING;
    int plugin = -1, traces[SW_PARTS_MAX];
    double trace_total = 0;
    long long trace_latest = 0;
    for (int p = 0; p < h->nparts; p++)
        traces[p] = -1;
    for (int k = 0; k < n; k++) {
        int i = entries[k];
        const grade_entry *e = &l->items[i];
        if (!sw_assignment_kind_ok(&h->parts[0].a, e->plugin, e->path, why, sizeof why) ||
            e->status == GRADE_SKIPPED || e->status == GRADE_MISSING)
            continue;
        if (e->plugin) {
            if (plugin < 0 || better(e, e->score.score, i, &l->items[plugin], l->items[plugin].score.score,
                                     plugin, h->rule))
                plugin = i;
            continue;
        }
        int p = e->part >= 0 && e->part < h->nparts ? e->part : 0; /* unchecked: 0 points on part 0 */
        if (traces[p] < 0 || better(e, part_score(e, p), i, &l->items[traces[p]],
                                    part_score(&l->items[traces[p]], p), traces[p], h->rule))
            traces[p] = i;
    }
    int any_trace = 0;
    for (int p = 0; p < h->nparts; p++)
        if (traces[p] >= 0) {
            any_trace = 1;
            trace_total += part_score(&l->items[traces[p]], p);
            if (l->items[traces[p]].mtime > trace_latest)
                trace_latest = l->items[traces[p]].mtime;
        }
    int use_plugin = plugin >= 0 &&
                     (!any_trace || (h->rule == SW_COUNT_BEST ? l->items[plugin].score.score >= trace_total
                                                              : l->items[plugin].mtime >= trace_latest));
    if (use_plugin) {
        out->max = h->max_of[1];
        for (int p = 0; p < h->nparts; p++)
            out->entry[p] = plugin;
        out->score = l->items[plugin].score.score;
        out->status = l->items[plugin].status;
        out->close_times = h->rule == SW_COUNT_LATEST && close_times(l, entries, n, plugin, 0);
        return;
    }
    if (!any_trace)
        return;
    out->status = SW_VERDICT_PASS;
    for (int p = 0; p < h->nparts; p++) {
        out->entry[p] = traces[p];
        if (traces[p] >= 0 && h->rule == SW_COUNT_LATEST && close_times(l, entries, n, traces[p], p))
            out->close_times = 1;
        int st = traces[p] >= 0 ? l->items[traces[p]].status : SW_VERDICT_FAIL;
        if (out->status == SW_VERDICT_PASS && st != SW_VERDICT_PASS)
            out->status = st;
    }
    out->score = trace_total;
}
