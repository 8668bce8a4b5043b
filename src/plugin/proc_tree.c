/* The CPU time and run state of a process tree, from /proc/PID/stat (and
 * whether a user id has any process, for a jail's choice of one): one
 * pass over /proc for every process's parent, state and times, then the
 * descendants of the root by repeated passes over what was read (a jail is
 * a few levels deep). Invariant: reads only; a process that ends while it
 * is read is left out. */
#define _GNU_SOURCE
#include "plugin/proc_tree.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define PROC_MAX 8192 /* processes looked at; a machine with more is read in part */
#define TREE_MAX 256  /* the tree's processes counted (a jail allows 64) */

typedef struct proc_row {
    pid_t pid, ppid;
    char state;
    unsigned long long ticks; /* utime + stime, in clock ticks */
} proc_row;

/* One /proc/PID/stat: "pid (comm) state ppid ... utime stime ...", comm
 * any bytes: the fields are counted from its last ')'. 0 or -1. */
static int read_stat(pid_t pid, proc_row *row)
{
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return -1;
    ssize_t n = read(fd, buf, sizeof buf - 1);
    close(fd);
    if (n <= 0)
        return -1;
    buf[n] = '\0';
    char *p = strrchr(buf, ')');
    if (!p)
        return -1;
    char state;
    int ppid;
    unsigned long long ut, st;
    /* state ppid pgrp session tty_nr tpgid flags minflt cminflt majflt cmajflt utime stime */
    if (sscanf(p + 1, " %c %d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &state, &ppid, &ut, &st) != 4)
        return -1;
    *row = (proc_row){ pid, (pid_t)ppid, state, ut + st };
    return 0;
}

int sw_proc_tree_read(pid_t root, sw_proc_tree *out)
{
    static proc_row rows[PROC_MAX];
    static unsigned char in[PROC_MAX];
    long hz = sysconf(_SC_CLK_TCK);
    DIR *d = opendir("/proc");
    if (!d || hz <= 0) {
        if (d)
            closedir(d);
        return -1;
    }
    int n = 0, found = 0;
    struct dirent *e;
    while (n < PROC_MAX && (e = readdir(d)) != NULL) {
        char *end;
        long pid = strtol(e->d_name, &end, 10);
        if (*end == '\0' && pid > 0 && read_stat((pid_t)pid, &rows[n]) == 0) {
            in[n] = rows[n].pid == root;
            found |= in[n];
            n++;
        }
    }
    closedir(d);
    if (!found)
        return -1;
    /* the tree's pids, grown pass by pass (the jail's processes are few:
     * beyond TREE_MAX the rest is left out) */
    pid_t tree[TREE_MAX];
    int nt = 1;
    tree[0] = root;
    for (int changed = 1; changed;) {
        changed = 0;
        for (int i = 0; i < n && nt < TREE_MAX; i++)
            for (int j = 0; !in[i] && j < nt; j++)
                if (rows[i].ppid == tree[j]) {
                    in[i] = 1;
                    tree[nt++] = rows[i].pid;
                    changed = 1;
                }
    }
    unsigned long long ticks = 0;
    *out = (sw_proc_tree){ 0 };
    for (int i = 0; i < n; i++)
        if (in[i]) {
            ticks += rows[i].ticks;
            out->runnable += rows[i].state == 'R';
            out->count++;
        }
    out->cpu_seconds = (double)ticks / (double)hz;
    return 0;
}

int sw_proc_uid_in_use(uid_t uid)
{
    DIR *d = opendir("/proc");
    if (!d)
        return -1;
    int used = 0;
    struct dirent *e;
    while (!used && (e = readdir(d)) != NULL) {
        char *end;
        struct stat st;
        long pid = strtol(e->d_name, &end, 10);
        used = *end == '\0' && pid > 0 && fstatat(dirfd(d), e->d_name, &st, 0) == 0 && st.st_uid == uid;
    }
    closedir(d);
    return used;
}
