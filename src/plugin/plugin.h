/* Student plugins, isolated: a plugin's code never runs in stepwise's own
 * process, nor in a copy of it. It runs in its host (the program
 * stepwise-plugin-host, plugin/host_proto.h), jailed, one per plugin:
 * loading calls sw_plugin_info() there under a watchdog, and each sim that
 * steps the plugin gets a slot there that runs its steps ahead in batches,
 * with its work vectors and y each followed by an inaccessible guard. A
 * plugin that exits, crashes, loops, allocates, overruns its vectors or
 * writes to the ode is reported as such with the step; it can never take
 * stepwise down or pass for a correct method. Pure C, no printing. */
#ifndef SW_PLUGIN_PLUGIN_H
#define SW_PLUGIN_PLUGIN_H

#include <stddef.h>

#include "stepwise/sim.h"
#include "util/escape.h" /* sw_escape: how a plugin's bytes reach a message */

#define SW_PLUGIN_MAX SW_REGISTERED_MAX /* each registers its method */
/* Names: 1 to 40 bytes of [A-Za-z0-9._+-], starting with a letter or digit. */
#define SW_PLUGIN_NAME_MAX 40
/* Labels: 1 to 80 bytes of printable text (UTF-8), no control characters,
 * no leading or trailing blank. */
#define SW_PLUGIN_LABEL_MAX 80
/* Default watchdog: seconds a plugin may take for one call (its step, or
 * loading and sw_plugin_info()). STEPWISE_PLUGIN_TIMEOUT overrides it. */
#define SW_PLUGIN_TIMEOUT 2.0

/* How a plugin failed (beyond a numerical blow-up). */
typedef enum sw_plugin_fault {
    SW_PF_NONE = 0,
    SW_PF_EXIT,         /* the plugin ended its process (exit(), _exit()) */
    SW_PF_CRASH,        /* a fatal signal: SIGSEGV, SIGABRT, SIGFPE, ... */
    SW_PF_OVERRUN_WORK, /* wrote past its work vectors */
    SW_PF_OVERRUN_Y,    /* wrote past the end of y */
    SW_PF_UNDERRUN,     /* wrote before the start of y or of its work vectors */
    SW_PF_ODE,          /* changed a field of the ode (dim, order, callbacks) */
    SW_PF_TIMEOUT,      /* did not return within the watchdog's limit */
    SW_PF_CANCELLED,    /* the user interrupted the wait (Ctrl-C, SIGTERM) */
    SW_PF_START,        /* its child process could not be started or load it */
    SW_PF_DISABLED,     /* disabled after an earlier failure (play) */
    SW_PF_FORGED,       /* sent the sandbox a record it could not have sent */
    SW_PF_LIMIT,        /* ran out of a resource limit: its CPU time (SIGXCPU) */
    SW_PF_ALLOC         /* allocated memory in its step (a step must not allocate) */
} sw_plugin_fault;

/* Whether name is an allowed plugin name that shadows no built-in method
 * (also not by case); 1, or 0 with why filled. */
int sw_plugin_name_ok(const char *name, char *why, size_t whylen);
/* Whether label is an allowed label; 1, or 0 with why filled. */
int sw_plugin_label_ok(const char *label, char *why, size_t whylen);

/* The grader's limits for every plugin process from now on: memory and
 * output each, CPU time for all of them and this process together (each
 * new one gets what is left, at least a second). NULL: none. */
struct sw_limits;
void sw_plugin_set_limits(const struct sw_limits *lim);

/* The grader's measuring runs (the order, the stability limit): between
 * sw_plugin_grader_runs(1) and (0) every plugin's host is one of their
 * own, on the grader's budget (SW_GRADER_CPU of the limits' CPU time,
 * for all of them together: a host started again gets what is left), and
 * the CPU time they used is never counted in what is left of the
 * submission's. Each call ends the hosts running. */
#define SW_GRADER_CPU(cpu) (4 * (cpu) + 30)
void sw_plugin_grader_runs(int on);
/* The submission's CPU-time limit set (--cpu, seconds); 0 none. */
double sw_plugin_cpu_limit(void);
/* The CPU time the submission's own processes (its builds, its graded
 * runs' hosts) have used so far, once reaped: never the grader's. */
double sw_plugin_own_cpu(void);
/* Every plugin's host ends now (each starts afresh at its next step):
 * nothing a plugin keeps in its process passes to the runs after. */
void sw_plugin_hosts_end(void);

/* Grading: a plugin whose name or label is not allowed (a name that
 * shadows a built-in method, a label not UTF-8) is loaded all the same,
 * as SW_PLUGIN_GRADED_NAME or with its name as its label; what it was
 * renamed for is sw_plugin_renamed's. Elsewhere such a plugin is refused. */
#define SW_PLUGIN_GRADED_NAME "student-plugin"
void sw_plugin_set_any_name(int on);
/* Why m was loaded under another name or label than its own, or NULL. */
const char *sw_plugin_renamed(const sw_integrator *m);

/* Watchdog for each call into a plugin, in seconds (> 0). */
void sw_plugin_set_timeout(double seconds);
double sw_plugin_timeout(void);
/* The plugin host program, opened once (its descriptor, or -1 with err
 * saying where it was looked for): grade asks before it grades anything. */
int sw_plugin_host_fd(char *err, size_t errlen);

/* Load the plugin at path: in its host under the watchdog, dlopen it and
 * call sw_plugin_info(); check the interface version, name, label, step
 * function and work vectors; register its integrator (at most
 * SW_PLUGIN_MAX). Messages name it as shown_as (the file the user gave,
 * when path is a build of it; NULL: path). *out is the registered method.
 * 0, or SW_EINVAL / SW_EIO with a one-line message (names escaped) in err. */
int sw_plugin_load(const char *path, const char *shown_as, const sw_integrator **out, char *err,
                   size_t errlen);

/* After a sim stopped: when its plugin failed (not a numerical blow-up),
 * rewrite s->blow_reason to say how ("the plugin crashed with SIGSEGV
 * (invalid memory access) at step 3") and return the fault; else SW_PF_NONE. */
sw_plugin_fault sw_plugin_failed(sw_sim *s);
/* The last failure of method m's plugin in any run (stability probes,
 * benchmarks): the fault, with its description in buf; SW_PF_NONE when none. */
sw_plugin_fault sw_plugin_last_failure(const sw_integrator *m, char *buf, size_t len);
/* The bytes method m's plugin has printed to stdout and stderr in all its
 * runs so far (each host counts them as it drops them, and says so at
 * each run's end and when it dies); -1 when m is no plugin. */
long long sw_plugin_printed(const sw_integrator *m);
/* Forget m's plugin's last failure, so that the next run starts it afresh
 * (its host again if it died): a homework's next part is a check of its
 * own, which a crash on an earlier part must not decide. Not after
 * sw_plugin_disable. */
void sw_plugin_forgive(const sw_integrator *m);
/* Refuse method m from now on, saying why (play disables a crashed plugin). */
void sw_plugin_disable(const sw_integrator *m, const char *why);

#endif
