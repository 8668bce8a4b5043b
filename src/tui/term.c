/* ncurses behind a small interface: start/stop with the terminal always
 * restored (atexit, after htop's CRT_done and tig's done_display; a fatal
 * signal through util/signals), colours that respect NO_COLOR, keys
 * translated to SW_KEY_*, a terminal that went away noticed, painting cells. */
#include "tui/term.h"

#include <curses.h>
#include <term.h>
#include <errno.h>
#include <locale.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>
#include <wchar.h>

#include "stepwise/base.h"
#include "util/escape.h"
#include "util/signals.h"
#include "util/utf8.h"

static int started;
static pid_t owner; /* the process that started curses: a forked child never restores it */
static int colour;
static int utf8;
static attr_t style_attr[SW_STYLE_ALL];
static short style_pair[SW_STYLE_ALL];

void sw_term_stop(void)
{
    if (!started || getpid() != owner)
        return;
    started = 0;
    sw_signals_fatal_disarm();
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

/* ---- what a fatal signal writes: computed now, written by the handler ----------------- */

static char reset_seq[SW_SIGNALS_RESET_MAX];
static size_t reset_len;

static int reset_putc(int c)
{
    if (reset_len < sizeof reset_seq)
        reset_seq[reset_len++] = (char)c;
    return c;
}

/* The terminal's own strings to leave the UI (padding expanded by tputs):
 * attributes off, colours back, keypad off, cursor shown, the shell's
 * screen back; then a newline so the shell's prompt starts on a line of its own. */
static void arm_fatal(const struct termios *modes)
{
    static const char *const caps[] = { "sgr0", "op", "rmkx", "cnorm", "rmcup" };
    reset_len = 0;
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; i++) {
        char *s = tigetstr(caps[i]);
        if (s && s != (char *)-1)
            tputs(s, 1, reset_putc);
    }
    reset_putc('\r');
    reset_putc('\n');
    sw_signals_fatal_arm(STDOUT_FILENO, modes, reset_seq, reset_len);
}

/* ---- start ------------------------------------------------------------------------------ */

/* A terminal type without an entry gets a message naming it; checked with
 * setupterm before newterm, which would leak its half-made screen. */
static int check_term(char *err, size_t errlen)
{
    const char *term = getenv("TERM");
    if (!term || !*term) {
        snprintf(err, errlen, "TERM is not set, so the terminal's type is unknown; expected it set, "
                 "e.g. TERM=xterm-256color");
        return SW_EIO;
    }
    int why = 0;
    if (setupterm(term, STDOUT_FILENO, &why) != OK) {
        char shown[120];
        sw_escape(term, 60, shown, sizeof shown);
        if (why == 0)
            snprintf(err, errlen, "unknown terminal type TERM='%s' (no terminfo entry for it); expected "
                     "one this system knows, e.g. TERM=xterm-256color", shown);
        else
            snprintf(err, errlen, "cannot use terminal type TERM='%s' (no terminfo database found); "
                     "expected the ncurses terminfo files installed", shown);
        return SW_EIO;
    }
    del_curterm(cur_term);
    return SW_OK;
}

int sw_term_start(char *err, size_t errlen)
{
    if (started)
        return SW_OK;
    setlocale(LC_ALL, "");         /* wide characters for Braille and ✓ */
    setlocale(LC_NUMERIC, "C");    /* but numbers stay 0.05, never 0,05: traces and lessons */
    utf8 = sw_utf8_locale();
    static int term_known; /* checked once: the menu starts curses again after each lesson */
    if (!term_known && check_term(err, errlen) != SW_OK)
        return SW_EIO;
    term_known = 1;
    struct termios modes;
    int have_modes = tcgetattr(STDOUT_FILENO, &modes) == 0;
    if (!newterm(NULL, stdout, stdin)) {
        char shown[120];
        sw_escape(getenv("TERM"), 60, shown, sizeof shown);
        snprintf(err, errlen, "cannot start the terminal (TERM='%s')", shown);
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
    if (have_modes)
        arm_fatal(&modes);
    return SW_OK;
}

int sw_term_utf8(void) { return utf8; }

void sw_term_size(int *cols, int *rows)
{
    getmaxyx(stdscr, *rows, *cols);
}

/* After getch found no key: has input ended? A hung-up terminal polls as
 * HUP/ERR, or as readable with nothing to read (end of file); either way
 * every later read returns at once, and a loop waiting for keys would spin. */
static int input_gone(void)
{
    struct pollfd p = { .fd = STDIN_FILENO, .events = POLLIN };
    int n = poll(&p, 1, 0);
    if (n < 0)
        return errno != EINTR && errno != EAGAIN;
    if (n == 0)
        return 0;
    if (p.revents & (POLLHUP | POLLERR | POLLNVAL))
        return 1;
    int avail = 0;
    return (p.revents & POLLIN) && ioctl(STDIN_FILENO, FIONREAD, &avail) == 0 && avail == 0;
}

int sw_term_key(int timeout_ms)
{
    timeout(timeout_ms);
    int ch = getch();
    switch (ch) {
    case ERR:
        return input_gone() ? SW_TERM_GONE : -1;
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

/* One cell: what the composer put there, as the terminal will show it. The
 * composer gives a wide character two cells (the second SW_SCREEN_WIDE_TAIL);
 * anything whose width here differs (another locale, a stray half) becomes
 * a space or '?', so no character ever shifts the rest of a row. */
static wchar_t cell_char(const sw_screen *s, int r, int c, int cols, int *wide)
{
    size_t i = (size_t)r * (size_t)s->cols + (size_t)c;
    uint32_t cp = s->cp[i];
    *wide = 0;
    if (cp == SW_SCREEN_WIDE_TAIL)
        return L' ';
    if (cp < 0x80)
        return (wchar_t)cp;
    int w = wcwidth((wchar_t)cp);
    if (sw_utf8_width(cp) == 2) {
        int tail = c + 1 < s->cols && c + 1 < cols && s->cp[i + 1] == SW_SCREEN_WIDE_TAIL;
        if (w == 2 && tail) {
            *wide = 1;
            return (wchar_t)cp;
        }
        return w == 1 ? (wchar_t)cp : L'?';
    }
    return w == 1 ? (wchar_t)cp : L'?';
}

void sw_term_paint(const sw_screen *s)
{
    int rows, cols;
    getmaxyx(stdscr, rows, cols);
    for (int r = 0; r < s->rows && r < rows; r++)
        for (int c = 0; c < s->cols && c < cols; c++) {
            size_t i = (size_t)r * (size_t)s->cols + (size_t)c;
            int wide;
            wchar_t w[2] = { cell_char(s, r, c, cols, &wide), 0 };
            int st = s->style[i] < SW_STYLE_ALL ? s->style[i] : SW_STYLE_TEXT;
            attr_t a = style_attr[st];
            if (s->fade[i])
                a |= A_DIM;
            cchar_t cc;
            setcchar(&cc, w, a, style_pair[st], NULL);
            mvadd_wch(r, c, &cc);
            c += wide; /* the wide character covers the next cell too */
        }
    refresh();
}
