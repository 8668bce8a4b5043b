/* Partial credit: the assignment's "# points" lines and a submission's score
 * on each check. Invariant: a column is in at most one group, so no value is
 * paid for twice; a check the submission's kind cannot have (a trace's
 * order) is left out, not scored 0. */
#include "grade/points.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "grade/assignment.h"
#include "stepwise/stepwise.h"
#include "util/num.h"

static int column_matches(const char *pattern, const char *name, size_t len)
{
    if (len > 0 && pattern[len - 1] == '*')
        return strncmp(pattern, name, len - 1) == 0;
    return strlen(name) == len && strncmp(pattern, name, len) == 0;
}

int sw_points_has_column(const sw_points *p, const char *column)
{
    const char *s = p->what;
    while (*s) {
        while (*s == ' ')
            s++;
        size_t len = strcspn(s, " ");
        if (len > 0 && column_matches(s, column, len))
            return 1;
        s += len;
    }
    return 0;
}

/* "N1 within T1, N2 within T2, ...": 0 with p's tiers, or -1. */
static int parse_tiers(sw_points *p, const char *value)
{
    char text[256], *save = NULL;
    if (strlen(value) >= sizeof text)
        return -1;
    snprintf(text, sizeof text, "%s", value);
    for (char *part = strtok_r(text, ",", &save); part; part = strtok_r(NULL, ",", &save)) {
        char *at = strstr(part, " within ");
        if (!at || p->ntiers == SW_TIERS_MAX)
            return -1;
        *at = '\0';
        double n, within;
        if (sw_parse_double(part, &n) != SW_OK || sw_parse_double(at + 8, &within) != SW_OK ||
            !(n >= 0 && n <= SW_POINTS_LIMIT) || !(within > 0 && within <= 1))
            return -1;
        if (p->ntiers > 0 && !(within > p->tier_within[p->ntiers - 1] && n <= p->tier_points[p->ntiers - 1]))
            return -1;
        p->tier_points[p->ntiers] = n;
        p->tier_within[p->ntiers] = within;
        p->ntiers++;
    }
    return p->ntiers > 0 ? 0 : -1;
}

int sw_points_parse(sw_points_set *set, const char *what, const char *value, long line,
                    const char *where, char *err, size_t errlen)
{
    while (*what == ' ')
        what++;
    if (set->n == SW_POINTS_MAX) {
        snprintf(err, errlen, "%s: more than %d points lines", where, SW_POINTS_MAX);
        return SW_EINVAL;
    }
    sw_points *p = &set->items[set->n];
    memset(p, 0, sizeof *p);
    double v;
    if (strstr(value, "within")) {
        int columns = strcmp(what, "header") != 0 && strcmp(what, "order") != 0 && strcmp(what, "stability") != 0;
        if (!columns || parse_tiers(p, value) != 0) {
            snprintf(err, errlen, "%s: 'points %.40s' %s, not '%.60s'", where, what,
                     columns ? "wants tiers 'N within T, ...': points from 0 to 1000 each, tolerances T in "
                               "(0, 1] widening and points not growing, e.g. '3 within 1e-9, 2 within 1e-6, "
                               "1 within 1e-3' (at most 4)"
                             : "takes a number of points: tiers ('within') are for columns", value);
            return SW_EINVAL;
        }
        v = p->tier_points[0];
    } else if (sw_parse_double(value, &v) != SW_OK || !(v >= 0 && v <= SW_POINTS_LIMIT)) {
        snprintf(err, errlen, "%s: 'points %.40s' wants a number of points from 0 to %g, not "
                 "'%.40s'", where, what, SW_POINTS_LIMIT, value);
        return SW_EINVAL;
    }
    if (!*what || strlen(what) >= sizeof p->what) {
        snprintf(err, errlen, "%s: 'points' wants what it pays for: header, order, stability, or "
                 "column names (x0, energy, 'x*' for every x<i>)", where);
        return SW_EINVAL;
    }
    snprintf(p->what, sizeof p->what, "%s", what);
    p->kind = strcmp(what, "header") == 0      ? SW_POINTS_HEADER
              : strcmp(what, "order") == 0     ? SW_POINTS_ORDER
              : strcmp(what, "stability") == 0 ? SW_POINTS_STABILITY
                                               : SW_POINTS_COLUMNS;
    p->points = v;
    p->line = line;
    for (int i = 0; i < set->n; i++)
        if (set->items[i].kind != SW_POINTS_COLUMNS && set->items[i].kind == p->kind) {
            snprintf(err, errlen, "%s: 'points %s' is given twice (line %ld too)", where, what,
                     set->items[i].line);
            return SW_EINVAL;
        }
    set->n++;
    return SW_OK;
}

