/* The fuzz targets (see fuzz_targets.h). */
#include "fuzz_targets.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <math.h>

#include "app/app.h"
#include "app/runner.h"
#include "grade/check.h"
#include "plugin/plugin_box.h"
#include "grade/roster.h"
#include "grade/similar.h"
#include "trace/trace.h"
#include "lesson/lesson.h"
#include "render/canvas.h"
#include "render/draw.h"
#include "stepwise/scene.h"
#include "stepwise/stepwise.h"
#include "util/csv.h"
#include "util/kv.h"
#include "util/num.h"

int sw_fuzz_lesson(const uint8_t *data, size_t len)
{
    sw_lesson lesson;
    char err[SW_LESSON_ERRLEN];
    int ok = sw_lesson_parse("fuzz.lesson", (const char *)data, len, &lesson, err, sizeof err) == SW_OK;
    if (ok) {
        /* exercise what the runner reads from every page */
        for (int p = 0; p < lesson.npages; p++)
            for (int g = 0; g < lesson.pages[p].ngoals; g++) {
                char text[160];
                sw_lesson_obs obs;
                sw_lesson_obs_init(&obs);
                sw_lesson_goal_text(&lesson.pages[p].goals[g], text, sizeof text);
                sw_lesson_goal_met(&lesson.pages[p].goals[g], &obs);
            }
    }
    sw_lesson_free(&lesson);
    return ok;
}

/* Write len bytes to /tmp/sw-fuzz-PID.SUFFIX, named in path; 0, or -1. */
static int temp_file(char *path, size_t pathlen, const char *suffix, const uint8_t *data, size_t len)
{
    snprintf(path, pathlen, "/tmp/sw-fuzz-%ld.%s", (long)getpid(), suffix);
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    fwrite(data, 1, len, f);
    return fclose(f) == 0 ? 0 : -1;
}

int sw_fuzz_trace(const uint8_t *data, size_t len)
{
    char path[64];
    int ok = 0;
    if (temp_file(path, sizeof path, "trace", data, len) != 0)
        return -1;
    sw_trace_reader r;
    char err[SW_ERRLEN];
    if (sw_trace_read_open(&r, path, err, sizeof err) == SW_OK) {
        if (sw_trace_read_header(&r, err, sizeof err) == SW_OK) {
            double *row = malloc((size_t)r.ncols * sizeof *row);
            int rc = 1;
            for (int n = 0; row && n < 100000 && (rc = sw_trace_read_row(&r, row, err, sizeof err)) == 1; n++)
                ;
            ok = row && rc == 0;
            free(row);
        }
        sw_trace_read_close(&r);
    }
    remove(path);
    return ok;
}

int sw_fuzz_parse(const uint8_t *data, size_t len)
{
    if (len < 1 || len > 4096)
        return 0;
    char *text = malloc(len);
    if (!text)
        return -1;
    memcpy(text, data + 1, len - 1);
    text[len - 1] = '\0';
    const sw_scene *sc = sw_scene_at(data[0] % sw_scene_count());
    double p[SW_MAX_PARAMS], v;
    long l;
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    int ok = sw_scene_set(sc, p, text, err, sizeof err) == SW_OK;
    if (ok) {
        /* an accepted value is inside its range */
        sw_kv kv;
        char name[64] = "";
        if (sw_kv_next(text, strlen(text), 0, &kv) > 0 && kv.name_len < sizeof name)
            snprintf(name, sizeof name, "%.*s", (int)kv.name_len, text + kv.name_at);
        int i = sw_scene_param_index(sc, name);
        if (i < 0 || sw_scene_check_value(sc, i, p[i], err, sizeof err) != SW_OK)
            abort();
    }
    sw_parse_double((const char *)text, &v);
    sw_parse_long((const char *)text, -1000, 1000, &l);
    free(text);
    return ok;
}

/* Bytes as doubles (8 at a time, any bit pattern: NaN, infinities,
 * subnormals, huge), then as small integers. */
