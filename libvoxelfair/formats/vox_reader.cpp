#include "formats/vox.h"

#include "formats/format_error.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace voxelfair {

namespace {

// The spec's default palette (vox-spec-base.txt §8), entry c for colour index c, as 0xAABBGGRR:
// the bytes R, G, B, A in file order read as a little-endian integer.
constexpr uint32_t kDefaultPalette[256] = {
    0x00000000, 0xffffffff, 0xffccffff, 0xff99ffff, 0xff66ffff, 0xff33ffff, 0xff00ffff, 0xffffccff, 0xffccccff,
    0xff99ccff, 0xff66ccff, 0xff33ccff, 0xff00ccff, 0xffff99ff, 0xffcc99ff, 0xff9999ff, 0xff6699ff, 0xff3399ff,
    0xff0099ff, 0xffff66ff, 0xffcc66ff, 0xff9966ff, 0xff6666ff, 0xff3366ff, 0xff0066ff, 0xffff33ff, 0xffcc33ff,
    0xff9933ff, 0xff6633ff, 0xff3333ff, 0xff0033ff, 0xffff00ff, 0xffcc00ff, 0xff9900ff, 0xff6600ff, 0xff3300ff,
    0xff0000ff, 0xffffffcc, 0xffccffcc, 0xff99ffcc, 0xff66ffcc, 0xff33ffcc, 0xff00ffcc, 0xffffcccc, 0xffcccccc,
    0xff99cccc, 0xff66cccc, 0xff33cccc, 0xff00cccc, 0xffff99cc, 0xffcc99cc, 0xff9999cc, 0xff6699cc, 0xff3399cc,
    0xff0099cc, 0xffff66cc, 0xffcc66cc, 0xff9966cc, 0xff6666cc, 0xff3366cc, 0xff0066cc, 0xffff33cc, 0xffcc33cc,
    0xff9933cc, 0xff6633cc, 0xff3333cc, 0xff0033cc, 0xffff00cc, 0xffcc00cc, 0xff9900cc, 0xff6600cc, 0xff3300cc,
    0xff0000cc, 0xffffff99, 0xffccff99, 0xff99ff99, 0xff66ff99, 0xff33ff99, 0xff00ff99, 0xffffcc99, 0xffcccc99,
    0xff99cc99, 0xff66cc99, 0xff33cc99, 0xff00cc99, 0xffff9999, 0xffcc9999, 0xff999999, 0xff669999, 0xff339999,
    0xff009999, 0xffff6699, 0xffcc6699, 0xff996699, 0xff666699, 0xff336699, 0xff006699, 0xffff3399, 0xffcc3399,
    0xff993399, 0xff663399, 0xff333399, 0xff003399, 0xffff0099, 0xffcc0099, 0xff990099, 0xff660099, 0xff330099,
    0xff000099, 0xffffff66, 0xffccff66, 0xff99ff66, 0xff66ff66, 0xff33ff66, 0xff00ff66, 0xffffcc66, 0xffcccc66,
    0xff99cc66, 0xff66cc66, 0xff33cc66, 0xff00cc66, 0xffff9966, 0xffcc9966, 0xff999966, 0xff669966, 0xff339966,
    0xff009966, 0xffff6666, 0xffcc6666, 0xff996666, 0xff666666, 0xff336666, 0xff006666, 0xffff3366, 0xffcc3366,
    0xff993366, 0xff663366, 0xff333366, 0xff003366, 0xffff0066, 0xffcc0066, 0xff990066, 0xff660066, 0xff330066,
    0xff000066, 0xffffff33, 0xffccff33, 0xff99ff33, 0xff66ff33, 0xff33ff33, 0xff00ff33, 0xffffcc33, 0xffcccc33,
    0xff99cc33, 0xff66cc33, 0xff33cc33, 0xff00cc33, 0xffff9933, 0xffcc9933, 0xff999933, 0xff669933, 0xff339933,
    0xff009933, 0xffff6633, 0xffcc6633, 0xff996633, 0xff666633, 0xff336633, 0xff006633, 0xffff3333, 0xffcc3333,
    0xff993333, 0xff663333, 0xff333333, 0xff003333, 0xffff0033, 0xffcc0033, 0xff990033, 0xff660033, 0xff330033,
    0xff000033, 0xffffff00, 0xffccff00, 0xff99ff00, 0xff66ff00, 0xff33ff00, 0xff00ff00, 0xffffcc00, 0xffcccc00,
    0xff99cc00, 0xff66cc00, 0xff33cc00, 0xff00cc00, 0xffff9900, 0xffcc9900, 0xff999900, 0xff669900, 0xff339900,
    0xff009900, 0xffff6600, 0xffcc6600, 0xff996600, 0xff666600, 0xff336600, 0xff006600, 0xffff3300, 0xffcc3300,
    0xff993300, 0xff663300, 0xff333300, 0xff003300, 0xffff0000, 0xffcc0000, 0xff990000, 0xff660000, 0xff330000,
    0xff0000ee, 0xff0000dd, 0xff0000bb, 0xff0000aa, 0xff000088, 0xff000077, 0xff000055, 0xff000044, 0xff000022,
    0xff000011, 0xff00ee00, 0xff00dd00, 0xff00bb00, 0xff00aa00, 0xff008800, 0xff007700, 0xff005500, 0xff004400,
    0xff002200, 0xff001100, 0xffee0000, 0xffdd0000, 0xffbb0000, 0xffaa0000, 0xff880000, 0xff770000, 0xff550000,
    0xff440000, 0xff220000, 0xff110000, 0xffeeeeee, 0xffdddddd, 0xffbbbbbb, 0xffaaaaaa, 0xff888888, 0xff777777,
    0xff555555, 0xff444444, 0xff222222, 0xff111111,
};

constexpr uint64_t kChunkHeaderBytes = 12;
constexpr uint64_t kRgbaBytes = 1024;

uint32_t load32(const uint8_t *p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

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

// A chunk's id and extent: content [contentBegin, contentEnd), children up to childrenEnd.
struct Chunk {
    std::string id;
    uint64_t offset = 0;
    uint64_t contentBegin = 0, contentEnd = 0, childrenEnd = 0;

    std::string where() const { return "chunk '" + id + "' at byte " + std::to_string(offset); }
};

// The chunk whose header is at `offset`, checked to lie inside its parent, which ends at `end`.
Chunk readChunk(const uint8_t *data, uint64_t offset, uint64_t end, const std::string &parent) {
    if (end - offset < kChunkHeaderBytes)
        throw FormatError("truncated: a chunk header at byte " + std::to_string(offset) + " needs 12 bytes but " +
                          parent + " ends at byte " + std::to_string(end));
    Chunk chunk;
    chunk.id = chunkName(data + offset);
    chunk.offset = offset;
    const uint64_t content = load32(data + offset + 4);
    const uint64_t children = load32(data + offset + 8);
    chunk.contentBegin = offset + kChunkHeaderBytes;
    if (content + children > end - chunk.contentBegin)
        throw FormatError(chunk.where() + ": its " + std::to_string(content) + " content and " +
                          std::to_string(children) + " children bytes run past the end of " + parent + " (byte " +
                          std::to_string(end) + ")");
    chunk.contentEnd = chunk.contentBegin + content;
    chunk.childrenEnd = chunk.contentEnd + children;
    return chunk;
}

using Dict = std::vector<std::pair<std::string, std::string>>;

// The value of `key` (the last one when repeated), or null.
const std::string *lookup(const Dict &dict, std::string_view key) {
    for (auto it = dict.rbegin(); it != dict.rend(); ++it)
        if (it->first == key) return &it->second;
    return nullptr;
}

// Sequential reads inside one chunk's content; every read is checked against the content's end,
// so that an error names the chunk and the field.
class ContentReader {
public:
    ContentReader(const uint8_t *data, const Chunk &chunk) : data_(data), chunk_(chunk), pos_(chunk.contentBegin) {}

    uint64_t remaining() const { return chunk_.contentEnd - pos_; }

    [[noreturn]] void fail(const std::string &problem) const { throw FormatError(chunk_.where() + ": " + problem); }

    const uint8_t *bytes(uint64_t count, const char *what) {
        if (count > remaining())
            fail(std::string("truncated: ") + what + " at byte " + std::to_string(pos_) + " needs " +
                 std::to_string(count) + " bytes but the chunk's content ends at byte " +
                 std::to_string(chunk_.contentEnd));
        const uint8_t *p = data_ + pos_;
        pos_ += count;
        return p;
    }

    int32_t i32(const char *what) { return int32_t(load32(bytes(4, what))); }

    // A count of items of at least `itemBytes` bytes each, checked against the bytes left so that
    // nothing is reserved for items the chunk cannot hold.
    size_t count(uint64_t itemBytes, const char *what) {
        const int32_t n = i32(what);
        if (n < 0) fail(std::string(what) + " is negative (" + std::to_string(n) + ")");
        if (uint64_t(n) * itemBytes > remaining())
            fail(std::string(what) + " " + std::to_string(n) + " needs at least " +
                 std::to_string(uint64_t(n) * itemBytes) + " bytes but only " + std::to_string(remaining()) +
                 " remain in the chunk");
        return size_t(n);
    }

    std::string string(const char *what) {
        const size_t length = count(1, what);
        const uint8_t *p = bytes(length, what);
        return std::string(reinterpret_cast<const char *>(p), length);
    }

    Dict dict(const char *what) {
        Dict dict(count(8, what));  // each pair holds two 4-byte lengths at least
        for (auto &[key, value] : dict) {
            key = string("dictionary key");
            value = string("dictionary value");
        }
        return dict;
    }

private:
    const uint8_t *data_;
    const Chunk &chunk_;
    uint64_t pos_;
};

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

// `_r`: bits 0-1 and 2-3 are the columns of the non-zero entries of rows 0 and 1 (row 2 takes the
// remaining column), bits 4, 5, 6 negate rows 0, 1, 2 (vox-spec-extension.txt (c)).
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
        if (!parseInt(token, INT32_MIN, INT32_MAX, v)) fail();
        t[axis] = float(v);
        rest.remove_prefix(token.size());
    }
    if (rest.find_first_not_of(' ') != std::string_view::npos) fail();
    return t;
}

