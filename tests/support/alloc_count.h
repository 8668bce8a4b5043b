/* Allocation counter for tests (see alloc_count.c). */
#ifndef SW_ALLOC_COUNT_H
#define SW_ALLOC_COUNT_H

#include <stddef.h>

/* malloc + calloc + realloc calls from linked objects so far. */
long sw_test_allocations(void);
/* Bytes those calls asked for so far (a realloc counts its new size). */
size_t sw_test_allocated_bytes(void);

#endif
