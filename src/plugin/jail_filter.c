/* The jail's seccomp filters and Landlock rules. A COMPUTE payload (a
 * plugin's host, which installs them on itself before the plugin loads)
 * gets an allow-list: what loading a shared object and stepping need,
 * every other system call is refused with SIGSYS, which ends the process
 * (the parent says so); seccomp() is not on it, so no second filter can ever be added. A
 * COMPILE payload gets a deny-list of what could reach outside the jail. */
#define _GNU_SOURCE /* namespaces, setresuid, pipe2, sethostname: Linux-only by design */
#include "plugin/jail_filter.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/landlock.h>
#include <sched.h>
#include <seccomp.h>
#include <stdint.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

/* ---- Landlock ---------------------------------------------------------------- */

#ifndef LANDLOCK_ACCESS_FS_REFER
#define LANDLOCK_ACCESS_FS_REFER (1ULL << 13)
#endif
#ifndef LANDLOCK_ACCESS_FS_TRUNCATE
#define LANDLOCK_ACCESS_FS_TRUNCATE (1ULL << 14)
#endif
#define LL_NET_BIND_TCP (1ULL << 0)
#define LL_NET_CONNECT_TCP (1ULL << 1)
#define LL_SCOPE_SIGNAL (1ULL << 1)

/* struct landlock_ruleset_attr as of ABI 6; older kernels read a prefix. */
typedef struct ll_ruleset {
    uint64_t handled_access_fs, handled_access_net, scoped;
} ll_ruleset;

static int ll_allow(int ruleset, const char *path, uint64_t access)
{
    int fd = open(path, O_PATH | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT ? 0 : errno;
    struct stat st;
    if (fstat(fd, &st) == 0 && !S_ISDIR(st.st_mode)) /* a file takes a file's rights only */
        access &= LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_READ_FILE |
                  LANDLOCK_ACCESS_FS_TRUNCATE;
    struct landlock_path_beneath_attr rule = { .allowed_access = access, .parent_fd = fd };
    int rc = syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) == 0 ? 0 : errno;
    close(fd);
    return rc;
}

int sw_jail_landlock_abi(void)
{
    long abi = syscall(SYS_landlock_create_ruleset, NULL, 0, LANDLOCK_CREATE_RULESET_VERSION);
    return abi < 1 ? 0 : abi > 1000 ? 1000 : (int)abi;
}

int sw_jail_landlock_rules(const char *const *read_dirs, int nread, const char *const *full, int nfull)
{
    int abi = sw_jail_landlock_abi();
    if (abi < 1) /* no Landlock here: the namespaces and seccomp still hold (the jail of a
                  * user of its own, which has no namespaces, is refused before: jail.c) */
        return 0;
    uint64_t fs = (1ULL << 13) - 1; /* ABI 1: EXECUTE .. MAKE_SYM */
    if (abi >= 2)
        fs |= LANDLOCK_ACCESS_FS_REFER;
    if (abi >= 3)
        fs |= LANDLOCK_ACCESS_FS_TRUNCATE;
    ll_ruleset attr = { .handled_access_fs = fs };
    size_t size = sizeof attr.handled_access_fs;
    if (abi >= 4) {
        attr.handled_access_net = LL_NET_BIND_TCP | LL_NET_CONNECT_TCP;
        size = 2 * sizeof(uint64_t);
    }
    if (abi >= 6) {
        attr.scoped = LL_SCOPE_SIGNAL;
        size = sizeof attr;
    }
    int ruleset = (int)syscall(SYS_landlock_create_ruleset, &attr, size, 0);
    if (ruleset < 0)
        return errno;
    uint64_t read = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR | LANDLOCK_ACCESS_FS_EXECUTE;
    int rc = 0;
    for (int i = 0; rc == 0 && i < nread; i++)
        rc = ll_allow(ruleset, read_dirs[i], read);
    for (int i = 0; rc == 0 && i < nfull; i++)
        rc = ll_allow(ruleset, full[i], fs);
    if (rc == 0)
        rc = ll_allow(ruleset, "/dev/null", LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_WRITE_FILE |
                                                (abi >= 3 ? LANDLOCK_ACCESS_FS_TRUNCATE : 0));
    if (rc == 0 && syscall(SYS_landlock_restrict_self, ruleset, 0) != 0)
        rc = errno;
    close(ruleset);
    return rc;
}