int sw_points_resolve(sw_points_set *set, const sw_system *sys, const char *path, char *err,
                      size_t errlen)
{
    if (set->n == 0) {
        set->items[0] = (sw_points){ .kind = SW_POINTS_HEADER, .what = "header", .points = 1 };
        set->items[1] = (sw_points){ .kind = SW_POINTS_COLUMNS, .what = "*", .points = 1 };
        set->n = 2;
        return SW_OK;
    }
    int ncols = sw_trace_ncols(sys);
    char name[32];
    for (int i = 0; i < set->n; i++) {
        const sw_points *p = &set->items[i];
        if (p->kind != SW_POINTS_COLUMNS)
            continue;
        /* Each name or prefix must match a column of the run. */
        const char *s = p->what;
        while (*s) {
            while (*s == ' ')
                s++;
            size_t len = strcspn(s, " ");
            int hits = 0;
            for (int c = 1; c < ncols && len > 0; c++) {
                sw_trace_colname(sys, c, name, sizeof name);
                hits += column_matches(s, name, len);
            }
            if (len > 0 && hits == 0) {
                snprintf(err, errlen, "%.200s:%ld: 'points %s': no column '%.*s' in a %s trace "
                         "(columns: t, x<i>, y<i>%s%s; a prefix ending in '*' names several)",
                         path, p->line, p->what, (int)len, s, sys->scene->name,
                         sys->ode->order == 2 ? ", vx<i>, vy<i>" : "",
                         sys->scene->energy ? ", energy" : "");
                return SW_EINVAL;
            }
            s += len;
        }
        for (int c = 1; c < ncols; c++) {
            sw_trace_colname(sys, c, name, sizeof name);
            if (!sw_points_has_column(p, name))
                continue;
            for (int j = 0; j < i; j++)
                if (set->items[j].kind == SW_POINTS_COLUMNS && sw_points_has_column(&set->items[j], name)) {
                    snprintf(err, errlen, "%.200s:%ld: column %s is paid for twice: by 'points %s' "
                             "and by line %ld's 'points %s'", path, p->line, name, p->what,
                             set->items[j].line, set->items[j].what);
                    return SW_EINVAL;
                }
        }
    }
    return SW_OK;
}

/* ---- scoring --------------------------------------------------------------- */

static void give(sw_score_check *c, int pass, const char *fmt, const char *a, const char *b)
{
    c->score = pass ? c->max : 0;
    snprintf(c->output, sizeof c->output, fmt, a ? a : "", b ? b : "");
}

/* Graded closeness: the largest difference over the group's columns, as
 * |got - expected| / (1 + |expected|), against each tier in turn. */
