/* The lesson's arena: chunks that never move, so every string and array a
 * parsed lesson points to stays valid until sw_lesson_free. */
#include "lesson/parse.h"

#include <stdlib.h>
#include <string.h>

struct sw_lesson_chunk {
    struct sw_lesson_chunk *next;
    size_t used, cap;
    max_align_t data[];
};

void *sw_lp_alloc(sw_lesson *l, size_t n)
{
    size_t a = _Alignof(max_align_t);
    n = (n + a - 1) / a * a;
    struct sw_lesson_chunk *c = l->mem;
    if (!c || c->cap - c->used < n) {
        size_t cap = n > 16384 ? n : 16384;
        c = malloc(sizeof *c + cap);
        if (!c)
            return NULL;
        c->next = l->mem;
        c->used = 0;
        c->cap = cap;
        l->mem = c;
    }
    void *p = (char *)c->data + c->used;
    c->used += n;
    return p;
}

char *sw_lp_strdup(sw_lesson *l, const char *s, size_t len)
{
    char *d = sw_lp_alloc(l, len + 1);
    if (d) {
        memcpy(d, s, len);
        d[len] = '\0';
    }
    return d;
}

void sw_lesson_free(sw_lesson *lesson)
{
    if (!lesson)
        return;
    struct sw_lesson_chunk *c = lesson->mem;
    while (c) {
        struct sw_lesson_chunk *next = c->next;
        free(c);
        c = next;
    }
    free(lesson->pages);
    memset(lesson, 0, sizeof *lesson);
}
