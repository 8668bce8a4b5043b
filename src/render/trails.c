/* Trails: a ring buffer of recent positions, allocated once, drawn with two
 * fade levels. Invariant: pushing and drawing never allocate. */
#include "render/trails.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"

int sw_trails_init(sw_trails *tr, int points, int capacity, char *err, size_t errlen)
{
    memset(tr, 0, sizeof *tr);
    if (points < 1 || capacity < 1 || (long long)points * capacity > SW_TRAILS_MAX) {
        snprintf(err, errlen, "trails of %d points x %d frames: both must be at least 1 "
                 "and their product at most %d", points, capacity, SW_TRAILS_MAX);
        return SW_EINVAL;
    }
    tr->xy = malloc((size_t)points * (size_t)capacity * 2 * sizeof *tr->xy);
    if (!tr->xy) {
        snprintf(err, errlen, "out of memory for trails of %d points x %d frames", points, capacity);
        return SW_ENOMEM;
    }
    tr->points = points;
    tr->capacity = capacity;
    return SW_OK;
}

/* The slot for the next push; advancing drops the oldest frame when full. */
static double *next_frame(sw_trails *tr)
{
    double *f = tr->xy + (size_t)tr->head * (size_t)tr->points * 2;
    tr->head = (tr->head + 1) % tr->capacity;
    if (tr->count < tr->capacity)
        tr->count++;
    return f;
}

void sw_trails_push(sw_trails *tr, const double *xy, int n)
{
    if (!tr->xy)
        return;
    double *f = next_frame(tr);
    for (int i = 0; i < tr->points; i++) {
        f[2 * i] = i < n ? xy[2 * i] : NAN;
        f[2 * i + 1] = i < n ? xy[2 * i + 1] : NAN;
    }
}

static int is_alive(const sw_system *sys, const double *y, double t, int i)
{
    return !sys->scene || !sys->scene->alive || sys->scene->alive(sys, t, y, i);
}

void sw_trails_push_system(sw_trails *tr, const sw_system *sys, const double *y, double t)
{
    if (!tr->xy)
        return;
    double *f = next_frame(tr);
    for (int i = 0; i < tr->points; i++) {
        int shown = i < sys->n && is_alive(sys, y, t, i);
        f[2 * i] = shown ? y[2 * i] : NAN;
        f[2 * i + 1] = shown ? y[2 * i + 1] : NAN;
    }
}

void sw_trails_clear(sw_trails *tr)
{
    tr->head = 0;
    tr->count = 0;
}

void sw_trails_free(sw_trails *tr)
{
    free(tr->xy);
    memset(tr, 0, sizeof *tr);
}

void sw_canvas_draw_trails(sw_canvas *c, const sw_trails *tr, int style)
{
    if (!tr->xy)
        return;
    for (int age = tr->count - 1; age >= 0; age--) {
        int slot = ((tr->head - 1 - age) % tr->capacity + tr->capacity) % tr->capacity;
        const double *f = tr->xy + (size_t)slot * (size_t)tr->points * 2;
        int fade = 1 + (int)((2LL * age) / tr->capacity);
        uint32_t glyph = fade == 1 ? SW_GLYPH_TRAIL_NEW : SW_GLYPH_TRAIL_OLD;
        sw_canvas_layer(c, f, tr->points, NULL, NULL, c->mode == SW_CANVAS_BRAILLE, glyph, style, fade);
    }
}
