/* The jail's namespaces, root and lockdown (see jail.h). Invariant: nothing
 * of the host is visible inside but the read-only system directories, three
 * device nodes and what the spec copies in; the payload holds no capability
 * and cannot gain one (no new privileges, an empty bounding set). */
#define _GNU_SOURCE /* namespaces, setresuid, pipe2, sethostname: Linux-only by design */
#include "plugin/jail.h"

#include <dirent.h>
#include <grp.h>
#include <signal.h>
#include <sys/wait.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/capability.h>
#include <sched.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/file.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "plugin/jail_filter.h"
#include "plugin/proc_tree.h"
#include "util/tmpdir.h"

static int disabled = -1;

int sw_jail_enabled(void)
{
    if (disabled < 0) {
        const char *env = getenv("STEPWISE_SANDBOX");
        disabled = env && strcmp(env, "off") == 0;
    }
    return !disabled;
}

void sw_jail_set_enabled(int on) { disabled = !on; }


static sw_jail_kind kind;

sw_jail_kind sw_jail_kind_now(void)
{
    if (!kind) {
        const char *env = getenv("STEPWISE_JAIL");
        kind = env && strcmp(env, "uid") == 0 && geteuid() == 0 ? SW_JAIL_UID : SW_JAIL_NS;
    }
    return kind;
}

void sw_jail_kind_set(sw_jail_kind k) { kind = k; }

int sw_jail_uid_allowed(void)
{
    const char *env = getenv("STEPWISE_JAIL");
    return geteuid() == 0 && !(env && strcmp(env, "ns") == 0);
}

const char *const sw_jail_system_dirs[] = { "/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32",
                                            "/etc/ld.so.cache", NULL };

int sw_jail_unshare(const char **step)
{
    *step = "unshare(CLONE_NEWUSER and the other namespaces)";
    if (unshare(CLONE_NEWUSER | CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS |
                CLONE_NEWCGROUP) != 0)
        return errno;
    return 0;
}

static int write_proc(int pid, const char *file, const char *text)
{
    char path[64];
    snprintf(path, sizeof path, "/proc/%d/%s", pid, file);
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0)
        return -1;
    ssize_t n = write(fd, text, strlen(text));
    int saved = errno;
    close(fd);
    errno = saved;
    return n == (ssize_t)strlen(text) ? 0 : -1;
}

int sw_jail_map_user(int pid, char *why, size_t len)
{
    char map[64];
    /* setgroups must be denied before an unprivileged gid_map; harmless for root. */
    if (write_proc(pid, "setgroups", "deny") != 0 && errno != ENOENT) {
        snprintf(why, len, "cannot write /proc/%d/setgroups: %s", pid, strerror(errno));
        return -1;
    }
    /* As root, the jail's root is "nobody" outside: even a file it could
     * reach is accessed as nobody. Elsewhere it can only be ourselves. */
    if (getuid() == 0) {
        if (write_proc(pid, "uid_map", "0 65534 1\n") == 0 && write_proc(pid, "gid_map", "0 65534 1\n") == 0)
            return 0;
    }
    snprintf(map, sizeof map, "0 %u 1\n", (unsigned)getuid());
    if (write_proc(pid, "uid_map", map) != 0) {
        snprintf(why, len, "cannot map the sandbox's user (/proc/%d/uid_map): %s", pid, strerror(errno));
        return -1;
    }
    snprintf(map, sizeof map, "0 %u 1\n", (unsigned)getgid());
    if (write_proc(pid, "gid_map", map) != 0) {
        snprintf(why, len, "cannot map the sandbox's group (/proc/%d/gid_map): %s", pid, strerror(errno));
        return -1;
    }
    return 0;
}

/* ---- the root --------------------------------------------------------------- */

/* The jail's root: a tmpfs mounted over /tmp in our own mount namespace. */
#define NEWROOT "/tmp"

/* The flags a bind mount must keep when remounted (a mount inherited from
 * a more privileged namespace has them locked). */
static unsigned long kept_flags(const char *path)
{
    struct statvfs sv;
    unsigned long f = 0;
    if (statvfs(path, &sv) != 0)
        return f;
    if (sv.f_flag & ST_NOSUID) f |= MS_NOSUID;
    if (sv.f_flag & ST_NODEV) f |= MS_NODEV;
    if (sv.f_flag & ST_NOEXEC) f |= MS_NOEXEC;
    if (sv.f_flag & ST_NOATIME) f |= MS_NOATIME;
    if (sv.f_flag & ST_NODIRATIME) f |= MS_NODIRATIME;
    if (sv.f_flag & ST_RELATIME) f |= MS_RELATIME;
    return f;
}

