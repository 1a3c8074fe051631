// See vox_chunks.h.
#include "formats/vox_chunks.h"

#include <algorithm>
#include <charconv>
#include <climits>

namespace voxelfair::vox {

namespace {

// A chunk id for messages: printable characters as they are, others as \xNN.
std::string chunkName(const uint8_t *id) {
    static const char kHex[] = "0123456789abcdef";
    std::string name;
    for (int i = 0; i < 4; ++i) {
        if (id[i] >= 0x20 && id[i] < 0x7f) {
            name += char(id[i]);
        } else {
            name += "\\x";
            name += kHex[id[i] >> 4];
            name += kHex[id[i] & 15];
        }
    }
    return name;
}

// A whole decimal integer in [lo, hi] ("-12"; no sign "+", no spaces), or false.
bool parseInt(std::string_view text, long long lo, long long hi, long long &value) {
    const char *end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    return result.ec == std::errc() && result.ptr == end && value >= lo && value <= hi;
}

// A file's string for a message, cut short: a corrupt file may hold long or binary values.
std::string quoted(const std::string &text) {
    return "\"" + (text.size() <= 32 ? text : text.substr(0, 32) + "...") + "\"";
}

}  // namespace

Chunk readChunk(const ByteReader &data, uint64_t offset, uint64_t end, const std::string &parent) {
    if (end - offset < kChunkHeaderBytes)
        throw FormatError("truncated: a chunk header at byte " + std::to_string(offset) + " needs 12 bytes but " +
                          parent + " ends at byte " + std::to_string(end));
    const uint8_t *header = data.bytes(offset, kChunkHeaderBytes, "a chunk header");
    Chunk chunk;
    chunk.id = chunkName(header);
    chunk.offset = offset;
    const uint64_t content = ByteReader::load32(header + 4);
    const uint64_t children = ByteReader::load32(header + 8);
    chunk.contentBegin = offset + kChunkHeaderBytes;
    if (content + children > end - chunk.contentBegin)
        throw FormatError(chunk.where() + ": its " + std::to_string(content) + " content and " +
                          std::to_string(children) + " children bytes run past the end of " + parent + " (byte " +
                          std::to_string(end) + ")");
    chunk.contentEnd = chunk.contentBegin + content;
    chunk.childrenEnd = chunk.contentEnd + children;
    return chunk;
}

const std::string *lookup(const Dict &dict, std::string_view key) {
    for (auto it = dict.rbegin(); it != dict.rend(); ++it)
        if (it->first == key)
            return &it->second;
    return nullptr;
}

const uint8_t *ContentReader::bytes(uint64_t count, const char *what) {
    if (count > remaining())
        fail(std::string("truncated: ") + what + " at byte " + std::to_string(pos_) + " needs " +
             std::to_string(count) + " bytes but the chunk's content ends at byte " +
             std::to_string(chunk_.contentEnd));
    const uint8_t *p = data_.bytes(pos_, count, what);
    pos_ += count;
    return p;
}

size_t ContentReader::count(uint64_t itemBytes, const char *what) {
    const int32_t n = i32(what);
    if (n < 0)
        fail(std::string(what) + " is negative (" + std::to_string(n) + ")");
    if (uint64_t(n) * itemBytes > remaining())
        fail(std::string(what) + " " + std::to_string(n) + " needs at least " +
             std::to_string(uint64_t(n) * itemBytes) + " bytes but only " + std::to_string(remaining()) +
             " remain in the chunk");
    return size_t(n);
}

std::string ContentReader::string(const char *what) {
    const size_t length = count(1, what);
    const uint8_t *p = bytes(length, what);
    return std::string(reinterpret_cast<const char *>(p), length);
}

Dict ContentReader::dict(const char *what) {
    Dict dict(count(8, what));  // each pair holds two 4-byte lengths at least
    for (auto &[key, value] : dict) {
        key = string("dictionary key");
        value = string("dictionary value");
    }
    return dict;
}

// `_r`: bits 0-1 and 2-3 are the columns of the non-zero entries of rows 0 and 1 (row 2 takes the
// remaining column), bits 4, 5, 6 negate rows 0, 1, 2 (the extension's ROTATION type).
glm::mat4 parseRotation(const std::string &text, const ContentReader &in, const std::string &where) {
    long long bits = 0;
    if (!parseInt(text, 0, 127, bits))
        in.fail(where + ": rotation _r " + quoted(text) + " is not a byte value in 0..127");
    const int column[3] = {int(bits & 3), int(bits >> 2 & 3), 3 - int(bits & 3) - int(bits >> 2 & 3)};
    if (column[0] > 2 || column[1] > 2 || column[0] == column[1])
        in.fail(where + ": rotation _r " + quoted(text) + " is not a valid rotation (rows 0 and 1 use columns " +
                std::to_string(column[0]) + " and " + std::to_string(column[1]) + ")");
    glm::mat4 rotation(0.0f);
    rotation[3][3] = 1.0f;
    for (int row = 0; row < 3; ++row)
        rotation[column[row]][row] = (bits >> (4 + row) & 1) ? -1.0f : 1.0f;  // glm: [column][row]
    return rotation;
}

// `_t`: three integers separated by spaces.
glm::vec3 parseTranslation(const std::string &text, const ContentReader &in, const std::string &where) {
    const auto fail = [&] { in.fail(where + ": translation _t " + quoted(text) + " is not three integers"); };
    glm::vec3 t(0.0f);
    std::string_view rest = text;
    for (int axis = 0; axis < 3; ++axis) {
        rest.remove_prefix(std::min(rest.find_first_not_of(' '), rest.size()));
        const std::string_view token = rest.substr(0, rest.find(' '));
        long long v = 0;
        if (!parseInt(token, INT32_MIN, INT32_MAX, v))
            fail();
        t[axis] = float(v);
        rest.remove_prefix(token.size());
    }
    if (rest.find_first_not_of(' ') != std::string_view::npos)
        fail();
    return t;
}

int parseFrame(const Dict &dict, const ContentReader &in, const std::string &where) {
    const std::string *text = lookup(dict, "_f");
    long long frame = 0;
    if (text != nullptr && !parseInt(*text, 0, INT32_MAX - 1, frame))
        in.fail(where + ": frame index _f " + quoted(*text) + " is not a non-negative integer");
    return int(frame);
}

bool isHidden(const Dict &dict) {
    const std::string *text = lookup(dict, "_hidden");
    return text != nullptr && *text == "1";
}

}  // namespace voxelfair::vox
