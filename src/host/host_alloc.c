/* The plugin host's allocator watch: this program defines malloc and its
 * relatives, so the plugin's calls (and the C library's) come here first
 * and go on to the C library's own, found with dlsym(RTLD_NEXT). While a
 * step runs, any allocation is noted: "a step must not allocate" is
 * checked, not only asked. While the C library's allocator is being looked
 * up, requests are served from a small static pool. */
#define _GNU_SOURCE /* RTLD_NEXT */
#include "host/host.h"

#include <dlfcn.h>
#include <errno.h>
#include <malloc.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

volatile int sw_host_in_step;
volatile int sw_host_allocated;

static void *(*real_malloc)(size_t);
static void *(*real_calloc)(size_t, size_t);
static void *(*real_realloc)(void *, size_t);
static void (*real_free)(void *);
static void *(*real_memalign)(size_t, size_t);
static int resolving;

static _Alignas(max_align_t) unsigned char boot[8192];
static size_t boot_used;

static int from_boot(const void *p)
{
    return (const unsigned char *)p >= boot && (const unsigned char *)p < boot + sizeof boot;
}

static void *boot_alloc(size_t n)
{
    size_t a = (n + 15) & ~(size_t)15;
    if (a > sizeof boot - boot_used)
        return NULL;
    void *p = boot + boot_used;
    boot_used += a;
    return p;
}

static void resolve(void)
{
    resolving = 1;
    *(void **)&real_malloc = dlsym(RTLD_NEXT, "malloc");
    *(void **)&real_calloc = dlsym(RTLD_NEXT, "calloc");
    *(void **)&real_realloc = dlsym(RTLD_NEXT, "realloc");
    *(void **)&real_free = dlsym(RTLD_NEXT, "free");
    *(void **)&real_memalign = dlsym(RTLD_NEXT, "memalign");
    resolving = 0;
}

static int ready(void)
{
    if (!real_malloc && !resolving)
        resolve();
    if (sw_host_in_step)
        sw_host_allocated = 1;
    return real_malloc && real_calloc && real_realloc && real_free && real_memalign;
}

void *malloc(size_t n)
{
    return ready() ? real_malloc(n) : boot_alloc(n);
}

void *calloc(size_t n, size_t size)
{
    if (!ready()) {
        if (size && n > SIZE_MAX / size)
            return NULL;
        return boot_alloc(n * size); /* static: zeroed */
    }
    return real_calloc(n, size);
}

void *realloc(void *p, size_t n)
{
    if (!ready() || from_boot(p)) {
        void *q = ready() ? real_malloc(n) : boot_alloc(n);
        if (q && p) {
            size_t room = (size_t)(boot + sizeof boot - (unsigned char *)p);
            memcpy(q, p, n < room ? n : room);
        }
        return q;
    }
    return real_realloc(p, n);
}

void free(void *p)
{
    if (!p || from_boot(p))
        return;
    if (real_free)
        real_free(p);
}

void *memalign(size_t align, size_t n)
{
    return ready() ? real_memalign(align, n) : NULL;
}

void *aligned_alloc(size_t align, size_t n) { return memalign(align, n); }

int posix_memalign(void **out, size_t align, size_t n)
{
    if (align < sizeof(void *) || (align & (align - 1)))
        return EINVAL;
    void *p = memalign(align, n);
    if (!p)
        return ENOMEM;
    *out = p;
    return 0;
}

void *valloc(size_t n) { return memalign(4096, n); }
void *pvalloc(size_t n) { return memalign(4096, (n + 4095) & ~(size_t)4095); }
