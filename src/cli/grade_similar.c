/* `grade --similarity`: pairs of submissions a teacher should read side by
 * side (grade/similar.h: MOSS-style winnowing of plugin sources with the
 * handout removed; traces byte-identical, correct ones never flagged).
 * Invariant: a flag is a remark beside the verdict, never a verdict; the
 * parent reads a submission only bounded and never through a link. */
#include "cli/grade.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "grade/similar.h"
#include "plugin/plugin_headers.h"
#include "util/escape.h"
#include "util/infile.h"

/* The bytes of a submission, at most max: opened as grade_collect.c judged
 * it (no link followed, never waiting); NULL when it cannot be. */
static char *read_bounded(const char *path, size_t max, size_t *len)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat st;
    char *text = NULL;
    if (fd < 0)
        return NULL;
    if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && sw_infile_read(fd, max, &text, len) != 0)
        text = NULL;
    close(fd);
    return text;
}

_Static_assert(SW_SIMILAR_SOURCE_MAX >= SW_PLUGIN_SOURCE_MAX + SW_HEADERS_MAX,
               "what a plugin build takes must be compared whole");

/* A source with the headers it was built with (plugin_headers.h), one
 * text of at most max bytes: copied code in a header is copied code.
 * NULL where it is more (it was not built either: nothing is dropped). */
static char *read_source(const char *path, int own_folder, size_t max, size_t *len)
{
    char *text = read_bounded(path, max, len), err[SW_ERRLEN];
    sw_headers hd;
    if (!text || sw_headers_find(path, !own_folder, &hd, err, sizeof err) != 0)
        return text;
    for (int i = 0; i < hd.n && text; i++) {
        int fd = sw_headers_open(&hd, i);
        char *more = NULL, *all;
        size_t n = 0;
        if (fd >= 0 && *len < max && sw_infile_read(fd, max - *len - 1, &more, &n) == 0 &&
            (all = realloc(text, *len + n + 2))) {
            text = all;
            text[(*len)++] = '\n';
            memcpy(text + *len, more, n);
            *len += n;
            text[*len] = '\0';
        } else { /* too large or unreadable: not compared, and counted so */
            free(text);
            text = NULL;
        }
        free(more);
        if (fd >= 0)
            close(fd);
    }
    return text;
}

/* Whether the students of two identical correct traces were drawn the same
 * values for the trace's part (a range of 11 values in a class of 22 gives
 * many such pairs): then identical is what honest work looks like, and no
 * copy. Unknown students or an unreadable homework: not the same. */
static int same_values(const grade_list *l, const grade_entry *a, const grade_entry *b)
{
    const char *ka = grade_student_key(l, a), *kb = grade_student_key(l, b);
    char err[SW_ERRLEN];
    if (!l->hw || !ka || !kb || !ka[0] || !kb[0] || a->part != b->part || a->part < 0)
        return 0;
    static sw_homework ha, hb;
    int ok = sw_homework_read(&ha, l->hw->path, ka, err, sizeof err) == SW_OK;
    ok = sw_homework_read(&hb, l->hw->path, kb, err, sizeof err) == SW_OK && ok;
    for (int i = 0; ok && i < ha.nvarying; i++)
        if (ha.varying[i].part < 0 || ha.varying[i].part == a->part)
            ok = ha.varying[i].value == hb.varying[i].value;
    sw_homework_free(&ha);
    sw_homework_free(&hb);
    return ok;
}

/* A trace made with every parameter at its scene's default: a run without
 * --set, which two students make alike without copying (where one drew
 * the defaults, the other forgot their values). */
static int at_defaults(const grade_entry *e)
{
    sw_trace_reader r;
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    if (e->plugin || sw_trace_read_open(&r, e->path, err, sizeof err) != SW_OK)
        return 0;
    double def[SW_MAX_PARAMS];
    sw_scene_defaults(r.meta.scene, def);
    int same = 1;
    for (int i = 0; i < r.meta.scene->nparams; i++)
        same = same && r.meta.p[i] == def[i];
    sw_trace_read_close(&r);
    return same;
}

static void name_of(const grade_entry *e, char *buf, size_t len)
{
    char student[SW_TRACE_STUDENT_MAX], shown[160];
    grade_student_of(e, student, sizeof student);
    sw_escape(student, 60, shown, sizeof shown);
    const char *base = strrchr(e->path, '/');
    char file[160];
    sw_escape(base ? base + 1 : e->path, 60, file, sizeof file);
    snprintf(buf, len, "%s (%s)", shown, file);
}

static void add_similar(grade_entry *e, const char *text)
{
    size_t n = strlen(e->similar);
    snprintf(e->similar + n, sizeof e->similar - n, "%s%s", n ? "; " : "", text);
}

