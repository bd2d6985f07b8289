#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace lpe {

// A malformed light path expression or path string. `position` is the 0-based offset of the
// offending character in `text`; what() reads, for example,
//     LPE syntax error at column 5: expected ')' to close the group opened at column 2
//       E(D|G L
//             ^
class SyntaxError : public std::runtime_error {
public:
    SyntaxError(std::string text, std::size_t position, const std::string& message);

    const std::string& text() const { return text_; }
    std::size_t position() const { return position_; }
    const std::string& message() const { return message_; }  // without the caret drawing

private:
    std::string text_;
    std::size_t position_;
    std::string message_;
};

// A well-formed request the engine refuses to build: too many outputs, a repetition count or an
// automaton beyond the documented limits. Thrown instead of hanging or exhausting memory.
class LimitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace lpe