int sw_jail_landlock(void)
{
    static const char *const read_dirs[] = { "/" }, *const full[] = { "/work" };
    return sw_jail_landlock_rules(read_dirs, 1, full, 1);
}

int sw_jail_landlock_read(const char *const *read_dirs, int nread)
{
    return sw_jail_landlock_rules(read_dirs, nread, NULL, 0);
}

/* ---- seccomp ------------------------------------------------------------------ */

/* Memory, time, descriptors it has, its own signals, exit: what any step needs. */
static const int step_calls[] = {
    SCMP_SYS(read), SCMP_SYS(write), SCMP_SYS(readv), SCMP_SYS(writev), SCMP_SYS(close),
    SCMP_SYS(fstat), SCMP_SYS(lseek), SCMP_SYS(mmap), SCMP_SYS(mprotect), SCMP_SYS(munmap),
    SCMP_SYS(mremap), SCMP_SYS(madvise), SCMP_SYS(brk), SCMP_SYS(rt_sigaction),
    SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigreturn), SCMP_SYS(sigaltstack), SCMP_SYS(exit),
    SCMP_SYS(exit_group), SCMP_SYS(poll), SCMP_SYS(ppoll), SCMP_SYS(recvfrom), SCMP_SYS(sendto),
    SCMP_SYS(recvmsg), SCMP_SYS(sendmsg), SCMP_SYS(futex), SCMP_SYS(getpid), SCMP_SYS(gettid),
    SCMP_SYS(clock_gettime), SCMP_SYS(clock_getres), SCMP_SYS(gettimeofday), SCMP_SYS(time),
    SCMP_SYS(clock_nanosleep), SCMP_SYS(nanosleep), SCMP_SYS(getrandom), SCMP_SYS(sched_yield),
    SCMP_SYS(getrusage), SCMP_SYS(restart_syscall),
};

/* What loading a shared object needs on top (its constructors run here too). */
static const int load_calls[] = {
    SCMP_SYS(pread64), SCMP_SYS(newfstatat), SCMP_SYS(statx), SCMP_SYS(access), SCMP_SYS(faccessat),
    SCMP_SYS(faccessat2), SCMP_SYS(readlink), SCMP_SYS(readlinkat), SCMP_SYS(getcwd), SCMP_SYS(fcntl),
    SCMP_SYS(uname), SCMP_SYS(getuid), SCMP_SYS(geteuid), SCMP_SYS(getgid), SCMP_SYS(getegid),
    /* and no seccomp(): the filter a plugin's code first meets is the
     * last, so nothing it does can add a filter that fakes another */
};

/* Ways out of the jail a compiler never needs. */
static const int compile_denied[] = {
    SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev), SCMP_SYS(pidfd_open),
    SCMP_SYS(pidfd_getfd), SCMP_SYS(pidfd_send_signal), SCMP_SYS(socket), SCMP_SYS(socketpair),
    SCMP_SYS(mount), SCMP_SYS(umount2), SCMP_SYS(pivot_root), SCMP_SYS(chroot), SCMP_SYS(unshare),
    SCMP_SYS(setns), SCMP_SYS(keyctl), SCMP_SYS(add_key), SCMP_SYS(request_key), SCMP_SYS(bpf),
    SCMP_SYS(perf_event_open), SCMP_SYS(userfaultfd), SCMP_SYS(io_uring_setup), SCMP_SYS(kexec_load),
    SCMP_SYS(init_module), SCMP_SYS(finit_module), SCMP_SYS(delete_module), SCMP_SYS(open_by_handle_at),
    SCMP_SYS(name_to_handle_at), SCMP_SYS(fanotify_init), SCMP_SYS(mount_setattr), SCMP_SYS(fsopen),
    SCMP_SYS(fsmount), SCMP_SYS(move_mount), SCMP_SYS(open_tree), SCMP_SYS(clone3),
};

/* One condition on argument `arg` (libseccomp's SCMP_A* macros leave a
 * field to the compiler, which clang's -Wmissing-field-initializers
 * refuses): the syscall is matched when arg op a (MASKED_EQ: arg & a == b). */
static int rule1(scmp_filter_ctx f, uint32_t action, int call, unsigned arg, enum scmp_compare op,
                 scmp_datum_t a, scmp_datum_t b)
{
    struct scmp_arg_cmp cmp = { .arg = arg, .op = op, .datum_a = a, .datum_b = b };
    return seccomp_rule_add_array(f, action, call, 1, &cmp);
}

