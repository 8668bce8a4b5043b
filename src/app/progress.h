/* Lesson progress: pages completed per lesson file, kept in
 * $XDG_STATE_HOME/stepwise/progress (default ~/.local/state/stepwise/).
 * One line per lesson, "FILE PAGES"; FILE may hold spaces. */
#ifndef SW_APP_PROGRESS_H
#define SW_APP_PROGRESS_H

#include <stddef.h>

/* Pages completed of a lesson file; 0 when unknown or unreadable (the file
 * is read under the input-file rules: a FIFO, a device or a file of more
 * than 1 MiB is not read at all). */
int sw_progress_get(const char *file);
/* Record pages completed (never lowers it). Concurrent-safe: the update is
 * made under a lock on progress.lock and written through a uniquely named
 * temporary renamed into place, so two instances lose no update. A progress
 * file that cannot be read (sw_progress_readable) is left as it is. 0, or
 * SW_EIO / SW_EINVAL with err saying why. */
int sw_progress_set(const char *file, int done, char *err, size_t errlen);
/* Whether the progress file, when there is one, can be read: 0, or SW_EIO
 * with err naming it and what it is (a FIFO, a device, too large); then
 * every lesson starts at its first page and progress is not saved over it. */
int sw_progress_readable(char *err, size_t errlen);
/* Whether progress can be saved: the state directory exists or can be
 * made. 0, or SW_EIO with err naming the directory and why. */
int sw_progress_check(char *err, size_t errlen);

struct sw_lesson_entry;
/* The first of the n lessons e (the menu's order) not finished, looking from
 * index from on and wrapping round; -1 when every one is done (a lesson that
 * cannot be read is skipped). */
int sw_progress_next(const struct sw_lesson_entry *e, int n, int from);

#endif
