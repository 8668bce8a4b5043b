/* The library's version at run time, for a program that checks the
 * headers it was built with (SW_VERSION) against the library it links. */
#include "stepwise/base.h"

const char *sw_version(void) { return SW_VERSION; }