int grade_similar_run(grade_list *l)
{
    if (!l->similarity)
        return SW_EXIT_OK;
    char err[SW_ERRLEN + 512];
    sw_similar s;
    if (sw_similar_init(&s, NULL, err, sizeof err) != SW_OK ||
        sw_similar_add_default_base(&s, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: --similarity: %s", err);
    /* The class is larger than MOSS's default -m of 10: a fingerprint is
     * boilerplate only when a quarter of the students share it. */
    int students = 0;
    for (int i = 0; i < l->n; i++) {
        int first = 1; /* a roster's student counted at their first file */
        for (int j = 0; j < i && first && l->items[i].who >= 0; j++)
            first = l->items[j].who != l->items[i].who;
        students += first;
    }
    if (students / 4 > s.opt.max_docs)
        s.opt.max_docs = students / 4;
    s.opt.own_runs = l->hw && l->hw->nvarying > 0;
    int *entry_of = calloc((size_t)l->n + 1, sizeof *entry_of);
    if (!entry_of) {
        sw_similar_free(&s);
        return sw_cli_error("grade: out of memory");
    }
    int skipped = 0;
    for (int i = 0; i < l->n; i++) {
        const grade_entry *e = &l->items[i];
        int doc = -1;
        if (grade_is_source(e)) {
            size_t len;
            char *text = read_source(e->path, e->own_folder, SW_SIMILAR_SOURCE_MAX, &len);
            if (text)
                doc = sw_similar_add_source(&s, text, len, err, sizeof err);
            free(text);
        } else if (!e->plugin && (e->status == 0 || e->status == 1)) {
            /* A trace: correct ones are alike by design and never flagged;
             * so are wrong runs the explainer reproduced with stepwise. */
            sw_similar_digest d, rows;
            int fd = open(e->path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
            if (fd >= 0) {
                close(fd);
                if (sw_similar_digest_file(e->path, &d, &rows, err, sizeof err) == SW_OK)
                    doc = sw_similar_add_trace(&s, &d, &rows, e->status == 0 || e->kind[0], err,
                                               sizeof err);
                /* Its wrong rows, each one value: the worker's digest of the
                 * row, its top bits cleared so it is a finite double, which
                 * the library compares bit for bit. */
                for (int k = 0; doc >= 0 && k < e->nwrong; k++) {
                    uint64_t bits = e->wrong[k].hash >> 2;
                    double value;
                    memcpy(&value, &bits, sizeof value);
                    if (sw_similar_trace_row(&s, doc, (long)e->wrong[k].row, &value, 1, 1) != SW_OK)
                        break;
                }
            }
        } else
            continue;
        if (doc >= 0 && e->who >= 0)
            sw_similar_set_owner(&s, doc, e->who); /* else the doc is its own */
        if (doc >= 0)
            entry_of[doc] = i;
        else
            skipped++;
    }
    sw_similar_pair *pairs = NULL;
    int npairs = 0;
    if (sw_similar_pairs(&s, &pairs, &npairs, err, sizeof err) != SW_OK) {
        free(entry_of);
        sw_similar_free(&s);
        return sw_cli_error("grade: --similarity: %s", err);
    }
    char *table = NULL;
    size_t tlen = 0;
    FILE *t = open_memstream(&table, &tlen);
    int shown = 0;
    for (int p = 0; p < npairs && t; p++) {
        grade_entry *a = &l->items[entry_of[pairs[p].a]], *b = &l->items[entry_of[pairs[p].b]];
        /* Two files of one student (a resubmission) are no one's copy; nor
         * two correct traces of students who were drawn the same values. */
        if (a->who >= 0 && a->who == b->who)
            continue;
        if (s.opt.own_runs && !a->plugin && !b->plugin && (a->status == 0 || a->kind[0]) &&
            (b->status == 0 || b->kind[0]) &&
            same_values(l, a, b))
            continue;
        char an[400], bn[400], text[800];
        name_of(a, an, sizeof an);
        name_of(b, bn, sizeof bn);
        const char *why = pairs[p].reason,
                   *note = s.opt.own_runs && at_defaults(a) && at_defaults(b)
                               ? "; both at the scene's default parameters, as a run without --set is "
                                 "(one may have forgotten their values)"
                               : "";
        if (shown++ == 0)
            fprintf(t, "similar pairs (%s; for a person to read, not a verdict):\n",
                    "plugin sources as MOSS-style fingerprints, the handout removed; traces "
                    "byte-identical, with the same rows under another header, or with identical "
                    "wrong rows, correct ones never");
        fprintf(t, "  %.2f  %s  ~  %s: %s%s\n", pairs[p].score, an, bn, why, note);
        snprintf(text, sizeof text, "%.2f with %s: %s%s", pairs[p].score, bn, why, note);
        add_similar(a, text);
        snprintf(text, sizeof text, "%.2f with %s: %s%s", pairs[p].score, an, why, note);
        add_similar(b, text);
    }
    if (t && shown == 0)
        fprintf(t, "similar pairs: none flagged among %d plugin sources and traces compared\n",
                s.ndocs);
    if (t && s.ncommon)
        fprintf(t, "  (%zu fingerprint%s shared by more than %d students %s taken as common code and not "
                "counted: code that many students share is never paired; read such sources side by side)\n",
                s.ncommon, s.ncommon == 1 ? "" : "s", s.opt.max_docs, s.ncommon == 1 ? "was" : "were");
    if (t && skipped)
        fprintf(t, "  (%d submission%s could not be compared: unreadable or larger than %zu KiB)\n",
                skipped, skipped == 1 ? "" : "s", SW_SIMILAR_SOURCE_MAX >> 10);
    if (t && fclose(t) == 0)
        l->similar_table = table;
    else
        free(table);
    snprintf(l->similar_summary, sizeof l->similar_summary, "%d similar pair%s", shown,
             shown == 1 ? "" : "s");
    free(pairs);
    free(entry_of);
    sw_similar_free(&s);
    return SW_EXIT_OK;
}
