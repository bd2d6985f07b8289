#include "cli/serve_command.h"

#include <spawn.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

#include "config/exit_codes.h"
#include "config/render_config.h"
#include "serve/server.h"
#include "serve/session.h"

extern char** environ;

namespace lightpath {
namespace {

struct ServeCommand {
    std::string scenePath;
    std::string host = "127.0.0.1";
    int port = 8080;
    int threads = 0;
    bool open = false;
};

// Ctrl-C (or SIGTERM) writes one byte here; a thread waiting on the other end stops the server.
// A signal handler may only do async-signal-safe things such as write(2).
int stopPipe[2] = {-1, -1};

void onStopSignal(int) {
    const char byte = 1;
    [[maybe_unused]] const ssize_t ignored = ::write(stopPipe[1], &byte, 1);
}

// Ctrl-C must stop the server within a second (docs/serve.md).
constexpr double kStopWaitSeconds = 0.25;

bool isLoopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }

void openBrowser(const std::string& url) {
    std::array<char*, 3> argv{const_cast<char*>("xdg-open"), const_cast<char*>(url.c_str()), nullptr};
    pid_t child = 0;
    if (posix_spawnp(&child, "xdg-open", nullptr, nullptr, argv.data(), environ) != 0)
        std::cerr << "lightpath serve: --open: cannot run xdg-open; open " << url << " yourself\n";
}

void run(const ServeCommand& command) {
    RenderConfig config;
    config.scenePath = command.scenePath;
    serve::Session session(config.loadScene(), command.scenePath, command.threads);
    serve::Server server(session);
    int port = 0;
    try {
        port = server.bind(command.host, command.port);
    } catch (const std::runtime_error& e) {
        throw CLI::RuntimeError(std::string("--host/--port: ") + e.what(), kExitBadInput);
    }
    if (!isLoopback(command.host))
        std::cerr << "warning: --host " << command.host
                  << ": anyone who can reach this address can use the server; it has no authentication (docs/serve.md)\n";

    if (::pipe(stopPipe) != 0) throw std::runtime_error("pipe failed");
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    bool workerStopped = true;
    std::jthread stopper([&] {
        char byte = 0;
        while (::read(stopPipe[0], &byte, 1) < 0 && errno == EINTR) {
        }
        // Cancels the render in flight, which stops at its next pixel; a renderer still building
        // its BVH cannot be interrupted, and is not waited for.
        workerStopped = session.stopWithin(kStopWaitSeconds);
        server.stop();
    });

    const std::string shownHost = command.host.find(':') != std::string::npos ? "[" + command.host + "]" : command.host;
    const std::string url = "http://" + shownHost + ":" + std::to_string(port) + "/";
    std::printf("lightpath serve: %s at %s (Ctrl-C stops)\n", command.scenePath.c_str(), url.c_str());
    std::fflush(stdout);
    if (command.open) openBrowser(url);
    server.run();
    onStopSignal(0);  // the listening loop ended on its own: let the stopper finish too
    stopper.join();
    std::printf("lightpath serve: stopped\n");
    std::fflush(stdout);
    // Nothing is left to save: end the process rather than wait for a renderer under construction.
    if (!workerStopped) std::quick_exit(kExitOk);
}

}  // namespace

void addServeCommand(CLI::App& app) {
    auto command = std::make_shared<ServeCommand>();
    CLI::App* sub = app.add_subcommand("serve", "Explore a scene's light paths live in the browser");
    sub->add_option("scene", command->scenePath, "Scene file (TOML, see scenes/README.md)")->required();
    sub->add_option("--port", command->port, "TCP port (0: any free port)")->check(CLI::Range(0, 65535))->capture_default_str();
    sub->add_option("--host", command->host,
                    "Address to listen on. Anything but 127.0.0.1 exposes the server, which has no authentication, "
                    "to everyone who can reach that address")
        ->capture_default_str();
    sub->add_option("--threads", command->threads,
                    "Render threads (0 = all cores; fewer leave the projector's browser a core)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    sub->add_flag("--open", command->open, "Open the page in the default browser (xdg-open)");
    sub->footer(
        "The page renders progressively, edits the LPEs, switches the integrator, explains a clicked pixel\n"
        "with its paths drawn over the image and a top view, draws the automaton, and downloads the\n"
        "render. Only the scene given here (and the files it names) is read. See docs/serve.md.\n\n"
        "Examples:\n"
        "  lightpath serve scenes/lecture-room.toml\n"
        "  lightpath serve scenes/cornell-mirror.toml --port 9000 --open");
    sub->callback([command] { run(*command); });
}

}  // namespace lightpath