typedef struct fuzz_bytes { const uint8_t *p; size_t len, at; } fuzz_bytes;

static double take_double(fuzz_bytes *b)
{
    double v = 0;
    if (b->at + sizeof v <= b->len) {
        memcpy(&v, b->p + b->at, sizeof v);
        b->at += sizeof v;
    } else if (b->at < b->len) {
        v = (double)(int8_t)b->p[b->at++] / 7.0;
    }
    return v;
}

static unsigned take_byte(fuzz_bytes *b) { return b->at < b->len ? b->p[b->at++] : 0; }

int sw_fuzz_canvas(const uint8_t *data, size_t len)
{
    fuzz_bytes b = { data, len, 0 };
    int cols = 1 + (int)(take_byte(&b) % 120), rows = 1 + (int)(take_byte(&b) % 60);
    sw_canvas c;
    char err[SW_ERRLEN];
    if (sw_canvas_init(&c, cols, rows, err, sizeof err) != SW_OK)
        return -1;
    sw_canvas_set_mode(&c, take_byte(&b) & 1 ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII);
    sw_view v = { take_double(&b), take_double(&b), take_double(&b), take_double(&b) };
    int ok = sw_canvas_set_view(&c, &v, err, sizeof err) == SW_OK;
    double xy[64];
    int n = 0;
    while (b.at < b.len && n < 64) {
        unsigned op = take_byte(&b) % 5;
        double x0 = take_double(&b), y0 = take_double(&b), x1 = take_double(&b), y1 = take_double(&b);
        uint32_t glyph = take_byte(&b);
        if (op == 0)
            sw_canvas_point(&c, x0, y0, glyph, 0);
        else if (op == 1)
            sw_canvas_mark(&c, x0, y0, glyph, 1);
        else if (op == 2)
            sw_canvas_line(&c, x0, y0, x1, y1, glyph, 2);
        xy[n++] = x0;
        xy[n++] = y0;
    }
    sw_canvas_density(&c, xy, n / 2, 3);
    /* a scene drawn at a fuzzed state: walls, springs, anchors, the sun */
    sw_system sys;
    const sw_scene *sc = sw_scene_at((int)(take_byte(&b) % (unsigned)sw_scene_count()));
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(sc, p);
    int nparam = sw_scene_param_index(sc, "n");
    if (nparam >= 0)
        p[nparam] = fmin(p[nparam], 20); /* small: the bytes run out anyway */
    if (sw_system_build(&sys, sc, p, err, sizeof err) == SW_OK) {
        for (int i = 0; i < sys.ode->dim && b.at < b.len; i++)
            sys.y[i] = take_double(&b);
        sw_canvas_draw_system(&c, &sys, sys.y, take_double(&b), 0, SW_STYLE_MAIN);
        sw_system_free(&sys);
    }
    size_t cap = sw_canvas_text_size(&c);
    char *text = malloc(cap);
    if (text)
        sw_canvas_to_text(&c, text, cap);
    free(text);
    sw_canvas_free(&c);
    return ok;
}

/* A page whose system is small enough: a step of its costliest method
 * within 1e6 state evaluations (sw_truth_step_work; the galaxy at its
 * default 101 stars is 6e6 under rodas4, seconds a frame under the
 * sanitizers). Scenes that spawn particles as they run (fireworks' bursts)
 * are left alone: their start says nothing of their cost. */
static int light_page(const sw_lesson_page *page)
{
    if (sw_scene_param_index(page->scene, "bursts") >= 0)
        return 0;
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, page->scene, page->p, err, sizeof err) != SW_OK)
        return 1; /* the runner says why */
    double worst = 0;
    for (int i = 0; i < sw_integrator_count(); i++)
        worst = fmax(worst, sw_truth_step_work(&sys, sw_integrator_at(i)));
    sw_system_free(&sys);
    return worst <= 1e6;
}

