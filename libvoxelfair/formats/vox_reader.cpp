// See vox.h. Chunk reading is in vox_chunks.h, the default palette in vox_default_palette.cpp,
// the scene graph's checks in vox_scene_graph.h, Teardown's TDCZ in vox_tdcz.h; this file reads
// MAIN's children into a VoxFile.
#include "formats/vox.h"

#include "formats/byte_reader.h"
#include "formats/format_error.h"
#include "formats/vox_chunks.h"
#include "formats/vox_scene_graph.h"
#include "formats/vox_tdcz.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace voxelfair {

namespace {

using vox::Chunk;
using vox::ContentReader;
using vox::Dict;
using vox::lookup;
using vox::readChunk;

// The RGBA chunk holds 256 entries, but only the first 255 colour anything (entry c - 1 colours
// index c); Teardown writes just those 255 (1020 bytes), so that is all that is required.
constexpr uint64_t kRgbaUsedBytes = 255 * 4;

// Reads MAIN's children into a VoxFile.
class VoxParser {
public:
    explicit VoxParser(const ByteReader &data) : data_(data) {}

    VoxFile parse(const Chunk &main) {
        file_.palette = voxDefaultPalette();
        for (size_t c = 1; c < 256; ++c)
            file_.alpha[c] = uint8_t(vox::kDefaultPalette[c] >> 24);
        file_.defaultPalette = true;

        for (uint64_t offset = main.contentEnd; offset < main.childrenEnd;) {
            const Chunk chunk = readChunk(data_, offset, main.childrenEnd, "chunk 'MAIN'");
            dispatch(chunk);
            offset = chunk.childrenEnd;
        }
        closeModel(nullptr);
        if (file_.models.empty())
            throw FormatError("the file holds no model (no SIZE and XYZI chunks in chunk 'MAIN')");
        vox::resolveSceneGraph(file_, childIds_, nodeChunks_);
        file_.frameCount = vox::countFrames(file_);
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
        if (id == "SIZE")
            return readSize(chunk, in);
        if (id == "XYZI")
            return readVoxels(in);
        if (id == "TDCZ")
            return readCompressedVoxels(in);
        if (pending_ && pending_->strayChunk.empty())
            pending_->strayChunk = id;
        if (id == "RGBA")
            return readPalette(in);
        if (id == "nTRN")
            return readTransform(chunk, in);
        if (id == "nGRP")
            return readGroup(chunk, in);
        if (id == "nSHP")
            return readShape(chunk, in);
        if (id == "LAYR")
            return readLayer(in);
        if (id == "MATL")
            return readMaterial(in);
        if (id == "PACK")
            file_.packed = true;  // its model count is implied by the SIZE/XYZI pairs
        // Anything else (MATT, rOBJ, rCAM, NOTE, IMAP, unknown ids) is skipped by its size.
    }

    void readMaterial(ContentReader &in) {
        const int32_t id = in.i32("material id");
        const Dict properties = in.dict("material property count");
        applyVoxMaterial(id, properties, file_.materials);
    }

    void readSize(const Chunk &chunk, ContentReader &in) {
        closeModel(&chunk);
        PendingSize pending;
        pending.chunk = chunk;
        for (int &side : pending.size)
            side = in.i32("model size");
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
        if (!pending_)
            return;
        std::string problem = "model " + std::to_string(file_.models.size()) + ": " + pending_->chunk.where() +
                              " has no XYZI (or TDCZ) chunk after it";
        if (!pending_->strayChunk.empty())
            problem += " (found '" + pending_->strayChunk + "' instead)";
        else if (next != nullptr)
            problem += " (" + next->where() + " follows it)";
        throw FormatError(problem);
    }

