/* --plugin PATH for every subcommand: a shared object loaded as is, a C
 * source built first (plugin/plugin_build.c) into a private temporary
 * directory removed when stepwise ends, however it ends (util/tmpdir.h: at
 * exit, or by a watcher after a signal or a crash). */
#include "cli/cli.h"

#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "plugin/plugin.h"
#include "plugin/plugin_build.h"
#include "util/tmpdir.h"

static char build_dir[PATH_MAX];
static pid_t build_dir_owner;

/* The plugin layer's message names the file; the flag, where one was
 * typed, goes before it: "--plugin 'x.c' does not compile ...". */
static int plugin_error(const char *flag, const char *err)
{
    return sw_cli_error("%s%s%s", flag, *flag ? " " : "", err);
}

/* Compile a plugin's C source with the documented flags into a private
 * temporary directory (removed at exit); the .so's path into so. */
static int sw_cli_build_plugin(const char *flag, const char *src, char *so, size_t solen,
                               sw_build_warnings *warn)
{
    static int count;
    char err[SW_ERRLEN + 256], name[16];
    if (!build_dir[0] || build_dir_owner != getpid()) {
        if (sw_tmpdir_make("plugins", build_dir, sizeof build_dir, err, sizeof err) != SW_OK) {
            build_dir[0] = '\0';
            return sw_cli_error("%s%s%s", flag, *flag ? ": " : "", err);
        }
        build_dir_owner = getpid();
        count = 0;
    }
    if (count == 64)
        return sw_cli_error("%s%sat most 64 plugins are built per run", flag, *flag ? ": " : "");
    snprintf(name, sizeof name, "p%d", count++);
    if (sw_plugin_compile(src, NULL, 0, build_dir, name, so, solen, warn, err, sizeof err) != SW_OK)
        return plugin_error(flag, err);
    return SW_EXIT_OK;
}


int sw_cli_plugin(const char *flag, const char *path, sw_build_warnings *warn)
{
    char err[SW_ERRLEN + 256], so[4200];
    const char *given = path;
    size_t len = strlen(path);
    if (len > 2 && strcmp(path + len - 2, ".c") == 0) {
        if (sw_cli_build_plugin(flag, path, so, sizeof so, warn) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
        path = so;
    }
    if (sw_plugin_load(path, given, NULL, err, sizeof err) != SW_OK)
        return plugin_error(flag, err);
    return SW_EXIT_OK;
}
