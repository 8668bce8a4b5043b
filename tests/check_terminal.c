/* What the terminal work rests on, without a terminal: escaping untrusted
 * text for messages, display widths (CJK and emoji take two cells) and the
 * screen grid's wide cells, and the fatal-signal path that restores a
 * terminal (a pseudo-terminal here) before the process dies. */
#define _GNU_SOURCE 1
#include <check.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include "render/screen.h"
#include "util/escape.h"
#include "util/signals.h"
#include "util/utf8.h"

/* ---- escaping ---------------------------------------------------------------------------- */

START_TEST(escape_controls)
{
    char out[64];
    sw_escape("spr\x1b[2Jing", 100, out, sizeof out);
    ck_assert_str_eq(out, "spr\\x1b[2Jing");
    sw_escape("a\nb\rc\td\x7f", 100, out, sizeof out);
    ck_assert_str_eq(out, "a\\x0ab\\x0dc\\x09d\\x7f");
    /* a backslash is escaped too, so the result reads back unambiguously */
    sw_escape("a\\x1b", 100, out, sizeof out);
    ck_assert_str_eq(out, "a\\x5cx1b");
    /* printable UTF-8 stays; C1 controls (U+009B is a CSI) and invalid bytes do not */
    sw_escape("Δt ✓ 日本 \xc2\x9b \xff\xfe \xe2\x9c", 100, out, sizeof out);
    ck_assert_str_eq(out, "Δt ✓ 日本 \\xc2\\x9b \\xff\\xfe \\xe2\\x9c");
    /* invisible formatting too: a right-to-left override (U+202E), a
     * zero-width space (U+200B), a line separator (U+2028), a BOM (U+FEFF);
     * the characters beside them stay (U+2030 per mille, U+200A hair space) */
    sw_escape("a" "\xe2\x80\xae" "b" "\xe2\x80\x8b" "c" "\xe2\x80\xa8" "d" "\xef\xbb\xbf" "\xe2\x80\xb0" "\xe2\x80\x8a", 100, out,
              sizeof out);
    ck_assert_str_eq(out, "a\\xe2\\x80\\xaeb\\xe2\\x80\\x8bc\\xe2\\x80\\xa8d\\xef\\xbb\\xbf" "\xe2\x80\xb0" "\xe2\x80\x8a");
    /* cut by max or by the buffer: marked, never inside a character or an escape */
    sw_escape("abcdef", 3, out, sizeof out);
    ck_assert_str_eq(out, "abc...");
    sw_escape("日本語日本語", 100, out, 12);
    ck_assert_str_eq(out, "日本...");
    sw_escape("\x1b\x1b\x1b\x1b", 100, out, 12);
    ck_assert_str_eq(out, "\\x1b\\x1b...");
    sw_escape(NULL, 10, out, sizeof out);
    ck_assert_str_eq(out, "");
}
END_TEST

START_TEST(escape_messages)
{
    char msg[64];
    snprintf(msg, sizeof msg, "unknown scene '%s'; see \\x1b", "a\nb\x1b[31m");
    sw_escape_message(msg, sizeof msg);
    /* one line, no ESC; backslashes already in the message are kept */
    ck_assert_str_eq(msg, "unknown scene 'a\\x0ab\\x1b[31m'; see \\x1b");
    char small[10] = "abc\ndefgh";
    sw_escape_message(small, sizeof small);
    ck_assert_str_eq(small, "abc...");
    for (size_t i = 0; small[i]; i++)
        ck_assert((unsigned char)small[i] >= 0x20);
}
END_TEST

/* ---- widths ------------------------------------------------------------------------------- */