// `_f`, 0 when absent.
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

Palette decodePalette(const uint32_t (&entries)[256]) {
    Palette palette;
    for (size_t c = 0; c < 256; ++c)
        palette.colours[c] = Rgb{uint8_t(entries[c]), uint8_t(entries[c] >> 8), uint8_t(entries[c] >> 16)};
    return palette;
}

// Reads MAIN's children into a VoxFile.
class VoxParser {
public:
    explicit VoxParser(const uint8_t *data) : data_(data) {}

    VoxFile parse(const Chunk &main) {
        file_.palette = voxDefaultPalette();
        for (size_t c = 1; c < 256; ++c) file_.alpha[c] = uint8_t(kDefaultPalette[c] >> 24);
        file_.defaultPalette = true;

        for (uint64_t offset = main.contentEnd; offset < main.childrenEnd;) {
            const Chunk chunk = readChunk(data_, offset, main.childrenEnd, "chunk 'MAIN'");
            dispatch(chunk);
            offset = chunk.childrenEnd;
        }
        closeModel(nullptr);
        if (file_.models.empty())
            throw FormatError("the file holds no model (no SIZE and XYZI chunks in chunk 'MAIN')");
        resolveSceneGraph();
        file_.frameCount = countFrames();
        return std::move(file_);
    }

private:
    // A SIZE chunk waiting for its XYZI.
    struct PendingSize {
        Chunk chunk;
        int size[3] = {0, 0, 0};
        std::string strayChunk;  // the first other chunk met before the XYZI
    };

