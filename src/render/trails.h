/* Trails: where the particles were over the last frames. */
#ifndef SW_RENDER_TRAILS_H
#define SW_RENDER_TRAILS_H

#include "render/canvas.h"
#include "stepwise/scene.h"

/* Trails: a ring of the last `capacity` frames of positions for the first
 * `points` particles, allocated once; pushing never allocates. */
typedef struct sw_trails {
    int points;     /* particles tracked per frame */
    int capacity;   /* frames kept */
    int head;       /* slot the next push writes */
    int count;      /* frames held, <= capacity */
    double *xy;     /* capacity × points × 2; NaN marks a particle not shown */
} sw_trails;

/* Largest points × capacity accepted. */
#define SW_TRAILS_MAX (1 << 22)

/* Allocate an empty ring (points >= 1, capacity >= 1, points·capacity <=
 * SW_TRAILS_MAX); 0, SW_EINVAL or SW_ENOMEM with err filled. */
int sw_trails_init(sw_trails *tr, int points, int capacity, char *err, size_t errlen);
/* Push one frame: positions of the first min(n, points) of xy (the rest NaN);
 * once full, the oldest frame is overwritten. */
void sw_trails_push(sw_trails *tr, const double *xy, int n);
/* Push one frame of a system at state y and time t; particles not alive at t
 * are stored as NaN so dead particles leave no trail. */
void sw_trails_push_system(sw_trails *tr, const sw_system *sys, const double *y, double t);
/* Forget every frame (capacity kept). */
void sw_trails_clear(sw_trails *tr);
void sw_trails_free(sw_trails *tr);
/* Draw the held frames oldest first with style: a frame of age a (0 = the
 * latest push) gets fade 1 + floor(2a / capacity), glyph ':' for fade 1 and
 * '.' for fade 2; in Braille mode dots, with the cell's fade set likewise. */
void sw_canvas_draw_trails(sw_canvas *c, const sw_trails *tr, int style);

#endif
