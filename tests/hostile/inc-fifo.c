/* A compiler that never ends: pipe.h beside this file is a FIFO nobody
 * writes (the test makes it), so the compiler blocks opening it. The row
 * must come within the limits, and no compiler may outlive grade. */
#include "pipe.h"
