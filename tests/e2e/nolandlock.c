/* nolandlock: run a command as on a kernel whose Landlock is built but not
 * enabled (not in the boot's lsm= list, as on many container hosts): every
 * landlock_create_ruleset, the ABI query included, fails with EOPNOTSUPP.
 * usage: nolandlock COMMAND [ARG]...  Exits 77 when the filter cannot be
 * installed (the caller skips), else as the command. */
#define _GNU_SOURCE
#include <errno.h>
#include <seccomp.h>
#include <stdio.h>
#include <sys/prctl.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: nolandlock COMMAND [ARG]...\n");
        return 2;
    }
    scmp_filter_ctx f = seccomp_init(SCMP_ACT_ALLOW);
    if (!f || seccomp_rule_add(f, SCMP_ACT_ERRNO(EOPNOTSUPP), SCMP_SYS(landlock_create_ruleset), 0) != 0 ||
        prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || seccomp_load(f) != 0) {
        perror("nolandlock");
        return 77;
    }
    execvp(argv[1], argv + 1);
    perror("nolandlock: exec");
    return 127;
}