/* Bind host path at the same place under the new root, read-only. A
 * symbolic link (a merged /usr's /lib -> usr/lib) is copied as a link. */
static int bind_ro(const char *host, int is_dir)
{
    char target[256];
    snprintf(target, sizeof target, NEWROOT "%s", host);
    struct stat st;
    if (lstat(host, &st) != 0)
        return 0; /* not on this system: nothing to show */
    if (S_ISLNK(st.st_mode)) {
        char link[256];
        ssize_t n = readlink(host, link, sizeof link - 1);
        if (n <= 0)
            return errno ? errno : EINVAL;
        link[n] = '\0';
        return symlink(link, target) == 0 ? 0 : errno;
    }
    if (is_dir ? mkdir(target, 0755) != 0 : close(open(target, O_WRONLY | O_CREAT | O_CLOEXEC, 0644)) != 0)
        return errno;
    if (mount(host, target, NULL, MS_BIND | MS_REC, NULL) != 0)
        return errno;
    if (mount(NULL, target, NULL, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | kept_flags(target), NULL) != 0)
        return errno;
    return 0;
}

/* Copy what fd holds to path (at most SW_JAIL_FILE_MAX bytes). */
static int copy_in(int fd, const char *path, mode_t mode)
{
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
        return EINVAL;
    if ((size_t)st.st_size > SW_JAIL_FILE_MAX)
        return EFBIG;
    int out = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
    if (out < 0)
        return errno;
    char buf[65536];
    off_t at = 0;
    size_t total = 0;
    for (;;) {
        ssize_t n = pread(fd, buf, sizeof buf, at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0 || (total += (size_t)n) > SW_JAIL_FILE_MAX) {
            int rc = n < 0 ? errno : n == 0 ? 0 : EFBIG;
            close(out);
            return rc;
        }
        at += n;
        for (ssize_t done = 0; done < n;) {
            ssize_t w = write(out, buf + done, (size_t)(n - done));
            if (w <= 0) {
                int rc = errno ? errno : EIO;
                close(out);
                return rc;
            }
            done += w;
        }
    }
}

