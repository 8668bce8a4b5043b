/* `grade --roster FILE`: every row of the class belongs to a roster student
 * or says why it does not. Invariants: the student comes from where a file
 * is (its path below the submissions directory, Gradescope's metadata),
 * never from what it says; a "# student:" line naming someone else is
 * reported, not believed; every roster student gets a row, a `missing` one
 * when nothing of theirs was found. */
#include "cli/grade.h"

#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "util/escape.h"

int grade_roster_load(grade_list *l, const char *path)
{
    char err[SW_ERRLEN + 512];
    sw_roster *r = calloc(1, sizeof *r);
    if (!r)
        return sw_cli_error("grade: out of memory");
    if (sw_roster_read(path, r, err, sizeof err) != SW_OK) {
        sw_roster_free(r);
        free(r);
        return sw_cli_error("grade: --roster: %s", err);
    }
    if (r->n == 0) {
        sw_roster_free(r);
        free(r);
        return sw_cli_error("grade: --roster '%.200s' lists no students", path);
    }
    l->roster = r;
    return SW_EXIT_OK;
}

/* Read Gradescope's metadata when the submissions hold it. */
static int read_metadata(grade_list *l)
{
    char err[SW_ERRLEN + 512];
    if (!l->gs_metadata)
        return SW_EXIT_OK;
    if (sw_roster_read_gradescope(l->roster, l->gs_metadata, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    return SW_EXIT_OK;
}

static void add_remark(grade_entry *e, const char *text)
{
    size_t n = strlen(e->remarks);
    snprintf(e->remarks + n, sizeof e->remarks - n, "%s%s", n ? "; " : "", text);
}

/* Whose the entry is: owner set from the roster, or (for a graded one,
 * remark set) the reason why none. */
static void assign_one(const sw_roster *r, grade_entry *e, int graded)
{
    char why[500];
    e->who = SW_ROSTER_NONE;
    if (!e->rel || !e->rel[0])
        return;
    int who = sw_roster_match(r, e->rel, why, sizeof why);
    e->who = who;
    if (who >= 0) {
        const sw_student *s = &r->students[who];
        snprintf(e->owner, sizeof e->owner, "%s", s->name);
        snprintf(e->owner_id, sizeof e->owner_id, "%s", s->nids ? s->ids[0] : "");
    } else if (graded) {
        /* Shown by its file name in brackets: what the file says of itself
         * is not believed, and the brackets say it is nobody on the list. */
        const char *base = strrchr(e->path, '/');
        base = base ? base + 1 : e->path;
        size_t n = strcspn(base, ".");
        snprintf(e->owner, sizeof e->owner, "[%.*s]", (int)(n ? n : strlen(base)), base);
        char text[600];
        snprintf(text, sizeof text, "matches no roster student: %s", why);
        add_remark(e, text);
    }
}

static void grade_roster_assign(grade_list *l)
{
    if (!l->roster)
        return;
    for (int i = 0; i < l->n; i++)
        assign_one(l->roster, &l->items[i], 1);
    for (int i = 0; i < l->ignored; i++)
        if (l->refused[i].status != GRADE_MISSING && l->refused[i].rel &&
            !(l->gs_metadata && strcmp(l->refused[i].path, l->gs_metadata) == 0))
            assign_one(l->roster, &l->refused[i], 0);
}

void grade_roster_claim(const grade_list *l, grade_entry *e)
{
    if (!l->roster || !e->student[0])
        return;
    char why[500];
    int other = -1;
    sw_roster_claim c = sw_roster_check_claim(l->roster, e->who, e->student, &other, why, sizeof why);
    if (c == SW_CLAIM_OTHER || c == SW_CLAIM_UNKNOWN)
        add_remark(e, why);
}

int grade_roster_missing(grade_list *l)
{
    if (!l->roster)
        return SW_EXIT_OK;
    int rc = read_metadata(l);
    if (rc != SW_EXIT_OK)
        return rc;
    grade_roster_assign(l);
    const sw_roster *r = l->roster;
    unsigned char *seen = calloc((size_t)r->n, 1);
    int *skipped = calloc((size_t)r->n + 1, sizeof *skipped);
    if (!seen || !skipped) {
        free(seen);
        free(skipped);
        return sw_cli_error("grade: out of memory");
    }
    /* Every member of a group submission has submitted. A student whose
     * files were all left out (a README, a link, a .pdf) has not: their
     * row is a missing one, saying so, and counts in the gradebook. */
    for (int i = 0; i < l->n + l->ignored; i++) {
        const grade_entry *e = i < l->n ? &l->items[i] : &l->refused[i - l->n];
        int members[SW_ROSTER_GROUP_MAX];
        if (e->who < 0 || !e->rel)
            continue;
        if (i >= l->n) {
            skipped[e->who] += e->status == GRADE_SKIPPED;
            continue;
        }
        int k = sw_roster_match_all(r, e->rel, members, SW_ROSTER_GROUP_MAX, NULL, 0);
        for (int j = 0; j < k; j++)
            seen[members[j]] = 1;
        seen[e->who] = 1;
    }
    for (int s = 0; s < r->n && rc == SW_EXIT_OK; s++) {
        /* Regrading some files: a student with rows in the gradebook keeps
         * them, and is not missing for having no file among these. */
        if (seen[s] || grade_book_has_student(l, r->students[s].name))
            continue;
        /* A row with no file: it is in refused, where rows not graded are. */
        if (l->ignored == l->refused_cap) {
            int cap = l->refused_cap ? 2 * l->refused_cap : 16;
            grade_entry *m = realloc(l->refused, (size_t)cap * sizeof *m);
            if (!m) {
                rc = sw_cli_error("grade: out of memory");
                break;
            }
            l->refused = m;
            l->refused_cap = cap;
        }
        grade_entry *e = &l->refused[l->ignored];
        memset(e, 0, sizeof *e);
        if (!(e->path = strdup(""))) {
            rc = sw_cli_error("grade: out of memory");
            break;
        }
        l->ignored++;
        e->status = GRADE_MISSING;
        e->failing_step = -1;
        e->part = -1; /* of no part: nothing was handed in */
        e->who = s;
        snprintf(e->owner, sizeof e->owner, "%s", r->students[s].name);
        snprintf(e->owner_id, sizeof e->owner_id, "%s",
                 r->students[s].nids ? r->students[s].ids[0] : "");
        snprintf(e->kind, sizeof e->kind, "%s", skipped[s] ? "left-out" : "missing");
        if (skipped[s])
            snprintf(e->message, sizeof e->message, "no gradable submission: the %d entr%s matched to this "
                     "student (roster line %ld) %s not graded, each row says why", skipped[s],
                     skipped[s] == 1 ? "y" : "ies", r->students[s].line, skipped[s] == 1 ? "was" : "were");
        else
            snprintf(e->message, sizeof e->message, "no submission matched this student (roster "
                     "line %ld)", r->students[s].line);
    }
    free(seen);
    free(skipped);
    return rc;
}

/* The JSON string at s (after its opening quote) into out: escapes other
 * than \" \\ \/ are refused (an e-mail has none). 0 or -1. */
static int json_string(const char *s, char *out, size_t outlen)
{
    size_t n = 0;
    for (; *s && *s != '"'; s++) {
        if (*s == '\\') {
            s++;
            if (*s != '"' && *s != '\\' && *s != '/')
                return -1;
        }
        if ((unsigned char)*s < 0x20 || n + 1 >= outlen)
            return -1;
        out[n++] = *s;
    }
    out[n] = '\0';
    return *s == '"' && n > 0 ? 0 : -1;
}

int grade_read_submission_metadata(grade_list *l, const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = malloc(SW_ROSTER_FILE_MAX + 1);
    size_t len = f && text ? fread(text, 1, SW_ROSTER_FILE_MAX, f) : 0;
    if (f)
        fclose(f);
    if (!f || !text) {
        free(text);
        return sw_cli_error("grade: --submission-metadata '%.200s': cannot read it", path);
    }
    text[len] = '\0';
    const char *users = strstr(text, "\"users\"");
    const char *email = users ? strstr(users, "\"email\"") : NULL;
    const char *colon = email ? email + 7 : NULL;
    while (colon && (*colon == ' ' || *colon == ':' || *colon == '\n' || *colon == '\t' || *colon == '\r'))
        colon++;
    char value[128];
    int ok = colon && *colon == '"' && json_string(colon + 1, value, sizeof value) == 0;
    free(text);
    if (!ok)
        return sw_cli_error("grade: --submission-metadata '%.200s' names no user's email (Gradescope's "
                            "submission_metadata.json: \"users\": [{\"email\": ...}])", path);
    sw_homework_student_key(value, l->student_email, sizeof l->student_email);
    return SW_EXIT_OK;
}

const char *grade_student_key(const grade_list *l, const grade_entry *e)
{
    if (l->student_email[0])
        return l->student_email;
    if (l->roster && e->who >= 0)
        return l->roster->students[e->who].email;
    return "";
}

int grade_student_keys_check(const grade_list *l)
{
    if (!l->hw || l->hw->nvarying == 0 || l->student_email[0])
        return SW_EXIT_OK;
    if (!l->roster)
        return sw_cli_error("grade: %.200s:%ld draws parameters per student: give --roster FILE (with "
                            "an email column) or --submission-metadata FILE, so that each submission "
                            "is graded with its own student's values", l->hw->path, l->hw->varying[0].line);
    /* A student without an e-mail gets an error row of their own (the
     * worker says why); a roster with none at all is the wrong file. */
    for (int s = 0; s < l->roster->n; s++)
        if (l->roster->students[s].email[0])
            return SW_EXIT_OK;
    return sw_cli_error("grade: %.200s:%ld draws parameters per student from each e-mail, and the "
                        "roster has no email column", l->hw->path, l->hw->varying[0].line);
}

int grade_is_source(const grade_entry *e)
{
    size_t n = strlen(e->path);
    return e->plugin && n > 2 && strcmp(e->path + n - 2, ".c") == 0;
}

/* The length of path's folder part ("a/b/x.c": 3; "x.c": 0). */
static size_t folder_len(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? (size_t)(slash - path) : 0;
}

void grade_mark_own_folders(grade_list *l, int one_student)
{
    for (int i = 0; i < l->n; i++) {
        grade_entry *e = &l->items[i];
        if (!grade_is_source(e))
            continue;
        int own = one_student || e->who >= 0;
        size_t len = folder_len(e->path);
        for (int j = 0; own && !one_student && j < l->n; j++) {
            const grade_entry *f = &l->items[j];
            if (j != i && grade_is_source(f) && folder_len(f->path) == len && strncmp(f->path, e->path, len) == 0)
                own = f->who == e->who;
        }
        e->own_folder = own;
    }
    for (int i = 0; i < l->ignored; i++) {
        grade_entry *h = &l->refused[i];
        if (strncmp(h->message, GRADE_HEADER_SHARED, strlen(GRADE_HEADER_SHARED)) != 0)
            continue;
        size_t len = folder_len(h->path);
        for (int j = 0; j < l->n; j++) {
            const grade_entry *f = &l->items[j];
            if (f->own_folder && folder_len(f->path) == len && strncmp(f->path, h->path, len) == 0) {
                snprintf(h->message, sizeof h->message, GRADE_HEADER_BUILT);
                break;
            }
        }
    }
}
