// Hostile submission: opens network connections: to a port the test listens on (on the host's
// loopback, @PORT@) and to a public address. The sandbox has no network; it reports and aborts.
#include "pathlab/lab.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    for (const auto& [address, port] : {std::pair{"127.0.0.1", @PORT@}, std::pair{"1.1.1.1", 80}}) {
        const int s = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in to{};
        to.sin_family = AF_INET;
        to.sin_port = htons(static_cast<uint16_t>(port));
        ::inet_pton(AF_INET, address, &to.sin_addr);
        if (s >= 0 && ::connect(s, reinterpret_cast<sockaddr*>(&to), sizeof to) == 0)
            std::fprintf(stderr, "network: CONNECTED to %s:%d\n", address, port);
        else
            std::fprintf(stderr, "network: no connection to %s:%d: %s\n", address, port, std::strerror(errno));
        if (s >= 0) ::close(s);
    }
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
