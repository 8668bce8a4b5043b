/* Private temporary directories ($TMPDIR/stepwise-KIND-XXXXXX, mode 0700)
 * that go away however the process that made them ends: removed on request,
 * at exit, and — after a signal, SIGKILL or a crash, when no exit code runs —
 * by a watcher process that waits for its maker to end and then removes it. */
#ifndef SW_UTIL_TMPDIR_H
#define SW_UTIL_TMPDIR_H

#include <stddef.h>

/* Make a directory for KIND (a short word: "grade", "plugins") and start
 * its watcher; dir gets the path. Removed at exit (atexit, by the process
 * that made it only: forked children leave it alone). 0, or SW_EIO with err
 * filled. */
int sw_tmpdir_make(const char *kind, char *dir, size_t len, char *err, size_t errlen);

/* Remove dir and everything under it now, never following a symbolic link
 * (a link is removed, not its target). Safe on a missing directory and
 * when called twice. Returns 0, or -1 when something could not be removed. */
int sw_tmpdir_remove(const char *dir);

#endif
