/* ncurses behind a small interface: start/stop with the terminal always
 * restored (atexit, after htop's CRT_done and tig's done_display), colours
 * that respect NO_COLOR, keys translated to SW_KEY_*, and painting cells. */
#include "tui/term.h"

#include <curses.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <wchar.h>

#include "stepwise/base.h"
#include "util/signals.h"

static int started;
static pid_t owner; /* the process that started curses: a forked child never restores it */
static int colour;
static attr_t style_attr[SW_STYLE_ALL];
static short style_pair[SW_STYLE_ALL];

void sw_term_stop(void)
{
    if (!started || getpid() != owner)
        return;
    started = 0;
    curs_set(1);
    endwin();
}

static void set_styles(void)
{
    /* colour pairs: foreground per style, default background */
    static const short fg[SW_STYLE_ALL] = {
        [SW_STYLE_MAIN] = COLOR_YELLOW, [SW_STYLE_COMPARE1] = COLOR_CYAN, [SW_STYLE_COMPARE2] = COLOR_MAGENTA,
        [SW_STYLE_GHOST] = COLOR_GREEN, [SW_STYLE_SPRING] = COLOR_WHITE, [SW_STYLE_WALL] = COLOR_BLUE,
        [SW_STYLE_TRAIL] = COLOR_YELLOW, [SW_STYLE_WARN] = COLOR_RED, [SW_STYLE_TEXT] = -1,
        [SW_STYLE_STATUS] = -1, [SW_STYLE_TITLE] = -1, [SW_STYLE_OK] = COLOR_GREEN, [SW_STYLE_BAD] = COLOR_RED,
        [SW_STYLE_DIM] = -1,
    };
    static const attr_t mono[SW_STYLE_ALL] = {
        [SW_STYLE_MAIN] = A_BOLD, [SW_STYLE_GHOST] = A_DIM, [SW_STYLE_TRAIL] = A_DIM, [SW_STYLE_WARN] = A_BOLD,
        [SW_STYLE_TITLE] = A_BOLD, [SW_STYLE_OK] = A_BOLD, [SW_STYLE_BAD] = A_REVERSE | A_BOLD,
        [SW_STYLE_DIM] = A_DIM,
    };
    const char *no = getenv("NO_COLOR");
    colour = has_colors() && !(no && *no);
    if (colour) {
        start_color();
        use_default_colors();
    }
    for (int s = 0; s < SW_STYLE_ALL; s++) {
        style_attr[s] = mono[s];
        if (colour && fg[s] >= 0) {
            init_pair((short)(s + 1), fg[s], -1);
            style_pair[s] = (short)(s + 1);
        }
    }
}

int sw_term_start(char *err, size_t errlen)
{
    if (started)
        return SW_OK;
    setlocale(LC_ALL, "");         /* wide characters for Braille and ✓ */
    setlocale(LC_NUMERIC, "C");    /* but numbers stay 0.05, never 0,05: traces and lessons */
    if (!newterm(NULL, stdout, stdin)) {
        snprintf(err, errlen, "cannot start the terminal (is TERM set?)");
        return SW_EIO;
    }
    started = 1;
    owner = getpid();
    atexit(sw_term_stop);
    sw_signals_catch();
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    curs_set(0);
    set_escdelay(25);
    set_styles();
    return SW_OK;
}

void sw_term_size(int *cols, int *rows)
{
    getmaxyx(stdscr, *rows, *cols);
}

int sw_term_key(int timeout_ms)
{
    timeout(timeout_ms);
    int ch = getch();
    switch (ch) {
    case ERR:
        return -1;
    case KEY_RESIZE:
        return -2;
    case KEY_UP:
        return SW_KEY_UP;
    case KEY_DOWN:
        return SW_KEY_DOWN;
    case KEY_LEFT:
        return SW_KEY_LEFT;
    case KEY_RIGHT:
        return SW_KEY_RIGHT;
    case '\t':
        return SW_KEY_TAB;
    case KEY_BTAB:
        return SW_KEY_BTAB;
    case KEY_NPAGE:
        return SW_KEY_PGDN;
    case KEY_PPAGE:
        return SW_KEY_PGUP;
    case 27:
        return SW_KEY_ESC;
    default:
        return ch >= 0 && ch < 256 ? ch : -1;
    }
}

void sw_term_paint(const sw_screen *s)
{
    int rows, cols;
    getmaxyx(stdscr, rows, cols);
    for (int r = 0; r < s->rows && r < rows; r++)
        for (int c = 0; c < s->cols && c < cols; c++) {
            size_t i = (size_t)r * (size_t)s->cols + (size_t)c;
            wchar_t w[2] = { (wchar_t)s->cp[i], 0 };
            int st = s->style[i] < SW_STYLE_ALL ? s->style[i] : SW_STYLE_TEXT;
            attr_t a = style_attr[st];
            if (s->fade[i])
                a |= A_DIM;
            cchar_t cc;
            setcchar(&cc, w, a, style_pair[st], NULL);
            mvadd_wch(r, c, &cc);
        }
    refresh();
}