    void dispatch(const Chunk &chunk) {
        ContentReader in(data_, chunk);
        const std::string &id = chunk.id;
        if (id == "SIZE") return readSize(chunk, in);
        if (id == "XYZI") return readVoxels(in);
        if (pending_ && pending_->strayChunk.empty()) pending_->strayChunk = id;
        if (id == "RGBA") return readPalette(in);
        if (id == "nTRN") return readTransform(chunk, in);
        if (id == "nGRP") return readGroup(chunk, in);
        if (id == "nSHP") return readShape(chunk, in);
        if (id == "LAYR") return readLayer(in);
        if (id == "PACK") file_.packed = true;  // its model count is implied by the SIZE/XYZI pairs
        // Anything else (MATL, MATT, rOBJ, rCAM, NOTE, IMAP, unknown ids) is skipped by its size.
    }

    void readSize(const Chunk &chunk, ContentReader &in) {
        closeModel(&chunk);
        PendingSize pending;
        pending.chunk = chunk;
        for (int &side : pending.size) side = in.i32("model size");
        const int *s = pending.size;
        const auto sizeText = [&] {
            return std::to_string(s[0]) + " x " + std::to_string(s[1]) + " x " + std::to_string(s[2]);
        };
        for (int side : pending.size)
            if (side < 1 || side > kMaxVolumeSide)
                in.fail("model " + std::to_string(file_.models.size()) + " has size " + sizeText() +
                        "; each side must be in 1.." + std::to_string(kMaxVolumeSide));
        if (file_.models.size() >= size_t(kMaxVoxModels))
            in.fail("more than " + std::to_string(kMaxVoxModels) + " models");
        columns_ += uint64_t(s[0]) * uint64_t(s[1]);
        if (columns_ > kMaxVoxColumns)
            in.fail("model " + std::to_string(file_.models.size()) + " (" + sizeText() +
                    ") takes the models' columns to " + std::to_string(columns_) + ", over the limit of " +
                    std::to_string(kMaxVoxColumns) + " (sizeX * sizeY summed over models)");
        pending_ = std::move(pending);
    }

