/* Where the running binary is: a directory beside it or a few levels up,
 * read from /proc/self/exe (a build tree's lessons/, include/, src/). */
#include "util/beside.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

int sw_beside_binary(const char *sub, int (*ok)(const char *path), char *out, size_t len)
{
    char exe[2048];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return 0;
    exe[n] = '\0';
    for (int up = 0; up < 4; up++) {
        char *slash = strrchr(exe, '/');
        if (!slash)
            break;
        *slash = '\0';
        snprintf(out, len, "%s/%s", exe, sub);
        if (ok(out))
            return 1;
    }
    return 0;
}