/* The headers a plugin includes: every regular *.h of the directory. */
static int copy_headers(int dir_fd, const char *to)
{
    int fd = openat(dir_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d)
        return errno ? errno : EINVAL;
    int rc = 0;
    for (struct dirent *e; rc == 0 && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (e->d_name[0] == '.' || len < 3 || strcmp(e->d_name + len - 2, ".h") != 0 || len > 100)
            continue;
        int h = openat(dir_fd, e->d_name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (h < 0)
            continue;
        char path[256];
        if ((size_t)snprintf(path, sizeof path, "%s/%s", to, e->d_name) < sizeof path)
            rc = copy_in(h, path, 0644);
        close(h);
    }
    closedir(d);
    return rc;
}

static int fail_at(const char **step, const char *what, int err)
{
    *step = what;
    return err ? err : EINVAL;
}

/* The step that failed, as the refusal names it. */
static const char *landlock_step(int rc)
{
    return rc == EOPNOTSUPP ? "Landlock, the file boundary of a jail without user namespaces, which this "
                              "kernel does not enable,"
                            : "Landlock";
}

int sw_jail_build(const sw_jail *spec, const char **step)
{
    static const char *const system_dirs[] = { "/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64",
                                               "/libx32" };
    static const char *const devices[] = { "/dev/null", "/dev/zero", "/dev/urandom" };
    char opts[64];
    int rc;
    if (setresgid(0, 0, 0) != 0 || setresuid(0, 0, 0) != 0)
        return fail_at(step, "setresuid(0) in the user namespace", errno);
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0)
        return fail_at(step, "making the mounts private", errno);
    if (mount("tmpfs", NEWROOT, "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,nr_inodes=256,mode=0755") != 0)
        return fail_at(step, "mounting the jail's root", errno);
    for (size_t i = 0; i < sizeof system_dirs / sizeof system_dirs[0]; i++)
        if ((rc = bind_ro(system_dirs[i], 1)) != 0)
            return fail_at(step, "binding the system directories read-only", rc);
    if (mkdir(NEWROOT "/dev", 0755) != 0 || mkdir(NEWROOT "/etc", 0755) != 0)
        return fail_at(step, "making /dev and /etc", errno);
    for (size_t i = 0; i < sizeof devices / sizeof devices[0]; i++)
        if ((rc = bind_ro(devices[i], 0)) != 0)
            return fail_at(step, "binding /dev/null, /dev/zero and /dev/urandom", rc);
    if ((rc = bind_ro("/etc/ld.so.cache", 0)) != 0)
        return fail_at(step, "binding /etc/ld.so.cache", rc);
    size_t disk = spec->disk_bytes ? spec->disk_bytes : (size_t)64 << 20;
    snprintf(opts, sizeof opts, "size=%zu,nr_inodes=4096,mode=0755", disk);
    if (mkdir(NEWROOT "/work", 0755) != 0 ||
        mount("tmpfs", NEWROOT "/work", "tmpfs", MS_NOSUID | MS_NODEV, opts) != 0)
        return fail_at(step, "mounting /work", errno);
    if (symlink("work", NEWROOT "/tmp") != 0)
        return fail_at(step, "linking /tmp to /work", errno);
    for (int i = 0; i < spec->nin; i++) {
        char path[256];
        snprintf(path, sizeof path, NEWROOT "/work/%s", spec->in[i].name);
        if ((rc = copy_in(spec->in[i].fd, path, spec->in[i].executable ? 0755 : 0644)) != 0)
            return fail_at(step, SW_JAIL_STEP_SUBMISSION, rc);
    }
    if (spec->include_fd >= 0) {
        if (mkdir(NEWROOT "/include", 0755) != 0 || mkdir(NEWROOT "/include/stepwise", 0755) != 0 ||
            (rc = copy_headers(spec->include_fd, NEWROOT "/include/stepwise")) != 0)
            return fail_at(step, "copying stepwise's headers", rc ? rc : errno);
    }
    /* pivot_root(".", "."): the old root ends up on top of the new one and
     * is then detached whole, so nothing of it stays reachable. */
    if (chdir(NEWROOT) != 0 || syscall(SYS_pivot_root, ".", ".") != 0)
        return fail_at(step, "pivot_root into the jail", errno);
    if (umount2(".", MNT_DETACH) != 0 || chdir("/") != 0)
        return fail_at(step, "detaching the host's file system", errno);
    if (mount(NULL, "/", NULL, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV, NULL) != 0)
        return fail_at(step, "making the jail's root read-only", errno);
    if (chdir("/work") != 0)
        return fail_at(step, "entering /work", errno);
    return 0;
}

/* ---- the separate user (no namespaces) ------------------------------------ */

/* The jail's user: one of its own per jail, so that no two jails (nor
 * anything else) share it: an id from a range Debian leaves to be made
 * on demand, by the first process's pid; nobody where it is not mapped. */
#define UID_BASE 61000u
#define UID_RANGE 3000u

static char uid_dir[512]; /* the jail's directory, for Landlock */
static int drop_bounding(void);

/* Whether every directory on path (absolute) lets others pass through
 * (o+x): the jail's user, which owns none of them, must reach its work/. */
static int others_may_pass(const char *path)
{
    char prefix[512];
    size_t len = strlen(path);
    if (path[0] != '/' || len >= sizeof prefix)
        return 0;
    for (size_t i = 1; i <= len; i++)
        if (path[i] == '/' || path[i] == '\0') {
            memcpy(prefix, path, i);
            prefix[i] = '\0';
            struct stat st;
            if (stat(prefix, &st) != 0 || !S_ISDIR(st.st_mode) || !(st.st_mode & S_IXOTH))
                return 0;
        }
    return 1;
}

void sw_jail_uid_dir(int pid, char *dir, size_t dirlen)
{
    /* $TMPDIR when the jail's user can reach into it (a grader's private
     * TMPDIR, mode 0700, it cannot), else /tmp */
    const char *tmp = getenv("TMPDIR");
    if (!tmp || strlen(tmp) > 300 || !others_may_pass(tmp))
        tmp = "/tmp";
    snprintf(dir, dirlen, "%s/stepwise-jail-%d", tmp, pid);
}

static void claim_path(unsigned id, char *path, size_t len)
{
    snprintf(path, len, "/tmp/stepwise-uid-%u.lock", id);
}