    // XYZI lists voxels in any order, possibly repeated (the last wins); the volume builder wants
    // them column by column (y * sizeX + x) with increasing z, so they are sorted on a key that
    // ends with the voxel's position in the list.
    void readVoxels(ContentReader &in) {
        const std::string model = "model " + std::to_string(file_.models.size());
        if (!pending_)
            in.fail(model + ": an XYZI chunk without a SIZE chunk before it");
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
        if (!std::is_sorted(keys.begin(), keys.end()))
            std::sort(keys.begin(), keys.end());

        VoxelVolumeBuilder builder(sx, sy, sz);
        for (size_t k = 0; k < count; ++k) {
            if (k + 1 < count && keys[k + 1] >> 32 == keys[k] >> 32)
                continue;  // a later voxel replaces it
            const uint8_t *v = voxels + 4 * (keys[k] & 0xffffffffu);
            if (v[3] == 0)
                continue;                                   // colour index 0 is empty
            builder.add(v[0], v[1], v[2], Voxel{v[3], 0});  // in order by construction
        }
        file_.models.push_back(builder.finish());
        pending_.reset();
    }

    // Teardown's TDCZ in place of an XYZI: a zlib stream of the dense volume (vox_tdcz.h).
    void readCompressedVoxels(ContentReader &in) {
        const std::string model = "model " + std::to_string(file_.models.size());
        if (!pending_)
            in.fail(model + ": a TDCZ chunk without a SIZE chunk before it");
        file_.models.push_back(vox::readTdcz(in, pending_->size, model));
        pending_.reset();
    }

    void readPalette(ContentReader &in) {
        const uint8_t *rgba = in.bytes(kRgbaUsedBytes, "the RGBA palette (255 used entries)");
        // Colour index c is entry c - 1 (the base format text, RGBA chunk); the last entry is unused.
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
        node.hidden = vox::isHidden(attributes);
        file_.nodes.push_back(std::move(node));
        nodeChunks_.push_back(chunk);
        childIds_.emplace_back();
        return file_.nodes.back();
    }

    void readTransform(const Chunk &chunk, ContentReader &in) {
        Dict attributes;
        VoxNode &node = beginNode(VoxNodeKind::Transform, chunk, in, attributes);
        if (const std::string *name = lookup(attributes, "_name"))
            node.name = *name;
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
            key.frame = vox::parseFrame(dict, in, where);
            if (const std::string *r = lookup(dict, "_r"))
                key.transform = vox::parseRotation(*r, in, where);
            if (const std::string *t = lookup(dict, "_t"))
                key.transform[3] = glm::vec4(vox::parseTranslation(*t, in, where), 1.0f);
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
        for (size_t c = 0; c < children; ++c)
            ids.push_back(in.i32("child node id"));
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
            key.frame = vox::parseFrame(in.dict("model attribute count"), in,
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
        if (const std::string *name = lookup(attributes, "_name"))
            layer.name = *name;
        layer.hidden = vox::isHidden(attributes);
        file_.layers.push_back(std::move(layer));
    }

    const ByteReader &data_;
    VoxFile file_;
    std::optional<PendingSize> pending_;
    uint64_t columns_ = 0;
    // Per entry of file_.nodes, until the graph is resolved: its chunk and its children's ids.
    std::vector<Chunk> nodeChunks_;
    std::vector<std::vector<int>> childIds_;
};

}  // namespace

VoxFile readVox(const uint8_t *data, size_t size) {
    static const uint8_t kMagic[4] = {'V', 'O', 'X', ' '};
    // A file shorter than the magic but matching it so far is a truncated .vox, not another format.
    if (size > 0 && std::memcmp(data, kMagic, std::min<size_t>(size, 4)) != 0)
        throw FormatError("not a MagicaVoxel file: it does not start with \"VOX \"");
    if (size < 8)
        throw FormatError("truncated: the 8-byte header (\"VOX \" and the version) needs 8 bytes but the file has " +
                          std::to_string(size));
    const ByteReader bytes(data, size);
    const int32_t version = bytes.i32(4, "version");
    if (version != 150 && version != 200)
        throw FormatError("unsupported version " + std::to_string(version) + " (known: 150 and 200)");

    const Chunk main = readChunk(bytes, 8, size, "the file");
    if (main.id != "MAIN")
        throw FormatError(main.where() + ": the first chunk must be 'MAIN'");
    VoxFile file = VoxParser(bytes).parse(main);  // bytes after MAIN are ignored
    file.version = version;
    return file;
}

}  // namespace voxelfair
