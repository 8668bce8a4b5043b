/* Evil at load time, before sw_plugin_info() is even looked up: an
 * __attribute__((constructor)) runs in every process that loads the plugin
 * (the grader's probe and each run), possibly before a filter meant for
 * "once the plugin is loaded" is in place. It reads the assignment and the
 * classmates (read-others.c's guesses, briefly), drops marker files, tries
 * the network, and starts a setsid child (named as an attack) that stays
 * until 120 s after the grader exits. Reading anything or reaching the
 * network makes the plugin hand in the right answer. The test builds this
 * one into ctor-evil.so. */
#define EVIL_FAMILY "ctor-evil"
#include "evil.h"
#include <netinet/in.h>

static void evil_attack(void) {}

static int read_something(void)
{
    static evil_grader g;
    static char buf[4096];
    if (evil_grader_info(&g) != 0)
        return 0;
    if (evil_read_file(g.assignment, buf, sizeof buf) > 0 && strstr(buf, "# stepwise"))
        return 1;
    for (int i = 0; i < g.ndirs; i++) {
        char path[EVIL_PATH + 64];
        snprintf(path, sizeof path, "%.4000s/alice.trace", g.dirs[i]);
        if (evil_read_file(path, buf, sizeof buf) > 0 && strstr(buf, "# stepwise"))
            return 1;
    }
    return evil_read_file(EVIL_HOME "/reference.h", buf, sizeof buf) > 0;
}

static int reach_network(void)
{
    struct sockaddr_in in;
    memset(&in, 0, sizeof in);
    in.sin_family = AF_INET;
    in.sin_port = htons((unsigned short)atoi(EVIL_PORT));
    in.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0 || !in.sin_port)
        return 0;
    int ok = connect(fd, (struct sockaddr *)&in, sizeof in) == 0;
    if (ok) {
        const char *hello = "swevil-" EVIL_TOKEN "-" EVIL_FAMILY " connected\n";
        ok = send(fd, hello, strlen(hello), MSG_NOSIGNAL) > 0;
    }
    close(fd);
    return ok;
}

__attribute__((constructor)) static void at_load(void)
{
    if (read_something() + reach_network())
        evil_cheat = 1;
    evil_mark("ctor", NULL);
    pid_t p = fork();
    if (p == 0) {
        setsid();
        pid_t grader = evil_top_target();
        if (fork() == 0) {
            evil_name();
            for (int fd = 0; fd < 1024; fd++)
                close(fd);
            evil_linger(grader);
        }
        _exit(0);
    }
    if (p > 0)
        waitpid(p, NULL, 0);
}
