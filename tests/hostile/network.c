/* Reaching the network: connects to 127.0.0.1:@PORT@ over TCP and to the
 * abstract Unix socket @swevil-net-RUN, where the test listens and logs who
 * came, and says who it is. Either connection counts as success: the
 * plugin then hands in the right answer. */
#define EVIL_FAMILY "network"
#include "evil.h"
#include <netinet/in.h>
#include <poll.h>
#include <sys/un.h>

static int say(int fd, const struct sockaddr *a, socklen_t len)
{
    int ok = 0;
    fcntl(fd, F_SETFL, O_NONBLOCK);
    if (connect(fd, a, len) == 0 || errno == EINPROGRESS) {
        struct pollfd p = { .fd = fd, .events = POLLOUT };
        int err = 0;
        socklen_t el = sizeof err;
        if (poll(&p, 1, 1000) == 1 && getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &el) == 0 && err == 0) {
            const char *hello = "swevil-" EVIL_TOKEN "-" EVIL_FAMILY " connected\n";
            ok = send(fd, hello, strlen(hello), MSG_NOSIGNAL) > 0;
        }
    }
    close(fd);
    return ok;
}

static void evil_attack(void)
{
    int reached = 0;
    struct sockaddr_in in;
    memset(&in, 0, sizeof in);
    in.sin_family = AF_INET;
    in.sin_port = htons((unsigned short)atoi(EVIL_PORT));
    in.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd >= 0 && in.sin_port)
        reached += say(fd, (struct sockaddr *)&in, sizeof in);
    struct sockaddr_un un;
    memset(&un, 0, sizeof un);
    un.sun_family = AF_UNIX;
    int len = snprintf(un.sun_path + 1, sizeof un.sun_path - 1, "swevil-net-%.6s", EVIL_TOKEN);
    fd = socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd >= 0)
        reached += say(fd, (struct sockaddr *)&un, (socklen_t)(offsetof(struct sockaddr_un, sun_path) + 1 + (size_t)len));
    if (reached) {
        evil_cheat = 1;
        evil_mark("network", NULL);
    }
}
