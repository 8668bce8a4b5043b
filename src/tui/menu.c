/* The lesson menu on the terminal: lines drawn onto a screen grid, arrows
 * or a digit to choose, Enter to open. What the lines say is the caller's. */
#include "tui/loop.h"

#include <stdio.h>

#include "stepwise/base.h"
#include "tui/term.h"
#include "util/signals.h"

int sw_tui_menu(const char *title, const char *const *lines, int n, int *sel, char *err, size_t errlen)
{
    if (sw_term_start(err, errlen) != SW_OK)
        return -3;
    int cols, rows, chosen = -1;
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
        sw_screen_clear(&scr);
        sw_screen_text(&scr, 0, 2, cols - 2, SW_STYLE_TITLE, title);
        sw_screen_text(&scr, 1, 2, cols - 2, SW_STYLE_DIM, "Up/Down or a number to choose, Enter to open, q to quit");
        for (int i = 0; i < n && 3 + i < rows - 1; i++) {
            char row[512];
            snprintf(row, sizeof row, "%s %s", i == *sel ? ">" : " ", lines[i]);
            sw_screen_text(&scr, 3 + i, 2, cols - 2, i == *sel ? SW_STYLE_MAIN : SW_STYLE_TEXT, row);
        }
        sw_term_paint(&scr);
        int key = sw_term_key(500);
        if (key == 'q' || key == SW_KEY_ESC) {
            sw_screen_free(&scr);
            sw_term_stop();
            return -1;
        }
        if (key == SW_KEY_UP && *sel > 0)
            (*sel)--;
        else if (key == SW_KEY_DOWN && *sel + 1 < n)
            (*sel)++;
        else if (key >= '1' && key <= '9' && key - '1' < n)
            *sel = key - '1';
        else if (key == '\r' || key == '\n' || key == SW_KEY_RIGHT)
            chosen = *sel;
    }
    sw_screen_free(&scr);
    if (chosen < 0) {
        sw_term_stop();
        return -2;
    }
    return chosen;
}
