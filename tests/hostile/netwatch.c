/* The test's listener for network.c and ctor-evil.c (not a submission):
 *
 *     netwatch PORTFILE LOG NAME SECONDS
 *
 * listens on 127.0.0.1 (an ephemeral port, written to PORTFILE once it
 * listens) and on the abstract Unix socket @NAME; appends the first line
 * each connection sends (at most 200 bytes), after "tcp " or "unix ", to
 * LOG; ends after SECONDS. A plugin that reaches either has reached the
 * network (or another network namespace's sockets). */
#define _GNU_SOURCE
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: netwatch PORTFILE LOG NAME SECONDS\n");
        return 2;
    }
    int tcp = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in in;
    memset(&in, 0, sizeof in);
    in.sin_family = AF_INET;
    in.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof in;
    if (tcp < 0 || bind(tcp, (struct sockaddr *)&in, sizeof in) != 0 || listen(tcp, 64) != 0 ||
        getsockname(tcp, (struct sockaddr *)&in, &len) != 0) {
        perror("netwatch: tcp");
        return 1;
    }
    int unx = socket(AF_UNIX, SOCK_STREAM, 0);
    struct sockaddr_un un;
    memset(&un, 0, sizeof un);
    un.sun_family = AF_UNIX;
    int n = snprintf(un.sun_path + 1, sizeof un.sun_path - 1, "%s", argv[3]);
    if (unx < 0 || bind(unx, (struct sockaddr *)&un, (socklen_t)(offsetof(struct sockaddr_un, sun_path) + 1 + (size_t)n)) != 0 ||
        listen(unx, 64) != 0) {
        perror("netwatch: unix");
        return 1;
    }
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", argv[1]);
    FILE *pf = fopen(tmp, "w");
    if (!pf || fprintf(pf, "%d\n", ntohs(in.sin_port)) < 0 || fclose(pf) != 0 || rename(tmp, argv[1]) != 0) {
        perror("netwatch: port file");
        return 1;
    }
    time_t end = time(NULL) + atoi(argv[4]);
    while (time(NULL) < end) {
        struct pollfd p[2] = { { .fd = tcp, .events = POLLIN }, { .fd = unx, .events = POLLIN } };
        if (poll(p, 2, 500) <= 0)
            continue;
        for (int i = 0; i < 2; i++) {
            if (!(p[i].revents & POLLIN))
                continue;
            int c = accept(p[i].fd, NULL, NULL);
            if (c < 0)
                continue;
            char buf[201] = "";
            struct pollfd q = { .fd = c, .events = POLLIN };
            ssize_t got = poll(&q, 1, 1000) == 1 ? read(c, buf, 200) : 0;
            buf[got > 0 ? got : 0] = '\0';
            buf[strcspn(buf, "\n")] = '\0';
            int log = open(argv[2], O_WRONLY | O_CREAT | O_APPEND, 0644);
            if (log >= 0) {
                dprintf(log, "%s %s\n", i ? "unix" : "tcp", buf);
                close(log);
            }
            close(c);
        }
    }
    return 0;
}
