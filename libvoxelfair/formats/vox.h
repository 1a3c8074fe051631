// MagicaVoxel .vox reader (file versions 150 and 200). Byte layout: the MagicaVoxel
// author's public spec (MagicaVoxel-file-format-vox.txt and its extension; doc/formats/magicavoxel.md).
//
// Coordinates are MagicaVoxel's, kept as they are: right-handed, z up ("gravity direction"), one
// unit per voxel -- the same frame as Westwood VXL, so both formats reach the scene layer alike.
// Voxel (x, y, z) of a model is the unit cube [x, x+1] x [y, y+1] x [z, z+1].
//
// The reader keeps the scene graph as the file states it, keyframes included: which models are
// shown where depends on the animation frame, and scene/vox_scene.h flattens it for one frame.
#pragma once

#include "formats/palette.h"
#include "formats/vox_materials.h"
#include "volume/voxel_volume.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace voxelfair {

// Limits that keep a hostile file from making the reader allocate or recurse without bound.
// Each model's column index (sizeX * sizeY entries) is allocated from a 12-byte SIZE chunk, so
// the sum is capped rather than trusted: 2^24 columns (64 MiB of index) hold 256 models of
// MagicaVoxel's largest 256 x 256 footprint.
constexpr size_t kMaxVoxColumns = size_t(1) << 24;
constexpr int kMaxVoxModels = 65536;
// Nodes may be shared (vengi writes one shape under several transforms), so a small graph could
// expand to exponentially many instances; real scenes nest a few levels and hold thousands.
constexpr int kMaxVoxGraphDepth = 256;
constexpr size_t kMaxVoxInstances = size_t(1) << 20;
// Each instance shows its model's voxels again, so a few hundred bytes of graph over one large
// model could show billions. The voxels shown (summed over instances, a shape counted with its
// largest keyframe model) are capped at 2^24, one full 256^3 model, or at the voxels the models
// hold when that is more (8ontop shows 12096, test-transform 621232).
constexpr size_t kMaxVoxShownVoxels = size_t(1) << 24;

// One keyframe of a transform node (nTRN): its placement from `frame` on.
struct VoxTransformKey {
    int frame = 0;              // `_f`
    glm::mat4 transform{1.0f};  // child space -> parent space: rotation `_r`, then translation `_t`
};

// One keyframe of a shape node (nSHP): the model it shows from `frame` on.
struct VoxShapeKey {
    int frame = 0;  // `_f`
    int model = 0;  // index into VoxFile::models
};

enum class VoxNodeKind { Transform, Group, Shape };

struct VoxNode {
    VoxNodeKind kind = VoxNodeKind::Group;
    int id = 0;                 // the node id in the file
    std::string name;           // `_name` (MagicaVoxel names transform nodes)
    bool hidden = false;        // `_hidden` is "1"
    int layer = -1;             // transform nodes: a LAYR id, -1 for none
    std::vector<int> children;  // indices into VoxFile::nodes; a transform has exactly one
    // Sorted by frame, at least one for a transform (transformKeys) or a shape (shapeKeys).
    std::vector<VoxTransformKey> transformKeys;
    std::vector<VoxShapeKey> shapeKeys;
};

struct VoxLayer {
    int id = 0;
    std::string name;
    bool hidden = false;
};

struct VoxFile {
    int version = 150;
    // Model id = index (the order of the SIZE/XYZI pairs). Voxel::colour is the colour index
    // (1..255), Voxel::normal is 0.
    std::vector<VoxelVolume> models;
    // colours[c] and alpha[c] belong to colour index c, i.e. the file's RGBA entry c - 1; index 0
    // (empty) is black with alpha 0.
    Palette palette;
    std::array<uint8_t, 256> alpha{};
    bool defaultPalette = false;  // no RGBA chunk: the spec's default palette is used
    // MATL chunks by colour index (formats/vox_materials.h); all _diffuse when the file has none.
    VoxMaterialTable materials;

    // The scene graph in file order (empty when the file has none); `root` indexes node id 0.
    std::vector<VoxNode> nodes;
    int root = -1;
    std::vector<VoxLayer> layers;

    // A PACK chunk (MagicaVoxel 0.98): without a scene graph its models are animation frames.
    bool packed = false;
    // Animation frames: 1 + the largest `_f` of the scene graph; for a PACK animation, the
    // number of models; otherwise 1.
    int frameCount = 1;
};

// Parses a whole .vox file. A model is a SIZE followed by an XYZI, or by Teardown's zlib-compressed
// TDCZ (formats/vox_tdcz.h). Unknown chunks (and the children of known ones) are skipped by their
// sizes; MATL chunks fill VoxFile::materials (vox_materials.h); MATT (deprecated), rOBJ, rCAM, NOTE
// and IMAP are skipped too (IMAP only reorders the editor's palette view, not the colours). Throws FormatError saying what is wrong and where ("chunk
// 'nTRN' at byte 1234: ..."): bad magic or version, truncation, a chunk past its parent, a SIZE
// without voxels, voxels outside their model, corrupt or short compressed voxels, bad rotations or
// translations, missing or cyclic node references, and the limits above. Never reads out of
// bounds, and allocates in proportion to the bytes present (within those limits).
VoxFile readVox(const uint8_t *data, size_t size);

// The palette the spec prescribes when a file has no RGBA chunk (entry c is colour index c).
Palette voxDefaultPalette();

}  // namespace voxelfair
