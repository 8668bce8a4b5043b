/* The registry of loaded plugins and the limits their processes get: what
 * loading (plugin.c) and stepping (plugin_box.c) both look up, below both,
 * so neither calls the other back. */
#include "plugin/plugin_box.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

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

void sw_plugin_limits(sw_limits *lim)
{
    *lim = limits;
    if (limits.cpu_seconds > 0) {
        /* every plugin process ends in this process's children's account */
        struct rusage self, kids;
        getrusage(RUSAGE_SELF, &self);
        getrusage(RUSAGE_CHILDREN, &kids);
        double used = seconds_of(self.ru_utime) + seconds_of(self.ru_stime) + seconds_of(kids.ru_utime) +
                      seconds_of(kids.ru_stime);
        double left = limits.cpu_seconds - used;
        lim->cpu_seconds = left > 1 ? left : 1;
    }
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

#define JAIL_NAME "plugin.so"

const char *sw_plugin_entry_file(const sw_plugin_entry *e)
{
    return sw_jail_enabled() ? "/work/" JAIL_NAME : e->path;
}

void sw_plugin_entry_jail_in(const sw_plugin_entry *e, sw_jail *spec)
{
    spec->in[0].fd = e->fd;
    spec->in[0].name = JAIL_NAME;
    spec->nin = 1;
}

sw_plugin_entry *sw_plugin_entry_next(void)
{
    return nentries < SW_PLUGIN_MAX ? &entries[nentries] : NULL;
}

void sw_plugin_entry_commit(void) { nentries++; }
