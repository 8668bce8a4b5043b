/* The channel between stepwise and a student plugin's host (src/host/): a
 * small program of its own, exec'd in the jail, that holds the plugin, the
 * plugin interface and the derivative of the systems it is asked to step —
 * nothing else of stepwise (no method table, no built-in step, no fused
 * path, no grader). Every record is fixed-size, then a known number of
 * doubles; the parent validates every field before it uses one.
 *
 *   host -> parent, at start:   'L' (loaded), 'I' (calling sw_plugin_info),
 *                               then 'R' and a host_info.
 *   parent -> host:  OPEN slot  a system to build (a scene by name and its
 *                               parameters, or a 2x2 test system)
 *                    RUN slot   (t, h, steps, keep) + y + extra: replies
 *                               PRINT + f(t, y), then per step STEP + y, then END
 *                               (its index: the bytes the plugin printed in
 *                               this host so far, never decreasing)
 *                    CLOSE slot, QUIT
 *   host -> parent, on a fault: FAULT, then the host dies; on a fatal
 *                  signal or exit() in a step: DYING (its index: the bytes
 *                  the plugin printed to stdout and stderr in this host,
 *                  for a diagnosis only), then the host dies.
 * Replies are gathered and sent in large writes (at the latest every
 * SW_HOST_FLUSH_MS, so the parent's watchdog sees progress), or one by one
 * in a careful run: when a host dies in a run, the parent asks a new host
 * for the same run carefully, to learn the exact step it died in.
 * Private to plugin/ and the host. */
#ifndef SW_PLUGIN_HOST_PROTO_H
#define SW_PLUGIN_HOST_PROTO_H

#include <stdint.h>

/* Systems a host keeps built at once (one per stepper that uses it). */
#define SW_HOST_SLOTS 64
/* The longest scene name, and the most parameters and extra numbers. */
#define SW_HOST_SCENE_MAX 32
#define SW_HOST_PARAMS 8
#define SW_HOST_EXTRA_MAX (1 << 20)
/* The largest state a host steps (doubles). */
#define SW_HOST_DIM_MAX (1 << 24)
/* The most steps one RUN asks for. */
#define SW_HOST_BATCH_MAX 256
/* The longest a reply waits in the host's buffer. */
#define SW_HOST_FLUSH_MS 20
/* The most derivative evaluations (and solves) one step may report. */
#define SW_HOST_COUNT_MAX 1000000000LL

enum { SW_HOST_OPEN = 1, SW_HOST_RUN = 2, SW_HOST_CLOSE = 3, SW_HOST_QUIT = 4 };
enum {
    SW_HOST_OPENED = 'O',
    SW_HOST_PRINT = 'P',
    SW_HOST_STEP = 'S',
    SW_HOST_END = 'E',
    SW_HOST_FAULT = 'F',
    SW_HOST_DYING = 'D'     /* every step before this one was sent: the host ends now */
};

/* What loading found (after 'R'): numbers, and byte strings the parent
 * terminates itself (a string that fills its field is "too long"). */
enum { SW_HOST_STAGE_DLOPEN = 1, SW_HOST_STAGE_SYMBOL, SW_HOST_STAGE_NULL, SW_HOST_STAGE_OK };
typedef struct sw_host_info {
    int32_t stage;
    int32_t abi, order, evals, work_vectors, has_step, has_label;
    char name[257], label[257];
    char dlerr[512];
} sw_host_info;

/* parent -> host */
typedef struct sw_host_cmd {
    int32_t op, slot;
    /* OPEN */
    int32_t maker_kind;           /* SW_MAKER_SCENE or SW_MAKER_LINEAR2 */
    int32_t order, dim, nextra, work_vectors;
    char scene[SW_HOST_SCENE_MAX];
    double p[SW_HOST_PARAMS];     /* SCENE: the parameter values; LINEAR2: J, row-major */
    /* RUN */
    int32_t steps;                /* 1 .. SW_HOST_BATCH_MAX */
    int32_t keep;                 /* steps of the slot's last RUN that were used (-1: all) */
    int32_t careful;              /* 1: each reply sent as soon as it is made (see below) */
    int32_t pad;
    double t, h;
} sw_host_cmd;

/* host -> parent */
typedef struct sw_host_reply {
    int32_t tag;
    int32_t rc;          /* STEP: the plugin's return value; OPENED: 0 or a status; END: steps run */
    int32_t fault;       /* FAULT: SW_PF_OVERRUN_WORK, _OVERRUN_Y, _UNDERRUN, _ODE or _ALLOC */
    int32_t field;       /* SW_PF_ODE: which field; SW_PF_UNDERRUN: 0 y, 1 work */
    int64_t index;       /* the element touched, relative to the vector */
    int64_t was, now;    /* SW_PF_ODE: the field's value before and after */
    int64_t evals, solves, iters; /* STEP: what this step used, counted by the host */
} sw_host_reply;

/* The fields of the plugin's view of the ode a step must not change, in
 * the order a FAULT's field names them. */
#define SW_HOST_ODE_FIELDS { "dim", "order", "deriv", "solve", "ctx", "prepare", "fast", "maker" }
enum { SW_HOST_ODE_NFIELDS = 8 };

#endif
