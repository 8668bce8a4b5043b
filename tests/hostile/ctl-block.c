/* The control block a plugin shares with its parent (as of the issue: a
 * MAP_SHARED page before y, holding the step's handshake, the fault code,
 * the index of the ode field changed and a text). The plugin finds it from
 * /proc/self/maps — the shared writable mapping just before the guard
 * before y — and writes a fault "changed an ode field" with a field index
 * of 2^30, and a text with no NUL full of escapes, then returns. A parent
 * that trusts it indexes its table of field names out of bounds. Nothing
 * writable may be shared: with no such mapping the plugin does nothing
 * (and fails, being Euler). stepwise must never crash or print escapes. */
#define EVIL_FAMILY "ctl-block"
#define EVIL_CUSTOM_STEP
#include "evil.h"
#include <stdatomic.h>

typedef struct box_control {
    atomic_int cmd, done;
    atomic_int parent_waiting, child_waiting;
    int quit;
    double t, h;
    int rc;
    long evals, solves, iters;
    volatile sig_atomic_t fault;
    long index;
    int field;
    long was, now;
    char detail[200];
} box_control;

static void evil_attack(void) {}

/* The mapping holding addr: its start, end and whether it is shared and
 * writable; and the mapping before it. 0 when found. */
typedef struct span { uintptr_t lo, hi; char perms[8]; } span;

static int find_ctl(const void *y, box_control **out)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f)
        return -1;
    static span s[4096];
    int n = 0;
    char line[512];
    while (n < 4096 && fgets(line, sizeof line, f)) {
        unsigned long lo, hi;
        char perms[8];
        if (sscanf(line, "%lx-%lx %7s", &lo, &hi, perms) == 3) {
            s[n].lo = lo;
            s[n].hi = hi;
            memcpy(s[n].perms, perms, sizeof perms);
            n++;
        }
    }
    fclose(f);
    uintptr_t a = (uintptr_t)y;
    for (int i = 2; i < n; i++) {
        if (a < s[i].lo || a >= s[i].hi)
            continue;
        /* y's mapping, the guard before it, and the control block before that */
        if (strncmp(s[i].perms, "rw-s", 4) == 0 && s[i - 1].hi == s[i].lo &&
            strncmp(s[i - 1].perms, "---", 3) == 0 && s[i - 2].hi == s[i - 1].lo &&
            strncmp(s[i - 2].perms, "rw-s", 4) == 0) {
            *out = (box_control *)s[i - 2].lo;
            return 0;
        }
        return -1;
    }
    return -1;
}

static int evil_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    box_control *ctl;
    if (t == 0 && find_ctl(y, &ctl) == 0) {
        evil_mark("ctl", NULL);
        memset(ctl->detail, 'A', sizeof ctl->detail);
        memcpy(ctl->detail, "\033[2J\033]0;SWEVIL:ctl-block\007", 26);
        ctl->field = 1 << 30;
        ctl->was = 1;
        ctl->now = 2;
        ctl->fault = 6; /* "changed an ode field" */
    }
    return evil_euler(ode, t, y, h, work);
}