    // Errors unless the previous SIZE got its XYZI. `next` is the chunk that ends the wait (null
    // at the end of MAIN).
    void closeModel(const Chunk *next) {
        if (!pending_) return;
        std::string problem = "model " + std::to_string(file_.models.size()) + ": " + pending_->chunk.where() +
                              " has no XYZI chunk after it";
        if (!pending_->strayChunk.empty())
            problem +=
                " (found '" + pending_->strayChunk + "' instead" +
                (pending_->strayChunk == "TDCZ" ? ": Teardown's compressed TDCZ voxel chunks are not supported" : "") +
                ")";
        else if (next != nullptr)
            problem += " (" + next->where() + " follows it)";
        throw FormatError(problem);
    }

    // XYZI lists voxels in any order, possibly repeated (the last wins); the volume builder wants
    // them column by column (y * sizeX + x) with increasing z, so they are sorted on a key that
    // ends with the voxel's position in the list.
    void readVoxels(ContentReader &in) {
        const std::string model = "model " + std::to_string(file_.models.size());
        if (!pending_) in.fail(model + ": an XYZI chunk without a SIZE chunk before it");
        const int sx = pending_->size[0], sy = pending_->size[1], sz = pending_->size[2];
        const size_t count = in.count(4, "voxel count");
        const uint8_t *voxels = in.bytes(4 * uint64_t(count), "voxels");

        std::vector<uint64_t> keys(count);
        for (size_t i = 0; i < count; ++i) {
            const uint8_t *v = voxels + 4 * i;
            if (v[0] >= sx || v[1] >= sy || v[2] >= sz)
                in.fail(model + ": voxel " + std::to_string(i) + " at (" + std::to_string(v[0]) + ", " +
                        std::to_string(v[1]) + ", " + std::to_string(v[2]) + ") lies outside the model's size " +
                        std::to_string(sx) + " x " + std::to_string(sy) + " x " + std::to_string(sz));
            const uint64_t column = uint64_t(v[1]) * uint64_t(sx) + v[0];  // < 2^22, z < 2^8, i < 2^32
            keys[i] = column << 40 | uint64_t(v[2]) << 32 | i;
        }
        if (!std::is_sorted(keys.begin(), keys.end())) std::sort(keys.begin(), keys.end());

        VoxelVolumeBuilder builder(sx, sy, sz);
        for (size_t k = 0; k < count; ++k) {
            if (k + 1 < count && keys[k + 1] >> 32 == keys[k] >> 32) continue;  // a later voxel replaces it
            const uint8_t *v = voxels + 4 * (keys[k] & 0xffffffffu);
            if (v[3] == 0) continue;                        // colour index 0 is empty
            builder.add(v[0], v[1], v[2], Voxel{v[3], 0});  // in order by construction
        }
        file_.models.push_back(builder.finish());
        pending_.reset();
    }

