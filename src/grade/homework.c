/* Homeworks: the assignment file's metadata lines are read once here and
 * sorted into the shared lines and each part's; every part is then read by
 * the assignment reader through a filter that shows it its own lines, the
 * shared ones it does not replace, and this student's values in place of
 * each "per student" range. Invariant: the values come from the student's
 * key and the course secret alone (SipHash-2-4), so handout, grade and the
 * Gradescope autograder draw the same ones on any machine. */
#include "grade/homework.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stepwise/stepwise.h"
#include "util/escape.h"
#include "util/infile.h"
#include "util/num.h"
#include "util/siphash.h"

#define HOMEWORK_FILE_MAX (1u << 20) /* bytes of an assignment read for its metadata */

const char *sw_visibility_name(sw_visibility v)
{
    switch (v) {
    case SW_VIS_VISIBLE:
        return "visible";
    case SW_VIS_HIDDEN:
        return "hidden";
    case SW_VIS_AFTER_DUE_DATE:
        return "after_due_date";
    case SW_VIS_AFTER_PUBLISHED:
        return "after_published";
    }
    return "hidden";
}

const char *sw_visibility_words(sw_visibility v)
{
    switch (v) {
    case SW_VIS_VISIBLE:
        return "shown at once";
    case SW_VIS_HIDDEN:
        return "never shown to students";
    case SW_VIS_AFTER_DUE_DATE:
        return "shown after the due date";
    case SW_VIS_AFTER_PUBLISHED:
        return "shown when the grades are published";
    }
    return "never shown to students";
}

void sw_homework_student_key(const char *email, char *out, size_t outlen)
{
    size_t n = 0;
    while (*email == ' ' || *email == '\t')
        email++;
    for (; *email && n + 1 < outlen; email++)
        out[n++] = (char)tolower((unsigned char)*email);
    while (n > 0 && (out[n - 1] == ' ' || out[n - 1] == '\t'))
        n--;
    if (outlen)
        out[n] = '\0';
}

/* A metadata line's key ("scene", "param k", "part") and value, trimmed;
 * the key into key, NULL value when the line has no colon. */
static const char *split_line(const char *text, char *key, size_t keylen)
{
    const char *s = text + 1, *colon = strchr(s, ':');
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = colon ? (size_t)(colon - s) : strlen(s);
    if (n >= keylen)
        n = keylen - 1;
    memcpy(key, s, n);
    key[n] = '\0';
    while (n > 0 && (key[n - 1] == ' ' || key[n - 1] == '\t'))
        key[--n] = '\0';
    if (!colon)
        return NULL;
    colon++;
    while (*colon == ' ' || *colon == '\t')
        colon++;
    return colon;
}

/* "part NAME" or "part: NAME": the name, else NULL. */
static const char *part_header(const char *text, char *name, size_t namelen)
{
    const char *s = text + 1;
    while (*s == ' ')
        s++;
    if (strncmp(s, "part", 4) != 0 || (s[4] != ' ' && s[4] != ':'))
        return NULL;
    s += 4;
    while (*s == ' ' || *s == ':')
        s++;
    snprintf(name, namelen, "%s", s);
    size_t n = strlen(name);
    while (n > 0 && (name[n - 1] == ' ' || name[n - 1] == '\t' || name[n - 1] == '\r'))
        name[--n] = '\0';
    return name;
}

static int fail(const sw_homework *h, long line, char *err, size_t errlen, const char *what)
{
    snprintf(err, errlen, "%.200s:%ld: %s", h->path, line, what);
    return SW_EINVAL;
}

/* The digits after the point of a decimal number as written ("0.50": 2),
 * or -1 when text is not a plain decimal. */
static int decimals(const char *text)
{
    const char *s = text;
    if (*s == '-' || *s == '+')
        s++;
    int digits = 0, point = 0, any = 0;
    for (; *s; s++) {
        if (*s == '.' && !point)
            point = 1;
        else if (isdigit((unsigned char)*s)) {
            any = 1;
            digits += point;
        } else
            return -1;
    }
    return any ? digits : -1;
}

