/* What a submission left running outside the jail (under --no-sandbox, the
 * jail's PID namespace does not end it): a daemon that left its process
 * group and session (fork, setsid, fork) is adopted by the grader, which
 * is its children's subreaper, and killed before any result is written. */
#include "plugin/sandbox.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

void sw_sandbox_adopt_orphans(void) { prctl(PR_SET_CHILD_SUBREAPER, 1); }

/* The parent pid of process pid from /proc/PID/stat ("pid (comm) state
 * ppid ...", comm may hold spaces and parentheses), or -1. */
static pid_t parent_of(const char *pid)
{
    char path[64], buf[512];
    snprintf(path, sizeof path, "/proc/%s/stat", pid);
    FILE *f = fopen(path, "re");
    if (!f)
        return -1;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char *close_paren = strrchr(buf, ')');
    int ppid;
    char state;
    if (!close_paren || sscanf(close_paren + 1, " %c %d", &state, &ppid) != 2)
        return -1;
    return (pid_t)ppid;
}

int sw_sandbox_kill_orphans(void)
{
    pid_t self = getpid();
    int killed = 0;
    for (int round = 0; round < 100; round++) {
        int found = 0;
        DIR *d = opendir("/proc");
        if (!d)
            break;
        for (struct dirent *e; (e = readdir(d));) {
            if (e->d_name[0] < '1' || e->d_name[0] > '9' || parent_of(e->d_name) != self)
                continue;
            pid_t pid = (pid_t)atol(e->d_name);
            if (kill(pid, SIGKILL) == 0) {
                found++;
                killed++;
            }
        }
        closedir(d);
        while (waitpid(-1, NULL, WNOHANG) > 0)
            ;
        if (!found)
            break;
        usleep(1000); /* a killed parent's own children come to us next */
    }
    while (waitpid(-1, NULL, WNOHANG) > 0)
        ;
    return killed;
}
