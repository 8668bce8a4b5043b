/* The lesson menu on the terminal: lines drawn onto a screen grid, arrows,
 * PgUp/PgDn or a number to choose, Enter to open. The list scrolls so the
 * chosen line is always shown, however many lessons there are. What the
 * lines say is the caller's. */
#include "tui/loop.h"

#include <stdio.h>
#include <string.h>

#include "stepwise/base.h"
#include "tui/term.h"
#include "util/clock.h"
#include "util/signals.h"
#include "util/utf8.h"

#define NOTE_ROWS 3 /* a note longer than a row wraps onto up to this many */

/* Rows the note takes at the bottom of a screen cols wide. */
static int note_rows(const char *note, int cols)
{
    if (!note || !*note || cols < 1)
        return 0;
    size_t w = sw_utf8_columns(note, strlen(note));
    int r = (int)((w + (size_t)cols - 1) / (size_t)cols);
    return r > NOTE_ROWS ? NOTE_ROWS : r;
}

/* First line shown so that sel is within [top, top + visible). */
static int scroll_to(int top, int sel, int visible, int n)
{
    if (sel < top)
        top = sel;
    if (sel >= top + visible)
        top = sel - visible + 1;
    if (top > n - visible)
        top = n - visible;
    return top < 0 ? 0 : top;
}

static void draw(sw_screen *scr, const char *title, const char *const *lines, int n, int sel, int top,
                 int visible, const char *note)
{
    int cols = scr->cols;
    char row[512];
    sw_screen_clear(scr);
    sw_screen_text(scr, 0, 2, cols - 2, SW_STYLE_TITLE, title);
    sw_screen_text(scr, 1, 2, cols - 2, SW_STYLE_DIM,
                   "Up/Down, PgUp/PgDn or a number to choose, Enter to open, q to quit");
    if (top > 0) {
        snprintf(row, sizeof row, "  (%d more above)", top);
        sw_screen_text(scr, 2, 2, cols - 2, SW_STYLE_DIM, row);
    }
    for (int i = top; i < n && i < top + visible; i++) {
        snprintf(row, sizeof row, "%s %s", i == sel ? ">" : " ", lines[i]);
        sw_screen_text(scr, 3 + i - top, 2, cols - 2, i == sel ? SW_STYLE_MAIN : SW_STYLE_TEXT, row);
    }
    if (top + visible < n) {
        snprintf(row, sizeof row, "  (%d more below)", n - top - visible);
        sw_screen_text(scr, 3 + visible, 2, cols - 2, SW_STYLE_DIM, row);
    }
    int nr = note_rows(note, cols);
    const char *p = note;
    for (int r = scr->rows - nr; nr > 0 && r < scr->rows && *p; r++) {
        size_t len = strlen(p), k = sw_utf8_fit(p, len, (size_t)cols, NULL);
        if (k == 0)
            break;
        snprintf(row, sizeof row, "%.*s", (int)(k < sizeof row ? k : sizeof row - 1), p);
        sw_screen_text(scr, r, 0, cols, SW_STYLE_BAD, row);
        p += k;
    }
}

int sw_tui_menu(const char *title, const char *const *lines, int n, int *sel, const char *note, char *err,
                size_t errlen)
{
    if (sw_term_start(err, errlen) != SW_OK)
        return -3;
    int cols, rows, chosen = -1, top = 0, typed = 0;
    double typed_at = 0;
    sw_screen scr = { 0 };
    while (chosen < 0 && !sw_signal_caught) {
        sw_term_size(&cols, &rows);
        if (scr.cols != cols || scr.rows != rows) {
            sw_screen_free(&scr);
            if (sw_screen_init(&scr, cols < 1 ? 1 : cols, rows < 1 ? 1 : rows, err, errlen) != SW_OK) {
                sw_term_stop();
                return -3;
            }
        }
        /* title, keys, "more above", the list, "more below", the note */
        int visible = scr.rows - 4 - (note_rows(note, scr.cols) > 0 ? note_rows(note, scr.cols) : 1);
        if (visible < 1)
            visible = 1;
        top = scroll_to(top, *sel, visible, n);
        draw(&scr, title, lines, n, *sel, top, visible, note);
        sw_term_paint(&scr);
        int key = sw_term_key(500);
        if (key == SW_TERM_GONE) {
            sw_signals_hangup();
            break;
        }
        if (key == -1 || key == -2)
            continue;
        note = NULL; /* a key read it */
        if (key == 'q' || key == SW_KEY_ESC) {
            sw_screen_free(&scr);
            sw_term_stop();
            return -1;
        }
        int was = *sel;
        if (key == SW_KEY_UP && *sel > 0)
            (*sel)--;
        else if (key == SW_KEY_DOWN && *sel + 1 < n)
            (*sel)++;
        else if (key == SW_KEY_PGUP)
            *sel = *sel - visible < 0 ? 0 : *sel - visible;
        else if (key == SW_KEY_PGDN)
            *sel = *sel + visible >= n ? n - 1 : *sel + visible;
        else if (key >= '0' && key <= '9') {
            /* digits typed within a second make one number: 4 then 6 is lesson 46 */
            double now = sw_clock_now();
            int more = typed * 10 + (key - '0');
            typed = typed > 0 && now - typed_at < 1.0 && more <= n ? more : key - '0';
            typed_at = now;
            if (typed >= 1 && typed <= n)
                *sel = typed - 1;
        } else if (key == '\r' || key == '\n' || key == SW_KEY_RIGHT)
            chosen = *sel;
        if (*sel != was && key != SW_KEY_UP && key != SW_KEY_DOWN)
            top = scroll_to(*sel - visible / 2 < 0 ? 0 : *sel - visible / 2, *sel, visible, n);
    }
    sw_screen_free(&scr);
    if (chosen < 0) {
        sw_term_stop();
        return -2;
    }
    return chosen;
}