/* The steps a frame may take: 2000, fewer where the sims' steps together
 * cost more than a tenth of a key press. */
static long frame_steps(const sw_app *a)
{
    double work = 0;
    for (int i = 0; i < a->nsims; i++)
        work += sw_truth_step_work(&a->sims[i].sys, a->sims[i].method);
    double most = 0.1 * a->work_key / work;
    return most >= 2000 ? 2000 : most >= 1 ? (long)most : 1;
}

/* The lesson runner: the bytes up to the first 0xFF are a lesson file, the
 * rest keys pressed on its pages, with time advancing between them. Pages
 * that ask for large systems are left alone (light_page), and a key press
 * or a frame may spend a thousandth of the usual work (otherwise the runner
 * would only be slow). */
int sw_fuzz_runner(const uint8_t *data, size_t len)
{
    size_t cut = 0;
    while (cut < len && data[cut] != 0xFF)
        cut++;
    char path[64];
    if (temp_file(path, sizeof path, "lesson", data, cut) != 0)
        return -1;
    sw_lesson probe;
    char err[SW_LESSON_ERRLEN];
    int ok = sw_lesson_load(path, &probe, err, sizeof err) == SW_OK;
    for (int pg = 0; ok && pg < probe.npages; pg++)
        ok = light_page(&probe.pages[pg]);
    if (ok) {
        sw_runner r;
        sw_app a;
        if (sw_runner_start(&r, &a, path, 0, err, sizeof err) == SW_OK) {
            /* SW_WORK_KEY is seconds of work at full speed (the gyre's
             * work-precision sweep: 2 s), and 64 keys come in a unit: under
             * the sanitizers, 10 times slower, past the unit's timeout. */
            a.work_key = SW_WORK_KEY / 1000;
            for (size_t i = cut + 1; i < len && i < cut + 1 + 64; i++) {
                int key = data[i];
                if (!sw_runner_key(&r, &a, key))
                    sw_app_key(&a, key, 1);
                sw_app_advance(&a, 1.0 / 30, frame_steps(&a));
                sw_runner_update(&r, &a);
                sw_runner_side(&r, &a, 80 + (int)(data[i] % 60));
                if (a.quit)
                    break;
            }
            sw_app_free(&a);
            sw_runner_free(&r);
        } else {
            ok = 0;
        }
    }
    sw_lesson_free(&probe);
    remove(path);
    return ok;
}

/* The check path as `stepwise check FILE` runs it: read the trace, rebuild
 * the run its metadata describes (within a small work budget here), and
 * compare row by row. */
int sw_fuzz_check(const uint8_t *data, size_t len)
{
    char path[64];
    if (temp_file(path, sizeof path, "check.trace", data, len) != 0)
        return -1;
    sw_trace_reader r;
    char err[SW_ERRLEN];
    int ok = 0;
    if (sw_trace_read_open(&r, path, err, sizeof err) == SW_OK) {
        if (sw_trace_read_header(&r, err, sizeof err) == SW_OK && r.meta.method &&
            (double)r.sys.ode->dim * (double)r.max_rows * r.meta.method->evals < 1e6) {
            sw_sim s;
            if (sw_trace_meta_sim(&r, &s, NULL, err, sizeof err) == SW_OK) {
                sw_row_source want = { .sim = &s, .spec = r.meta.spec }, got = { .reader = &r };
                sw_check_result res;
                ok = sw_check_compare(&want, &got, r.ncols, 1e-9, 1e-9, &res, err, sizeof err) == SW_OK &&
                     res.pass;
                sw_sim_free(&s);
            }
        }
        sw_trace_read_close(&r);
    }
    remove(path);
    return ok;
}

int sw_fuzz_channel(const uint8_t *data, size_t len)
{
    if (len == 0)
        return 0;
    char why[SW_ERRLEN];
    int dim = (data[0] & 15) + 1, wv = (data[0] >> 4) & 3;
    return sw_plugin_box_replay(data + 1, len - 1, dim, wv, why, sizeof why) == SW_PF_NONE;
}

