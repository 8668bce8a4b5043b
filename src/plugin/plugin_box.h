/* Private to plugin/: the registry of loaded plugins (plugin_registry.c),
 * the parent's end of a plugin's host (host_link.c) and the sandboxed step
 * every plugin method runs through (plugin_box.c). */
#ifndef SW_PLUGIN_PLUGIN_BOX_H
#define SW_PLUGIN_PLUGIN_BOX_H

#include "engine/stepper.h"
#include "plugin/host_proto.h"
#include "plugin/jail.h"
#include "plugin/plugin.h"
#include "plugin/sandbox.h"
#include "stepwise/stepwise.h"

/* A plugin's host as the parent sees it: one process for every run of the
 * plugin (a jail per submission, not per run), each run in a slot. */
/* What ended a wait for the host (host_link.c's watchdog): its own CPU
 * time spent, so long asleep, the wall-time bound, or nothing. */
typedef enum sw_host_watched { SW_WATCH_NONE, SW_WATCH_CPU, SW_WATCH_ASLEEP, SW_WATCH_WALL } sw_host_watched;

typedef struct sw_host_link {
    sw_child child;
    int alive;
    int generation;                        /* bumped by every start: slots of an older one are gone */
    unsigned long long slots;              /* the slots in use, one bit each */
    sw_host_reply fault;                   /* a FAULT record the host sent before it died */
    int have_fault;
    int dying;                             /* it said DYING: every step before was sent */
    long long printed;                     /* ... and the plugin had printed this many bytes */
    long long printed_end;                 /* bytes printed by the last END of this host */
    sw_host_watched watched;               /* why the watchdog ended the last wait it ended, */
    double waited;                         /* ... and after how long (wall seconds) */
    int graders;                           /* started for the grader's measuring runs */
    unsigned char rbuf[1 << 16];           /* what was read from the host and not yet used */
    size_t rpos, rlen;
} sw_host_link;

typedef struct sw_plugin_entry {
    char path[4096];                       /* absolute: what the user named */
    char shown[200];                       /* how messages name it (escaped) */
    int fd;                                /* the file as loaded: what every host gets */
    char name[SW_PLUGIN_NAME_MAX + 1];
    char label[SW_PLUGIN_LABEL_MAX + 1];
    char own_name[257];                    /* the name its sw_plugin_info() gives (a host's check) */
    char renamed[SW_ERRLEN];               /* why it was given name or label (grading), or "" */
    int work_vectors;
    const sw_integrator *method;           /* the registered copy */
    sw_plugin_fault last_fault;            /* the last failure in any run */
    char last_failure[SW_ERRLEN];
    int disabled;
    char disabled_why[SW_ERRLEN];
    long long printed_before;              /* bytes printed in its hosts before the current one */
    sw_host_link host;
} sw_plugin_entry;

/* The next free entry (NULL: SW_PLUGIN_MAX are loaded), and taking it
 * once it is filled in. */
sw_plugin_entry *sw_plugin_entry_next(void);
void sw_plugin_entry_commit(void);
/* The i-th loaded entry, or NULL. */
sw_plugin_entry *sw_plugin_entry_at(int i);
/* The entry behind a plugin method, or NULL. */
sw_plugin_entry *sw_plugin_entry_for(const sw_integrator *m);
/* The limits a new plugin process gets (sw_plugin_set_limits). */
void sw_plugin_limits(sw_limits *lim);
/* Whether the grader's account is open (sw_plugin_grader_runs), and
 * opening (1) or closing (0) it once its hosts have ended. */
int sw_plugin_grader_open(void);
void sw_plugin_account(int grader);
/* ... and its path (once found). */
const char *sw_plugin_host_path(void);

/* host_link.c. Start the entry's host: load the plugin there and read
 * what loading found into *info (its strings terminated here). 0; or
 * SW_EINVAL / SW_EIO with a one-line message naming the plugin as shown
 * (how loading failed, or why the host could not start). */
int sw_host_start(sw_plugin_entry *e, sw_host_info *info, char *err, size_t errlen);
/* End the entry's host (QUIT, then reaped). */
void sw_host_stop(sw_plugin_entry *e);
/* Read exactly len bytes from the host within `seconds` (the wait for the
 * next piece, not the whole) of its own CPU time, or asleep (the watchdog:
 * a busy machine only makes the wait longer): 1, or as sw_sandbox_read. */
int sw_host_read(sw_plugin_entry *e, void *buf, size_t len, double seconds);
/* What the watchdog saw when it ended a wait, as "<it> ...": "used 2 s of
 * its own CPU time without returning", "slept 2 s ...", "did not return
 * within 2 s". */
void sw_host_watch_says(const sw_host_link *h, double seconds, char *out, size_t len);
/* Read one reply of the host within `seconds`: 1, or as sw_sandbox_read
 * (0 the host ended, -1 cancelled, -2 timed out, -3 error); a FAULT
 * record in range is kept in the link and reads as 0 (the host dies
 * next); -4 a FAULT out of range (forged). */
int sw_host_reply_read(sw_plugin_entry *e, sw_host_reply *r, double seconds);
/* The host ended or stopped answering: kill and reap it, *end how it
 * ended (killed: 1 when we killed it). */
void sw_host_lost(sw_plugin_entry *e, sw_child_end *end);

/* The step of every plugin method: runs ahead in batches on the host and
 * serves each step from what came back. */
sw_step_fn sw_plugin_step;
/* The fault of the stepper's runs, described as a sentence that names the
 * step ("the plugin crashed with SIGSEGV (...) at step 4"). */
sw_plugin_fault sw_plugin_box_fault(const sw_stepper *s, long step, char *buf, size_t len);

/* The parent's side of one run on bytes a host might have sent (the fuzz
 * target and tests: no host): a system of dim doubles, a run of up to 4
 * steps. The fault those bytes make (SW_PF_NONE: at least one valid step
 * and a proper end), described in why. Never reads past len, never crashes. */
sw_plugin_fault sw_plugin_box_replay(const unsigned char *data, size_t len, int dim, int wv, char *why,
                                     size_t whylen);

#endif
