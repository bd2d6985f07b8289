#pragma once
// Who may drive the server: only its own page (docs/serve.md, "Safety"). Checked on every request
// before anything else:
//  - Host must name the server as printed (127.0.0.1, localhost, [::1] or --host, with the port):
//    a page of another site that rebinds its own name to 127.0.0.1 (DNS rebinding) sends its own
//    name, and is refused (421) before it can read anything. A request without Host (HTTP/1.0) is
//    answered: browsers always send one, so only a client that already reaches the socket, and
//    could write any Host, can omit it.
//  - An Origin, when sent, must be the server's own (http:// and an accepted Host): another
//    site's page is refused (403) whatever the method.
//  - A request that may change state (any method but GET, HEAD and OPTIONS) must be
//    Content-Type: application/json, which a browser sends across origins only after a preflight
//    that this server never grants (it sends no CORS headers); a "simple" text/plain or form POST
//    is refused (403).
#include <string>
#include <vector>

#include "serve/http_message.h"

namespace lightpath::serve {

class RequestGuard {
public:
    // `host` as given to --host (an IPv6 address without brackets), `port` the one bound.
    RequestGuard(const std::string& host, int port);

    // Throws RequestError (400, 403 or 421, naming the header) when `request` is refused.
    void check(const Request& request) const;

    // "127.0.0.1:8080, localhost:8080 or [::1]:8080": the Host values accepted, each after
    // `prefix` ("http://": the origins), for messages.
    std::string acceptedHosts(const std::string& prefix = "") const;

private:
    bool acceptedHost(std::string_view value) const;

    std::vector<std::string> names_;  // lower case, IPv6 in brackets
    int port_;
};

// Whether a request with this method may change state (RFC 9110 9.2.1: GET, HEAD and OPTIONS are
// the safe methods the API has).
bool changesState(std::string_view method);

}  // namespace lightpath::serve
