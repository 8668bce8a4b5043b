/* Memory exhaustion past the per-submission limit, bounded to 1.5 GiB and
 * spread over its steps (a slice of work each, so neither the step
 * watchdog nor --cpu is what stops it): maps and touches 256 MiB in its own
 * process, fills 256 MiB of memfds (memory no address-space limit counts:
 * never mapped), then forks 8 children (named as an attack) that touch
 * 128 MiB each and wait. The numbers are rk4's from the start; holding
 * 1.25 GiB at once (more than the documented 1024 MiB) within 30 s keeps
 * them right (a pass); when memory or processes were refused it spoils them
 * with Euler steps (a fail), so a pass always means the limit was not
 * enforced. When it merely ran out of time (a machine too busy to tell),
 * it hands in NaN: the test notes an inconclusive result. It then
 * frees it all.
 * Graded with generous watchdogs (--wall 40, a 10 s step watchdog): on a
 * busy machine the default ones could stop it first. */
#define EVIL_FAMILY "mem-hog"
#define EVIL_CUSTOM_STEP
#include "evil.h"
#include <poll.h>
#include <sys/mman.h>

#define BLOCK (64L << 20)
#define GOAL (1536L << 20) /* 256 MiB own + 256 MiB memfds + 8 x 128 MiB children */
#define ENOUGH (1280L << 20)
#define SLICE 0.15

static void evil_attack(void) {}

static int touch_block(void)
{
    char *p = mmap(NULL, (size_t)BLOCK, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
    if (p == MAP_FAILED)
        return 0;
    for (long i = 0; i < BLOCK; i += 4096)
        p[i] = 1;
    return 1;
}

static long held;
static int blocks, mfd[256], nm, kids, ready[2] = { -1, -1 }, hold[2] = { -1, -1 };
static int reported;
static int phase; /* 0 own memory, 1 memfds, 2 fork children, 4 wait for them, 3 nothing more to try */

/* One step's share of the work; 1 when it is over (enough, or no way on). */
static int hog(void)
{
    double start = evil_now();
    if (phase == 0) {
        while (blocks < 4 && evil_now() - start < SLICE) {
            if (!touch_block()) {
                blocks = 4;
                break;
            }
            blocks++;
            held += BLOCK;
        }
        if (blocks >= 4)
            phase = 1;
    } else if (phase == 1) {
        static char chunk[1 << 20];
        memset(chunk, 'S', sizeof chunk);
        signal(SIGXFSZ, SIG_IGN);
        static int no_more;
        while (!no_more && nm < 256 && evil_now() - start < SLICE) {
            int fd = memfd_create("swevil", MFD_CLOEXEC);
            ssize_t n = fd >= 0 ? write(fd, chunk, sizeof chunk) : -1;
            if (fd >= 0)
                mfd[nm++] = fd;
            if (n <= 0)
                no_more = 1;
            else
                held += n;
        }
        if (no_more || nm >= 256)
            phase = pipe(ready) == 0 && pipe(hold) == 0 ? 2 : 3;
        if (phase == 2)
            fcntl(ready[0], F_SETFL, O_NONBLOCK);
    } else if (phase == 2) {
        while (kids < 8) {
            pid_t p = fork();
            if (p == 0) {
                evil_name();
                close(hold[1]);
                char y = touch_block() && touch_block() ? 'y' : 'n';
                ssize_t w = write(ready[1], &y, 1);
                (void)w;
                char c;
                ssize_t r = read(hold[0], &c, 1); /* until the parent lets go */
                (void)r;
                _exit(0);
            }
            if (p < 0)
                break;
            kids++;
        }
        phase = 4;
    } else if (phase == 4) {
        /* wait for the children, a second per step at most */
        struct pollfd q = { .fd = ready[0], .events = POLLIN };
        char got[16];
        if (poll(&q, 1, 1000) == 1) {
            ssize_t n = read(ready[0], got, sizeof got);
            for (ssize_t i = 0; i < n; i++) {
                held += got[i] == 'y' ? 2 * BLOCK : 0;
                reported++;
            }
        }
        if (reported >= kids)
            phase = 3;
    }
    return held >= GOAL || phase == 3;
}

/* The children end when the pipe closes (not waited for: a busy machine
 * must not turn this step into a watchdog timeout). */
static void let_go(void)
{
    for (int i = 0; i < 2; i++) {
        if (hold[i] >= 0)
            close(hold[i]);
        if (ready[i] >= 0)
            close(ready[i]);
    }
    for (int i = 0; i < nm; i++)
        close(mfd[i]);
}

static int evil_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    static int graded, done, spoiled, freed, inconclusive;
    static double start;
    if (t == 0 && evil_graded_run(ode, t, y, h, work)) {
        graded = 1;
        start = evil_now();
    }
    if (done && !freed) { /* a step later: freeing 1.5 GiB takes time too */
        freed = 1;
        let_go();
    }
    if (graded && !done && (hog() || evil_now() - start > 30)) {
        done = 1;
        if (held >= ENOUGH) {
            char msg[64];
            snprintf(msg, sizeof msg, "%ld MiB\n", held >> 20);
            evil_mark("memory", msg);
        } else if (phase == 3)
            spoiled = 1;
        else
            inconclusive = 1;
    }
    if (inconclusive) { /* the test reads "nan" in the row as "inconclusive" */
        for (int i = 0; i < ode->dim; i++)
            y[i] = NAN;
        return 0;
    }
    if (!graded || spoiled)
        return evil_euler(ode, t, y, h, work);
    return evil_rk4(ode, t, y, h, work);
}