int sw_jail_claim_uid(unsigned from, unsigned *uid)
{
    for (unsigned k = 0; k < UID_RANGE; k++) {
        unsigned id = UID_BASE + (from + k) % UID_RANGE;
        char path[64];
        claim_path(id, path, sizeof path);
        /* never through a link; one that someone else holds or made
         * unopenable (protected_regular) is a claimed id */
        int fd = open(path, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0 && errno != ENOENT && errno != EROFS)
            continue;
        /* held, or let go and removed since we opened it (its holder
         * removes it before letting go: sw_jail_release_uid), or made anew
         * by another since: claimed */
        struct stat held, named;
        if (fd >= 0 && (flock(fd, LOCK_EX | LOCK_NB) != 0 || fstat(fd, &held) != 0 || lstat(path, &named) != 0 ||
                        held.st_ino != named.st_ino || held.st_dev != named.st_dev)) {
            close(fd);
            continue;
        }
        if (sw_proc_uid_in_use((uid_t)id) == 1) { /* a jail's user left over, or not a jail's */
            if (fd >= 0)
                close(fd);
            continue;
        }
        *uid = id;
        return fd; /* -1: no /tmp to claim in; the process check alone */
    }
    return -2;
}

void sw_jail_release_uid(unsigned uid, int claim)
{
    if (claim < 0)
        return;
    char path[64];
    claim_path(uid, path, sizeof path);
    unlink(path); /* while still held: whoever opened it before sees it gone */
    close(claim);
}

int sw_jail_build_uid(const sw_jail *spec, char *dir, size_t dirlen, unsigned *uid, int *claim, const char **step)
{
    int rc;
    /* no namespaces: Landlock is this jail's only file boundary */
    if (sw_jail_landlock_abi() < 1)
        return fail_at(step, landlock_step(EOPNOTSUPP), EOPNOTSUPP);
    /* from the pid's place in the range, the first id that no other jail
     * has claimed and no process runs as (two jails started together, or
     * whose pids agree mod UID_RANGE, never share one) */
    *claim = sw_jail_claim_uid((unsigned)getpid() % UID_RANGE, uid);
    if (*claim == -2)
        return fail_at(step, "claiming a user id for the jail (every one of 61000-63999 is in use)", EAGAIN);
    sw_jail_uid_dir(getpid(), dir, dirlen);
    /* made here or not at all: a path someone else made is never taken
     * (removed once: a jail of an earlier process of this pid, killed) */
    if (mkdir(dir, 0700) != 0) {
        if (errno != EEXIST)
            return fail_at(step, "making the jail's directory", errno);
        sw_tmpdir_remove(dir);
        if (mkdir(dir, 0700) != 0)
            return fail_at(step, "making the jail's directory", errno);
    }
    snprintf(uid_dir, sizeof uid_dir, "%s", dir);
    char work[600], inc[600];
    snprintf(work, sizeof work, "%s/work", dir);
    snprintf(inc, sizeof inc, "%s/include", dir);
    if (chmod(dir, 0711) != 0 || mkdir(work, 0700) != 0)
        return fail_at(step, "making the jail's directory", errno);
    for (int i = 0; i < spec->nin; i++) {
        char path[700];
        snprintf(path, sizeof path, "%s/%s", work, spec->in[i].name);
        if ((rc = copy_in(spec->in[i].fd, path, spec->in[i].executable ? 0755 : 0644)) != 0)
            return fail_at(step, SW_JAIL_STEP_SUBMISSION, rc);
    }
    if (spec->include_fd >= 0) {
        char stepwise[700];
        snprintf(stepwise, sizeof stepwise, "%s/stepwise", inc);
        if (mkdir(inc, 0755) != 0 || mkdir(stepwise, 0755) != 0 ||
            (rc = copy_headers(spec->include_fd, stepwise)) != 0)
            return fail_at(step, "copying stepwise's headers", rc ? rc : errno);
    }
    if (chown(work, *uid, *uid) != 0 && errno == EINVAL) { /* not mapped here: nobody, unclaimed */
        sw_jail_release_uid(*uid, *claim);
        *claim = -1;
        *uid = 65534;
    }
    if (chown(work, *uid, *uid) != 0)
        return fail_at(step, "giving the jail's user its directory", errno);
    if (chdir(work) != 0)
        return fail_at(step, "entering the jail's directory", errno);
    return 0;
}

int sw_jail_become(unsigned uid, const char **step)
{
    /* the bounding set while we may still change it; the rest goes with root */
    int rc = drop_bounding();
    if (rc != 0)
        return fail_at(step, "dropping capabilities", rc);
    if (setgroups(0, NULL) != 0)
        return fail_at(step, "dropping supplementary groups", errno);
    if (setresgid(uid, uid, uid) != 0 || setresuid(uid, uid, uid) != 0)
        return fail_at(step, "becoming the jail's user", errno);
    return 0;
}