    void readPalette(ContentReader &in) {
        const uint8_t *rgba = in.bytes(kRgbaBytes, "the RGBA palette (256 entries)");
        // Colour index c is entry c - 1 (vox-spec-base.txt §7); the last entry is unused.
        file_.palette.colours[0] = Rgb{};
        file_.alpha[0] = 0;
        for (size_t c = 1; c < 256; ++c) {
            const uint8_t *e = rgba + 4 * (c - 1);
            file_.palette.colours[c] = Rgb{e[0], e[1], e[2]};
            file_.alpha[c] = e[3];
        }
        file_.defaultPalette = false;
    }

    // Starts a node: its id, its attributes and where it came from.
    VoxNode &beginNode(VoxNodeKind kind, const Chunk &chunk, ContentReader &in, Dict &attributes) {
        VoxNode node;
        node.kind = kind;
        node.id = in.i32("node id");
        attributes = in.dict("node attribute count");
        node.hidden = isHidden(attributes);
        file_.nodes.push_back(std::move(node));
        nodeChunks_.push_back(chunk);
        childIds_.emplace_back();
        return file_.nodes.back();
    }

    void readTransform(const Chunk &chunk, ContentReader &in) {
        Dict attributes;
        VoxNode &node = beginNode(VoxNodeKind::Transform, chunk, in, attributes);
        if (const std::string *name = lookup(attributes, "_name")) node.name = *name;
        childIds_.back().push_back(in.i32("child node id"));
        in.i32("reserved id");
        node.layer = in.i32("layer id");
        const size_t frames = in.count(4, "frame count");
        if (frames == 0)
            in.fail("node " + std::to_string(node.id) + " has no frames (the frame count must be at least 1)");
        node.transformKeys.reserve(frames);
        for (size_t f = 0; f < frames; ++f) {
            const Dict dict = in.dict("frame attribute count");
            const std::string where = "node " + std::to_string(node.id) + " frame " + std::to_string(f);
            VoxTransformKey key;
            key.frame = parseFrame(dict, in, where);
            if (const std::string *r = lookup(dict, "_r")) key.transform = parseRotation(*r, in, where);
            if (const std::string *t = lookup(dict, "_t"))
                key.transform[3] = glm::vec4(parseTranslation(*t, in, where), 1.0f);
            node.transformKeys.push_back(key);
        }
        std::stable_sort(node.transformKeys.begin(), node.transformKeys.end(),
                         [](const VoxTransformKey &a, const VoxTransformKey &b) { return a.frame < b.frame; });
    }

    void readGroup(const Chunk &chunk, ContentReader &in) {
        Dict attributes;
        beginNode(VoxNodeKind::Group, chunk, in, attributes);
        const size_t children = in.count(4, "child count");
        std::vector<int> &ids = childIds_.back();
        ids.reserve(children);
        for (size_t c = 0; c < children; ++c) ids.push_back(in.i32("child node id"));
    }