/* Parse a per-student value ("LO..HI per student", "one of A, B"); 1 when
 * it is one, 0 when the value is a plain one, or an error. */
static int parse_varying(sw_homework *h, const char *param, const char *value, int part,
                         long line, char *err, size_t errlen)
{
    char text[256], msg[400];
    snprintf(text, sizeof text, "%s", value);
    const char *dots = strstr(text, "..");
    int list = strncmp(text, "one of ", 7) == 0;
    if (!dots && !list)
        return 0;
    if (h->nvarying == SW_VARYING_MAX)
        return fail(h, line, err, errlen, "more than 16 per-student parameters");
    sw_varying *v = &h->varying[h->nvarying];
    memset(v, 0, sizeof *v);
    snprintf(v->param, sizeof v->param, "%s", param);
    v->part = part;
    v->line = line;
    if (list) {
        char *save = NULL;
        for (char *item = strtok_r(text + 7, ",", &save); item; item = strtok_r(NULL, ",", &save)) {
            while (*item == ' ')
                item++;
            size_t n = strlen(item);
            while (n > 0 && item[n - 1] == ' ')
                item[--n] = '\0';
            if (v->nlist == SW_VARYING_LIST_MAX || sw_parse_double(item, &v->list[v->nlist]) != SW_OK)
                goto bad;
            v->nlist++;
        }
        if (v->nlist < 2)
            goto bad;
        for (int i = 0; i < v->nlist; i++)
            for (int j = 0; j < i; j++)
                if (v->list[i] == v->list[j]) {
                    snprintf(msg, sizeof msg, "'param %.40s' per student: %g is listed twice (each "
                             "value once, so that each is as likely)", param, v->list[i]);
                    return fail(h, line, err, errlen, msg);
                }
    } else {
        char lo[64], hi[64];
        size_t n = (size_t)(dots - text);
        const char *tail = strstr(dots + 2, " per student");
        if (!tail || strcmp(tail, " per student") != 0 || n == 0 || n >= sizeof lo ||
            (size_t)(tail - dots - 2) >= sizeof hi)
            goto bad;
        memcpy(lo, text, n);
        lo[n] = '\0';
        snprintf(hi, sizeof hi, "%.*s", (int)(tail - dots - 2), dots + 2);
        int dl = decimals(lo), dh = decimals(hi);
        double a, b;
        if (dl < 0 || dh < 0 || sw_parse_double(lo, &a) != SW_OK || sw_parse_double(hi, &b) != SW_OK)
            goto bad;
        v->digits = dl > dh ? dl : dh;
        if (!(b > a)) {
            snprintf(msg, sizeof msg, "'param %.40s' per student: the range's low end comes first and "
                     "below its high end (%s..%s)", param, lo, hi);
            return fail(h, line, err, errlen, msg);
        }
        if (v->digits > 9)
            goto bad;
        double scale = pow(10, v->digits);
        double la = nearbyint(a * scale), lb = nearbyint(b * scale);
        if (fabs(la) > 1e15 || fabs(lb) > 1e15 || lb - la > 1e9)
            goto bad;
        v->lo = (long long)la;
        v->count = (long long)(lb - la) + 1;
    }
    h->nvarying++;
    return 1;
bad:
    snprintf(msg, sizeof msg, "'param %.40s' per student reads 'LO..HI per student' (e.g. 8..12 "
             "per student: values on the ends' decimal grid) or 'one of A, B, ...' (2 to %d "
             "numbers)", param, SW_VARYING_LIST_MAX);
    return fail(h, line, err, errlen, msg);
}

static double grid_value(const sw_varying *v, long long k)
{
    return (double)(v->lo + k) / pow(10, v->digits);
}

/* This student's value of v: drawn from their key and the secret, or the
 * first value for the teacher's preview. */
