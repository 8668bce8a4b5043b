/* NAME=VALUE splitting with one whitespace rule for every caller. */
#include "util/kv.h"

static int blank(char c) { return c == ' ' || c == '\t'; }

int sw_kv_next(const char *s, size_t len, size_t pos, sw_kv *kv)
{
    size_t i = pos;
    while (i < len && blank(s[i]))
        i++;
    if (i >= len)
        return 0;
    kv->name_at = i;
    while (i < len && s[i] != '=' && !blank(s[i]))
        i++;
    kv->name_len = i - kv->name_at;
    while (i < len && blank(s[i]))
        i++;
    kv->eq_at = i;
    kv->value_at = kv->value_len = 0;
    kv->end = i;
    if (i >= len || s[i] != '=')
        return -1;
    i++;
    while (i < len && blank(s[i]))
        i++;
    kv->value_at = i;
    while (i < len && !blank(s[i]))
        i++;
    kv->value_len = i - kv->value_at;
    kv->end = i;
    return 1;
}
