/* Helpers every subcommand shares: error messages that name what is allowed,
 * lookups by name, number parsing for flags, and run options. */
#include "cli/cli.h"

#include <dirent.h>
#include <errno.h>
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "engine/stepper.h"
#include "util/num.h"

int sw_cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("stepwise: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return SW_EXIT_USAGE;
}

int sw_cli_flush_stdout(void)
{
    errno = 0;
    if (fflush(stdout) == 0 && !ferror(stdout))
        return SW_EXIT_OK;
    int e = errno;
    clearerr(stdout); /* reported once */
    return sw_cli_error("cannot write standard output: %s", e ? strerror(e) : "write error");
}

int sw_cli_scene(const char *name, const sw_scene **out)
{
    *out = sw_scene_find(name);
    if (*out)
        return SW_EXIT_OK;
    char names[400];
    sw_scene_names(names, sizeof names);
    return sw_cli_error("unknown scene '%.60s'; scenes: %s", name, names);
}

int sw_cli_integrator(const char *name, const sw_integrator **out)
{
    *out = sw_integrator_find(name);
    if (*out)
        return SW_EXIT_OK;
    char names[400];
    sw_integrator_names(names, sizeof names);
    return sw_cli_error("unknown integrator '%.60s'; integrators: %s", name, names);
}

int sw_cli_dt(const char *flag, const char *text, double *out)
{
    double v;
    if (sw_parse_double(text, &v) != SW_OK || !(v >= SW_DT_MIN && v <= SW_DT_MAX))
        return sw_cli_error("%s '%.40s' is not allowed: the step must be a number in [%g, %g]",
                            flag, text, SW_DT_MIN, SW_DT_MAX);
    *out = v;
    return SW_EXIT_OK;
}

int sw_cli_positive(const char *flag, const char *text, double *out)
{
    double v;
    if (sw_parse_double(text, &v) != SW_OK || !(v > 0))
        return sw_cli_error("%s '%.40s' is not allowed: it takes a positive finite number", flag, text);
    *out = v;
    return SW_EXIT_OK;
}

int sw_cli_long(const char *flag, const char *text, long min, long max, long *out)
{
    if (sw_parse_long(text, min, max, out) != SW_OK)
        return sw_cli_error("%s '%.40s' is not allowed: it takes a whole number in [%ld, %ld]",
                            flag, text, min, max);
    return SW_EXIT_OK;
}

int sw_cli_add_set(sw_run_opts *o, const char *assignment)
{
    if (o->nsets == (int)(sizeof o->sets / sizeof o->sets[0]))
        return sw_cli_error("too many --set options (at most %d)", (int)(sizeof o->sets / sizeof o->sets[0]));
    o->sets[o->nsets++] = assignment;
    return SW_EXIT_OK;
}

int sw_cli_finish_opts(sw_run_opts *o)
{
    char err[SW_ERRLEN];
    sw_scene_defaults(o->scene, o->p);
    for (int i = 0; i < o->nsets; i++)
        if (sw_scene_set(o->scene, o->p, o->sets[i], err, sizeof err) != SW_OK)
            return sw_cli_error("%s", err);
    if (!o->method)
        o->method = sw_integrator_find(o->scene->integrator);
    if (!(o->dt > 0))
        o->dt = o->scene->dt;
    if (!(o->rtol > 0))
        o->rtol = SW_RTOL_DEFAULT;
    if (!(o->atol > 0))
        o->atol = SW_ATOL_DEFAULT;
    return SW_EXIT_OK;
}

