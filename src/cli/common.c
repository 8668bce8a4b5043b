/* Helpers every subcommand shares: error messages that name what is allowed,
 * lookups by name, number parsing for flags, and run options. */
#include "cli/cli.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "trace/trace.h"
#include "util/beside.h"
#include "util/escape.h"
#include "util/num.h"

/* One line of printable text, whatever the arguments held (a newline or an
 * escape sequence in a name, a path, a value typed). */
static void say(const char *fmt, va_list ap)
{
    char msg[2048];
    vsnprintf(msg, sizeof msg, fmt, ap);
    sw_escape_message(msg, sizeof msg);
    fprintf(stderr, "stepwise: %s\n", msg);
}

int sw_cli_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say(fmt, ap);
    va_end(ap);
    return SW_EXIT_USAGE;
}

void sw_cli_note(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say(fmt, ap);
    va_end(ap);
}

void sw_cli_warn_public_secret(const char *assignment)
{
    sw_cli_note("warning: %s: its '# secret:' is the examples' words, which anyone can read: every "
                "student's values can be drawn from them (write words of your own, and hand the sheets out "
                "again)", assignment);
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

int sw_cli_range(const char *flag, const char *text, double min, double max, const char *unit,
                 double *out)
{
    double v;
    if (sw_parse_double(text, &v) != SW_OK || !(v >= min && v <= max))
        return sw_cli_error("%s '%.40s' is not allowed: %s must be between %.15g and %.15g%s%s",
                            flag, text, flag, min, max, unit && *unit ? " " : "", unit ? unit : "");
    *out = v;
    return SW_EXIT_OK;
}

int sw_cli_tolerance(const char *flag, const char *text, double *out)
{
    double v;
    if (sw_parse_double(text, &v) != SW_OK || !(v >= SW_TRACE_TOL_MIN && v <= 1))
        return sw_cli_error("%s '%.40s' is not allowed: a tolerance is a number in [%g, 1] (below "
                            "%g no double-precision run can meet it)", flag, text, SW_TRACE_TOL_MIN,
                            SW_TRACE_TOL_MIN);
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

int sw_cli_events(const char *text, sw_events_mode *out)
{
    char err[SW_ERRLEN];
    if (sw_events_mode_parse(text, out, err, sizeof err) != SW_OK)
        return sw_cli_error("--events: %s", err);
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
        o->dt = sw_scene_dt(o->scene, o->p);
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
    if (sw_sim_set_events(s, o->events, err, sizeof err) != SW_OK) {
        sw_sim_free(s);
        return sw_cli_error("%s", err);
    }
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
    if (sw_beside_binary("lessons", has_lessons, dir, sizeof dir))
        return dir;
    if (has_lessons("lessons"))
        return "lessons";
    return SW_DATADIR "/lessons";
}
