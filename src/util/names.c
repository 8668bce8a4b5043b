/* Name lists. Invariant: every join is bounded by the caller's buffer and
 * ends in a NUL, however many names there are. */
#include "util/names.h"

#include <stdio.h>
#include <string.h>

size_t sw_names_join(char *buf, size_t len, sw_name_at_fn *at, const void *ctx, int n)
{
    size_t used = 0;
    if (!len)
        return 0;
    buf[0] = '\0';
    for (int i = 0; i < n && used + 1 < len; i++) {
        int w = snprintf(buf + used, len - used, "%s%s", i ? ", " : "", at(ctx, i));
        if (w < 0)
            break;
        used += (size_t)w < len - used ? (size_t)w : len - used - 1;
    }
    return used;
}

int sw_names_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 40 || lb > 40)
        return 99;
    int row[41];
    for (size_t j = 0; j <= lb; j++)
        row[j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        int diag = row[0];
        row[0] = (int)i;
        for (size_t j = 1; j <= lb; j++) {
            int up = row[j];
            int best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best)
                best = up + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[lb];
}

const char *sw_names_nearest(const char *word, sw_name_at_fn *at, const void *ctx, int n)
{
    const char *best = NULL;
    int bestd = 3;
    for (int i = 0; i < n; i++) {
        int d = sw_names_distance(word, at(ctx, i));
        if (d < bestd) {
            bestd = d;
            best = at(ctx, i);
        }
    }
    return best && bestd < (int)strlen(word) ? best : NULL;
}