static void draw(const sw_homework *h, sw_varying *v)
{
    uint64_t r = 0;
    if (h->student[0]) {
        /* the student, the part, the parameter and its range: a value
         * shown on one part's sheet (or one homework's, under the same
         * secret) says nothing of another's */
        char msg[1400];
        int len = snprintf(msg, sizeof msg, "%.200s\n%s\n%s\n", h->student,
                           v->part >= 0 ? h->parts[v->part].name : "", v->param);
        for (int i = 0; i < v->nlist && len > 0 && (size_t)len < sizeof msg; i++)
            len += snprintf(msg + len, sizeof msg - (size_t)len, "%.17g,", v->list[i]);
        if (v->nlist == 0 && len > 0 && (size_t)len < sizeof msg)
            len += snprintf(msg + len, sizeof msg - (size_t)len, "%lld+%lld*1e-%d", v->lo, v->count,
                            v->digits);
        size_t n = len < 0 ? 0 : (size_t)len < sizeof msg ? (size_t)len : sizeof msg - 1;
        r = sw_siphash24(h->key, (const unsigned char *)msg, n);
    }
    if (v->nlist > 0)
        v->value = v->list[r % (uint64_t)v->nlist];
    else
        v->value = grid_value(v, (long long)(r % (uint64_t)v->count));
}

/* The metadata lines, read once, bounded: line 1 and the "#" lines after
 * it up to the first that is not one. */
static int load_lines(sw_homework *h, char *err, size_t errlen)
{
    struct stat st;
    const char *what = NULL;
    int fd = sw_infile_open(h->path, &st, &what);
    if (fd < 0) {
        /* the trace reader's words for a file it cannot read, as before */
        sw_trace_reader r;
        int rc = sw_trace_read_open_as(&r, h->path, 1, err, errlen);
        if (rc == SW_OK) {
            sw_trace_read_close(&r);
            snprintf(err, errlen, "%.200s:1: cannot read: %s", h->path, what ? what : strerror(errno));
            rc = SW_EIO;
        }
        return rc;
    }
    h->text = malloc(HOMEWORK_FILE_MAX + 1);
    size_t len = 0;
    ssize_t got = 0;
    while (h->text && len < HOMEWORK_FILE_MAX &&
           ((got = read(fd, h->text + len, HOMEWORK_FILE_MAX - len)) > 0 || (got < 0 && errno == EINTR)))
        len += got > 0 ? (size_t)got : 0;
    close(fd);
    if (!h->text) {
        snprintf(err, errlen, "out of memory");
        return SW_ENOMEM;
    }
    h->text[len] = '\0';
    char *s = h->text;
    for (long n = 0; s && *s; n++) {
        char *nl = strchr(s, '\n');
        if (nl)
            *nl = '\0';
        if (n > 0 && s[0] != '#')
            break;
        if (n == SW_HOMEWORK_LINES)
            return fail(h, n + 1, err, errlen, "more than 512 metadata lines");
        size_t l = strlen(s);
        if (l > 0 && s[l - 1] == '\r')
            s[l - 1] = '\0';
        h->line_text[n] = s;
        h->nlines = n + 1;
        s = nl ? nl + 1 : NULL;
    }
    return SW_OK;
}

