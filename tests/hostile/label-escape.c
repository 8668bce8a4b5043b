/* Terminal escapes in the plugin's label (clear screen, a window title):
 * refused at load; whatever message names it must show it escaped, never
 * raw, on the teacher's terminal and in the gradebook. */
#define EVIL_FAMILY "label-escape"
#define EVIL_CUSTOM_INFO
#include "evil.h"

static void evil_attack(void) {}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "evil-" EVIL_FAMILY,
    .label = "\033[2J\033]0;SWEVIL:label-escape\007\033[32mPASS\033[0m",
    .order = 1, .evals = 1, .work_vectors = 5, .step = evil_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
