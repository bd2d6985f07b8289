#include "lpe/error.h"

#include <utility>

namespace lpe {
namespace {

// The text as it will be shown under the message: control bytes become spaces so that every byte
// still takes one column and the caret line stays aligned.
std::string printable(const std::string& text) {
    std::string shown = text;
    for (char& c : shown) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) c = ' ';
    }
    return shown;
}

// Terminals draw a UTF-8 character in one column whatever its byte count: count only the bytes
// that start a character (not continuation bytes 10xxxxxx) so the caret lands under the culprit.
std::size_t displayColumn(const std::string& text, std::size_t position) {
    std::size_t column = 0;
    for (std::size_t i = 0; i < position && i < text.size(); ++i) {
        if ((static_cast<unsigned char>(text[i]) & 0xc0) != 0x80) ++column;
    }
    return column;
}

std::string render(const std::string& text, std::size_t position, const std::string& message) {
    return "LPE syntax error at column " + std::to_string(position + 1) + ": " + message + "\n  " +
           printable(text) + "\n  " + std::string(displayColumn(text, position), ' ') + "^";
}

}  // namespace

SyntaxError::SyntaxError(std::string text, std::size_t position, const std::string& message)
    : std::runtime_error(render(text, position, message)),
      text_(std::move(text)),
      position_(position),
      message_(message) {}

}  // namespace lpe