/* Sort the lines into shared and parts; read the homework's own keys. */
static int sort_lines(sw_homework *h, sw_visibility *shared_vis, char *err, size_t errlen)
{
    char key[64], name[64], msg[300];
    int part = -1;
    for (long i = 0; i < h->nlines; i++) {
        const char *t = h->line_text[i];
        long line = i + 1;
        h->line_part[i] = i == 0 ? -2 : part;
        if (i == 0)
            continue;
        if (part_header(t, name, sizeof name)) {
            size_t n = strlen(name);
            int ok = n > 0 && n < SW_PART_NAME_MAX;
            for (size_t c = 0; ok && c < n; c++)
                ok = isalnum((unsigned char)name[c]) || name[c] == '-' || name[c] == '_';
            for (int p = 0; ok && p < h->nparts; p++)
                ok = strcmp(h->parts[p].name, name) != 0;
            if (!ok)
                return fail(h, line, err, errlen, "a part's name is 1 to 31 letters, digits, '-' or "
                            "'_', each name once ('# part chain')");
            if (h->nparts == SW_PARTS_MAX)
                return fail(h, line, err, errlen, "more than 8 parts");
            part = h->nparts++;
            memcpy(h->parts[part].name, name, n + 1); /* n < SW_PART_NAME_MAX, checked above */
            h->parts[part].line = line;
            h->parts[part].visibility = *shared_vis;
            h->line_part[i] = -3; /* a part's header */
            continue;
        }
        const char *value = split_line(t, key, sizeof key);
        if (!value)
            continue; /* the reader names the mistake */
        int own = strcmp(key, "secret") == 0 || strcmp(key, "count") == 0;
        if ((own || strcmp(key, "kind") == 0 || strcmp(key, "title") == 0 || strcmp(key, "submit") == 0) &&
            part >= 0) {
            snprintf(msg, sizeof msg, "'%s' is the homework's, not a part's: give it before the "
                     "first '# part'", key);
            return fail(h, line, err, errlen, msg);
        }
        if (strcmp(key, "secret") == 0) {
            if (!*value)
                return fail(h, line, err, errlen, "'secret' needs some words (kept from students)");
            unsigned long long k0[2] = { 0x7374657077697365ull, 0x2073656372657421ull };
            h->key[0] = sw_siphash24(k0, (const unsigned char *)value, strlen(value));
            k0[0] ^= 1;
            h->key[1] = sw_siphash24(k0, (const unsigned char *)value, strlen(value));
            h->secret_set = 1;
            h->secret_public = strcmp(value, SW_EXAMPLE_SECRET) == 0;
        } else if (strcmp(key, "count") == 0) {
            if (strcmp(value, "best") != 0 && strcmp(value, "latest") != 0)
                return fail(h, line, err, errlen, "'count' is best or latest (which of a student's "
                            "submissions counts)");
            h->rule = strcmp(value, "latest") == 0 ? SW_COUNT_LATEST : SW_COUNT_BEST;
        } else if (strcmp(key, "visibility") == 0) {
            sw_visibility v = SW_VIS_VISIBLE;
            while (v <= SW_VIS_AFTER_PUBLISHED && strcmp(value, sw_visibility_name(v)) != 0)
                v++;
            if (v > SW_VIS_AFTER_PUBLISHED)
                return fail(h, line, err, errlen, "'visibility' is visible, hidden, after_due_date "
                            "or after_published (Gradescope's)");
            if (part >= 0)
                h->parts[part].visibility = v;
            else
                *shared_vis = v;
        } else if (strncmp(key, "param ", 6) == 0) {
            int rc = parse_varying(h, key + 6 + strspn(key + 6, " "), value, part, line, err, errlen);
            if (rc < 0)
                return rc;
        }
    }
    return SW_OK;
}

/* The filter's context: which part is being read. */
typedef struct part_view {
    sw_homework *h;
    int part;
} part_view;

static int filter(void *ctx, long line, char *buf, size_t *len, size_t cap)
{
    part_view *pv = ctx;
    sw_homework *h = pv->h;
    if (line < 1 || line > h->nlines)
        return 0;
    int owner = h->line_part[line - 1];
    if (owner == -3 || (owner >= 0 && owner != pv->part))
        return 1;
    char key[64], other[64];
    const char *value = split_line(buf, key, sizeof key);
    if (!value)
        return 0;
    if (strcmp(key, "secret") == 0 || strcmp(key, "count") == 0 || strcmp(key, "visibility") == 0)
        return 1;
    if (owner == -1 && pv->part >= 0)
        for (long i = 0; i < h->nlines; i++)
            if (h->line_part[i] == pv->part && split_line(h->line_text[i], other, sizeof other) &&
                strcmp(other, key) == 0)
                return 1; /* the part gives its own */
    for (int i = 0; i < h->nvarying; i++)
        if (h->varying[i].line == line) {
            char num[40];
            sw_fmt_shortest(num, sizeof num, h->varying[i].value);
            int n = snprintf(buf, cap, "# %s: %s", key, num);
            *len = n > 0 && (size_t)n < cap ? (size_t)n : cap - 1;
        }
    return 0;
}

/* Each per-student range within the scene's range for its parameter, at
 * both ends (a range the scene refuses would fail some students only). */
