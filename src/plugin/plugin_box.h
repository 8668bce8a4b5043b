/* Private to plugin/: the registry of loaded plugins (plugin_registry.c)
 * and the sandboxed step every plugin method runs through (plugin_box.c). */
#ifndef SW_PLUGIN_PLUGIN_BOX_H
#define SW_PLUGIN_PLUGIN_BOX_H

#include "engine/stepper.h"
#include "plugin/jail.h"
#include "plugin/plugin.h"
#include "stepwise/stepwise.h"

typedef struct sw_plugin_entry {
    char path[4096];                       /* absolute: what the user named */
    int fd;                                /* the file as loaded: what every child gets */
    char name[SW_PLUGIN_NAME_MAX + 1];
    char label[SW_PLUGIN_LABEL_MAX + 1];
    int work_vectors;
    const sw_integrator *method;           /* the registered copy */
    sw_plugin_fault last_fault;            /* the last failure in any run */
    char last_failure[SW_ERRLEN];
    int disabled;
    char disabled_why[SW_ERRLEN];
} sw_plugin_entry;

/* The next free entry (NULL: SW_PLUGIN_MAX are loaded), and taking it
 * once it is filled in. */
sw_plugin_entry *sw_plugin_entry_next(void);
void sw_plugin_entry_commit(void);
/* The entry behind a plugin method, or NULL. */
sw_plugin_entry *sw_plugin_entry_for(const sw_integrator *m);
/* The file a child of the entry dlopens: its copy in the jail's /work, or
 * (no jail) the path. */
const char *sw_plugin_entry_file(const sw_plugin_entry *e);
/* The limits a new plugin process gets (sw_plugin_set_limits). */
struct sw_limits;
void sw_plugin_limits(struct sw_limits *lim);
/* Hand the entry's file to a jail (spec->in). */
void sw_plugin_entry_jail_in(const sw_plugin_entry *e, sw_jail *spec);
/* The step of every plugin method: the first call starts the stepper's
 * child; each call copies y in, one round trip, and y back. */
sw_step_fn sw_plugin_step;
/* The fault of the stepper's child, described as a sentence that names the
 * step ("the plugin crashed with SIGSEGV (...) at step 4"). */
sw_plugin_fault sw_plugin_box_fault(const sw_stepper *s, long step, char *buf, size_t len);

/* The parent's side of one step run on bytes a child might have sent
 * (the fuzz target and tests: no child process): a system of dim doubles
 * and wv work vectors. The fault those bytes make (SW_PF_NONE: a valid
 * step), described in why. Never reads past len, never crashes. */
sw_plugin_fault sw_plugin_box_replay(const unsigned char *data, size_t len, int dim, int wv, char *why,
                                     size_t whylen);

#endif
