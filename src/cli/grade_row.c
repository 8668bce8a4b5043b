/* What one row of a gradebook says, in the words every report uses: its
 * verdict, its student, its points. Shared by the table, the CSV and
 * results.json (grade_out.c, grade_book.c), below both. */
#include "cli/grade.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/escape.h"

const char *grade_verdict_word(int status)
{
    return status == 0 ? "pass" : status == 1 ? "fail" : status == GRADE_SKIPPED ? "skipped"
           : status == GRADE_LIMIT ? "limit" : status == GRADE_MISSING ? "missing" : "error";
}

void grade_student_of(const grade_entry *e, char *buf, size_t len)
{
    if (e->owner[0]) {
        snprintf(buf, len, "%s", e->owner);
        return;
    }
    if (e->student[0]) {
        snprintf(buf, len, "%s", e->student);
        return;
    }
    const char *base = strrchr(e->path, '/');
    base = base ? base + 1 : e->path;
    snprintf(buf, len, "%s", base);
    char *dot = strrchr(buf, '.');
    if (dot && dot != buf)
        *dot = '\0';
}

void grade_points_of(const grade_list *l, const grade_entry *e, double *score, double *max)
{
    *score = e->score.n ? e->score.score : 0;
    *max = e->score.n ? e->score.max : !l->hw ? 1 : l->hw->kind != SW_KIND_ANY ? l->hw->max : l->hw->max_of[e->plugin != 0];
}

char *grade_text_shown(const char *text)
{
    size_t n = strlen(text), cap = 4 * n + 8, used = 0;
    char *out = malloc(cap);
    if (!out)
        return NULL;
    for (const char *line = text; *line;) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        sw_escape_kept(line, len, out + used, cap - used);
        used += strlen(out + used);
        if (end)
            out[used++] = '\n';
        line += len + (end != NULL);
    }
    out[used] = '\0';
    return out;
}
