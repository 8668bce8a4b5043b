/* The stage view (see stages.h). Invariant: every point and arrow drawn is
 * read from the recorded step (sim/stages.c) — the stage states, their
 * slopes and the state the method's step ended in — never worked out again
 * here; the picture is zoomed on the step so that it reads at 80×24. */
#include "render/stages.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/stages.h"
#include "render/text.h"
#include "stepwise/stepwise.h"
#include "util/num.h"

/* An arrow in world coordinates, its label and style. */
typedef struct arrow {
    double x0, y0, x1, y1;
    uint32_t mark;        /* the glyph at its start (0: none) */
    const char *label;
    int style;
} arrow;

/* Velocity of particle p in y (a flow: its slope, dx/dt, from the recorded k). */
static void velocity(const sw_system *sys, const double *y, int p, double *vx, double *vy)
{
    int half = sys->ode->dim / 2;
    *vx = y[half + 2 * p];
    *vy = y[half + 2 * p + 1];
}

/* The arrow view v of the script adds (1, or 2 for a kick: before and after). */
static int arrows_of(const sw_stages *r, const sw_system *sys, int p, const sw_stage_view *v, int style, arrow *out)
{
    double h = r->h, x0 = r->y0[2 * p], y0 = r->y0[2 * p + 1], x1 = r->y1[2 * p], y1 = r->y1[2 * p + 1], vx, vy;
    switch (v->shape) {
    case SW_STAGE_SLOPE: {
        const sw_stage *s = &r->st[v->stage];
        double px = s->y[2 * p], py = s->y[2 * p + 1];
        out[0] = (arrow){ px, py, px + h * s->k[2 * p], py + h * s->k[2 * p + 1], (uint32_t)('1' + v->stage - r->st[0].cached),
                          v->label, style };
        return 1;
    }
    case SW_STAGE_SUM:
        out[0] = (arrow){ x0, y0, x1, y1, 'o', v->label, style };
        return 1;
    case SW_STAGE_KICK:
        velocity(sys, r->y0, p, &vx, &vy);
        out[0] = (arrow){ x0, y0, x0 + h * vx, y0 + h * vy, 'o', "v", SW_STYLE_TRAIL };
        out[1] = (arrow){ x0, y0, x1, y1, 'o', v->label, style }; /* x1 - x0 = h·(the kicked v) */
        return 2;
    case SW_STAGE_DRIFT:
        out[0] = (arrow){ x1, y1, x1, y1, 'o', v->label, style };
        return 1;
    case SW_STAGE_KICK_END:
        velocity(sys, r->y1, p, &vx, &vy);
        out[0] = (arrow){ x1, y1, x1 + h * vx, y1 + h * vy, 'o', v->label, style };
        return 1;
    }
    return 0;
}

/* A view that holds every point of the whole step (so it does not jump
 * between presses), with a margin; 0 when the step does not move. */
static int step_view(const arrow *ar, int n, const sw_stages *r, sw_view *v)
{
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int j = 0; j < r->path_n; j++) {
        xmin = fmin(xmin, r->path[2 * j]);
        xmax = fmax(xmax, r->path[2 * j]);
        ymin = fmin(ymin, r->path[2 * j + 1]);
        ymax = fmax(ymax, r->path[2 * j + 1]);
    }
    for (int i = 0; i < n; i++) {
        xmin = fmin(xmin, fmin(ar[i].x0, ar[i].x1));
        xmax = fmax(xmax, fmax(ar[i].x0, ar[i].x1));
        ymin = fmin(ymin, fmin(ar[i].y0, ar[i].y1));
        ymax = fmax(ymax, fmax(ar[i].y0, ar[i].y1));
    }
    double span = fmax(xmax - xmin, ymax - ymin);
    if (!(span > 0) || !isfinite(span))
        return 0;
    double m = 0.2 * span; /* room for the labels */
    *v = (sw_view){ xmin - m, xmax + m, ymin - m, ymax + m };
    return 1;
}

/* The arrow's head by its direction on screen (a cell spans s across and 2·s
 * up, so world angles are screen angles). */
static uint32_t head_glyph(const arrow *a, int unicode)
{
    static const uint32_t arrows8[8] = { 0x2192, 0x2197, 0x2191, 0x2196, 0x2190, 0x2199, 0x2193, 0x2198 };
    static const uint32_t arrows4[4] = { '>', '^', '<', 'v' };
    double ang = atan2(a->y1 - a->y0, a->x1 - a->x0);
    return unicode ? arrows8[((int)lround(ang / (SW_PI / 4)) % 8 + 8) % 8]
                   : arrows4[((int)lround(ang / (SW_PI / 2)) % 4 + 4) % 4];
}

