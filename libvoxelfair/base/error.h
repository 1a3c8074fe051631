// The library's one error style (doc/architecture.md): bad input throws an exception derived
// from Error whose message says what is wrong and names the item (chunk, section, polygon,
// option); expected outcomes ("nothing to do", skipped vertices) are values in the result.
// The adapters (plugins, tools) catch Error once and prefix the file's name.
#pragma once

#include <stdexcept>

namespace voxelfair {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Bytes a reader cannot accept (formats/).
class FormatError : public Error {
public:
    using Error::Error;
};

// Arrays that do not form a valid polygon mesh: bad offsets, indices out of range, missing arrays,
// sizes past 32-bit indices (mesh/).
class MeshError : public Error {
public:
    using Error::Error;
};

// An option out of its documented range (fairing, attributes, atlas options).
class OptionError : public Error {
public:
    using Error::Error;
};

}  // namespace voxelfair
