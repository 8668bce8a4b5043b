/* SipHash-2-4 (Aumasson and Bernstein, "SipHash: a fast short-input PRF",
 * 2012): a 64-bit keyed hash of msg under the 128-bit key k (k[0] the
 * first eight key bytes, little-endian). Portable: the same value on every
 * machine. */
#ifndef SW_UTIL_SIPHASH_H
#define SW_UTIL_SIPHASH_H

#include <stddef.h>
#include <stdint.h>

uint64_t sw_siphash24(const unsigned long long k[2], const unsigned char *msg, size_t len);

#endif
