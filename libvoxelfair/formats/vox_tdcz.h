// Teardown's compressed voxel chunk TDCZ (private to the VOX reader). Teardown's tools write it in
// place of XYZI after a SIZE: three uint32 sizes, then a zlib stream (RFC 1950/1951) of
// x * y * z bytes, one colour index per voxel (0 = empty), x fastest, then y, then z -- the
// layout vengi's copy of ogt_vox reads.
//
// Teardown compresses in blocks with a sync flush and never finishes the stream: there is no
// final block and no Adler-32. So the stream is decoded until x * y * z bytes are out; a stream
// that ends or breaks before that is an error, its end and checksum are not required.
#pragma once

#include "formats/vox_chunks.h"
#include "volume/voxel_volume.h"

namespace voxelfair::vox {

// Deflate expands at most 1032:1; a TDCZ claiming more voxels than its compressed bytes can hold
// is refused before anything is allocated, so allocation stays proportional to the input. Each
// model is also capped at 2^27 voxels (a 512^3 cube; Teardown's and MagicaVoxel's models are at
// most 256 a side).
constexpr uint64_t kMaxDeflateRatio = 1032;
constexpr uint64_t kMaxTdczVoxels = uint64_t(1) << 27;

// Reads a TDCZ chunk's content for the model whose SIZE gave `size`; `model` names it ("model 3").
// Throws FormatError (naming the chunk) for sizes that differ from the SIZE, over the limits,
// corrupt zlib data, or a stream shorter than the voxels.
VoxelVolume readTdcz(ContentReader &in, const int (&size)[3], const std::string &model);

}  // namespace voxelfair::vox