static int check_ranges(const sw_homework *h, int part, char *err, size_t errlen)
{
    const sw_scene *sc = h->parts[part].a.meta.scene;
    char msg[300];
    for (int i = 0; i < h->nvarying; i++) {
        const sw_varying *v = &h->varying[i];
        if (v->part != -1 && v->part != part)
            continue;
        const sw_param *p = NULL;
        for (int k = 0; k < sc->nparams; k++)
            if (strcmp(sc->params[k].name, v->param) == 0)
                p = &sc->params[k];
        if (!p)
            continue; /* the reader has said so */
        int n = v->nlist > 0 ? v->nlist : 2;
        for (int k = 0; k < n; k++) {
            double x = v->nlist > 0 ? v->list[k] : grid_value(v, k == 0 ? 0 : v->count - 1);
            if (x < p->min || x > p->max || (p->integer && x != floor(x))) {
                snprintf(msg, sizeof msg, "'param %s' per student: %g is outside %s's range for it, "
                         "[%g, %g]%s", v->param, x, sc->name, p->min, p->max, p->integer ? ", whole numbers" : "");
                return fail(h, v->line, err, errlen, msg);
            }
        }
    }
    return SW_OK;
}

int sw_homework_read(sw_homework *h, const char *path, const char *student, char *err,
                     size_t errlen)
{
    memset(h, 0, sizeof *h);
    snprintf(h->path, sizeof h->path, "%s", path);
    sw_homework_student_key(student ? student : "", h->student, sizeof h->student);
    sw_visibility shared_vis = SW_VIS_VISIBLE;
    int rc = load_lines(h, err, errlen);
    if (rc == SW_OK)
        rc = sort_lines(h, &shared_vis, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (h->nvarying > 0 && !h->secret_set)
        return fail(h, h->varying[0].line, err, errlen, "per-student values need '# secret: WORDS' "
                    "before the first part (any words the students never see: the values are "
                    "drawn from it and each student's e-mail)");
    for (int i = 0; i < h->nvarying; i++)
        draw(h, &h->varying[i]);
    int parts = h->nparts > 0 ? h->nparts : 1, checks[2] = { 0, 0 };
    if (h->nparts == 0) {
        h->nparts = 1; /* one unnamed part */
        h->parts[0].visibility = shared_vis;
    }
    for (int p = 0; p < parts; p++) {
        part_view pv = { h, h->parts[0].line ? p : -1 };
        rc = sw_assignment_read_filtered(&h->parts[p].a, path, filter, &pv, err, errlen);
        if (rc == SW_OK)
            rc = check_ranges(h, p, err, errlen);
        if (rc != SW_OK)
            return rc;
        for (int plugin = 0; plugin < 2; plugin++) {
            sw_score none;
            sw_score_facts f = { .is_plugin = plugin, .usable = 0, .error = "" };
            sw_points_score(&h->parts[p].a.points, &f, &none);
            h->max_of[plugin] += none.max;
            checks[plugin] += none.n;
        }
    }
    h->max = h->max_of[h->parts[0].a.kind == SW_KIND_PLUGIN];
    if (checks[0] > SW_SCORE_CHECKS || checks[1] > SW_SCORE_CHECKS)
        return fail(h, h->parts[h->nparts - 1].line, err, errlen, "more than 32 checks over the parts "
                    "together (each part's '# points' lines, or its defaults)");
    h->kind = h->parts[0].a.kind;
    snprintf(h->title, sizeof h->title, "%s", h->parts[0].a.title);
    return SW_OK;
}

void sw_homework_free(sw_homework *h)
{
    free(h->text);
    h->text = NULL;
}

int sw_homework_varies(const sw_homework *h, int part, const char *param)
{
    for (int i = 0; i < h->nvarying; i++)
        if ((h->varying[i].part == -1 || h->varying[i].part == part) &&
            strcmp(h->varying[i].param, param) == 0)
            return 1;
    return 0;
}

int sw_homework_hidden_parts(const sw_homework *h)
{
    int n = 0;
    for (int p = 0; p < h->nparts; p++)
        n += h->parts[p].visibility != SW_VIS_VISIBLE;
    return n;
}

/* Whether word (a part's name) is the base name of file or a word of it. */
static int names_part(const char *file, const char *word)
{
    const char *base = strrchr(file, '/');
    base = base ? base + 1 : file;
    size_t n = strlen(word);
    for (const char *s = base; *s; s++) {
        if (s != base && isalnum((unsigned char)s[-1]))
            continue;
        if (strncasecmp(s, word, n) == 0 && !isalnum((unsigned char)s[n]))
            return 1;
    }
    return 0;
}

int sw_homework_part_of_trace(const sw_homework *h, const char *file, const sw_trace_meta *m,
                              char *why, size_t whylen)
{
    if (h->nparts == 1)
        return 0;
    int found = -1, named = 0, by_scene = 0, with_params = 0, candidate = -1;
    for (int p = 0; p < h->nparts; p++)
        if (names_part(file, h->parts[p].name)) {
            found = named++ ? -2 : p;
        }
    if (named == 1)
        return found;
    for (int p = 0; p < h->nparts; p++) {
        const sw_trace_meta *w = &h->parts[p].a.meta;
        if (w->scene != m->scene)
            continue;
        by_scene++;
        candidate = p;
        int same = 1;
        for (int i = 0; i < w->scene->nparams; i++)
            same &= w->p[i] == m->p[i];
        if (same) {
            with_params++;
            found = p;
        }
    }
    if (by_scene == 1)
        return candidate;
    if (with_params == 1)
        return found;
    size_t used = (size_t)snprintf(why, whylen, "which part this trace is for cannot be told: name "
                                   "the file after its part (");
    for (int p = 0; p < h->nparts && used < whylen; p++)
        used += (size_t)snprintf(why + used, whylen - used, "%s%s.trace: %s", p ? ", " : "",
                                 h->parts[p].name, h->parts[p].a.meta.scene->name);
    if (used < whylen)
        snprintf(why + used, whylen - used, ")");
    return -1;
}

/* The most part p gives a plugin (its checks' points together). */
static double plugin_part_max(const sw_homework *h, int p)
{
    static sw_score none; /* 22 kB: not on a stack */
    sw_score_facts f = { .is_plugin = 1, .usable = 0, .error = "" };
    sw_points_score(&h->parts[p].a.points, &f, &none);
    return none.max;
}

int sw_homework_write_sheet(const sw_homework *h, FILE *f, const char *who)
{
    int plugin = h->kind == SW_KIND_PLUGIN, left_out = 0;
    double left_points = 0;
    for (int p = 0; plugin && p < h->nparts; p++)
        if (h->parts[p].line && h->parts[p].visibility != SW_VIS_VISIBLE) {
            left_out++;
            left_points += plugin_part_max(h, p);
        }
    char key[64], num[40], shown[200];
    for (long i = 0; i < h->nlines; i++) {
        const char *t = h->line_text[i];
        int owner = h->line_part[i];
        if (owner == -3) /* a part's header: its own part's */
            for (int p = 0; p < h->nparts; p++)
                if (h->parts[p].line == i + 1)
                    owner = p;
        if (owner >= 0 && plugin && h->parts[owner].visibility != SW_VIS_VISIBLE)
            continue;
        const char *value = i > 0 ? split_line(t, key, sizeof key) : NULL;
        if (value && (strcmp(key, "secret") == 0 || strcmp(key, "count") == 0))
            continue;
        int drawn = 0;
        for (int k = 0; k < h->nvarying; k++)
            if (h->varying[k].line == i + 1) {
                sw_fmt_shortest(num, sizeof num, h->varying[k].value);
                fprintf(f, "# %s: %s\n", key, num);
                drawn = 1;
            }
        if (!drawn)
            fprintf(f, "%s\n", t);
        if (i == 0) {
            sw_escape(who ? who : "", 120, shown, sizeof shown);
            fprintf(f, "# note: the assignment sheet of %s%s", shown,
                    h->nvarying ? ", with their own parameters" : "");
            if (left_out) /* their points, so that the sheet's sum is not taken for the whole */
                fprintf(f, "; %d more part%s graded, not shown here, for %g of the %g points", left_out,
                        left_out == 1 ? " is" : "s are", left_points, h->max);
            fputc('\n', f);
        }
    }
    return ferror(f) ? SW_EIO : SW_OK;
}
