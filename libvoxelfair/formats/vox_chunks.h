// MagicaVoxel .vox chunk reading (private to the VOX reader): the RIFF-like chunk header, a
// bounds-checked reader over one chunk's content, and the extension's STRING/DICT values and
// the node attributes they hold (_r, _t, _f, _hidden). Layout: MagicaVoxel's vox file format
// texts (base chunks and the scene-graph extension).
//
// Every read is checked against the chunk's content, so a FormatError names the chunk, its byte
// offset and the field ("chunk 'nTRN' at byte 1234: truncated: ...").
#pragma once

#include "formats/byte_reader.h"
#include "formats/format_error.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::vox {

constexpr uint64_t kChunkHeaderBytes = 12;

// A chunk's id and extent: content [contentBegin, contentEnd), children up to childrenEnd.
struct Chunk {
    std::string id;
    uint64_t offset = 0;
    uint64_t contentBegin = 0, contentEnd = 0, childrenEnd = 0;

    std::string where() const { return "chunk '" + id + "' at byte " + std::to_string(offset); }
};

// The chunk whose header is at `offset`, checked to lie inside its parent, which ends at `end`
// (`parent` names it in messages).
Chunk readChunk(const ByteReader &data, uint64_t offset, uint64_t end, const std::string &parent);

using Dict = std::vector<std::pair<std::string, std::string>>;

// The value of `key` (the last one when repeated), or null.
const std::string *lookup(const Dict &dict, std::string_view key);

// Sequential reads inside one chunk's content.
class ContentReader {
public:
    ContentReader(const ByteReader &data, const Chunk &chunk) : data_(data), chunk_(chunk), pos_(chunk.contentBegin) {}

    const Chunk &chunk() const { return chunk_; }
    uint64_t remaining() const { return chunk_.contentEnd - pos_; }

    [[noreturn]] void fail(const std::string &problem) const { throw FormatError(chunk_.where() + ": " + problem); }

    const uint8_t *bytes(uint64_t count, const char *what);
    int32_t i32(const char *what) { return int32_t(ByteReader::load32(bytes(4, what))); }

    // A count of items of at least `itemBytes` bytes each, checked against the bytes left so that
    // nothing is reserved for items the chunk cannot hold.
    size_t count(uint64_t itemBytes, const char *what);
    std::string string(const char *what);
    Dict dict(const char *what);

private:
    const ByteReader &data_;
    const Chunk &chunk_;
    uint64_t pos_;
};

// Node attributes; `where` names the node (and frame) in messages.
glm::mat4 parseRotation(const std::string &text, const ContentReader &in, const std::string &where);     // `_r`
glm::vec3 parseTranslation(const std::string &text, const ContentReader &in, const std::string &where);  // `_t`
int parseFrame(const Dict &dict, const ContentReader &in, const std::string &where);  // `_f`, 0 when absent
bool isHidden(const Dict &dict);                                                      // `_hidden` is "1"

// The spec's default palette, entry c for colour index c, as 0xAABBGGRR (vox_default_palette.cpp).
extern const uint32_t kDefaultPalette[256];

}  // namespace voxelfair::vox