/* A match's result is a student, NONE or AMBIGUOUS, and its why one line. */
static void fuzz_match(const sw_roster *r, const char *path)
{
    char why[SW_ERRLEN];
    int m = sw_roster_match(r, path, why, sizeof why);
    if (m < SW_ROSTER_AMBIGUOUS || m >= r->n || !why[0] || strchr(why, '\n'))
        abort();
}

int sw_fuzz_roster(const uint8_t *data, size_t len)
{
    size_t cut = 0;
    while (cut < len && data[cut] != 0xFF)
        cut++;
    sw_roster r;
    char err[SW_ERRLEN], why[SW_ERRLEN];
    err[0] = '\0';
    if (sw_roster_parse("fuzz.csv", (const char *)data, cut, &r, err, sizeof err) != SW_OK) {
        if (r.n != 0 || !err[0] || strchr(err, '\n'))
            abort();
        sw_roster_free(&r);
        return 0;
    }
    const char *rest = (const char *)data + cut + 1;
    size_t nrest = cut < len ? len - cut - 1 : 0;
    if (nrest > 0)
        sw_roster_parse_gradescope(&r, "fuzz.yml", rest, nrest, err, sizeof err);
    static const char *const forms[] = { "%s_euler.c", "%s/rk4.c", "x%s_1_2_y.c",
                                         "%s_7_assignsubmission_file_a.c", "submission_%s/a.c" };
    for (int i = 0; i < r.n && i < 64; i++) {
        const sw_student *s = &r.students[i];
        char path[1200];
        for (size_t f = 0; f < sizeof forms / sizeof forms[0]; f++) {
            snprintf(path, sizeof path, forms[f], s->name);
            fuzz_match(&r, path);
            snprintf(path, sizeof path, forms[f], s->words);
            fuzz_match(&r, path);
        }
        for (int j = 0; j < s->nids; j++) {
            snprintf(path, sizeof path, "%s_rk4.trace", s->ids[j]);
            fuzz_match(&r, path);
        }
        /* a student's own folded name always names them */
        if (sw_roster_check_claim(&r, i, s->words, NULL, why, sizeof why) != SW_CLAIM_SELF)
            abort();
        sw_roster_check_claim(&r, i, s->name, NULL, why, sizeof why);
        sw_roster_check_claim(&r, SW_ROSTER_NONE, s->email, NULL, why, sizeof why);
    }
    for (int lines = 0; nrest > 0 && lines < 64; lines++) {
        size_t n = 0;
        while (n < nrest && rest[n] != '\n')
            n++;
        char path[512];
        snprintf(path, sizeof path, "%.*s", (int)(n < 511 ? n : 511), rest);
        fuzz_match(&r, path);
        sw_roster_check_claim(&r, 0, path, NULL, why, sizeof why);
        rest += n < nrest ? n + 1 : n;
        nrest -= n < nrest ? n + 1 : n;
    }
    sw_roster_free(&r);
    return 1;
}

