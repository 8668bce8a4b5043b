/* The parent's end of a plugin's host: start the program
 * stepwise-plugin-host in the jail (the host and the plugin copied into
 * the jail's work/, the host exec'd there), read what loading found, and
 * read replies, buffered, within the watchdog. Invariant: every record is fixed-size and
 * read whole; every string is terminated here; no field is used unchecked. */
#include "plugin/plugin_box.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "plugin/proc_tree.h"

#define JAIL_PLUGIN "plugin.so"
#define JAIL_HOST "stepwise-plugin-host"

/* What the payload execs: the host, and the plugin it loads. */
typedef struct host_exec {
    const char *host;          /* a path, in the jail or not */
    const char *plugin;
    int jailed;
    char who[256];             /* this process's command line: whose host it is, for ps */
} host_exec;

/* This process's command line, its arguments joined by blanks. */
static void command_line(char *out, size_t len)
{
    out[0] = '\0';
    int fd = open("/proc/self/cmdline", O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return;
    ssize_t n = read(fd, out, len - 1);
    close(fd);
    if (n <= 0)
        n = 0;
    for (ssize_t i = 0; i < n; i++)
        if (out[i] == '\0')
            out[i] = ' ';
    out[n] = '\0';
}

/* The payload: become the host. Returns only when exec failed. */
static int exec_host(void *ctx, int in, int out)
{
    (void)in;
    (void)out;
    const host_exec *x = ctx;
    char *argv[40];
    int n = 0;
    argv[n++] = JAIL_HOST;
    argv[n++] = (char *)x->plugin;
    if (x->jailed) {
        /* NS: the jail's root holds nothing but the system and /work; UID:
         * the system's directories and the jail's own work/ */
        argv[n++] = "--jail";
        if (sw_jail_kind_now() == SW_JAIL_UID) {
            for (int i = 0; sw_jail_system_dirs[i] && n < 28; i++) {
                argv[n++] = "--read";
                argv[n++] = (char *)sw_jail_system_dirs[i];
            }
            argv[n++] = "--read";
            argv[n++] = ".";
        } else {
            argv[n++] = "--read";
            argv[n++] = "/";
        }
    }
    argv[n++] = "--for";
    argv[n++] = (char *)x->who;
    argv[n] = NULL;
    char *envp[] = { NULL };
    execve(x->host, argv, envp);
    return 126;
}

/* The watchdog on a wait for the host, looked at every WATCH_QUANTUM s: the
 * host has `seconds` of its own CPU time to answer, however busy the machine
 * (a step starved by load waits on a run queue, and is waited for), and at
 * most `seconds` of wall time when it is not running (asleep: no step
 * needs to sleep), all within WATCH_WALL times `seconds` whatever it does.
 * Where /proc cannot tell, `seconds` of wall time, as before. */
#define WATCH_QUANTUM 0.25
#define WATCH_WALL 50

typedef struct host_watch {
    double waited, asleep, cpu0;
    int started;
} host_watch;

/* After a quantum q without an answer: 1 wait on, 0 the watchdog ends the
 * wait (h->watched says why). */
static int watch_on(sw_host_link *h, host_watch *w, double q, double seconds)
{
    sw_proc_tree now;
    w->waited += q;
    h->waited = w->waited;
    if (sw_proc_tree_read(h->child.pid, &now) != 0) {
        h->watched = w->waited < seconds ? SW_WATCH_NONE : SW_WATCH_WALL;
        return w->waited < seconds;
    }
    if (!w->started) { /* its CPU time counts from the first look (one quantum's grace) */
        w->started = 1;
        w->cpu0 = now.cpu_seconds;
    }
    w->asleep += now.runnable ? 0 : q;
    h->watched = now.cpu_seconds - w->cpu0 >= seconds ? SW_WATCH_CPU
                 : w->asleep >= seconds               ? SW_WATCH_ASLEEP
                 : w->waited >= WATCH_WALL * seconds  ? SW_WATCH_WALL
                                                      : SW_WATCH_NONE;
    return h->watched == SW_WATCH_NONE;
}

void sw_host_watch_says(const sw_host_link *h, double seconds, char *out, size_t len)
{
    if (h->watched == SW_WATCH_CPU)
        snprintf(out, len, "used %g s of its own CPU time without returning", seconds);
    else if (h->watched == SW_WATCH_ASLEEP)
        snprintf(out, len, "slept %g s without returning", seconds);
    else
        snprintf(out, len, "did not return within %.3g s", h->waited > 0 ? h->waited : seconds);
}

int sw_host_read(sw_plugin_entry *e, void *buf, size_t len, double seconds)
{
    sw_host_link *h = &e->host;
    unsigned char *out = buf;
    while (len > 0) {
        if (h->rpos == h->rlen) {
            host_watch w = { 0 };
            double q = seconds < WATCH_QUANTUM ? seconds : WATCH_QUANTUM;
            long n;
            do
                n = sw_sandbox_read_some(h->child.from_child, h->rbuf, sizeof h->rbuf, q);
            while (n == -2 && watch_on(h, &w, q, seconds));
            if (n <= 0)
                return (int)n;
            h->rpos = 0;
            h->rlen = (size_t)n;
        }
        size_t take = h->rlen - h->rpos < len ? h->rlen - h->rpos : len;
        memcpy(out, h->rbuf + h->rpos, take);
        h->rpos += take;
        out += take;
        len -= take;
    }
    return 1;
}

int sw_host_reply_read(sw_plugin_entry *e, sw_host_reply *r, double seconds)
{
    sw_host_link *h = &e->host;
    int rc = sw_host_read(e, r, sizeof *r, seconds);
    if (rc == 1 && r->tag == SW_HOST_DYING) {
        h->dying = 1;
        h->printed = r->index > 0 ? r->index : 0;
        return 0; /* the host dies next */
    }
    if (rc == 1 && r->tag == SW_HOST_FAULT) {
        int ok = 0;
        switch (r->fault) {
        case SW_PF_OVERRUN_WORK:
        case SW_PF_OVERRUN_Y:
            ok = r->index >= 0 && r->index < ((int64_t)1 << 40);
            break;
        case SW_PF_UNDERRUN:
            ok = r->field == 0 || r->field == 1;
            break;
        case SW_PF_ODE:
            ok = r->field >= 0 && r->field < SW_HOST_ODE_NFIELDS;
            break;
        case SW_PF_ALLOC:
            ok = 1;
            break;
        default:
            break;
        }
        if (!ok)
            return -4;
        h->fault = *r;
        h->have_fault = 1;
        return 0; /* the host dies next */
    }
    return rc;
}

void sw_host_lost(sw_plugin_entry *e, sw_child_end *end)
{
    sw_host_link *h = &e->host;
    memset(end, 0, sizeof *end);
    if (h->child.pid > 0)
        sw_sandbox_reap(&h->child, 1.0, end);
    h->alive = 0;
    h->slots = 0;
}

void sw_host_stop(sw_plugin_entry *e)
{
    sw_host_link *h = &e->host;
    if (!h->alive)
        return;
    sw_host_cmd quit;
    memset(&quit, 0, sizeof quit);
    quit.op = SW_HOST_QUIT;
    /* a host that cannot be told (gone already) is reaped, or killed, below all the same */
    (void)sw_sandbox_write(h->child.to_child, &quit, sizeof quit);
    sw_child_end end;
    sw_sandbox_reap(&h->child, 0.5, &end);
    h->alive = 0;
    h->slots = 0;
}

int sw_host_start(sw_plugin_entry *e, sw_host_info *info, char *err, size_t errlen)
{
    sw_host_link *h = &e->host;
    char msg[SW_ERRLEN];
    int host_fd = sw_plugin_host_fd(msg, sizeof msg);
    if (host_fd < 0) {
        snprintf(err, errlen, "'%s': %s", e->shown, msg);
        return SW_EIO;
    }
    int jailed = sw_jail_enabled();
    /* jailed, both are in work/, the payload's current directory */
    host_exec x = { .host = jailed ? "./" JAIL_HOST : sw_plugin_host_path(),
                    .plugin = jailed ? "./" JAIL_PLUGIN : e->path, .jailed = jailed };
    command_line(x.who, sizeof x.who);
    sw_jail spec = { .profile = SW_JAIL_COMPUTE, .include_fd = -1 };
    spec.in[0] = (sw_jail_file){ .fd = e->fd, .name = JAIL_PLUGIN };
    spec.in[1] = (sw_jail_file){ .fd = host_fd, .name = JAIL_HOST, .executable = 1 };
    spec.nin = 2;
    sw_limits lim;
    sw_plugin_limits(&lim);
    h->graders = sw_plugin_grader_open();
    /* what the host before printed (to its death, or its last run's end) */
    e->printed_before += h->dying && h->printed > h->printed_end ? h->printed : h->printed_end;
    h->have_fault = h->dying = 0;
    h->printed = h->printed_end = 0;
    h->rpos = h->rlen = 0;
    if (sw_sandbox_spawn_jailed(&h->child, exec_host, &x, &lim, -1, &spec, msg, sizeof msg) != SW_OK) {
        snprintf(err, errlen, "'%s': %s", e->shown, msg);
        return SW_EIO;
    }
    h->alive = 1;
    h->generation++;
    h->slots = 0;
    double limit = sw_plugin_timeout();
    char stage = 0, tag;
    int rc, tags = 0;
    while ((rc = sw_host_read(e, &tag, 1, limit)) == 1 && tag != 'R' && ++tags < 3)
        stage = tag == 'I' ? 'I' : 'L';
    if (rc == 1 && tag != 'R')
        rc = -3; /* more progress tags than the host sends */
    if (rc == 1)
        rc = sw_host_read(e, info, sizeof *info, limit);
    const char *what = stage == 'I' ? "sw_plugin_info()" : "loading it (dlopen and its constructors)";
    sw_child_end end;
    if (rc == 1) {
        /* terminated here, whatever was sent: an unterminated field is "too long" */
        info->name[sizeof info->name - 1] = info->label[sizeof info->label - 1] = '\0';
        info->dlerr[sizeof info->dlerr - 1] = '\0';
        if (info->stage != SW_HOST_STAGE_OK)
            sw_host_lost(e, &end); /* it ends by itself: nothing to step */
        return SW_OK;
    }
    if (rc == -2 || rc == -1) {
        sw_sandbox_kill(&h->child, &end);
        h->alive = 0;
        char said[96];
        sw_host_watch_says(h, limit, said, sizeof said);
        if (rc == -2)
            snprintf(err, errlen, "'%s': %s %s (%s)", e->shown, what, said,
                     h->watched == SW_WATCH_ASLEEP ? "it must not wait" : "an endless loop?");
        else
            snprintf(err, errlen, "'%s': interrupted while %s ran", e->shown, what);
        return SW_EINVAL;
    }
    sw_host_lost(e, &end);
    if (end.exited && end.code == 126) {
        snprintf(err, errlen, "'%s': the plugin host could not be started (%s)", e->shown,
                 strerror(ENOEXEC));
        return SW_EIO;
    }
    sw_sandbox_describe(&end, msg, sizeof msg);
    snprintf(err, errlen, "'%s': %s %s%s", e->shown, what, msg,
             end.exited ? " (a plugin must not end the process: return from it)" : "");
    return SW_EINVAL;
}
