/* The registry of loaded plugins and the limits their processes get: what
 * loading (plugin.c) and stepping (plugin_box.c) both look up, below both,
 * so neither calls the other back. */
#include "plugin/plugin_box.h"

#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "plugin/sandbox.h"
#include "util/num.h"

static sw_plugin_entry entries[SW_PLUGIN_MAX];
static int nentries;
static double timeout_seconds;
static sw_limits limits;

void sw_plugin_set_limits(const sw_limits *lim)
{
    memset(&limits, 0, sizeof limits);
    if (lim)
        limits = *lim;
}

static double seconds_of(struct timeval tv) { return (double)tv.tv_sec + 1e-6 * (double)tv.tv_usec; }

/* CPU time of this process's reaped children (builds and hosts). */
static double children_cpu(void)
{
    struct rusage kids;
    getrusage(RUSAGE_CHILDREN, &kids);
    return seconds_of(kids.ru_utime) + seconds_of(kids.ru_stime);
}

/* The grader's account: open while its measuring runs go on; what its
 * hosts used (reaped when it closes) is never the submission's. */
static int grader_open;
static double grader_from, grader_used;

void sw_plugin_account(int grader)
{
    grader = grader != 0;
    if (grader == grader_open)
        return;
    if (grader)
        grader_from = children_cpu();
    else
        grader_used += children_cpu() - grader_from;
    grader_open = grader;
}

void sw_plugin_limits(sw_limits *lim)
{
    *lim = limits;
    if (limits.cpu_seconds > 0 && grader_open) {
        /* What is left of the grader's budget: a host restarted within its
         * measuring runs (one that died computing steps nobody asked for)
         * does not start a budget afresh. */
        double left = SW_GRADER_CPU(limits.cpu_seconds) - (children_cpu() - grader_from);
        lim->cpu_seconds = left > 1 ? left : 1;
    } else if (limits.cpu_seconds > 0) {
        /* The submission's own processes only (its builds and hosts, each
         * in this process's children's account once reaped): the
         * grader's work in this process, and its hosts', is never
         * charged to it. */
        double left = limits.cpu_seconds - (children_cpu() - grader_used);
        lim->cpu_seconds = left > 1 ? left : 1;
    }
}

int sw_plugin_grader_open(void) { return grader_open; }

double sw_plugin_cpu_limit(void) { return limits.cpu_seconds; }

double sw_plugin_own_cpu(void)
{
    return (grader_open ? grader_from : children_cpu()) - grader_used;
}

void sw_plugin_set_timeout(double seconds)
{
    if (seconds > 0 && isfinite(seconds))
        timeout_seconds = seconds;
}

double sw_plugin_timeout(void)
{
    if (timeout_seconds > 0)
        return timeout_seconds;
    const char *env = getenv("STEPWISE_PLUGIN_TIMEOUT");
    double v;
    if (env && sw_parse_double(env, &v) == SW_OK && v > 0 && v <= 3600)
        return v;
    return SW_PLUGIN_TIMEOUT;
}

sw_plugin_entry *sw_plugin_entry_for(const sw_integrator *m)
{
    if (!m || !(m->flags & SW_PLUGIN))
        return NULL;
    for (int i = 0; i < nentries; i++)
        if (strcmp(entries[i].name, m->name) == 0)
            return &entries[i];
    return NULL;
}

/* The host program: beside this program (a build tree's stepwise, or
 * build/ under it), in PREFIX/libexec/stepwise, or STEPWISE_PLUGIN_HOST. */
#define HOST_NAME "stepwise-plugin-host"
static int host_fd = -1;
static char host_path[4096];

static int try_host(const char *dir, const char *sub)
{
    if ((size_t)snprintf(host_path, sizeof host_path, "%s%s" HOST_NAME, dir, sub) >= sizeof host_path)
        return -1;
    host_fd = open(host_path, O_RDONLY | O_CLOEXEC);
    return host_fd;
}

int sw_plugin_host_fd(char *err, size_t errlen)
{
    if (host_fd >= 0)
        return host_fd;
    const char *env = getenv("STEPWISE_PLUGIN_HOST");
    if (env && *env) {
        snprintf(host_path, sizeof host_path, "%s", env);
        host_fd = open(host_path, O_RDONLY | O_CLOEXEC);
    } else {
        char exe[4096];
        ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) {
            exe[n] = '\0';
            char *slash = strrchr(exe, '/');
            if (slash)
                slash[1] = '\0';
            if (try_host(exe, "") < 0 && try_host(exe, "build/") < 0)
                try_host(exe, "../libexec/stepwise/");
        }
        if (host_fd < 0)
            try_host(SW_LIBEXECDIR "/", "");
    }
    if (host_fd < 0)
        snprintf(err, errlen, "the plugin host (" HOST_NAME ") is missing: build it with make, or install "
                 "stepwise (make install) to put it in " SW_LIBEXECDIR);
    return host_fd;
}

const char *sw_plugin_host_path(void) { return host_path; }

sw_plugin_entry *sw_plugin_entry_next(void)
{
    return nentries < SW_PLUGIN_MAX ? &entries[nentries] : NULL;
}

void sw_plugin_entry_commit(void) { nentries++; }

sw_plugin_entry *sw_plugin_entry_at(int i) { return i >= 0 && i < nentries ? &entries[i] : NULL; }
