#include "serve/server.h"

#include <thread>

#include <httplib.h>

#include <csignal>
#include <stdexcept>

namespace lightpath::serve {
namespace {

void send(const Response& answer, httplib::Response& res) {
    res.status = answer.status;
    for (const auto& [name, value] : answer.headers) res.set_header(name, value);
    res.set_content(answer.body, answer.contentType.c_str());
}

}  // namespace

Server::Server(Session& session) : api_(session), http_(std::make_unique<httplib::Server>()) {
    // A client that hangs up mid-response must not kill the process (writes to its socket, or to
    // Graphviz's pipe, would raise SIGPIPE).
    std::signal(SIGPIPE, SIG_IGN);
    http_->set_payload_max_length(kMaxBodyBytes);
    http_->set_read_timeout(kIoTimeoutSeconds, 0);
    http_->set_write_timeout(kIoTimeoutSeconds, 0);

    // Every method httplib routes, on every path, goes to the API (HEAD as GET; httplib drops
    // the body). The request target is passed as sent: the API parses path and query itself.
    const auto forward = [this](const httplib::Request& req, httplib::Response& res) {
        Request request{req.method, req.target, {req.headers.begin(), req.headers.end()}, req.body};
        send(api_.handle(request), res);
    };
    const std::string any = ".*";
    http_->Get(any, forward);
    http_->Post(any, forward);
    http_->Put(any, forward);
    http_->Patch(any, forward);
    http_->Delete(any, forward);
    http_->Options(any, forward);

    // What httplib refuses itself (a malformed request line, a body over the limit, a method it
    // routes nowhere) gets the API's JSON error too.
    http_->set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (!res.body.empty()) return;
        const std::string message = res.status == 413 ? "request body too large: at most " + std::to_string(kMaxBodyBytes) + " bytes"
                                                       : "bad request (HTTP " + std::to_string(res.status) + ")";
        send(errorResponse(res.status, message), res);
    });
}

Server::~Server() = default;

int Server::bind(const std::string& host, int port) {
    const int bound = port == 0 ? http_->bind_to_any_port(host) : (http_->bind_to_port(host, port) ? port : -1);
    if (bound < 0)
        throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) +
                                 " (in use, or not an address of this machine); try another --port");
    api_.listenOn(host, bound);
    return bound;
}

void Server::run() {
    {
        const std::lock_guard lock(lifecycle_);
        if (stopRequested_) return;
        entered_ = true;
    }
    http_->listen_after_bind();
    returned_ = true;
}

void Server::stop() {
    bool listening = false;
    {
        const std::lock_guard lock(lifecycle_);
        stopRequested_ = true;
        listening = entered_;
    }
    if (!listening) return;  // run() has not begun and now never listens
    // Waits for the event (the loop running, or run() over), microseconds after run() began.
    while (!http_->is_running() && !returned_) std::this_thread::yield();
    http_->stop();
}

}  // namespace lightpath::serve
