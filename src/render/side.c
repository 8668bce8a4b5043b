/* The lesson pane (render/side.h): where its lines go, not what they say
 * (the lesson runner builds them). */
#include "render/side.h"

#include "render/text.h"

static int side_style(sw_side_kind kind)
{
    static const int styles[] = {
        [SW_SIDE_TEXT] = SW_STYLE_TEXT, [SW_SIDE_VERBATIM] = SW_STYLE_STATUS, [SW_SIDE_TITLE] = SW_STYLE_TITLE,
        [SW_SIDE_OK] = SW_STYLE_OK, [SW_SIDE_BAD] = SW_STYLE_BAD, [SW_SIDE_DIM] = SW_STYLE_DIM,
        [SW_SIDE_HINT] = SW_STYLE_WARN,
    };
    return kind >= 0 && kind < (int)(sizeof styles / sizeof styles[0]) ? styles[kind] : SW_STYLE_TEXT;
}

/* Lines off + first .. off + n - 1 of the pane from row on, scrolled with
 * a row that says there is more above or below; returns first clamped. */
static int draw_scrolled(const sw_side *side, sw_screen *scr, int row, int col, int height, int width, int off,
                         int n, int first)
{
    int more_above = 0, more_below = 0, body = height;
    if (n <= height)
        first = 0; /* it all fits: nothing to scroll, no "more" rows */
    for (int pass = 0; pass < 3 && n > height; pass++) {
        more_above = first > 0;
        body = height - more_above;
        more_below = first + body < n;
        body -= more_below;
        int max_first = n - body;
        if (first > max_first)
            first = max_first;
        if (first < 0)
            first = 0;
    }
    int r = row;
    if (more_above)
        sw_screen_text(scr, r++, col, width, SW_STYLE_DIM, "(Up: more above)");
    for (int i = 0; first + i < n && i < body; i++)
        sw_screen_text(scr, r++, col, width,
                       side_style(side->kinds ? side->kinds[off + first + i] : SW_SIDE_TEXT),
                       side->lines[off + first + i]);
    if (more_below)
        sw_screen_text(scr, row + height - 1, col, width, SW_STYLE_DIM, "(Down: more below)");
    return first;
}

static void draw_lines(const sw_side *side, sw_screen *scr, int row, int col, int width, int from, int n)
{
    for (int i = 0; i < n; i++)
        sw_screen_text(scr, row + i, col, width, side_style(side->kinds ? side->kinds[from + i] : SW_SIDE_TEXT),
                       side->lines[from + i]);
}

/* The fewest rows the page's text keeps while the goals and the question
 * stay in sight below it. */
#define SIDE_TEXT_MIN 4

/* The lesson pane: the lesson's and the page's titles stay at its top; when
 * the rest is too long, the text scrolls and what the page asks (goals,
 * question) stays at its foot. A question with no room beside the text
 * folds into one line until the text has been read to its end (Down), and
 * then takes the room it needs, the text's last lines above it; Up folds
 * it again. Nothing here depends on a goal being met, so the pane moves
 * only with a key. */
void sw_side_draw(const sw_side *side, sw_screen *scr, int row, int col, int height, int width)
{
    int head = side->head < height - 2 ? side->head : 0;
    draw_lines(side, scr, row, col, width, 0, head);
    row += head;
    height -= head;
    int text = side->nlines - head - side->pinned, foot = side->pinned;
    int first = side->scroll ? *side->scroll : 0, window_rows = height;
    /* folded, the question leaves one line; the text's end is in sight from `open` on */
    int kept = foot - side->fold, window = height - kept - 1;
    int open = text <= window ? 1 : text - window + 1; /* (past the top, a row says "more above") */
    if (text + foot <= height || foot <= 0)
        first = draw_scrolled(side, scr, row, col, height, width, head, text + foot, first);
    else if (side->fold > 0 && window >= SIDE_TEXT_MIN && first < open) {
        window_rows = window;
        first = draw_scrolled(side, scr, row, col, window, width, head, text, first);
        draw_lines(side, scr, row + window, col, width, side->nlines - foot, kept);
        static const char *const stub[] = { "(a question below: Down; o: wide)", "(a question below: Down)",
                                            "(question: Down)" };
        int k = side->full; /* (in the reading mode already: no "o: wide") */
        while (k < 2 && sw_text_cells(stub[k]) > width)
            k++;
        sw_screen_text(scr, row + height - 1, col, width, SW_STYLE_TITLE, stub[k]);
    } else if (foot <= height - (side->fold > 0 ? 1 : SIDE_TEXT_MIN)) {
        /* the foot whole at the bottom, the text above it from where the
         * reader was (never its end at once: the lines between would be
         * skipped); a question that opened stays open */
        window_rows = height - foot; /* what a press moves: the rows the text has here */
        int shown = draw_scrolled(side, scr, row, col, height - foot, width, head, text, first);
        draw_lines(side, scr, row + height - foot, col, width, side->nlines - foot, foot);
        first = side->fold > 0 && shown < open ? open : shown;
    } else if (side->fold > 0 && window >= SIDE_TEXT_MIN) {
        /* the foot alone is taller than the pane: it scrolls on from where the fold opened */
        first = open + draw_scrolled(side, scr, row, col, height, width, side->nlines - foot, foot, first - open);
    } else
        first = draw_scrolled(side, scr, row, col, height, width, head, text + foot, first); /* as one */
    if (side->scroll)
        *side->scroll = first;
    /* a press moves the text's rows less the two "more" lines and one
     * line read before, so nothing is skipped */
    if (side->step)
        *side->step = window_rows - 3;
}
