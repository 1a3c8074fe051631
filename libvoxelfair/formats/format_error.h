// Readers report malformed input by throwing FormatError. The message says what is wrong and
// where (byte offset, section, column); the caller prefixes the file's name.
#pragma once

#include <stdexcept>

namespace voxelfair {

class FormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace voxelfair
