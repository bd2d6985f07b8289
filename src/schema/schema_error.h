#pragma once
#include <stdexcept>

namespace lightpath {

// A value a schema refuses, or a combination a type's make() refuses. what() is located
// ("FILE:LINE:COLUMN: KEY_PATH: ...") when the value came from a file.
class SchemaError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace lightpath
