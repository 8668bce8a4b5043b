/* Invisible and direction-changing characters in the plugin's label: U+202E
 * RIGHT-TO-LEFT OVERRIDE (what follows it is shown reversed: "ssap" reads
 * "pass"), U+2066 LEFT-TO-RIGHT ISOLATE and U+200B ZERO WIDTH SPACE. They
 * are not control characters (C0, C1, DEL), so a check for those lets
 * them by; on a terminal, in a spreadsheet or on a web page they reorder
 * or hide what the teacher reads next to them. The name is valid. Whether
 * the label is refused or shown, none of their bytes (E2 80 AE, E2 81 A6,
 * E2 80 8B, nor the other bidirectional and zero-width controls) may reach
 * any output: grade's table and messages, the CSV, results.json, the
 * feedback files, check's, try's and record's output, a recorded trace.
 * Explicit Euler: it fails the rk4 assignment. */
#define EVIL_FAMILY "label-bidi"
#define EVIL_CUSTOM_INFO
#include "evil.h"

static void evil_attack(void) {}

/* (each escape its own string: a hex escape would swallow the letters after it) */
static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "evil-" EVIL_FAMILY,
    .label = "SWEVIL:label-bidi "
             "\xe2\x80\xae" "ssap"          /* U+202E: shown as "pass" */
             "\xe2\x81\xa6" "rk4"           /* U+2066, never closed */
             "\xe2\x80\x8b" "ok",           /* U+200B */
    .order = 1, .evals = 1, .work_vectors = 5, .step = evil_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
