/* Scene features drawn from the scene's own data: the flow field evaluated
 * where the arrows go (so the whirls are the field's, not a sketch), the
 * river's rock from its radius parameter, the projectile's launch level. */
#include "render/decor.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "util/num.h"

#define ARROW_COLS 6
#define ARROW_ROWS 3
#define MAX_ARROWS 1024

static double param(const sw_system *sys, const char *name, double fallback)
{
    int i = sys->scene ? sw_scene_param_index(sys->scene, name) : -1;
    return i >= 0 ? sys->p[i] : fallback;
}

static void draw_field(sw_canvas *c, const sw_system *sys, double t, int unicode)
{
    static const uint32_t arrows8[8] = { 0x2192, 0x2197, 0x2191, 0x2196, 0x2190, 0x2199, 0x2193, 0x2198 };
    static const uint32_t arrows4[4] = { '>', '^', '<', 'v' };
    double pts[2 * MAX_ARROWS], vel[2 * MAX_ARROWS];
    int cols[MAX_ARROWS], rows[MAX_ARROWS], n = 0;
    sw_view vis = sw_canvas_visible(c);
    for (int row = ARROW_ROWS / 2; row < c->rows; row += ARROW_ROWS)
        for (int col = ARROW_COLS / 2 + (row / ARROW_ROWS % 2) * (ARROW_COLS / 2); col < c->cols && n < MAX_ARROWS;
             col += ARROW_COLS) {
            pts[2 * n] = vis.xmin + (col + 0.5) * c->scale;
            pts[2 * n + 1] = vis.ymax - (row + 0.5) * 2 * c->scale;
            cols[n] = col;
            rows[n] = row;
            n++;
        }
    if (n == 0)
        return;
    sys->flow.field(sys->flow.params, t, n, pts, vel);
    double fastest = 0;
    for (int k = 0; k < n; k++) {
        double s = hypot(vel[2 * k], vel[2 * k + 1]);
        if (isfinite(s) && s > fastest)
            fastest = s;
    }
    for (int k = 0; k < n; k++) {
        double vx = vel[2 * k], vy = vel[2 * k + 1], s = hypot(vx, vy);
        if (!(s > fastest / 20))
            continue;
        double a = atan2(vy, vx); /* y is up on screen too */
        uint32_t g = unicode ? arrows8[((int)lround(a / (SW_PI / 4)) % 8 + 8) % 8]
                             : arrows4[((int)lround(a / (SW_PI / 2)) % 4 + 4) % 4];
        sw_canvas_put(c, cols[k], rows[k], g, SW_STYLE_TRAIL);
        c->fade[(size_t)rows[k] * (size_t)c->cols + (size_t)cols[k]] = 2;
    }
}

/* A filled disc of radius r at (x0, y0): every cell whose centre lies inside. */
static void draw_disc(sw_canvas *c, double x0, double y0, double r, uint32_t glyph, int style)
{
    sw_view vis = sw_canvas_visible(c);
    for (int row = 0; row < c->rows; row++)
        for (int col = 0; col < c->cols; col++) {
            double x = vis.xmin + (col + 0.5) * c->scale, y = vis.ymax - (row + 0.5) * 2 * c->scale;
            if (hypot(x - x0, y - y0) <= r)
                sw_canvas_put(c, col, row, glyph, style);
        }
}

/* Write the first of the texts that fits the canvas at (col, row). */
static void text_fitted(sw_canvas *c, int col, int row, const char *const *texts, int n, int style)
{
    for (int k = 0; k < n; k++)
        if (col + (int)strlen(texts[k]) <= c->cols) {
            sw_canvas_text(c, col, row, texts[k], style);
            return;
        }
}

/* The launch level's name above its line, and what the energy change is
 * measured against: the launch's kinetic energy, since the potential is
 * zero at the launch height (sw_sim_energy_scale divides by E0 = that). */
static void projectile_labels(sw_canvas *c, const sw_system *sys)
{
    int col, row;
    if (sw_canvas_world_to_cell(c, sw_canvas_visible(c).xmin + c->scale, 0, &col, &row) && row >= 1) {
        static const char *const launch[] = { "launch height (no ground: the ball flies on below)",
                                              "launch height (no ground)", "launch height" };
        text_fitted(c, 1, row - 1, launch, 3, SW_STYLE_TRAIL);
    }
    double vx = param(sys, "vx", 0), vy = param(sys, "vy", 0), ke = 0.5 * param(sys, "m", 1) * (vx * vx + vy * vy);
    if (c->rows >= 4 && ke > 0) {
        char full[96], mid[64], brief[48];
        snprintf(full, sizeof full, "energy %% = change of the launch kinetic energy, %.3g J", ke);
        snprintf(mid, sizeof mid, "E%%: of launch kinetic energy, %.3g J", ke);
        snprintf(brief, sizeof brief, "E%% of launch KE %.3g J", ke);
        const char *const texts[] = { full, mid, brief };
        text_fitted(c, 1, 0, texts, 3, SW_STYLE_TRAIL);
    }
}

void sw_canvas_draw_decor(sw_canvas *c, const sw_system *sys, double t, int unicode)
{
    const char *name = sys->scene ? sys->scene->name : "";
    /* the field where the particles alone do not show it: the gyre's
     * whirls, the river's bend around the rock (the vortex's rings do) */
    if (sys->kind == SW_SYS_FLOW && sys->flow.field && strcmp(name, "vortex") != 0)
        draw_field(c, sys, t, unicode);
    if (strcmp(name, "river") == 0)
        draw_disc(c, 0, 0, param(sys, "R", 0.5), '#', SW_STYLE_WALL);
    if (strcmp(name, "projectile") == 0) {
        /* the launch level, faint and dashed: where the flight is judged
         * to end. Not a floor: the scene has no contact, and the ball flies
         * on below it (the bounce scene has a floor) */
        sw_view vis = sw_canvas_visible(c);
        sw_canvas_line(c, vis.xmin - c->scale, 0, vis.xmax + c->scale, 0, '-', SW_STYLE_TRAIL);
        projectile_labels(c, sys);
    }
}
