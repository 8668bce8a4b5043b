/* Two-dimensional vector helpers as static inline value functions (after
 * Chipmunk's cpVect). Everything is double; nothing allocates. */
#ifndef STEPWISE_VEC2_H
#define STEPWISE_VEC2_H

#include <math.h>

typedef struct sw_vec2 { double x, y; } sw_vec2;

static inline sw_vec2 sw_v2(double x, double y) { sw_vec2 r = { x, y }; return r; }
static inline sw_vec2 sw_v2add(sw_vec2 a, sw_vec2 b) { return sw_v2(a.x + b.x, a.y + b.y); }
static inline sw_vec2 sw_v2sub(sw_vec2 a, sw_vec2 b) { return sw_v2(a.x - b.x, a.y - b.y); }
static inline sw_vec2 sw_v2scale(sw_vec2 a, double s) { return sw_v2(a.x * s, a.y * s); }
static inline double sw_v2dot(sw_vec2 a, sw_vec2 b) { return a.x * b.x + a.y * b.y; }
static inline double sw_v2len(sw_vec2 a) { return hypot(a.x, a.y); }

#endif