static int add_all(scmp_filter_ctx f, const int *calls, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        int rc = seccomp_rule_add(f, SCMP_ACT_ALLOW, calls[i], 0);
        if (rc != 0 && rc != -EDOM)
            return -rc;
    }
    return 0;
}

/* Signals to itself only: abort() and raise() use tgkill on their own pid. */
static int own_signals(scmp_filter_ctx f)
{
    scmp_datum_t self = (scmp_datum_t)getpid();
    int rc = rule1(f, SCMP_ACT_ALLOW, SCMP_SYS(tgkill), 0, SCMP_CMP_EQ, self, 0);
    if (rc == 0)
        rc = rule1(f, SCMP_ACT_ALLOW, SCMP_SYS(kill), 0, SCMP_CMP_EQ, self, 0);
    if (rc == 0)
        rc = rule1(f, SCMP_ACT_ALLOW, SCMP_SYS(kill), 0, SCMP_CMP_EQ, 0, 0);
    /* isatty() on its output: "not a terminal", never a kill. */
    if (rc == 0)
        rc = seccomp_rule_add(f, SCMP_ACT_ERRNO(ENOTTY), SCMP_SYS(ioctl), 0);
    return -rc;
}

static int load(scmp_filter_ctx f, int rc)
{
    /* no new privileges is set already (sw_jail_lockdown): no prctl here */
    if (rc == 0)
        rc = -seccomp_attr_set(f, SCMP_FLTATR_CTL_NNP, 0);
    if (rc == 0)
        rc = -seccomp_load(f);
    seccomp_release(f);
    return rc;
}

static int compute_filter(void)
{
    /* A forbidden call raises SIGSYS (the call is not made): the host's
     * handler sends the steps before it, then the signal ends the host. */
    scmp_filter_ctx f = seccomp_init(SCMP_ACT_TRAP);
    if (!f)
        return ENOMEM;
    int rc = add_all(f, step_calls, sizeof step_calls / sizeof step_calls[0]);
    if (rc == 0)
        rc = own_signals(f);
    if (rc == 0) {
        rc = add_all(f, load_calls, sizeof load_calls / sizeof load_calls[0]);
        /* files: opened for reading only (the loader maps the plugin and its libraries) */
        scmp_datum_t mask = O_ACCMODE | O_CREAT | O_TRUNC | O_APPEND;
        if (rc == 0)
            rc = -rule1(f, SCMP_ACT_ALLOW, SCMP_SYS(openat), 2, SCMP_CMP_MASKED_EQ, mask, O_RDONLY);
        if (rc == 0)
            rc = -rule1(f, SCMP_ACT_ALLOW, SCMP_SYS(open), 1, SCMP_CMP_MASKED_EQ, mask, O_RDONLY);
        if (rc == 0) /* getrlimit only, never a new limit */
            rc = -rule1(f, SCMP_ACT_ALLOW, SCMP_SYS(prlimit64), 2, SCMP_CMP_EQ, 0, 0);
    }
    return load(f, rc);
}

static int compile_filter(void)
{
    scmp_filter_ctx f = seccomp_init(SCMP_ACT_ALLOW);
    if (!f)
        return ENOMEM;
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < sizeof compile_denied / sizeof compile_denied[0]; i++) {
        /* clone3 -> ENOSYS: the C library falls back to clone, whose flags are checked below */
        int err = compile_denied[i] == SCMP_SYS(clone3) ? ENOSYS : EPERM;
        rc = -seccomp_rule_add(f, SCMP_ACT_ERRNO(err), compile_denied[i], 0);
        if (rc == EDOM)
            rc = 0;
    }
    static const scmp_datum_t ns[] = { CLONE_NEWUSER, CLONE_NEWNS, CLONE_NEWPID, CLONE_NEWNET,
                                       CLONE_NEWIPC, CLONE_NEWUTS, CLONE_NEWCGROUP };
    for (size_t i = 0; rc == 0 && i < sizeof ns / sizeof ns[0]; i++) /* no new namespace from clone */
        rc = -rule1(f, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 0, SCMP_CMP_MASKED_EQ, ns[i], ns[i]);
    return load(f, rc);
}

int sw_jail_filter(sw_jail_profile profile)
{
    switch (profile) {
    case SW_JAIL_COMPUTE:
        return compute_filter();
    case SW_JAIL_COMPILE:
        return compile_filter();
    }
    return EINVAL;
}

