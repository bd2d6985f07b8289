#pragma once
// An HTTP request and its answer as plain values, so that the API (serve/api.h) is a function
// from one to the other: the server (serve/server.h) only moves them on and off the socket, and
// the fuzz target (tests/fuzz/fuzz_serve.cpp) calls the same function without one.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lightpath::serve {

using HeaderList = std::vector<std::pair<std::string, std::string>>;

struct Request {
    std::string method;  // "GET", "PUT", ...
    std::string target;  // the path and query as sent: "/api/explain?x=3&y=4"
    HeaderList headers;  // in the order sent; names compared without case
    std::string body;
};

struct Response {
    int status = 200;
    std::string contentType;
    std::string body;
    HeaderList headers;  // besides Content-Type
};

// The values of every header named `name` (case-insensitive, RFC 9110 5.1), in order.
std::vector<std::string_view> headerValues(const HeaderList& headers, std::string_view name);

// A request target split into its percent-decoded path and query parameters (a '+' in the query
// is a space), parameters in order; a parameter without '=' has an empty value.
struct Target {
    std::string path;
    std::vector<std::pair<std::string, std::string>> parameters;

    bool has(std::string_view key) const;
    // The first value of `key`; nullopt when absent.
    std::optional<std::string> value(std::string_view key) const;
};
Target parseTarget(std::string_view target);

bool equalsIgnoringCase(std::string_view a, std::string_view b);

}  // namespace lightpath::serve
