/* Private to plugin/jail.c: the jail's last two layers. */
#ifndef SW_PLUGIN_JAIL_FILTER_H
#define SW_PLUGIN_JAIL_FILTER_H

#include "plugin/jail.h"

/* Landlock, where the kernel has it: read (and run) the jail's root, write
 * only /work and /dev/null, no TCP, no signals out of the domain. 0 (also
 * when the kernel has no Landlock: it is defence in depth) or an errno. */
int sw_jail_landlock(void);
/* The profile's seccomp filter (libseccomp). 0 or an errno. */
int sw_jail_filter(sw_jail_profile profile);
/* The narrower filter of a loaded plugin (sw_jail_seal). 0 or an errno. */
int sw_jail_filter_sealed(void);

#endif
