#include "serve/request_guard.h"

#include <algorithm>

#include "serve/request_error.h"

namespace lightpath::serve {
namespace {

constexpr int kDefaultHttpPort = 80;  // a Host or Origin for it may leave the port out (RFC 9110 4.2.1)

std::string lowerCase(std::string_view text) {
    std::string result(text);
    std::transform(result.begin(), result.end(), result.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return result;
}

// What a header value shows in a message: at most 80 characters.
std::string quoted(std::string_view value) {
    std::string shown(value.substr(0, 80));
    if (value.size() > 80) shown += "...";
    return "\"" + shown + "\"";
}

// The media type of a Content-Type value, without its parameters and optional white space.
std::string_view mediaType(std::string_view value) {
    value = value.substr(0, value.find(';'));
    const auto space = [](char c) { return c == ' ' || c == '\t'; };
    while (!value.empty() && space(value.front())) value.remove_prefix(1);
    while (!value.empty() && space(value.back())) value.remove_suffix(1);
    return value;
}

}  // namespace

bool changesState(std::string_view method) { return method != "GET" && method != "HEAD" && method != "OPTIONS"; }

RequestGuard::RequestGuard(const std::string& host, int port) : names_{"127.0.0.1", "localhost", "[::1]"}, port_(port) {
    std::string given = lowerCase(host);
    if (given.find(':') != std::string::npos) given = '[' + given + ']';  // an IPv6 address, as a Host writes it
    if (std::find(names_.begin(), names_.end(), given) == names_.end()) names_.push_back(given);
}

std::string RequestGuard::acceptedHosts(const std::string& prefix) const {
    std::string list;
    for (std::size_t i = 0; i < names_.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names_.size() ? " or " : ", ") + prefix + names_[i] + ":" + std::to_string(port_);
    return list;
}

bool RequestGuard::acceptedHost(std::string_view value) const {
    const std::string host = lowerCase(value);
    std::string port(1, ':');  // appended, not ":" + ...: GCC 12 warns falsely about that (its bug 105329)
    port += std::to_string(port_);
    for (const std::string& name : names_) {
        if (host == name + port) return true;
        if (port_ == kDefaultHttpPort && host == name) return true;
    }
    return false;
}

void RequestGuard::check(const Request& request) const {
    const auto hosts = headerValues(request.headers, "Host");
    if (hosts.size() > 1) throw RequestError(400, "Host", "more than one Host header (RFC 9110 7.2)");
    if (hosts.size() == 1 && !acceptedHost(hosts[0]))
        throw RequestError(421, "Host",
                           "Host " + quoted(hosts[0]) + " is not this server: expected " + acceptedHosts() +
                               ". A page of another site can point its own name at this address (DNS rebinding); "
                               "open the address lightpath serve printed");

    const auto origins = headerValues(request.headers, "Origin");
    if (origins.size() > 1) throw RequestError(403, "Origin", "more than one Origin header");
    if (origins.size() == 1) {
        const std::string_view origin = origins[0];
        const std::string_view scheme = "http://";
        if (!(origin.size() > scheme.size() && equalsIgnoringCase(origin.substr(0, scheme.size()), scheme) &&
              acceptedHost(origin.substr(scheme.size()))))
            throw RequestError(403, "Origin",
                               "Origin " + quoted(origin) + " is not this server's page: only " + acceptedHosts("http://") +
                                   " may send requests; another site's page may not drive the server");
    }

    if (changesState(request.method)) {
        const auto types = headerValues(request.headers, "Content-Type");
        if (types.size() != 1 || !equalsIgnoringCase(mediaType(types[0]), "application/json"))
            throw RequestError(403, "Content-Type",
                               request.method + " needs Content-Type: application/json, got " +
                                   (types.empty() ? std::string("none") : quoted(types[0])) +
                                   ". A browser sends other types (text/plain, forms) from any site without asking "
                                   "first; application/json it sends across sites only after a preflight this server refuses");
    }
}

}  // namespace lightpath::serve