static void draw_arrow(sw_canvas *c, const arrow *a, int unicode)
{
    int c0, r0, c1, r1;
    int moves = a->x1 != a->x0 || a->y1 != a->y0;
    if (moves)
        sw_canvas_line(c, a->x0, a->y0, a->x1, a->y1, 0, a->style);
    if (a->mark && sw_canvas_world_to_cell(c, a->x0, a->y0, &c0, &r0))
        sw_canvas_put(c, c0, r0, a->mark, a->style);
    if (!sw_canvas_world_to_cell(c, a->x1, a->y1, &c1, &r1))
        return;
    if (moves)
        sw_canvas_put(c, c1, r1, head_glyph(a, unicode), a->style);
}

/* Whether cells col .. col + len - 1 of row may take a label: on the
 * canvas, and holding nothing but blanks and the lines' strokes (never a
 * stage point, an arrow's head, a particle or another label). */
static int label_room(const sw_canvas *c, int col, int row, int len)
{
    if (row < 0 || row >= c->rows || col < 0 || col + len > c->cols)
        return 0;
    for (int k = col - 1; k <= col + len; k++) {
        uint32_t g = sw_canvas_codepoint(c, k, row);
        int inside = k >= col && k < col + len;
        /* inside: strokes may be covered; the cells either side: no letter to run into */
        if (inside ? !(g == ' ' || g == '.' || g == '\'' || g == '\\' || g == '/' || g == '-' || g == '|')
                   : ((g >= 'a' && g <= 'z') || (g >= 'A' && g <= 'Z') || (g >= '0' && g <= '9')))
            return 0;
    }
    return 1;
}

/* The arrow's label beside its tip, after every mark is drawn: on the side
 * the arrow points to, else the other, else the row above or below; never
 * over a mark or another label (with no room it is left out: the message
 * line names the stage). */
static void arrow_label(sw_canvas *c, const arrow *a)
{
    int c1, r1, len = (int)strlen(a->label), right = a->x1 >= a->x0;
    if (!len || !sw_canvas_world_to_cell(c, a->x1, a->y1, &c1, &r1))
        return;
    const int spots[6][2] = { { right ? c1 + 1 : c1 - len, r1 }, { right ? c1 - len : c1 + 1, r1 },
                              { c1 - len / 2, r1 - 1 }, { c1 - len / 2, r1 + 1 },
                              { right ? c1 + 1 : c1 - len, r1 - 1 }, { right ? c1 + 1 : c1 - len, r1 + 1 } };
    for (int i = 0; i < 6; i++)
        if (label_room(c, spots[i][0], spots[i][1], len)) {
            sw_canvas_text(c, spots[i][0], spots[i][1], a->label, a->style);
            return;
        }
}

/* Whether number k (of n, at cells col/row; placed[j]: j's cell is final)
 * may sit at (cc, rr): a blank cell on the canvas with no letter or digit
 * beside it in its row, and no other number in or beside it (so that "2"
 * beside "3" never reads as 23). */
static int number_room(const sw_canvas *c, const int *col, const int *row, const int *placed, int n, int k, int cc,
                       int rr)
{
    if (rr < 0 || rr >= c->rows || cc < 0 || cc >= c->cols || sw_canvas_codepoint(c, cc, rr) != ' ')
        return 0;
    for (int d = cc - 1; d <= cc + 1; d += 2) {
        uint32_t g = sw_canvas_codepoint(c, d, rr);
        if ((g >= 'a' && g <= 'z') || (g >= 'A' && g <= 'Z') || (g >= '0' && g <= '9'))
            return 0;
    }
    for (int j = 0; j < n; j++)
        if (j != k && placed[j] && row[j] == rr && abs(col[j] - cc) <= 1)
            return 0;
    return 1;
}

/* The stage points' numbers, on top. A number in the same cell as a later
 * one or beside it in its row (at a small h, k2's and k3's points lie
 * O(h²) apart) is moved to a free cell above or below, else left out and
 * named in under ("2 under 3"). Returns how many were left out. */
