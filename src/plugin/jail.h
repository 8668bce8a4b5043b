/* The jail: Linux's own isolation around code from a submission, in layers
 * (after bubblewrap): new user, mount, PID, network, IPC, UTS and cgroup
 * namespaces; a minimal read-only root (the system's /usr and libraries,
 * /dev/null, /dev/zero, /dev/urandom, the submission copied into a private
 * size-limited tmpfs /work); no capabilities, PR_SET_NO_NEW_PRIVS, Landlock
 * where the kernel has it, and a seccomp filter (libseccomp). Needs no
 * setuid helper: unprivileged user namespaces do it. Pure C, no printing. */
#ifndef SW_PLUGIN_JAIL_H
#define SW_PLUGIN_JAIL_H

#include <stddef.h>

/* What runs inside. COMPUTE: a student's plugin in its host (the program
 * stepwise-plugin-host, copied into /work and exec'd: plugin/host_proto.h),
 * which installs Landlock and the seccomp filter on itself before the
 * plugin loads: no files but its own, no processes, no network. COMPILE: a
 * compiler exec'd on the submission: it may read the system and write
 * /work, fork within the jail's PID namespace, and nothing else. */
typedef enum sw_jail_profile { SW_JAIL_COMPUTE, SW_JAIL_COMPILE } sw_jail_profile;

/* A file handed in: the parent opens it (fd), the jail copies it to
 * /work/name before the payload runs (at most SW_JAIL_FILE_MAX bytes). */
typedef struct sw_jail_file {
    int fd;
    const char *name;
    int executable;            /* 1: mode 0755 (a program to exec), else 0644 */
} sw_jail_file;

#define SW_JAIL_FILE_MAX ((size_t)64 << 20)
/* The set-up step that copies the submission in: failing there with EFBIG
 * or ENOSPC, it is the submission that is too large, not the jail broken. */
#define SW_JAIL_STEP_SUBMISSION "copying the submission into /work"
#define SW_JAIL_FILES 16

typedef struct sw_jail {
    sw_jail_profile profile;
    sw_jail_file in[SW_JAIL_FILES];
    int nin;
    int include_fd;            /* -1, or a directory whose *.h go to /include/stepwise */
    const char *out[SW_JAIL_FILES]; /* /work files sent back once the payload ended */
    int nout;
    size_t disk_bytes;         /* the size of /work (0: 64 MiB) */
} sw_jail;

/* How the jail isolates. NS: the namespaces above (unprivileged user
 * namespaces). UID: where the kernel refuses them (Docker's default
 * profile, Gradescope's containers) and we are root: no namespaces, but a
 * user id of the jail's own (root may change ids without them), no new
 * privileges, the same limits, the same seccomp filter, and Landlock
 * narrowed to the system's directories and the jail's own directory under
 * $TMPDIR (its only file boundary: without Landlock no UID jail is built,
 * and the jail is refused). Chosen by the first jail built (NS, then UID when NS is refused
 * as root); STEPWISE_JAIL=uid forces UID, =ns forbids it (tests). */
typedef enum sw_jail_kind { SW_JAIL_NS = 1, SW_JAIL_UID = 2 } sw_jail_kind;
sw_jail_kind sw_jail_kind_now(void);
void sw_jail_kind_set(sw_jail_kind kind);
/* The kernel's Landlock ABI version, 0 where it has none (or it is not
 * enabled): the jail of a user of its own needs it (its file boundary),
 * the namespaces' jail takes it as defence in depth. */
int sw_jail_landlock_abi(void);
/* Whether UID may be used instead when NS is refused (root, not forbidden). */
int sw_jail_uid_allowed(void);
/* The system's directories a UID jail may read (NULL-terminated). */
extern const char *const sw_jail_system_dirs[];

/* Whether submissions run jailed (the default) or, after
 * sw_jail_set_enabled(0) (--no-sandbox, STEPWISE_SANDBOX=off), only in a
 * child process with limits, for a disposable container that holds one
 * submission. */
int sw_jail_enabled(void);
void sw_jail_set_enabled(int on);

/* ---- used by the sandbox (plugin/sandbox.c) -------------------------------- */

/* In the first child, right after fork: leave every namespace but the PID
 * one's children. 0, or the errno of the failed step with *step naming it. */
int sw_jail_unshare(const char **step);
/* In the parent: map the child's root to an unprivileged user ("nobody"
 * when we are root, else ourselves). 0 or -1 with why. */
int sw_jail_map_user(int pid, char *why, size_t len);
/* In the first child, once mapped: become the namespace's root, build the
 * jail's root from spec and pivot into it. 0, or an errno with *step. */
int sw_jail_build(const sw_jail *spec, const char **step);
/* UID: in the first child, as root: make the jail's directory (0711,
 * root's) under $TMPDIR with work/ (the jail's user's, its current
 * directory from now on) and include/; copy spec's files in. The user id
 * in *uid, claimed (sw_jail_claim_uid) by the fd in *claim, which the
 * first child keeps open to its end and no process of the jail gets.
 * 0, or an errno with *step; dir gets the directory's path. */
int sw_jail_build_uid(const sw_jail *spec, char *dir, size_t dirlen, unsigned *uid, int *claim,
                      const char **step);
/* UID: the first id of 61000-63999 from place `from` that no running jail
 * has claimed and no process runs as, into *uid. The claim is an flock on
 * /tmp/stepwise-uid-ID.lock, held while the returned fd stays open; -1:
 * there was no /tmp to claim in (the process check alone); -2: none free. */
int sw_jail_claim_uid(unsigned from, unsigned *uid);
/* UID: let go of the claim on uid (its file removed first); claim < 0:
 * nothing to do. Once no process of the jail's user is left. */
void sw_jail_release_uid(unsigned uid, int claim);
/* UID: the jail's directory of the first process pid ($TMPDIR/stepwise-jail-PID):
 * the parent removes it when it kills a jail that had no time to. */
void sw_jail_uid_dir(int pid, char *dir, size_t dirlen);
/* UID: in the payload's process: become the jail's user. 0 or an errno. */
int sw_jail_become(unsigned uid, const char **step);
/* UID: kill every process of the jail's user (after the payload ended). */
void sw_jail_kill_user(unsigned uid);

/* In the payload's process, last before the payload: drop every
 * capability, no new privileges; for COMPILE also Landlock and the
 * profile's seccomp filter (a COMPUTE payload execs the plugin's host,
 * which installs both itself). 0, or an errno with *step. */
int sw_jail_lockdown(sw_jail_profile profile, const char **step);
/* Whether the last two layers can be had here (the sandbox's probe):
 * Landlock as the host uses it and the COMPUTE filter, installed on the
 * calling process for good. 0, or an errno with *step. */
int sw_jail_compute_layers(const char **step);
/* In the jail's init process after the payload ended: send each spec->out
 * file over fd as [int64 size, -1 when absent or not a regular file][bytes]. */
void sw_jail_send_outputs(const sw_jail *spec, int fd);

#endif
