#pragma once
// A request the server refuses: an HTTP status (4xx) and a message naming what was wrong and what
// was expected. `field` locates it in the request ("lpes[2].expression", "x"); for an LPE syntax
// error `column` is the 0-based offset of the offending character in `expression`.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace lightpath::serve {

class RequestError : public std::runtime_error {
public:
    RequestError(int status, std::string field, const std::string& message)
        : std::runtime_error(message), status_(status), field_(std::move(field)) {}

    int status() const { return status_; }
    const std::string& field() const { return field_; }

    std::optional<std::size_t> column;
    std::string expression;

private:
    int status_;
    std::string field_;
};

}  // namespace lightpath::serve