static int stage_numbers(sw_canvas *c, const arrow *ar, int n, int first_now, char *under, size_t len)
{
    int col[2 * SW_STAGE_VIEWS], row[2 * SW_STAGE_VIEWS], placed[2 * SW_STAGE_VIEWS], crowded[2 * SW_STAGE_VIEWS];
    int dropped = 0, later[2 * SW_STAGE_VIEWS];
    size_t used = 0;
    under[0] = '\0';
    for (int i = 0; i < n; i++)
        placed[i] = ar[i].mark >= '1' && ar[i].mark <= '9' && sw_canvas_world_to_cell(c, ar[i].x0, ar[i].y0, &col[i], &row[i]);
    for (int i = 0; i < n; i++) {
        crowded[i] = 0;
        for (int j = i + 1; j < n && placed[i]; j++)
            if (placed[j] && row[j] == row[i] && abs(col[j] - col[i]) <= 1) {
                crowded[i] = 1;
                later[i] = j;
            }
        placed[i] &= !crowded[i];
    }
    static const int spots[6][2] = { { 0, -1 }, { 0, 1 }, { -1, -1 }, { 1, -1 }, { -1, 1 }, { 1, 1 } };
    for (int i = 0; i < n; i++) {
        if (!crowded[i])
            continue;
        int c0 = col[i], r0 = row[i];
        for (int s = 0; s < 6 && !placed[i]; s++)
            if (number_room(c, col, row, placed, n, i, c0 + spots[s][0], r0 + spots[s][1])) {
                col[i] = c0 + spots[s][0];
                row[i] = r0 + spots[s][1];
                placed[i] = 1;
            }
        if (!placed[i] && used + 16 < len) {
            used += (size_t)snprintf(under + used, len - used, "%s%c under %c", dropped ? ", " : "", (char)ar[i].mark,
                                     (char)ar[later[i]].mark);
            dropped++;
        }
    }
    for (int i = 0; i < n; i++)
        if (placed[i])
            sw_canvas_put(c, col[i], row[i], ar[i].mark, i >= first_now ? SW_STYLE_WARN : SW_STYLE_COMPARE1);
    return dropped;
}

/* What the formula's letters are, under it: every script writes its step
 * in y, f, h and k, or a particle's x, v and a (the lesson that first
 * shows the view has not named them yet); '>' marks the line drawn now.
 * Beside the picture one per line; below it, in short (next). */
#define FORMULA_KEYS 6
static const char *const formula_key[2][FORMULA_KEYS] = {
    { "> the line drawn now", "y: the state", "f: its rate, y' = f(t, y)", "k: a slope, f at a point",
      "h: the step, dt", "t: the time" },
    { "> the line drawn now", "x: the position", "v: the velocity", "a: the acceleration, a(x, v)",
      "h: the step, dt", "t: the time" },
};
/* Which key a script's formula needs: 1 when it writes a particle's x, v, a. */
static int key_of(const sw_stage_script *sc)
{
    for (int i = 0; i < SW_STAGE_LINES && sc->lines[i]; i++)
        if (strncmp(sc->lines[i], "x = ", 4) == 0 || strncmp(sc->lines[i], "v = ", 4) == 0)
            return 1;
    return 0;
}

/* The key in short, a field each (a narrow picture wraps it between them). */
static const char *const formula_key_short[2][FORMULA_KEYS] = {
    { "> now", "y state", "f its rate", "k a slope", "h = dt", "t time" },
    { "> now", "x position", "v velocity", "a acceleration", "h = dt", "t time" },
};
#define KEY_ROWS 3

/* The short key's lines for a width; returns how many. */
static int key_lines(const sw_stage_script *sc, int width, char (*lines)[SW_TEXT_LINE])
{
    sw_field f[FORMULA_KEYS];
    for (int i = 0; i < FORMULA_KEYS; i++) {
        snprintf(f[i].full, sizeof f[i].full, "%s", formula_key_short[key_of(sc)][i]);
        f[i].brief[0] = '\0';
        f[i].prio = FORMULA_KEYS - i;
    }
    return sw_text_fit_rows(lines, KEY_ROWS, width, f, FORMULA_KEYS, "  ", NULL);
}


/* The formula, the current line lit (a '>' in front where colour is not
 * seen), and its key under it. */
static int draw_formula(sw_screen *scr, const sw_stage_script *sc, int lit, int upto, int row, int col, int width,
                        int max, int beside)
{
    int used = 0;
    for (int i = 0; i < SW_STAGE_LINES && sc->lines[i] && used < max; i++) {
        char line[SW_TEXT_LINE];
        snprintf(line, sizeof line, "%s %s", i == lit ? ">" : " ", sc->lines[i]);
        int style = i == lit ? SW_STYLE_WARN : i < upto ? SW_STYLE_STATUS : SW_STYLE_DIM;
        if (sw_text_cells(line) <= width)
            used += sw_screen_text(scr, row + used, col, width, style, line) > 0;
        else
            used += sw_screen_wrapped(scr, row + used, col, width, max - used, style, line);
    }
    int k = key_of(sc);
    if (beside && used + 1 + FORMULA_KEYS <= max) {
        used++;
        for (int i = 0; i < FORMULA_KEYS; i++)
            used += sw_screen_text(scr, row + used, col + 2, width - 2, SW_STYLE_DIM, formula_key[k][i]) > 0;
    } else if (!beside && used < max) {
        char lines[KEY_ROWS][SW_TEXT_LINE];
        int n = key_lines(sc, width, lines);
        for (int i = 0; i < n && used < max; i++)
            used += sw_screen_text(scr, row + used, col, width, SW_STYLE_DIM, lines[i]) > 0;
    }
    return used;
}

