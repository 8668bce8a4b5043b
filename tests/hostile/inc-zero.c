/* A compiler that reads forever: /dev/zero as a header (an endless run of
 * NUL bytes, memory and CPU for the compiler). The row must come within
 * the limits, and no compiler may outlive grade. */
#include "/dev/zero"