START_TEST(display_widths)
{
    ck_assert_int_eq(sw_utf8_width('a'), 1);
    ck_assert_int_eq(sw_utf8_width(0x0394), 1);   /* Δ */
    ck_assert_int_eq(sw_utf8_width(0x2713), 1);   /* ✓ */
    ck_assert_int_eq(sw_utf8_width(0x2800), 1);   /* Braille */
    ck_assert_int_eq(sw_utf8_width(0x65E5), 2);   /* 日 */
    ck_assert_int_eq(sw_utf8_width(0xAC00), 2);   /* 가 */
    ck_assert_int_eq(sw_utf8_width(0xFF21), 2);   /* Ａ fullwidth */
    ck_assert_int_eq(sw_utf8_width(0x1F642), 2);  /* 🙂 */
    ck_assert_int_eq(sw_utf8_width(0x2705), 2);   /* ✅ */
    ck_assert_int_eq(sw_utf8_width(0x0301), 0);   /* combining acute */
    ck_assert_int_eq(sw_utf8_width(0x200D), 0);   /* zero-width joiner */
    ck_assert_int_eq(sw_utf8_width('\n'), 0);
    ck_assert_uint_eq(sw_utf8_columns("ab日本🙂", strlen("ab日本🙂")), 8);
    size_t used;
    /* 5 cells take "ab日" (4) but not half of 本 */
    ck_assert_uint_eq(sw_utf8_fit("ab日本", strlen("ab日本"), 5, &used), strlen("ab日"));
    ck_assert_uint_eq(used, 4);
    ck_assert_uint_eq(sw_utf8_fit("ab日本", strlen("ab日本"), 6, &used), strlen("ab日本"));
    ck_assert_uint_eq(used, 6);
    ck_assert_uint_eq(sw_utf8_fit("日", 3, 1, &used), 0);
}
END_TEST

START_TEST(screen_wide_cells)
{
    sw_screen s;
    char err[128], text[256];
    ck_assert_int_eq(sw_screen_init(&s, 10, 2, err, sizeof err), 0);
    /* two cells each; the third does not fit in 5 cells and is left out whole */
    ck_assert_int_eq(sw_screen_text(&s, 0, 0, 5, 0, "日本語"), 4);
    ck_assert_uint_eq(s.cp[0], 0x65E5);
    ck_assert_uint_eq(s.cp[1], SW_SCREEN_WIDE_TAIL);
    ck_assert_uint_eq(s.cp[4], ' ');
    /* at the screen's edge: never half a character */
    ck_assert_int_eq(sw_screen_text(&s, 1, 7, 10, 0, "a🙂🙂"), 3);
    ck_assert_uint_eq(s.cp[10 + 7], 'a');
    ck_assert_uint_eq(s.cp[10 + 8], 0x1F642);
    ck_assert_uint_eq(s.cp[10 + 9], SW_SCREEN_WIDE_TAIL);
    sw_screen_to_text(&s, text, sizeof text);
    ck_assert_str_eq(text, "日本\n       a🙂\n");
    /* overwriting half of a wide character blanks the other half */
    sw_screen_text(&s, 0, 1, 1, 0, "x");
    sw_screen_text(&s, 0, 2, 1, 0, "y");
    sw_screen_to_text(&s, text, sizeof text);
    ck_assert_str_eq(text, " xy\n       a🙂\n");
    /* combining marks take no cell */
    sw_screen_clear(&s);
    ck_assert_int_eq(sw_screen_text(&s, 0, 0, 10, 0, "e\xcc\x81z"), 2);
    sw_screen_to_text(&s, text, sizeof text);
    ck_assert_str_eq(text, "ez\n\n");
    sw_screen_free(&s);
}
END_TEST

/* ---- fatal signals ------------------------------------------------------------------------ */

/* A pseudo-terminal: the master to read what was written, the slave to
 * set modes on, as a terminal UI would. */
static void open_pty(int *master, int *slave)
{
    *master = posix_openpt(O_RDWR | O_NOCTTY);
    ck_assert_int_ge(*master, 0);
    ck_assert_int_eq(grantpt(*master), 0);
    ck_assert_int_eq(unlockpt(*master), 0);
    *slave = open(ptsname(*master), O_RDWR | O_NOCTTY);
    ck_assert_int_ge(*slave, 0);
}

/* Run a child that arms the restore on the pty, puts it in raw-ish modes
 * (as curses does) and dies of sig; forked_child: the signal arrives in a
 * grandchild forked after arming, which must not restore. Returns how the
 * child ended; the pty's modes and output are left for the caller. */
