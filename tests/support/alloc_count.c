/* Counts the allocations made by code linked into the test binary: the
 * Makefile links tests with -Wl,--wrap=malloc,calloc,realloc, so every call
 * from our static library lands here first. Used to prove step loops
 * allocate nothing (counted, not assumed). The counters are atomic: the
 * app's workers (the w sweep, a Δt measurement) allocate on threads of
 * their own. */
#include <stdatomic.h>
#include <stddef.h>

#include "alloc_count.h"

void *__real_malloc(size_t size);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t size);
void *__wrap_malloc(size_t size);
void *__wrap_calloc(size_t n, size_t size);
void *__wrap_realloc(void *p, size_t size);

static atomic_long count;
static atomic_size_t bytes;

void *__wrap_malloc(size_t size)
{
    atomic_fetch_add_explicit(&count, 1, memory_order_relaxed);
    atomic_fetch_add_explicit(&bytes, size, memory_order_relaxed);
    return __real_malloc(size);
}

void *__wrap_calloc(size_t n, size_t size)
{
    atomic_fetch_add_explicit(&count, 1, memory_order_relaxed);
    atomic_fetch_add_explicit(&bytes, n * size, memory_order_relaxed);
    return __real_calloc(n, size);
}

void *__wrap_realloc(void *p, size_t size)
{
    atomic_fetch_add_explicit(&count, 1, memory_order_relaxed);
    atomic_fetch_add_explicit(&bytes, size, memory_order_relaxed);
    return __real_realloc(p, size);
}

long sw_test_allocations(void) { return atomic_load(&count); }

size_t sw_test_allocated_bytes(void) { return atomic_load(&bytes); }
