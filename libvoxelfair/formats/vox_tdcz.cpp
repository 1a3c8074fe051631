// See vox_tdcz.h.
#include "formats/vox_tdcz.h"

#include <climits>
#include <vector>

#include <zlib.h>

namespace voxelfair::vox {

namespace {

// Inflates until `out` is full, without requiring the stream's end or its checksum.
void inflateInto(const uint8_t *in, uint64_t inBytes, std::vector<uint8_t> &out, const ContentReader &reader,
                 const std::string &model) {
    z_stream stream{};
    if (inflateInit(&stream) != Z_OK)
        reader.fail(model + ": zlib could not start inflating");
    struct End {
        z_stream &s;
        ~End() { inflateEnd(&s); }
    } end{stream};
    uint64_t inLeft = inBytes, outDone = 0;
    const uint8_t *next = in;
    while (outDone < out.size()) {
        const uInt inChunk = uInt(std::min<uint64_t>(inLeft, UINT_MAX));
        const uInt outChunk = uInt(std::min<uint64_t>(out.size() - outDone, UINT_MAX));
        stream.next_in = const_cast<Bytef *>(next);
        stream.avail_in = inChunk;
        stream.next_out = out.data() + outDone;
        stream.avail_out = outChunk;
        const int result = inflate(&stream, Z_SYNC_FLUSH);
        next += inChunk - stream.avail_in;
        inLeft -= inChunk - stream.avail_in;
        outDone += outChunk - stream.avail_out;
        if (result == Z_DATA_ERROR || result == Z_NEED_DICT || result == Z_MEM_ERROR || result == Z_STREAM_ERROR)
            reader.fail(model + ": corrupt zlib data in the compressed voxels after " + std::to_string(outDone) +
                        " of " + std::to_string(out.size()) + " bytes (" +
                        (stream.msg != nullptr ? stream.msg : "zlib error " + std::to_string(result)) + ")");
        if (outDone == out.size())
            break;
        const bool stuck = stream.avail_in == inChunk && stream.avail_out == outChunk;  // no progress
        if (result == Z_STREAM_END || stuck)
            reader.fail(model + ": the compressed voxels end after " + std::to_string(outDone) + " of the " +
                        std::to_string(out.size()) + " bytes the model's size needs");
    }
}

}  // namespace

VoxelVolume readTdcz(ContentReader &in, const int (&size)[3], const std::string &model) {
    int sides[3];
    for (int &side : sides)
        side = in.i32("TDCZ model size");
    if (sides[0] != size[0] || sides[1] != size[1] || sides[2] != size[2])
        in.fail(model + ": the compressed voxels' size " + std::to_string(sides[0]) + " x " + std::to_string(sides[1]) +
                " x " + std::to_string(sides[2]) + " differs from the SIZE chunk's " + std::to_string(size[0]) + " x " +
                std::to_string(size[1]) + " x " + std::to_string(size[2]));
    const uint64_t sx = uint64_t(size[0]), sy = uint64_t(size[1]), sz = uint64_t(size[2]);
    const uint64_t voxels = sx * sy * sz;
    const uint64_t compressed = in.remaining();
    if (voxels > kMaxTdczVoxels)
        in.fail(model + ": " + std::to_string(voxels) + " compressed voxels, over the limit of " +
                std::to_string(kMaxTdczVoxels));
    if (voxels > compressed * kMaxDeflateRatio + 64)
        in.fail(model + ": " + std::to_string(compressed) + " compressed bytes cannot hold the " +
                std::to_string(voxels) + " voxels of the model's size (deflate expands at most 1032:1)");
    const uint8_t *stream = in.bytes(compressed, "compressed voxels");

    std::vector<uint8_t> dense(voxels);
    inflateInto(stream, compressed, dense, in, model);

    VoxelVolumeBuilder builder(size[0], size[1], size[2]);
    for (uint64_t y = 0; y < sy; ++y)
        for (uint64_t x = 0; x < sx; ++x)
            for (uint64_t z = 0; z < sz; ++z) {
                const uint8_t colour = dense[x + sx * (y + sy * z)];
                if (colour != 0)
                    builder.add(int(x), int(y), int(z), Voxel{colour, 0});  // in order by construction
            }
    return builder.finish();
}

}  // namespace voxelfair::vox
