#pragma once
// A server on a free loopback port over one scene, for the API tests, and a client that waits for
// events (a pass published), never for a fixed time.
#include <doctest/doctest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "scene/scene_loader.h"
#include "serve/server.h"
#include "serve/session.h"

namespace lightpath::serve::test {

using nlohmann::json;

inline std::string scenePath(const std::string& name) { return std::string(LIGHTPATH_SOURCE_DIR) + "/scenes/" + name; }

class ServerFixture {
public:
    explicit ServerFixture(const std::string& scene)
        : session(loadScene(scenePath(scene)), scenePath(scene)), server(session) {
        port = server.bind("127.0.0.1", 0);
        thread = std::thread([this] { server.run(); });
    }
    ~ServerFixture() {
        server.stop();
        thread.join();
        session.stop();
    }

    std::unique_ptr<httplib::Client> client() const {
        auto c = std::make_unique<httplib::Client>("127.0.0.1", port);
        c->set_read_timeout(60, 0);
        return c;
    }

    // PUTs `settings` and returns the answer's JSON (status checked by the caller).
    httplib::Result put(const json& settings) const {
        return client()->Put("/api/settings", settings.dump(), "application/json");
    }

    // Long-polls /api/progress until the render of `generation` is done; fails after `limit`.
    json waitUntilDone(std::uint64_t generation, double limit = 120.0) const {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit);
        auto c = client();
        int pass = -1;
        while (std::chrono::steady_clock::now() < deadline) {
            const auto r = c->Get(("/api/progress?wait=5&generation=" + std::to_string(generation) +
                                   "&pass=" + std::to_string(pass)).c_str());
            REQUIRE(r);
            REQUIRE(r->status == 200);
            const json p = json::parse(r->body);
            if (p["generation"] == generation) {
                if (p["done"] == true) return p;
                pass = p["passes"];
            }
        }
        FAIL("the render of generation " << generation << " was not done within " << limit << " s");
        return {};
    }

    Session session;
    Server server;
    int port = 0;
    std::thread thread;
};

}  // namespace lightpath::serve::test