int sw_fuzz_similar(const uint8_t *data, size_t len)
{
    size_t cut = 0;
    while (cut < len && data[cut] != 0xFF)
        cut++;
    const char *a = (const char *)data, *b = a + (cut < len ? cut + 1 : cut);
    size_t na = cut, nb = cut < len ? len - cut - 1 : 0;
    sw_similar s;
    char err[SW_ERRLEN];
    if (sw_similar_init(&s, NULL, err, sizeof err) != SW_OK)
        return -1;
    int ok = 0;
    sw_similar_add_default_base(&s, err, sizeof err);
    int da = sw_similar_add_source(&s, a, na, err, sizeof err);
    int db = sw_similar_add_source(&s, b, nb, err, sizeof err);
    int dc = sw_similar_add_source(&s, a, na, err, sizeof err);
    if (da >= 0 && db >= 0 && dc >= 0) {
        sw_similar_pair p;
        if (sw_similar_compare(&s, da, db, &p) != SW_OK || !(p.score >= 0 && p.score <= 1) ||
            sw_similar_compare(&s, da, dc, &p) != SW_OK || p.score != 1)
            abort();
        sw_similar_add_base(&s, b, nb, err, sizeof err);
        if (sw_similar_compare(&s, da, db, &p) != SW_OK || sw_similar_fingerprints(&s, db) != 0)
            abort(); /* the base takes all of its own fingerprints */
        ok = 1;
    }
    /* the bytes as rows of two traces, 3 values a row, every other row wrong */
    sw_similar_digest d;
    sw_similar_digest_init(&d);
    sw_similar_digest_add(&d, data, len);
    int ta = sw_similar_add_trace(&s, &d, NULL, 0, err, sizeof err);
    int tb = sw_similar_add_trace(&s, &d, NULL, len & 1, err, sizeof err);
    for (size_t at = 0, row = 0; ta >= 0 && tb >= 0 && at + 24 <= len; at += 24, row++) {
        double v[3];
        memcpy(v, data + at, sizeof v);
        sw_similar_trace_row(&s, ta, (long)row, v, 3, row % 2);
        sw_similar_trace_row(&s, tb, (long)row, v, 3, data[at] & 1);
    }
    sw_similar_pair *pairs;
    int n;
    if (sw_similar_pairs(&s, &pairs, &n, err, sizeof err) == SW_OK)
        free(pairs);
    sw_similar_free(&s);
    return ok;
}

/* A header line, then the rows of d from first on, written as CSV into a
 * new string (NULL: no memory). The header stands for the gradebook's own,
 * which is always written first: a kept cell is never the file's first,
 * where a byte-order mark would be read as one. */
static char *csv_text(const sw_csv_doc *d, int first, size_t *len)
{
    char *text = NULL;
    FILE *f = open_memstream(&text, len);
    if (!f)
        return NULL;
    fputs("header\r\n", f);
    for (int r = first; r < d->nrows; r++)
        for (int c = 0; c < d->rows[r].n; c++) {
            sw_csv_field(f, d->rows[r].cells[c]);
            fputs(c + 1 < d->rows[r].n ? "," : "\r\n", f);
        }
    if (fclose(f) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

int sw_fuzz_gradebook(const uint8_t *data, size_t len)
{
    sw_csv_doc d, again, third;
    char err[SW_ERRLEN];
    if (sw_csv_parse("fuzz.csv", (const char *)data, len, &d, err, sizeof err) != SW_OK) {
        if (!err[0] || strchr(err, '\n'))
            abort(); /* a refusal is one line */
        sw_csv_doc_free(&d);
        return 0;
    }
    /* Kept rows go through sw_csv_field once more on every regrade: after
     * the first pass they must not drift (cells cut to 4095 bytes may end
     * in "...", then stay). */
    size_t n1 = 0, n2 = 0;
    char *t1 = csv_text(&d, 0, &n1);
    if (t1 && sw_csv_parse("fuzz.csv", t1, n1, &again, err, sizeof err) != SW_OK)
        abort(); /* what we write we must read */
    char *t2 = t1 ? csv_text(&again, 1, &n2) : NULL;
    if (t2 && sw_csv_parse("fuzz.csv", t2, n2, &third, err, sizeof err) == SW_OK) {
        char *t3 = NULL;
        size_t n3 = 0;
        t3 = csv_text(&third, 1, &n3);
        if (t3 && (n3 != n2 || memcmp(t2, t3, n2) != 0))
            abort(); /* a kept row written twice changed */
        free(t3);
        sw_csv_doc_free(&third);
    } else if (t2)
        abort();
    free(t1);
    free(t2);
    if (t1)
        sw_csv_doc_free(&again);
    sw_csv_doc_free(&d);
    return 1;
}
