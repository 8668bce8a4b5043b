/* Closing every inherited descriptor in a child process at the cost of a
 * few system calls, not one per possible descriptor. */
#ifndef SW_UTIL_FDS_H
#define SW_UTIL_FDS_H

/* Close every descriptor from `from` up except keep[0..n): close_range
 * (Linux 5.9) between the kept ones; where it is missing, the descriptors
 * /proc/self/fd lists; without /proc, each one below RLIMIT_NOFILE (at
 * most 65536). For a child after fork (the program is single-threaded). */
void sw_close_fds(int from, const int *keep, int n);
/* The same by one way only, for tests: 0 close_range, 1 /proc/self/fd,
 * 2 each descriptor in turn; 0, or -1 when that way is not available. */
int sw_close_fds_by(int way, int from, const int *keep, int n);

#endif