static int die_armed(int slave, int sig, int forked_child, int disarm)
{
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        /* a core would only litter the test directory */
        struct rlimit none = { 0, 0 };
        setrlimit(RLIMIT_CORE, &none);
        /* the action before arming is the default one (a sanitizer's own
         * handler would report and exit instead of dying of the signal) */
        signal(sig, SIG_DFL);
        struct termios saved, raw;
        tcgetattr(slave, &saved);
        raw = saved;
        raw.c_lflag &= ~(tcflag_t)(ICANON | ECHO);
        tcsetattr(slave, TCSANOW, &raw);
        static const char reset[] = "\033[?1049lRESET\r\n";
        sw_signals_fatal_arm(slave, &saved, reset, sizeof reset - 1);
        if (disarm)
            sw_signals_fatal_disarm();
        if (forked_child) {
            pid_t g = fork();
            if (g == 0) {
                raise(sig);
                _exit(0);
            }
            int st;
            waitpid(g, &st, 0);
            _exit(WIFSIGNALED(st) && WTERMSIG(st) == sig ? 42 : 43);
        }
        raise(sig);
        _exit(0);
    }
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    return status;
}

static size_t drain(int master, char *buf, size_t len)
{
    int fl = fcntl(master, F_GETFL);
    fcntl(master, F_SETFL, fl | O_NONBLOCK);
    size_t n = 0;
    for (ssize_t k; n + 1 < len && (k = read(master, buf + n, len - 1 - n)) > 0;)
        n += (size_t)k;
    buf[n] = '\0';
    return n;
}

START_TEST(fatal_signal_restores_terminal)
{
    static const int sigs[] = { SIGSEGV, SIGABRT, SIGQUIT, SIGBUS, SIGFPE };
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        int master, slave;
        open_pty(&master, &slave);
        int status = die_armed(slave, sigs[i], 0, 0);
        /* it died of the signal, as it would have unarmed */
        ck_assert_msg(WIFSIGNALED(status) && WTERMSIG(status) == sigs[i], "signal %d: status %#x", sigs[i],
                      status);
        struct termios now;
        ck_assert_int_eq(tcgetattr(slave, &now), 0);
        ck_assert_msg((now.c_lflag & ICANON) && (now.c_lflag & ECHO), "signal %d left the pty raw", sigs[i]);
        char out[256];
        drain(master, out, sizeof out);
        ck_assert_msg(strstr(out, "RESET") != NULL, "signal %d: reset sequence not written (got '%s')", sigs[i],
                      out);
        close(slave);
        close(master);
    }
}
END_TEST

START_TEST(fatal_signal_child_and_disarmed)
{
    int master, slave;
    /* a child forked after arming (a plugin's sandbox) dies plainly */
    open_pty(&master, &slave);
    int status = die_armed(slave, SIGSEGV, 1, 0);
    ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 42);
    char out[256];
    drain(master, out, sizeof out);
    ck_assert_ptr_null(strstr(out, "RESET"));
    close(slave);
    close(master);
    /* disarmed (the terminal was restored already): nothing written, still dies */
    open_pty(&master, &slave);
    status = die_armed(slave, SIGABRT, 0, 1);
    ck_assert(WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT);
    drain(master, out, sizeof out);
    ck_assert_ptr_null(strstr(out, "RESET"));
    struct termios now;
    ck_assert_int_eq(tcgetattr(slave, &now), 0);
    ck_assert(!(now.c_lflag & ICANON)); /* proves the raw modes would have stayed without the restore */
    close(slave);
    close(master);
}
END_TEST

Suite *make_terminal_suite(void);
Suite *make_terminal_suite(void)
{
    Suite *s = suite_create("terminal");
    TCase *tc = tcase_create("terminal");
    tcase_add_test(tc, escape_controls);
    tcase_add_test(tc, escape_messages);
    tcase_add_test(tc, display_widths);
    tcase_add_test(tc, screen_wide_cells);
    tcase_add_test(tc, fatal_signal_restores_terminal);
    tcase_add_test(tc, fatal_signal_child_and_disarmed);
    suite_add_tcase(s, tc);
    return s;
}
