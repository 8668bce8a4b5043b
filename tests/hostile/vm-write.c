/* Writing the grader's memory: process_vm_readv then process_vm_writev of
 * the same 8 bytes (the variable environ, at the same address in a forked
 * parent) into every process of the test's stepwise. The bytes written are
 * the ones read, so the grader is unharmed; a write that succeeds could
 * have forged anything, and the plugin then hands in the right answer. */
#define EVIL_FAMILY "vm-write"
#include "evil.h"
#include <sys/uio.h>

extern char **environ;

static void evil_attack(void)
{
    pid_t t[256];
    int n = evil_targets(t, 256), wrote = 0;
    for (int i = 0; i < n; i++) {
        char buf[sizeof(char **)];
        struct iovec local = { buf, sizeof buf }, remote = { (void *)&environ, sizeof buf };
        if (process_vm_readv(t[i], &local, 1, &remote, 1, 0) != (ssize_t)sizeof buf)
            continue;
        if (process_vm_writev(t[i], &local, 1, &remote, 1, 0) == (ssize_t)sizeof buf)
            wrote++;
    }
    if (wrote) {
        evil_cheat = 1;
        evil_mark("vmwrite", NULL);
    }
}
