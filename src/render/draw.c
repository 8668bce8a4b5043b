/* Scene drawing: a built system onto a canvas (walls, central body, springs,
 * anchors, particles alive now), in the draw order canvas.h gives. Knows
 * scenes and particles; the rasteriser below it knows neither. */
#include "render/draw.h"

#include <stddef.h>

/* Walls are half-planes: a side without a neighbouring wall runs on past the
 * visible rectangle, so it is drawn to one cell beyond it and clipped there. */
static void draw_walls(sw_canvas *c, const sw_walls *w)
{
    sw_view vis = sw_canvas_visible(c);
    double s = c->scale;
    double left = w->sides & SW_WALL_LEFT ? w->xmin : vis.xmin - s;
    double right = w->sides & SW_WALL_RIGHT ? w->xmax : vis.xmax + s;
    double bottom = w->sides & SW_WALL_FLOOR ? w->ymin : vis.ymin - s;
    double top = w->sides & SW_WALL_CEILING ? w->ymax : vis.ymax + s;
    if (w->sides & SW_WALL_LEFT)
        sw_canvas_line(c, w->xmin, bottom, w->xmin, top, SW_GLYPH_SIDE, SW_STYLE_WALL);
    if (w->sides & SW_WALL_RIGHT)
        sw_canvas_line(c, w->xmax, bottom, w->xmax, top, SW_GLYPH_SIDE, SW_STYLE_WALL);
    if (w->sides & SW_WALL_FLOOR)
        sw_canvas_line(c, left, w->ymin, right, w->ymin, SW_GLYPH_FLOOR, SW_STYLE_WALL);
    if (w->sides & SW_WALL_CEILING)
        sw_canvas_line(c, left, w->ymax, right, w->ymax, SW_GLYPH_FLOOR, SW_STYLE_WALL);
}

static int is_alive(const sw_system *sys, const double *y, double t, int i)
{
    return !sys->scene || !sys->scene->alive || sys->scene->alive(sys, t, y, i);
}

typedef struct alive_ctx { const sw_system *sys; const double *y; double t; } alive_ctx;

static int alive_at(const void *ctx, int i)
{
    const alive_ctx *a = ctx;
    return is_alive(a->sys, a->y, a->t, i);
}

/* A scene drawn by temperature: the living particles in three bands of
 * its heat (coolest third, middle, hottest), one layer each, hottest on top. */
typedef struct band_ctx { alive_ctx alive; int band; } band_ctx;

static int in_band(const void *ctx, int i)
{
    const band_ctx *b = ctx;
    const sw_system *sys = b->alive.sys;
    if (!is_alive(sys, b->alive.y, b->alive.t, i))
        return 0;
    double q = sys->scene->heat(sys, b->alive.y, i);
    return (q >= 2.0 / 3.0 ? 2 : q >= 1.0 / 3.0 ? 1 : 0) == b->band;
}

static void draw_by_heat(sw_canvas *c, const sw_system *sys, const double *y, double t, int style)
{
    static const uint32_t ramp[3] = { SW_GLYPH_COOL, SW_GLYPH_MAIN, SW_GLYPH_HOT };
    for (int band = 0; band < 3; band++) {
        band_ctx ctx = { { sys, y, t }, band };
        sw_canvas_layer(c, y, sys->n, in_band, &ctx, 0, ramp[band], style, 0);
    }
}

/* Springs as lines, then their anchors on top (an anchor ends its spring). */
static void draw_springs(sw_canvas *c, const sw_system *sys, const double *y, double t, int style)
{
    const sw_particles *p = &sys->particles;
    int n = sys->n, main_sim = style == SW_STYLE_MAIN, count = sw_particles_spring_count(p);
    for (int pass = 0; pass < 2; pass++)
        for (int j = 0; j < count; j++) {
            sw_spring spring, *sp = &spring;
            sw_particles_spring(p, j, sp);
            if (sp->a < 0 || sp->a >= n || sp->b >= n)
                continue;
            if (pass == 1) {
                if (sp->b < 0)
                    sw_canvas_mark(c, sp->ax, sp->ay, SW_GLYPH_ANCHOR, SW_STYLE_WALL);
                continue;
            }
            if (!is_alive(sys, y, t, sp->a) || (sp->b >= 0 && !is_alive(sys, y, t, sp->b)))
                continue;
            double bx = sp->b < 0 ? sp->ax : y[2 * sp->b];
            double by = sp->b < 0 ? sp->ay : y[2 * sp->b + 1];
            sw_canvas_line(c, y[2 * sp->a], y[2 * sp->a + 1], bx, by,
                           main_sim ? 0 : SW_GLYPH_GHOST_SPRING,
                           main_sim ? SW_STYLE_SPRING : style);
        }
}

void sw_canvas_draw_system(sw_canvas *c, const sw_system *sys, const double *y, double t,
                           uint32_t glyph, int style)
{
    int n = sys->n;
    if (!glyph)
        glyph = SW_GLYPH_MAIN;
    if (sys->kind == SW_SYS_PARTICLES) {
        const sw_particles *p = &sys->particles;
        if (p->walls.active)
            draw_walls(c, &p->walls);
        double cx, cy, mu;
        if (sw_particles_central(p, &cx, &cy, &mu))
            sw_canvas_mark(c, cx, cy, SW_GLYPH_SUN, SW_STYLE_WALL);
        draw_springs(c, sys, y, t, style);
    }
    int crowd = (long long)n > (long long)c->cols * c->rows / 4;
    /* one pass per layer; the alive test only where the scene has one */
    alive_ctx ctx = { sys, y, t };
    sw_canvas_keep_fn *keep = sys->scene && sys->scene->alive ? alive_at : NULL;
    if (glyph == SW_GLYPH_MAIN && c->mode != SW_CANVAS_BRAILLE && sys->scene && sys->scene->heat) {
        draw_by_heat(c, sys, y, t, style); /* its temperature, crowded or not: what the scene is there to show */
    } else if (c->mode == SW_CANVAS_BRAILLE && (crowd || sys->kind == SW_SYS_FLOW)) {
        sw_canvas_layer(c, y, n, keep, &ctx, 1, glyph, style, 0);
    } else if (crowd && glyph == SW_GLYPH_MAIN) {
        /* the main run as a density; a ghost or a compared run keeps its
         * own glyph, or it could not be told from the main one without colour */
        sw_canvas_density_where(c, y, n, keep, &ctx, style);
    } else {
        sw_canvas_layer(c, y, n, keep, &ctx, 0, glyph, style, 0);
    }
}