static int formula_width(const sw_stage_script *sc)
{
    int w = 0;
    for (int i = 0; i < SW_STAGE_LINES && sc->lines[i]; i++)
        w = w > (int)strlen(sc->lines[i]) + 2 ? w : (int)strlen(sc->lines[i]) + 2;
    for (int i = 0; i < FORMULA_KEYS; i++)
        w = w > (int)strlen(formula_key[key_of(sc)][i]) + 2 ? w : (int)strlen(formula_key[key_of(sc)][i]) + 2;
    return w;
}

static int formula_rows(const sw_stage_script *sc, int width)
{
    char lines[4][SW_TEXT_LINE], line[SW_TEXT_LINE];
    int n = 0;
    for (int i = 0; i < SW_STAGE_LINES && sc->lines[i]; i++) {
        snprintf(line, sizeof line, "> %s", sc->lines[i]);
        n += sw_text_wrap(line, width, lines, 4);
    }
    char keys[KEY_ROWS][SW_TEXT_LINE];
    return n + key_lines(sc, width, keys);
}

int sw_draw_stages(sw_frame *f, sw_app *a, sw_screen *scr, int row0, int col0, int rows, int cols)
{
    const sw_stages *r = sw_app_stages(a);
    const sw_stage_script *sc = r ? sw_stage_script_of(r->method) : NULL;
    char buf[SW_TEXT_LINE], err[SW_ERRLEN], under[64] = "";
    if (!r || !sc) {
        snprintf(buf, sizeof buf, "%s. Esc closes.", r ? "stages: not drawn" : a->stages_why);
        sw_screen_wrapped(scr, row0 + 1, col0 + 1, cols - 2, rows - 2, SW_STYLE_TEXT, buf);
        return 0;
    }
    const sw_sim *main = &a->sims[0];
    int shown = a->stage_shown < 1 ? 1 : a->stage_shown > sc->nviews ? sc->nviews : a->stage_shown;
    const sw_stage_view *cur = &sc->views[shown - 1];
    int p = r->particle;

    /* the formula beside the picture when there is room, else below it */
    int fw = formula_width(sc) + 1, side = cols - fw >= 40;
    int ccols = side ? cols - fw - 1 : cols, frows = side ? 0 : formula_rows(sc, cols);
    int crows = rows - 1 - frows; /* the caption is on the message line (app/stages.c) */
    if (crows < 4)
        crows = 0; /* too short for a picture: the formula only */
    int legend = crows > 5; /* the picture's last row says what its glyphs are */
    crows -= legend;

    /* the arrows of every view (the zoom holds the whole step), drawn up to the one shown */
    arrow ar[2 * SW_STAGE_VIEWS];
    int na = 0, drawn = 0, upto[SW_STAGE_VIEWS + 1];
    for (int i = 0; i < sc->nviews; i++) {
        upto[i] = na;
        na += arrows_of(r, &main->sys, p, &sc->views[i], i == shown - 1 ? SW_STYLE_WARN : SW_STYLE_COMPARE1, ar + na);
    }
    upto[sc->nviews] = na;
    sw_canvas *c = &f->canvas;
    sw_view v;
    if (crows > 0) {
        if (c->cols != ccols || c->rows != crows)
            sw_canvas_resize(c, ccols, crows, err, sizeof err);
        sw_canvas_set_mode(c, SW_CANVAS_ASCII); /* arrows and labels read best as glyphs */
        if (!step_view(ar, na, r, &v))
            v = sw_view_zoom(a->scene->view(&main->sys), a->zoom);
        sw_canvas_set_view(c, &v, err, sizeof err);
        sw_canvas_clear(c);
        sw_canvas_draw_system(c, &main->sys, r->y0, r->t0, SW_GLYPH_GHOST, SW_STYLE_GHOST);
        /* the true path over the step, below everything; named where the step lands */
        for (int j = 1; j < r->path_n; j++)
            sw_canvas_line(c, r->path[2 * j - 2], r->path[2 * j - 1], r->path[2 * j], r->path[2 * j + 1],
                           SW_GLYPH_GHOST, SW_STYLE_GHOST);
        arrow truth = { 0, 0, 0, 0, 0, "", SW_STYLE_GHOST };
        if (r->path_n && cur->shape != SW_STAGE_SLOPE) {
            const double *end = &r->path[2 * (r->path_n - 1)];
            truth = (arrow){ end[0], end[1], end[0], end[1], SW_GLYPH_GHOST, "true", SW_STYLE_GHOST };
            draw_arrow(c, &truth, f->unicode);
        }
        /* earlier stages: their points only (a kick: dim), so the current
         * arrow stands alone; then where the current stage is taken from
         * (a dotted line from the step's start), then the current stage */
        const arrow *now = &ar[upto[shown - 1]];
        if (cur->shape == SW_STAGE_SLOPE && (now->x0 != ar[0].x0 || now->y0 != ar[0].y0))
            sw_canvas_line(c, ar[0].x0, ar[0].y0, now->x0, now->y0, '.', SW_STYLE_TRAIL);
        sw_canvas_mark(c, r->y0[2 * p], r->y0[2 * p + 1], 'o', SW_STYLE_MAIN); /* the step's start */
        for (int i = 0; i < upto[shown - 1]; i++) {
            arrow e = ar[i];
            e.style = SW_STYLE_TRAIL;
            e.label = ""; /* only the current stage is named */
            if (e.mark >= '1' && e.mark <= '9')
                e.x1 = e.x0, e.y1 = e.y0, e.mark = 0; /* (its number comes last) */
            draw_arrow(c, &e, f->unicode);
        }
        for (int i = upto[shown - 1]; i < upto[shown]; i++) {
            arrow e = ar[i];
            if (e.mark >= '1' && e.mark <= '9')
                e.mark = 0;
            draw_arrow(c, &e, f->unicode);
        }
        stage_numbers(c, ar, upto[shown], upto[shown - 1], under, sizeof under); /* every stage point on top */
        /* the names last, where they cover nothing: the current stage's, then the true path's */
        for (int i = upto[shown - 1]; i < upto[shown]; i++)
            arrow_label(c, &ar[i]);
        arrow_label(c, &truth);
        drawn = upto[shown];
        sw_screen_blit(scr, c, row0 + 1, col0);
        if (legend) {
            static const sw_field key[] = {
                { "o the step's start", "o start", 9 },
                { "' the true path", "' true", 8 },
                { "-\\|/→ a slope", "→ slope", 7 },
                { ". earlier stages", ". earlier", 6 },
            };
            if (sw_text_fit(buf, sizeof buf, ccols, key, 4, "  ") > 0)
                sw_screen_text(scr, row0 + 1 + crows, col0, ccols, SW_STYLE_DIM, buf);
        }
    }
    /* the title: method, which stage, the keys */
    sw_field fl[6];
    int n = 0;
    snprintf(fl[n].full, sizeof fl[n].full, "one %s step, h = %g", r->method->name, r->h);
    snprintf(fl[n].brief, sizeof fl[n].brief, "%s", r->method->name);
    fl[n++].prio = 10;
    snprintf(fl[n].full, sizeof fl[n].full, "stage %d of %d: %s", shown, sc->nviews, cur->label);
    snprintf(fl[n].brief, sizeof fl[n].brief, "%d/%d %s", shown, sc->nviews, cur->label);
    fl[n++].prio = 9;
    snprintf(fl[n].full, sizeof fl[n].full, "zoomed on the step");
    snprintf(fl[n].brief, sizeof fl[n].brief, "zoomed");
    fl[n++].prio = 3;
    snprintf(fl[n].full, sizeof fl[n].full, "k %s  Esc close", shown < sc->nviews ? "next" : "closes");
    snprintf(fl[n].brief, sizeof fl[n].brief, "k %s", shown < sc->nviews ? "next" : "closes");
    fl[n++].prio = 5;
    if (under[0]) { /* stage points drawn over by a later one, said */
        snprintf(fl[n].full, sizeof fl[n].full, "(%.60s: one cell)", under);
        snprintf(fl[n].brief, sizeof fl[n].brief, "(%.60s)", under);
        fl[n++].prio = 8;
    }
    if (sw_text_fit(buf, sizeof buf, cols, fl, n, "  ") > 0)
        sw_screen_text(scr, row0, col0, cols, SW_STYLE_TITLE, buf);

    if (side)
        draw_formula(scr, sc, cur->line, cur->line, row0 + 1, col0 + ccols + 2, fw - 1, rows - 1, 1);
    else
        draw_formula(scr, sc, cur->line, cur->line, row0 + 1 + crows + legend, col0, cols, frows, 0);
    return drawn;
}
