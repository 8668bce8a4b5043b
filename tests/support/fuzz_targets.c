/* The fuzz targets (see fuzz_targets.h). */
#include "fuzz_targets.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "lab/trace.h"
#include "lesson/lesson.h"
#include "stepwise/scene.h"
#include "stepwise/stepwise.h"
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

int sw_fuzz_trace(const uint8_t *data, size_t len)
{
    char path[64];
    int ok = 0;
    snprintf(path, sizeof path, "/tmp/sw-fuzz-%ld.trace", (long)getpid());
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    fwrite(data, 1, len, f);
    fclose(f);
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
