/* A command's report for a terminal: each line too wide for it goes on
 * under its own text (try's "  check      PASS: ..." under "PASS"), broken
 * between words, so that a student at 80 columns reads whole words. */
#include "cli/cli.h"

#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "util/wrap.h"

typedef struct hang {
    FILE *to;
    int lead, hang, first;
} hang;

static void put_line(void *ctx, int lead, const char *text, size_t len)
{
    hang *h = ctx;
    (void)lead;
    fprintf(h->to, "%*s%.*s\n", h->first ? h->lead : h->hang, "", (int)len, text);
    h->first = 0;
}

/* Where a line's text starts after a label: "  order      claimed" hangs
 * under "claimed"; a line without one, two in from its own indent. */
static int hang_of(const char *line, int lead, int width)
{
    const char *p = line + lead;
    while (*p && *p != ' ')
        p++;
    const char *gap = p;
    while (*p == ' ')
        p++;
    int at = p - gap >= 2 && *p ? (int)(p - line) : lead + 2;
    return at <= width / 2 ? at : lead + 2;
}

void sw_cli_report_wrapped(FILE *to, const char *text, int width)
{
    for (const char *line = text; *line;) {
        const char *end = strchr(line, '\n');
        size_t n = end ? (size_t)(end - line) : strlen(line);
        char *one = strndup(line, n);
        int lead = 0;
        while (one && one[lead] == ' ')
            lead++;
        if (!one || (int)n <= width || width < 40) {
            fprintf(to, "%.*s\n", (int)n, line);
        } else {
            hang h = { to, lead, hang_of(one, lead, width), 1 };
            sw_wrap_paragraph(one + lead, width - h.hang, put_line, &h);
        }
        free(one);
        line = end ? end + 1 : line + n;
    }
}

int sw_cli_terminal_width(FILE *f)
{
    struct winsize ws;
    int fd = fileno(f);
    if (fd < 0 || !isatty(fd) || ioctl(fd, TIOCGWINSZ, &ws) != 0 || ws.ws_col == 0)
        return 0;
    return ws.ws_col;
}