    void readShape(const Chunk &chunk, ContentReader &in) {
        Dict attributes;
        VoxNode &node = beginNode(VoxNodeKind::Shape, chunk, in, attributes);
        const size_t models = in.count(8, "model count");
        if (models == 0)
            in.fail("node " + std::to_string(node.id) + " shows no model (the model count must be at least 1)");
        node.shapeKeys.reserve(models);
        for (size_t m = 0; m < models; ++m) {
            VoxShapeKey key;
            key.model = in.i32("model id");
            key.frame = parseFrame(in.dict("model attribute count"), in,
                                   "node " + std::to_string(node.id) + " model entry " + std::to_string(m));
            node.shapeKeys.push_back(key);  // model ids are checked once every model is read
        }
        std::stable_sort(node.shapeKeys.begin(), node.shapeKeys.end(),
                         [](const VoxShapeKey &a, const VoxShapeKey &b) { return a.frame < b.frame; });
    }

    void readLayer(ContentReader &in) {
        VoxLayer layer;
        layer.id = in.i32("layer id");
        const Dict attributes = in.dict("layer attribute count");
        if (const std::string *name = lookup(attributes, "_name")) layer.name = *name;
        layer.hidden = isHidden(attributes);
        file_.layers.push_back(std::move(layer));
    }

    std::string nodeLabel(size_t index) const {
        return "node " + std::to_string(file_.nodes[index].id) + " (" + nodeChunks_[index].where() + ")";
    }

    // Turns child node ids into indices and checks model ids, then the shape of the graph.
    void resolveSceneGraph() {
        if (file_.nodes.empty()) return;
        std::unordered_map<int, int> indexOf;
        for (size_t i = 0; i < file_.nodes.size(); ++i)
            if (!indexOf.emplace(file_.nodes[i].id, int(i)).second)
                throw FormatError(nodeLabel(i) + ": node id " + std::to_string(file_.nodes[i].id) + " is used twice");
        const auto root = indexOf.find(0);
        if (root == indexOf.end()) throw FormatError("the scene graph has no root (no node with id 0)");
        file_.root = root->second;

        for (size_t i = 0; i < file_.nodes.size(); ++i) {
            VoxNode &node = file_.nodes[i];
            for (int id : childIds_[i]) {
                const auto child = indexOf.find(id);
                if (child == indexOf.end())
                    throw FormatError(nodeLabel(i) + " refers to child node " + std::to_string(id) +
                                      ", which the file does not define");
                node.children.push_back(child->second);
            }
            for (const VoxShapeKey &key : node.shapeKeys)
                if (key.model < 0 || size_t(key.model) >= file_.models.size())
                    throw FormatError(nodeLabel(i) + " shows model " + std::to_string(key.model) +
                                      " but the file has " + std::to_string(file_.models.size()) + " models");
        }
        checkGraphShape();
    }

