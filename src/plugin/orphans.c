/* What a submission left running outside the jail (under --no-sandbox, the
 * jail's PID namespace does not end it): a daemon that left its process
 * group and session (fork, setsid, fork) is adopted by the grader, which
 * is its children's subreaper, and killed before any result is written. */
#include "plugin/sandbox.h"

#include <dirent.h>
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
static pid_t parent_of(pid_t pid)
{
    char path[64], buf[512];
    snprintf(path, sizeof path, "/proc/%ld/stat", (long)pid);
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

/* Every process below this one now (a chain of any depth: the parents
 * read once, the descendants closed over them), stopped and then killed;
 * how many. Stopped first, so none forks while the others are found. */
static int kill_descendants(pid_t self)
{
    size_t n = 0, cap = 256;
    pid_t *pid = malloc(cap * sizeof *pid), *ppid = malloc(cap * sizeof *ppid);
    DIR *d = opendir("/proc");
    if (!pid || !ppid || !d) {
        free(pid), free(ppid);
        if (d)
            closedir(d);
        return 0;
    }
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9')
            continue;
        if (n == cap) {
            pid_t *a = realloc(pid, 2 * cap * sizeof *a);
            if (!a)
                break;
            pid = a;
            pid_t *b = realloc(ppid, 2 * cap * sizeof *b);
            if (!b)
                break;
            ppid = b;
            cap *= 2;
        }
        pid[n] = (pid_t)atol(e->d_name);
        ppid[n] = parent_of(pid[n]);
        n++;
    }
    closedir(d);
    unsigned char *below = calloc(n + 1, 1);
    int found = 0;
    for (int grew = below != NULL; grew;) {
        grew = 0;
        for (size_t i = 0; i < n; i++) {
            if (below[i] || pid[i] == self || pid[i] <= 1 || ppid[i] <= 0)
                continue;
            int under = ppid[i] == self;
            for (size_t j = 0; !under && j < n; j++)
                under = below[j] && pid[j] == ppid[i];
            if (under) {
                kill(pid[i], SIGSTOP);
                below[i] = 1;
                grew = 1;
                found++;
            }
        }
    }
    for (size_t i = 0; i < n && below; i++)
        if (below[i])
            kill(pid[i], SIGKILL);
    free(below), free(pid), free(ppid);
    return found;
}

int sw_sandbox_kill_orphans(void)
{
    pid_t self = getpid();
    int killed = 0;
    double until = sw_sandbox_now() + 10.0;
    for (;;) {
        int found = kill_descendants(self);
        killed += found;
        while (waitpid(-1, NULL, WNOHANG) > 0)
            ;
        if (!found || sw_sandbox_now() > until)
            break;
        usleep(1000); /* the killed ones' children come to us in turn */
    }
    while (waitpid(-1, NULL, WNOHANG) > 0)
        ;
    return killed;
}