void sw_jail_kill_user(unsigned uid)
{
    pid_t pid = fork();
    if (pid == 0) {
        /* as the user: every process it may signal is one of its own */
        if (setresgid(uid, uid, uid) == 0 && setresuid(uid, uid, uid) == 0)
            kill(-1, SIGKILL);
        _exit(0);
    }
    if (pid > 0)
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR)
            ;
}

/* ---- the lockdown ----------------------------------------------------------- */


/* Empty the bounding set (what a capability could ever be regained from);
 * the capabilities held stay until drop_capabilities. */
static int drop_bounding(void)
{
    for (int cap = 0; cap <= 63; cap++)
        if (prctl(PR_CAPBSET_READ, cap, 0, 0, 0) == 1 && prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0 &&
            errno != EINVAL)
            return errno;
    prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0);
    return 0;
}

static int drop_capabilities(void)
{
    int rc = drop_bounding();
    if (rc != 0)
        return rc;
    struct __user_cap_header_struct head = { _LINUX_CAPABILITY_VERSION_3, 0 };
    struct __user_cap_data_struct data[2];
    memset(data, 0, sizeof data);
    if (syscall(SYS_capset, &head, data) != 0)
        return errno;
    return 0;
}

int sw_jail_lockdown(sw_jail_profile profile, const char **step)
{
    int rc;
    /* Root in the namespace regains every capability on exec: never. */
    if (prctl(PR_SET_SECUREBITS, 0x2f /* NOROOT, its lock, NO_SETUID_FIXUP, its lock, KEEP_CAPS_LOCKED */,
              0, 0, 0) != 0 && errno != EPERM)
        return fail_at(step, "setting the securebits", errno);
    if ((rc = drop_capabilities()) != 0)
        return fail_at(step, "dropping capabilities", rc);
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
        return fail_at(step, "PR_SET_NO_NEW_PRIVS", errno);
    prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
    if (profile == SW_JAIL_COMPUTE)
        return 0; /* the host installs the last two layers on itself */
    if (sw_jail_kind_now() == SW_JAIL_UID) {
        /* the system to read, the jail's directory to read (its headers) and its work/ to write */
        const char *read_dirs[16];
        int n = 0;
        for (int i = 0; sw_jail_system_dirs[i] && n < 14; i++)
            read_dirs[n++] = sw_jail_system_dirs[i];
        read_dirs[n++] = uid_dir;
        static const char *const full[] = { "." };
        rc = sw_jail_landlock_rules(read_dirs, n, full, 1);
    } else {
        rc = sw_jail_landlock();
    }
    if (rc != 0)
        return fail_at(step, landlock_step(rc), rc);
    if ((rc = sw_jail_filter(profile)) != 0)
        return fail_at(step, "the seccomp filter", rc);
    return 0;
}

int sw_jail_compute_layers(const char **step)
{
    static const char *const root[] = { "/" };
    int rc = sw_jail_kind_now() == SW_JAIL_UID ? sw_jail_landlock_read(sw_jail_system_dirs, 8)
                                              : sw_jail_landlock_read(root, 1);
    if (rc != 0)
        return fail_at(step, landlock_step(rc), rc);
    if ((rc = sw_jail_filter(SW_JAIL_COMPUTE)) != 0)
        return fail_at(step, "the seccomp filter", rc);
    return 0;
}

void sw_jail_send_outputs(const sw_jail *spec, int fd)
{
    for (int i = 0; i < spec->nout; i++) {
        char path[256];
        snprintf(path, sizeof path, "%s", spec->out[i]); /* in work/, the current directory */
        int in = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        struct stat st;
        int64_t size = -1;
        if (in >= 0 && fstat(in, &st) == 0 && S_ISREG(st.st_mode) && (size_t)st.st_size <= SW_JAIL_FILE_MAX)
            size = (int64_t)st.st_size;
        if (write(fd, &size, sizeof size) != (ssize_t)sizeof size)
            size = -1;
        char buf[65536];
        for (int64_t left = size; left > 0;) {
            ssize_t n = read(in, buf, left < (int64_t)sizeof buf ? (size_t)left : sizeof buf);
            if (n <= 0)
                memset(buf, 0, (size_t)(n = left < (int64_t)sizeof buf ? (ssize_t)left : (ssize_t)sizeof buf));
            if (write(fd, buf, (size_t)n) != n)
                break;
            left -= n;
        }
        if (in >= 0)
            close(in);
    }
}
