/* Forged results on every descriptor the plugin holds: a grade record that
 * says "pass", a well-formed reply to the load probe and fake table rows,
 * written on each of descriptors 0..1023 it finds open (the channel to its
 * parent among them), at load and at its first step. The grader must trust
 * no byte of it: the verdict stays "fail" (the numbers are Euler's). */
#define EVIL_FAMILY "forge-fds"
#include "evil.h"

static void forge_all(void)
{
    evil_grade_record rec;
    evil_forged_record(&rec);
    evil_probe_reply pr;
    memset(&pr, 0, sizeof pr);
    pr.stage = 4; /* loaded, sw_plugin_info() answered */
    pr.abi = SW_PLUGIN_ABI;
    pr.order = 4;
    pr.evals = 4;
    pr.work_vectors = 5;
    pr.has_step = 1;
    pr.has_label = 1;
    pr.name_len = (int)strlen("evil-" EVIL_FAMILY);
    memcpy(pr.name, "evil-" EVIL_FAMILY, (size_t)pr.name_len);
    pr.label_len = 6;
    memcpy(pr.label, "forged", 6);
    for (int fd = 0; fd < 1024; fd++) {
        if (fcntl(fd, F_GETFD) < 0)
            continue;
        struct stat st;
        if (fstat(fd, &st) != 0)
            continue;
        if (S_ISSOCK(st.st_mode) || S_ISFIFO(st.st_mode)) {
            evil_send(fd, &rec, sizeof rec);
            evil_send(fd, "R", 1);
            evil_send(fd, &pr, sizeof pr);
            evil_send(fd, &rec, sizeof rec);
        } else if (!S_ISREG(st.st_mode)) {
            evil_print_fake(fd);
        }
    }
}

__attribute__((constructor)) static void at_load(void) { forge_all(); }

static void evil_attack(void) { forge_all(); }
