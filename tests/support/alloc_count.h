/* Allocation counter for tests (see alloc_count.c). */
#ifndef SW_ALLOC_COUNT_H
#define SW_ALLOC_COUNT_H

/* malloc + calloc + realloc calls from linked objects so far. */
long sw_test_allocations(void);

#endif
