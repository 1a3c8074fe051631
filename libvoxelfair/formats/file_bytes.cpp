#include "formats/file_bytes.h"

#include "formats/format_error.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace voxelfair {

namespace {

struct FileCloser {
    void operator()(std::FILE *f) const { std::fclose(f); }
};

std::string withReason(const std::string &path, const char *what, int error) {
    return path + ": " + what + " (" + (error ? std::strerror(error) : "I/O error") + ")";
}

}  // namespace

std::vector<uint8_t> readFileBytes(const std::string &path, size_t maxBytes) {
    errno = 0;
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file)
        throw FormatError(withReason(path, "cannot open", errno));

    // Read in chunks rather than trusting a size query: pipes and devices have none, and the
    // limit must hold whatever the file claims.
    std::vector<uint8_t> bytes;
    constexpr size_t kChunk = size_t(1) << 16;
    for (;;) {
        const size_t used = bytes.size();
        const size_t room = maxBytes - used;
        const size_t want = room < kChunk ? room + 1 : kChunk;  // one byte past the limit detects "too large"
        bytes.resize(used + want);
        const size_t got = std::fread(bytes.data() + used, 1, want, file.get());
        bytes.resize(used + got);
        if (bytes.size() > maxBytes)
            throw FormatError(path + ": larger than " + std::to_string(maxBytes) + " bytes, not a model file");
        if (got < want)
            break;
    }
    if (std::ferror(file.get()))
        throw FormatError(withReason(path, "cannot read", errno));
    return bytes;
}

}  // namespace voxelfair
