/* --plugin PATH for every subcommand: a shared object loaded as is, a C
 * source built first (plugin_build.c). Apart from common.c so that the
 * helpers the builder uses never call back into it. */
#include "cli/cli.h"

#include <string.h>

#include "plugin/plugin.h"

int sw_cli_plugin(const char *path)
{
    char err[SW_ERRLEN + 256], so[4200];
    const char *given = path;
    size_t len = strlen(path);
    if (len > 2 && strcmp(path + len - 2, ".c") == 0) {
        if (sw_cli_build_plugin(path, so, sizeof so) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
        path = so;
    }
    if (sw_plugin_load(path, given, NULL, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    return SW_EXIT_OK;
}