int sw_cli_sim(sw_sim *s, const sw_run_opts *o)
{
    char err[SW_ERRLEN];
    if (sw_sim_init(s, o->scene, o->p, o->method, o->dt, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    sw_sim_set_tolerances(s, o->rtol, o->atol);
    return SW_EXIT_OK;
}

/* Loaded plugins, found again by method name: the registry keeps a copy of
 * the sw_integrator (not a pointer to it) and sw_stepper_init leaves
 * s->plugin NULL, so the step looks its plugin up on first use. */
static const sw_plugin *plugin_infos[8];
static int nplugin_infos;

static const sw_plugin *plugin_for(const sw_integrator *m)
{
    for (int i = 0; i < nplugin_infos; i++)
        if (strcmp(plugin_infos[i]->name, m->name) == 0)
            return plugin_infos[i];
    return NULL;
}

/* A plugin's step function behind the built-in step signature. */
static int plugin_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    if (!s->plugin)
        s->plugin = (void *)plugin_for(s->method);
    const sw_plugin *info = s->plugin;
    if (!info)
        return SW_EINVAL;
    int rc = info->step(ode, *t, y, h, s->work);
    *t += h;
    return rc == 0 ? SW_OK : SW_EDIVERGED;
}

int sw_cli_plugin(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return sw_cli_error("--plugin '%.200s': no such file (give the path to a .so built from "
                            "examples/euler_plugin.c)", path);
    /* dlopen searches the library path for bare names; a path with a slash is taken as is. */
    char full[4096];
    snprintf(full, sizeof full, "%s%s", strchr(path, '/') ? "" : "./", path);
    void *lib = dlopen(full, RTLD_NOW | RTLD_LOCAL);
    if (!lib)
        return sw_cli_error("--plugin '%.200s' could not be loaded: %s", path, dlerror());
    const sw_plugin *(*get)(void);
    *(void **)&get = dlsym(lib, "sw_plugin_info");
    if (!get)
        return sw_cli_error("--plugin '%.200s' has no sw_plugin_info symbol; a plugin must define "
                            "const sw_plugin *sw_plugin_info(void)", path);
    const sw_plugin *info = get();
    if (!info || info->abi != SW_PLUGIN_ABI)
        return sw_cli_error("--plugin '%.200s' was built for plugin interface %d; this stepwise "
                            "needs %d (rebuild it against this stepwise's integrator.h)",
                            path, info ? info->abi : -1, SW_PLUGIN_ABI);
    if (!info->name || !*info->name || !info->step || info->work_vectors < 0 || info->work_vectors > 64)
        return sw_cli_error("--plugin '%.200s': sw_plugin_info() must give a name, a step function "
                            "and 0..64 work vectors", path);
    static sw_integrator methods[8];
    static int nmethods;
    if (nmethods == 8)
        return sw_cli_error("at most 8 plugins can be loaded");
    sw_integrator *m = &methods[nmethods];
    *m = (sw_integrator){ .name = info->name, .label = info->label ? info->label : info->name,
                          .order = info->order, .evals = info->evals, .flags = SW_PLUGIN | SW_EXPLICIT,
                          .stability = NAN, .work_vectors = info->work_vectors,
                          .step = plugin_step, .summary = "student plugin" };
    char err[SW_ERRLEN];
    if (sw_integrator_register(m, err, sizeof err) != SW_OK)
        return sw_cli_error("--plugin '%.200s': %s", path, err);
    plugin_infos[nplugin_infos++] = info;
    nmethods++;
    return SW_EXIT_OK;
}

/* A directory holding at least one *.lesson file. */
static int has_lessons(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int found = 0;
    for (struct dirent *e; !found && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        found = len > 7 && strcmp(e->d_name + len - 7, ".lesson") == 0;
    }
    closedir(d);
    return found;
}

const char *sw_cli_lessons_dir(void)
{
    static char dir[2100];
    const char *env = getenv("STEPWISE_LESSONS");
    if (env && *env)
        return env;
    /* A build tree: lessons/ beside the binary or a few levels up (build/san/
     * stepwise finds the checkout's lessons); then the working directory;
     * then the installed lessons. */
    char exe[2048];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len > 0) {
        exe[len] = '\0';
        for (int up = 0; up < 4; up++) {
            char *slash = strrchr(exe, '/');
            if (!slash)
                break;
            *slash = '\0';
            snprintf(dir, sizeof dir, "%s/lessons", exe);
            if (has_lessons(dir))
                return dir;
        }
    }
    if (has_lessons("lessons"))
        return "lessons";
    return SW_DATADIR "/lessons";
}
