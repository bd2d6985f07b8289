#include "serve/graphviz.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>

extern char** environ;

namespace lightpath::serve {
namespace {

// Closes a descriptor once, whichever way the scope is left.
struct Descriptor {
    int fd = -1;
    ~Descriptor() { reset(); }
    void reset() {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
};

}  // namespace

std::string dotToSvg(const std::string& dot, double timeoutSeconds) {
    int in[2], out[2];
    if (::pipe2(in, O_CLOEXEC) != 0) throw GraphvizError(std::string("pipe: ") + std::strerror(errno));
    Descriptor inRead{in[0]}, inWrite{in[1]};
    if (::pipe2(out, O_CLOEXEC) != 0) throw GraphvizError(std::string("pipe: ") + std::strerror(errno));
    Descriptor outRead{out[0]}, outWrite{out[1]};

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, inRead.fd, STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, outWrite.fd, STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    std::array<char*, 3> argv{const_cast<char*>("dot"), const_cast<char*>("-Tsvg"), nullptr};
    pid_t child = 0;
    const int spawned = posix_spawnp(&child, "dot", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw GraphvizError(std::string("cannot run Graphviz's dot (") + std::strerror(spawned) +
                            "); install it with `apt-get install graphviz`");
    inRead.reset();
    outWrite.reset();
    ::fcntl(inWrite.fd, F_SETFL, O_NONBLOCK);

    // Feed stdin and drain stdout together, so neither pipe's buffer can block the child.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    std::string svg;
    std::size_t written = 0;
    bool timedOut = false;
    if (dot.empty()) inWrite.reset();
    while (outRead.fd >= 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        std::array<pollfd, 2> fds{pollfd{outRead.fd, POLLIN, 0}, pollfd{inWrite.fd, POLLOUT, 0}};
        const int n = ::poll(fds.data(), inWrite.fd >= 0 ? 2 : 1, static_cast<int>(left.count()));
        if (n < 0 && errno != EINTR) break;
        if (inWrite.fd >= 0 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP))) {
            const ssize_t w = ::write(inWrite.fd, dot.data() + written, dot.size() - written);
            if (w > 0) written += static_cast<std::size_t>(w);
            if (w < 0 && errno != EAGAIN) inWrite.reset();
            if (written == dot.size()) inWrite.reset();
        }
        if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
            char buffer[65536];
            const ssize_t r = ::read(outRead.fd, buffer, sizeof buffer);
            if (r > 0) svg.append(buffer, static_cast<std::size_t>(r));
            else if (r == 0 || errno != EAGAIN) outRead.reset();
        }
    }
    if (timedOut) ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut) throw GraphvizError("Graphviz's dot took longer than " + std::to_string(timeoutSeconds) + " s");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw GraphvizError("Graphviz's dot failed on the automaton");
    return svg;
}

}  // namespace lightpath::serve