static void score_tiers(const sw_points *p, const sw_score_facts *f, sw_score_check *c)
{
    int ncols = sw_trace_ncols(f->sys);
    double worst = 0;
    char name[32];
    for (int col = 1; col < ncols; col++) {
        sw_trace_colname(f->sys, col, name, sizeof name);
        if (sw_points_has_column(p, name) && !(f->col_worst[col] <= worst))
            worst = f->col_worst[col]; /* NaN and inf: beyond every tier */
    }
    const char *group = strcmp(p->what, "*") == 0 ? "the run" : p->what;
    char w[40], t[40];
    snprintf(w, sizeof w, "%.3g", worst);
    int k = 0;
    while (k < p->ntiers && !(worst <= p->tier_within[k]))
        k++;
    if (k == p->ntiers) {
        sw_fmt_shortest(t, sizeof t, p->tier_within[k - 1]);
        snprintf(c->output, sizeof c->output, "%s differs from the reference by up to %s (|got - expected| / "
                 "(1 + |expected|)): beyond every tier, the widest 'within %s'", group, w, t);
        c->score = 0;
        return;
    }
    c->score = p->tier_points[k];
    sw_fmt_shortest(t, sizeof t, p->tier_within[k]);
    if (worst == 0)
        snprintf(c->output, sizeof c->output, "every value of %s matches the reference exactly: tier 'within %s', "
                 "%g of %g points", group, t, c->score, c->max);
    else
        snprintf(c->output, sizeof c->output, "%s within %s of the reference (the largest difference %s, as "
                 "|got - expected| / (1 + |expected|)): %g of %g points", group, t, w, c->score, c->max);
    if (k > 0) {
        char next[40];
        sw_fmt_shortest(next, sizeof next, p->tier_within[k - 1]);
        size_t used = strlen(c->output);
        snprintf(c->output + used, sizeof c->output - used, "; 'within %s' (%g points) missed by a factor of %.3g",
                 next, p->tier_points[k - 1], worst / p->tier_within[k - 1]);
    }
}

static void score_columns(const sw_points *p, const sw_score_facts *f, sw_score_check *c)
{
    int ncols = sw_trace_ncols(f->sys);
    long failed = 0, values = 0;
    const sw_check_cell *first = NULL;
    char name[32], first_name[32] = "";
    for (int col = 1; col < ncols; col++) {
        sw_trace_colname(f->sys, col, name, sizeof name);
        if (!sw_points_has_column(p, name))
            continue;
        values++;
        failed += f->col_failed[col];
        const sw_check_cell *cell = &f->col_first[col];
        if (f->col_failed[col] > 0 && (!first || cell->step < first->step)) {
            first = cell;
            snprintf(first_name, sizeof first_name, "%s", name);
        }
    }
    if (f->fault) {
        give(c, 0, "not scored: %s", f->fault, NULL);
        return;
    }
    if (!f->comparable) {
        give(c, 0, "not compared: the trace has other columns than the assignment's run%s%s",
             NULL, NULL);
        return;
    }
    if (p->ntiers > 0 && f->col_worst && !f->rows_differ) {
        score_tiers(p, f, c);
        return;
    }
    if (failed == 0 && !f->rows_differ) {
        snprintf(c->output, sizeof c->output, "every value of %s matches the reference within "
                 "the tolerance", strcmp(p->what, "*") == 0 ? "every column" : p->what);
        c->score = c->max;
        return;
    }
    char what[400];
    if (first) {
        char e[40], g[40];
        sw_fmt_shortest(e, sizeof e, first->expected);
        sw_fmt_shortest(g, sizeof g, first->got);
        snprintf(what, sizeof what, "%ld value%s of %s outside the tolerance; the first at step "
                 "%ld, t = %g, column %s: expected %s, got %s", failed, failed == 1 ? "" : "s",
                 strcmp(p->what, "*") == 0 ? "the run" : p->what, first->step, first->t,
                 first_name, e, g);
    } else
        snprintf(what, sizeof what, "%s", f->rows_words ? f->rows_words : "rows missing or extra");
    (void)values;
    give(c, 0, "%s%s", what, "");
    if (f->explanation && *f->explanation) {
        size_t used = strlen(c->output);
        snprintf(c->output + used, sizeof c->output - used, "; %s", f->explanation);
    }
}