    // From the root: no cycle, at most kMaxVoxGraphDepth levels, at most kMaxVoxInstances shape
    // instances showing at most kMaxVoxShownVoxels voxels. Iterative, so a long chain cannot
    // overflow the stack; shared nodes are visited once and their subtree's figures reused.
    void checkGraphShape() const {
        enum : uint8_t { kUnvisited, kOnPath, kDone };
        const size_t n = file_.nodes.size();
        size_t heldVoxels = 0;
        for (const VoxelVolume &model : file_.models) heldVoxels += model.voxelCount();
        const size_t maxShown = std::max(kMaxVoxShownVoxels, heldVoxels);
        std::vector<uint8_t> state(n, kUnvisited);
        std::vector<size_t> height(n, 0), instances(n, 0), shown(n, 0);
        struct Step {
            int node;
            size_t nextChild;
        };
        std::vector<Step> path{{file_.root, 0}};
        state[size_t(file_.root)] = kOnPath;
        while (!path.empty()) {
            const int current = path.back().node;
            const VoxNode &node = file_.nodes[size_t(current)];
            if (path.back().nextChild < node.children.size()) {
                const int child = node.children[path.back().nextChild++];
                if (state[size_t(child)] == kOnPath)
                    throw FormatError("the scene graph has a cycle: " + nodeLabel(size_t(child)) +
                                      " is its own descendant (through node " + std::to_string(node.id) + ")");
                if (state[size_t(child)] == kUnvisited) {
                    state[size_t(child)] = kOnPath;
                    path.push_back({child, 0});
                }
                continue;
            }
            size_t h = 0, count = node.kind == VoxNodeKind::Shape ? 1 : 0, voxels = 0;
            for (const VoxShapeKey &key : node.shapeKeys)
                voxels = std::max(voxels, file_.models[size_t(key.model)].voxelCount());
            for (int child : node.children) {
                h = std::max(h, height[size_t(child)]);
                count = std::min(count + instances[size_t(child)], kMaxVoxInstances + 1);  // saturate
                voxels = std::min(voxels + shown[size_t(child)], maxShown + 1);
            }
            height[size_t(current)] = h + 1;
            instances[size_t(current)] = count;
            shown[size_t(current)] = voxels;
            state[size_t(current)] = kDone;
            path.pop_back();
        }
        const size_t root = size_t(file_.root);
        if (height[root] > size_t(kMaxVoxGraphDepth))
            throw FormatError("the scene graph is " + std::to_string(height[root]) +
                              " levels deep, over the limit of " + std::to_string(kMaxVoxGraphDepth));
        if (instances[root] > kMaxVoxInstances)
            throw FormatError("the scene graph expands to more than " + std::to_string(kMaxVoxInstances) +
                              " shape instances");
        if (shown[root] > maxShown)
            throw FormatError("the scene graph's shape instances show more than " + std::to_string(maxShown) +
                              " voxels in all (the larger of " + std::to_string(kMaxVoxShownVoxels) +
                              " and the voxels the models hold)");
    }

    int countFrames() const {
        if (file_.nodes.empty()) return file_.packed ? int(file_.models.size()) : 1;
        int last = 0;
        for (const VoxNode &node : file_.nodes) {
            for (const VoxTransformKey &key : node.transformKeys) last = std::max(last, key.frame);
            for (const VoxShapeKey &key : node.shapeKeys) last = std::max(last, key.frame);
        }
        return last + 1;
    }

    const uint8_t *data_;
    VoxFile file_;
    std::optional<PendingSize> pending_;
    uint64_t columns_ = 0;
    // Per entry of file_.nodes, until the graph is resolved: its chunk and its children's ids.
    std::vector<Chunk> nodeChunks_;
    std::vector<std::vector<int>> childIds_;
};

}  // namespace

Palette voxDefaultPalette() { return decodePalette(kDefaultPalette); }

VoxFile readVox(const uint8_t *data, size_t size) {
    static const uint8_t kMagic[4] = {'V', 'O', 'X', ' '};
    // A file shorter than the magic but matching it so far is a truncated .vox, not another format.
    if (size > 0 && std::memcmp(data, kMagic, std::min<size_t>(size, 4)) != 0)
        throw FormatError("not a MagicaVoxel file: it does not start with \"VOX \"");
    if (size < 8)
        throw FormatError("truncated: the 8-byte header (\"VOX \" and the version) needs 8 bytes but the file has " +
                          std::to_string(size));
    const int32_t version = int32_t(load32(data + 4));
    if (version != 150 && version != 200)
        throw FormatError("unsupported version " + std::to_string(version) + " (known: 150 and 200)");

    const Chunk main = readChunk(data, 8, size, "the file");
    if (main.id != "MAIN") throw FormatError(main.where() + ": the first chunk must be 'MAIN'");
    VoxFile file = VoxParser(data).parse(main);  // bytes after MAIN are ignored
    file.version = version;
    return file;
}

}  // namespace voxelfair
