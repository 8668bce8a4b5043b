/* stepwise-plugin-host: the program a student's plugin runs in (see
 * plugin/host_proto.h). stepwise execs it in the jail with the plugin's
 * path; it locks itself down (Landlock, then the seccomp filter, which has
 * no seccomp() in it: nothing the plugin does can add to it or fake it)
 * before a byte of the plugin runs, loads the plugin, says what it found,
 * and then steps the systems the parent describes, in batches, on the
 * channel at descriptor 3. It is built from the engine's derivatives and
 * the scenes' builders only: no method table, no built-in step, no fused
 * path, no grader is in its memory for a plugin to find and call.
 *
 * usage: stepwise-plugin-host PLUGIN.so [--jail [--read DIR]...] [--for WHO] */
#define _GNU_SOURCE /* fopencookie */
#include "host/host.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "plugin/jail_filter.h"

#define CHANNEL 3
#define MAX_READ_DIRS 16

/* stdout's buffer, given now so that a plugin's first printf in a step
 * does not allocate one. */
static char stdout_buf[4096];

volatile long long sw_host_printed;

/* stdout and stderr as the plugin sees them: counted, then dropped. */
static ssize_t count_printed(void *cookie, const char *buf, size_t len)
{
    (void)cookie;
    (void)buf;
    sw_host_printed += (long long)len;
    return (ssize_t)len;
}

static void count_what_is_printed(void)
{
    cookie_io_functions_t io = { .write = count_printed };
    FILE *out = fopencookie(NULL, "w", io), *err = fopencookie(NULL, "w", io);
    if (out && setvbuf(out, stdout_buf, _IOFBF, sizeof stdout_buf) == 0)
        stdout = out;
    if (err && setvbuf(err, NULL, _IONBF, 0) == 0)
        stderr = err;
}

static void copy_bounded(const char *src, char *dst, size_t size)
{
    size_t i = 0;
    while (i < size && src[i]) {
        dst[i] = src[i];
        i++;
    }
    if (i < size)
        dst[i] = '\0';
}

static int put(const void *buf, size_t len) { return sw_host_write_all(CHANNEL, buf, len); }

/* Load the plugin and describe it; the step function, or NULL. */
static sw_plugin_step_fn *load(const char *path, int *work_vectors)
{
    sw_host_info r;
    memset(&r, 0, sizeof r);
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    const sw_plugin *info = NULL;
    if (!lib) {
        const char *why = dlerror();
        r.stage = SW_HOST_STAGE_DLOPEN;
        snprintf(r.dlerr, sizeof r.dlerr, "%s", why ? why : "unknown error");
    } else {
        put("L", 1);
        const sw_plugin *(*get)(void);
        *(void **)&get = dlsym(lib, "sw_plugin_info");
        if (!get) {
            r.stage = SW_HOST_STAGE_SYMBOL;
        } else {
            put("I", 1);
            info = get();
            if (!info) {
                r.stage = SW_HOST_STAGE_NULL;
            } else {
                r.stage = SW_HOST_STAGE_OK;
                r.abi = info->abi;
                r.order = info->order;
                r.evals = info->evals;
                r.work_vectors = info->work_vectors;
                r.has_step = info->step != NULL;
                if (info->name)
                    copy_bounded(info->name, r.name, sizeof r.name);
                r.has_label = info->label != NULL;
                if (info->label)
                    copy_bounded(info->label, r.label, sizeof r.label);
            }
        }
    }
    if (put("R", 1) != 0 || put(&r, sizeof r) != 0 || r.stage != SW_HOST_STAGE_OK)
        return NULL;
    *work_vectors = r.work_vectors;
    return info->step;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "stepwise-plugin-host: started by stepwise only\n");
        return 2;
    }
    count_what_is_printed();
    int jail = 0, nread = 0;
    const char *read_dirs[MAX_READ_DIRS];
    for (int i = 2; i < argc; i++) {
        if (strcmp(argv[i], "--jail") == 0)
            jail = 1;
        else if (strcmp(argv[i], "--read") == 0 && i + 1 < argc && nread < MAX_READ_DIRS)
            read_dirs[nread++] = argv[++i];
        else if (strcmp(argv[i], "--for") == 0 && i + 1 < argc)
            i++; /* whose host this is, for ps: nothing to do */
        else
            return 2;
    }
    sw_host_watch_faults(CHANNEL);
    if (sw_host_start_ticks() != 0)
        return 4;
    /* Locked down before the plugin's constructors run: only what loading
     * and stepping need, for as long as this process lives. */
    if (jail && (sw_jail_landlock_read(read_dirs, nread) != 0 || sw_jail_filter(SW_JAIL_COMPUTE) != 0))
        return 4;
    int work_vectors = 0;
    sw_plugin_step_fn *step = load(argv[1], &work_vectors);
    if (!step)
        return 0;
    for (;;) {
        sw_host_cmd cmd;
        if (sw_host_read_all(CHANNEL, &cmd, sizeof cmd) != 0)
            return 0;
        switch (cmd.op) {
        case SW_HOST_OPEN: {
            sw_host_reply r;
            memset(&r, 0, sizeof r);
            r.tag = SW_HOST_OPENED;
            r.rc = sw_host_open(&cmd, work_vectors);
            if (put(&r, sizeof r) != 0)
                return 0;
            break;
        }
        case SW_HOST_RUN:
            if (sw_host_run(&cmd, step, CHANNEL) != 0)
                return 0;
            break;
        case SW_HOST_CLOSE:
            sw_host_close(cmd.slot);
            break;
        default: /* QUIT, or nothing the parent sends */
            return 0;
        }
    }
}