static void score_measure(const sw_points *p, const sw_score_facts *f, sw_score_check *c)
{
    int order = p->kind == SW_POINTS_ORDER;
    double got = order ? f->order : f->stability;
    double want = order ? f->expected_order : f->expected_stability;
    char g[40], w[40];
    snprintf(g, sizeof g, "%.3g", got);
    snprintf(w, sizeof w, "%.3g", want);
    if (f->fault) {
        give(c, 0, "not measured: %s", f->fault, NULL);
        return;
    }
    if (!order && f->stability_decided) {
        /* decided in two runs against the method's limit: the note says how */
        give(c, f->stability_given, "%s", f->measure_note, NULL);
        return;
    }
    if (isnan(got) || isnan(want)) {
        /* the verdict's note names what was not measured, and why */
        give(c, 0, "%s", f->measure_note && *f->measure_note ? f->measure_note
                                                             : "not measured: no figure", NULL);
        return;
    }
    /* An order within half of the method's; a stability limit within 5 %
     * (both unbounded, or both none, match). */
    int pass = order ? fabs(got - want) < SW_POINTS_ORDER_MARGIN
                     : (isinf(got) && isinf(want)) || (got == 0 && want == 0) ||
                           (isfinite(got) && isfinite(want) && fabs(got - want) <= SW_POINTS_STABILITY_MARGIN * fabs(want));
    if (order)
        give(c, pass, pass ? "measured order %s, the method's %s"
                           : "measured order %s; the method's is %s", g, w);
    else
        give(c, pass, pass ? "stability limit omega*dt = %s, the method's %s"
                           : "stability limit omega*dt = %s; the method's is %s", g, w);
}

void sw_points_score(const sw_points_set *set, const sw_score_facts *f, sw_score *s)
{
    memset(s, 0, sizeof *s);
    for (int i = 0; i < set->n; i++) {
        const sw_points *p = &set->items[i];
        if (f->is_plugin && p->kind == SW_POINTS_HEADER)
            continue; /* a plugin has no header: its run is the assignment's */
        if (!f->is_plugin && (p->kind == SW_POINTS_ORDER || p->kind == SW_POINTS_STABILITY))
            continue; /* measured on plugins only */
        sw_score_check *c = &s->checks[s->n++];
        c->max = p->points;
        switch (p->kind) {
        case SW_POINTS_HEADER:
            snprintf(c->name, sizeof c->name, "header");
            break;
        case SW_POINTS_COLUMNS:
            snprintf(c->name, sizeof c->name, "values: %s",
                     strcmp(p->what, "*") == 0 ? "every column" : p->what);
            break;
        case SW_POINTS_ORDER:
            snprintf(c->name, sizeof c->name, "order");
            break;
        case SW_POINTS_STABILITY:
            snprintf(c->name, sizeof c->name, "stability");
            break;
        }
        if (!f->usable) {
            give(c, 0, "not scored: %s", f->error, NULL);
        } else {
            switch (p->kind) {
            case SW_POINTS_HEADER:
                if (f->ndiffs == 0)
                    give(c, 1, "the header states the assignment's run%s%s", NULL, NULL);
                else
                    give(c, 0, "%s%s", f->header_words, NULL);
                break;
            case SW_POINTS_COLUMNS:
                score_columns(p, f, c);
                break;
            case SW_POINTS_ORDER:
            case SW_POINTS_STABILITY:
                score_measure(p, f, c);
                break;
            }
        }
        s->score += c->score;
        s->max += c->max;
    }
}

void sw_score_append(sw_score *into, const sw_score *part, const char *name, int visibility,
                     int index)
{
    for (int i = 0; i < part->n && into->n < SW_SCORE_CHECKS; i++) {
        sw_score_check *c = &into->checks[into->n++];
        *c = part->checks[i];
        if (name[0])
            snprintf(c->name, sizeof c->name, "%.30s: %.31s", name, part->checks[i].name);
        c->visibility = visibility;
        c->part = index;
        into->score += c->score;
        into->max += c->max;
    }
}

void sw_score_print(FILE *f, const sw_score *s, const char *indent, const char *tail)
{
    if (s->n == 0)
        return;
    fprintf(f, "%spoints: %g of %g%s\n", indent, s->score, s->max, tail);
    const char *said = NULL; /* a reason said once: a file not scored at all has one */
    for (int k = 0; k < s->n; k++) {
        const sw_score_check *c = &s->checks[k];
        int lost = c->score < c->max;
        fprintf(f, "%s  %s: %g of %g", indent, c->name, c->score, c->max);
        if (lost)
            fprintf(f, ": %s", said && strcmp(said, c->output) == 0 ? "the same" : c->output);
        said = lost ? c->output : said;
        fputc('\n', f);
    }
}
