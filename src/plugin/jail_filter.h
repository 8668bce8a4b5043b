/* Private to plugin/jail.c and the plugin host: the jail's last two layers. */
#ifndef SW_PLUGIN_JAIL_FILTER_H
#define SW_PLUGIN_JAIL_FILTER_H

#include "plugin/jail.h"

/* Landlock, where the kernel has it: read (and run) the jail's root, write
 * only /work and /dev/null, no TCP, no signals out of the domain. 0 (also
 * when the kernel has no Landlock: with namespaces it is defence in depth,
 * and the jail of a user of its own is not built without it) or an errno. */
int sw_jail_landlock(void);
/* Landlock for a plugin's host: read (and run) only beneath read_dirs,
 * write only /dev/null. 0 or an errno, as above. */
int sw_jail_landlock_read(const char *const *read_dirs, int nread);
/* The general form: read (and run) beneath read_dirs, everything beneath
 * full, and /dev/null. */
int sw_jail_landlock_rules(const char *const *read_dirs, int nread, const char *const *full, int nfull);
/* The profile's seccomp filter (libseccomp): for COMPUTE, what loading a
 * plugin and stepping need and no seccomp() (the plugin's host installs
 * it on itself); for COMPILE, a deny-list. 0 or an errno. */
int sw_jail_filter(sw_jail_profile profile);

#endif
