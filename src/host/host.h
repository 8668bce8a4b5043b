/* A student plugin's host (see plugin/host_proto.h): the program a
 * plugin's code runs in, exec'd in the jail. Private to src/host/. */
#ifndef SW_HOST_HOST_H
#define SW_HOST_HOST_H

#include <stddef.h>

#include "plugin/host_proto.h"
#include "stepwise/integrator.h"

/* Set while a step runs; any allocation then sets sw_host_allocated
 * (host_alloc.c). */
extern volatile int sw_host_in_step;
extern volatile int sw_host_allocated;
/* The bytes the plugin printed to stdout and stderr (host.c counts them
 * and drops them: they went to /dev/null before); a DYING record says it. */
extern volatile long long sw_host_printed;

/* One system the host keeps built, with the state and the work vectors
 * the plugin steps, each ending at a guard page (host_slot.c). */
typedef struct sw_host_slot sw_host_slot;

/* Build the system cmd describes into slot cmd->slot; 0 or a status. */
int sw_host_open(const sw_host_cmd *cmd, int work_vectors);
/* Forget slot i. */
void sw_host_close(int slot);
/* Run cmd (a RUN) on its slot with the plugin's step, writing the replies
 * to fd: PRINT, one STEP per step, END. y and extra follow cmd on fd.
 * 0, or -1 when the channel broke (the host then ends). */
int sw_host_run(const sw_host_cmd *cmd, sw_plugin_step_fn *step, int fd);
/* Read exactly len bytes, or write all of buf: 0, or -1 when the channel ended. */
int sw_host_read_all(int fd, void *buf, size_t len);
int sw_host_write_all(int fd, const void *buf, size_t len);
/* Arm the fault handler that names what a step wrote past, and the
 * handlers that send what is buffered before a fatal signal or while a
 * step runs long. */
void sw_host_watch_faults(int fd);
/* The tick those last handlers run on (setitimer: before the filter). 0 or -1. */
int sw_host_start_ticks(void);

#endif
