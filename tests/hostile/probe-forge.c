/* A forged reply to the load probe, from inside sw_plugin_info(): on every
 * socket it holds it sends the probe's "R" tag and a reply whose name
 * length says 256 (the name is 41 bytes where stepwise keeps it), so the
 * copy runs 216 bytes past it into what follows: a fault code ("crashed")
 * and a failure text full of terminal escapes (as of the issue's layout of
 * src/plugin). Then it answers truthfully. The parent must bound and
 * validate every field: no crash, no raw escapes, no pass. */
#define EVIL_FAMILY "probe-forge"
#define EVIL_CUSTOM_INFO
#include "evil.h"

static void evil_attack(void) {}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "evil-" EVIL_FAMILY, .label = "hostile: " EVIL_FAMILY,
    .order = 1, .evals = 1, .work_vectors = 5, .step = evil_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void)
{
    static const char escapes[] = "\033[2J\033[H\033]0;SWEVIL:probe-forge\007\033[31mSWEVIL:probe-forge "
                                  "forged failure\033[0m";
    evil_probe_reply r;
    memset(&r, 0, sizeof r);
    r.stage = 4;
    r.abi = SW_PLUGIN_ABI;
    r.order = 4;
    r.evals = 4;
    r.work_vectors = 5;
    r.has_step = 1;
    r.has_label = 1;
    r.name_len = 256;
    memcpy(r.name, "evil-" EVIL_FAMILY, strlen("evil-" EVIL_FAMILY));
    /* past the 41-byte name: label[81], work_vectors, method, then
     * last_fault at +136 and last_failure at +140 */
    int crashed = 2;
    memcpy(r.name + 136, &crashed, sizeof crashed);
    memcpy(r.name + 140, escapes, sizeof escapes < 116 ? sizeof escapes : 116);
    r.label_len = 6;
    memcpy(r.label, "forged", 6);
    memcpy(r.dlerr, escapes, sizeof escapes);
    for (int fd = 0; fd < 1024; fd++)
        if (evil_is_socket(fd)) {
            evil_send(fd, "R", 1);
            evil_send(fd, &r, sizeof r);
        }
    return &info;
}
