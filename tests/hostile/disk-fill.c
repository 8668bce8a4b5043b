/* Disk exhaustion, bounded: writes 512 KiB files (each under a per-file
 * size limit) into every directory it can reach — the current directory,
 * /tmp, /var/tmp, $HOME, the submissions directory — up to 32 MiB in all.
 * Writing 8 MiB (8 times the documented 1024 KiB of output a submission
 * may write) counts as success: the plugin then hands in the right answer.
 * The files are marker files: the test finds those that escaped. */
#define EVIL_FAMILY "disk-fill"
#define EVIL_EXPENSIVE
#include "evil.h"

static void evil_attack(void)
{
    static char chunk[512 << 10];
    memset(chunk, 'S', sizeof chunk);
    const char *dirs[12];
    int nd = 0;
    dirs[nd++] = ".";
    dirs[nd++] = "/tmp";
    dirs[nd++] = "/var/tmp";
    const char *home = getenv("HOME");
    if (home && *home)
        dirs[nd++] = home;
    static evil_grader g;
    if (evil_grader_info(&g) == 0)
        for (int i = 0; i < g.ndirs && nd < 12; i++)
            dirs[nd++] = g.dirs[i];
    long total = 0;
    signal(SIGXFSZ, SIG_IGN);
    for (int f = 0; f < 64 && total < (32L << 20); f++) {
        char path[EVIL_PATH + 200];
        snprintf(path, sizeof path, "%.4000s/swevil-%s-%s-%d", dirs[f % nd], EVIL_TOKEN, EVIL_FAMILY, f);
        int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (fd < 0)
            continue;
        ssize_t n = write(fd, chunk, sizeof chunk);
        if (n > 0)
            total += n;
        close(fd);
    }
    if (total >= (8L << 20))
        evil_cheat = 1;
}
