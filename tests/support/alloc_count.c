/* Counts the allocations made by code linked into the test binary: the
 * Makefile links tests with -Wl,--wrap=malloc,calloc,realloc, so every call
 * from our static library lands here first. Used to prove step loops
 * allocate nothing (counted, not assumed). */
#include <stddef.h>

#include "alloc_count.h"

void *__real_malloc(size_t size);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t size);
void *__wrap_malloc(size_t size);
void *__wrap_calloc(size_t n, size_t size);
void *__wrap_realloc(void *p, size_t size);

static long count;
static size_t bytes;

void *__wrap_malloc(size_t size)
{
    count++;
    bytes += size;
    return __real_malloc(size);
}

void *__wrap_calloc(size_t n, size_t size)
{
    count++;
    bytes += n * size;
    return __real_calloc(n, size);
}

void *__wrap_realloc(void *p, size_t size)
{
    count++;
    bytes += size;
    return __real_realloc(p, size);
}

long sw_test_allocations(void) { return count; }

size_t sw_test_allocated_bytes(void) { return bytes; }
