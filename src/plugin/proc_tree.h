/* What a process and its descendants are doing, from /proc: their CPU time
 * and whether any of them is running or waiting to run. The step
 * watchdog's measure (host_link.c): a plugin's host is charged its own CPU
 * time, never the machine's load. */
#ifndef SW_PLUGIN_PROC_TREE_H
#define SW_PLUGIN_PROC_TREE_H

#include <sys/types.h>

typedef struct sw_proc_tree {
    double cpu_seconds; /* user + system time of root and every descendant alive */
    int runnable;       /* how many of them are running or on a run queue (state R) */
    int count;          /* how many were found, root included */
} sw_proc_tree;

/* Read root's tree. 0, or -1 where /proc cannot tell (not mounted,
 * hidden, root gone): the caller falls back on wall time. */
int sw_proc_tree_read(pid_t root, sw_proc_tree *out);

/* Whether any process runs as uid (its /proc entry's owner): 1, 0, or
 * -1 where /proc cannot tell. */
int sw_proc_uid_in_use(uid_t uid);

#endif
