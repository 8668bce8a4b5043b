/* The scene picture's legend (legend.h): what the canvas holds, said in
 * words, in the order a reader needs it — the runs first, then what
 * changes their glyphs (a crowd, the ghost, a shared cell), then the
 * fixed furniture, then marks past the edge. */
#include "render/legend.h"

#include <stdio.h>
#include <string.h>

#include "render/gap.h"
#include "render/text.h"

/* The canvases read (lanes: one per run). */
typedef struct pictures {
    const sw_canvas *const *c;
    int n;
} pictures;

/* Whether any cell holds glyph g in style (style < 0: any). */
static int holds(pictures p, uint32_t g, int style)
{
    for (int i = 0; i < p.n; i++)
        for (int r = 0; r < p.c[i]->rows; r++)
            for (int k = 0; k < p.c[i]->cols; k++)
                if (sw_canvas_codepoint(p.c[i], k, r) == g && (style < 0 || sw_canvas_style(p.c[i], k, r) == style))
                    return 1;
    return 0;
}

static void add(sw_field *f, int *n, int max, int prio, const char *full, const char *brief)
{
    if (*n >= max)
        return;
    sw_field *x = &f[(*n)++];
    snprintf(x->full, sizeof x->full, "%s", full);
    snprintf(x->brief, sizeof x->brief, "%.63s", brief ? brief : "");
    x->prio = prio;
}

int sw_scene_legend(const sw_canvas *const *cs, int ncs, const sw_app *a, sw_field *f, int max)
{
    pictures c = { cs, ncs };
    static const uint32_t run_glyph[SW_APP_SIMS] = { SW_GLYPH_MAIN, SW_GLYPH_COMPARE1, SW_GLYPH_COMPARE2 };
    static const int run_style[SW_APP_SIMS] = { SW_STYLE_MAIN, SW_STYLE_COMPARE1, SW_STYLE_COMPARE2 };
    char full[160], brief[160], name[64];
    int n = 0;
    int heat = a->scene->heat != NULL && cs[0]->mode != SW_CANVAS_BRAILLE;
    /* the runs, each by its glyph (the main one's 'o' is its warm third on a scene drawn by heat) */
    if (heat && (holds(c, SW_GLYPH_HOT, SW_STYLE_MAIN) || holds(c, SW_GLYPH_MAIN, SW_STYLE_MAIN) ||
                 holds(c, SW_GLYPH_COOL, SW_STYLE_MAIN)))
        add(f, &n, max, 12, "@ hot  o warm  , cool", "@ hot o , cool");
    for (int i = heat; i < a->nsims && ncs == 1; i++) { /* (lanes: each lane's title says its run) */
        if (!holds(c, run_glyph[i], run_style[i]) && a->nsims == 1)
            continue; /* (compared runs are all named: the graph draws them too) */
        sw_text_brief_name(a->sims[i].method->name, name, sizeof name);
        snprintf(full, sizeof full, "%c %s", (char)run_glyph[i], a->sims[i].method->name);
        snprintf(brief, sizeof brief, "%c %s", (char)run_glyph[i], name[0] ? name : a->sims[i].method->name);
        add(f, &n, max, 12 - i, full, brief);
    }
    /* a crowd: the main run's ramp, the glyphs drawn (draw.c draws one
     * where a particle has under four cells) */
    const sw_sim *main = &a->sims[0];
    if (!heat && cs[0]->mode != SW_CANVAS_BRAILLE && (long long)main->sys.n > (long long)cs[0]->cols * cs[0]->rows / 4) {
        char ramp[16] = "";
        size_t k = 0;
        for (const char *g = &SW_DENSITY_RAMP[1]; *g && k + 1 < sizeof ramp; g++)
            if (*g != SW_GLYPH_MAIN && holds(c, (uint32_t)(unsigned char)*g, SW_STYLE_MAIN))
                ramp[k++] = *g;
        ramp[k] = '\0';
        if (k) {
            snprintf(full, sizeof full, "%s more dots in a cell", ramp);
            snprintf(brief, sizeof brief, "%s crowded", ramp);
            add(f, &n, max, 10, full, brief);
        }
    }
    if (holds(c, SW_GLYPH_GHOST, SW_STYLE_GHOST))
        add(f, &n, max, 9, a->truth.source == SW_TRUTH_EXACT ? "' exact" : "' reference", NULL);
    if (holds(c, SW_GLYPH_BOTH, -1))
        add(f, &n, max, 9, "& two in one cell", "& shared");
    /* the furniture: anchors (or a fixed obstacle), springs by the glyphs drawn */
    int springs = main->sys.kind == SW_SYS_PARTICLES && sw_particles_spring_count(&main->sys.particles) > 0;
    if (holds(c, SW_GLYPH_ANCHOR, SW_STYLE_WALL))
        add(f, &n, max, 8, springs ? "# anchor" : "# obstacle", NULL);
    char lines[8] = "";
    size_t nl = 0;
    static const char spring_glyph[] = { '-', '|', '/', '\\' };
    for (size_t g = 0; g < sizeof spring_glyph; g++)
        if (holds(c, (uint32_t)spring_glyph[g], SW_STYLE_SPRING))
            lines[nl++] = spring_glyph[g];
    lines[nl] = '\0';
    if (nl) {
        snprintf(full, sizeof full, "%s spring", lines);
        add(f, &n, max, 8, full, NULL);
    }
    for (int i = 1; i < a->nsims; i++)
        if (holds(c, SW_GLYPH_GHOST_SPRING, run_style[i])) {
            add(f, &n, max, 5, ". their springs", NULL);
            break;
        }
    if (holds(c, SW_GLYPH_SUN, SW_STYLE_WALL))
        add(f, &n, max, 8, "O the sun", "O sun");
    if (holds(c, SW_GLYPH_FLOOR, SW_STYLE_WALL))
        add(f, &n, max, 7, "= floor", NULL);
    if (holds(c, SW_GLYPH_SIDE, SW_STYLE_WALL))
        add(f, &n, max, 7, "| wall", NULL);
    if (holds(c, SW_GLYPH_TRAIL_NEW, SW_STYLE_TRAIL) || holds(c, SW_GLYPH_TRAIL_OLD, SW_STYLE_TRAIL))
        add(f, &n, max, 6, ": . trail", NULL);
    /* the flow's own arrows (decor), and marks that left the picture */
    static const uint32_t flow[] = { 0x2192, 0x2197, 0x2191, 0x2196, 0x2190, 0x2199, 0x2193, 0x2198 };
    for (size_t k = 0; k < sizeof flow / sizeof flow[0]; k++)
        if (holds(c, flow[k], SW_STYLE_TRAIL)) {
            add(f, &n, max, 6, "arrows: the flow g", "arrows: flow");
            break;
        }
    static const uint32_t edge[] = { '<', '>', '^', 'v' };
    for (int i = 0; i < a->nsims; i++)
        for (size_t k = 0; k < sizeof edge / sizeof edge[0]; k++)
            if (holds(c, edge[k], run_style[i])) {
                add(f, &n, max, 7, "< > ^ v: past the edge (z zooms out)", "<>^v off");
                i = a->nsims;
                break;
            }
    return n;
}
