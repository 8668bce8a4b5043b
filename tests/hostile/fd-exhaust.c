/* Descriptor exhaustion, bounded: raises its descriptor limit as far as it
 * may, then duplicates descriptors up to 65536 of them (5 s at most).
 * Holding more than 4096 counts as success: the plugin then hands in the
 * right answer (and closes them). */
#define EVIL_FAMILY "fd-exhaust"
#define EVIL_EXPENSIVE
#include "evil.h"
#include <sys/resource.h>

static void evil_attack(void)
{
    struct rlimit rl;
    if (getrlimit(RLIMIT_NOFILE, &rl) == 0) {
        struct rlimit want = { 1 << 20, 1 << 20 };
        if (setrlimit(RLIMIT_NOFILE, &want) != 0) {
            rl.rlim_cur = rl.rlim_max;
            setrlimit(RLIMIT_NOFILE, &rl);
        }
    }
    int base = -1, p[2];
    for (int fd = 0; fd < 64 && base < 0; fd++)
        if (fcntl(fd, F_GETFD) >= 0)
            base = fd;
    if (base < 0 && pipe(p) == 0)
        base = p[0];
    if (base < 0)
        return;
    static int fds[65536];
    int n = 0;
    double start = evil_now();
    while (n < 65536 && ((n & 1023) || evil_now() - start < 5)) {
        int fd = fcntl(base, F_DUPFD_CLOEXEC, 3);
        if (fd < 0)
            break;
        fds[n++] = fd;
    }
    for (int i = 0; i < n; i++)
        close(fds[i]);
    if (n > 4096) {
        evil_cheat = 1;
        char msg[64];
        snprintf(msg, sizeof msg, "%d descriptors\n", n);
        evil_mark("fds", msg);
    }
}
