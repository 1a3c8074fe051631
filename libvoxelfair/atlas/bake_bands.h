// The bake's bands of rows (bake.cpp paints each band on a thread of its own, only its rows):
// where the texture's rows are cut, and which faces each band takes, in face order.
//
// The cut only balances the threads, never changes a texel (each band paints every face that
// reaches it, in order, on its rows only): the rows are cut where the faces, counted at the
// lowest row they reach, pass multiples of faces / bands, so each band holds about as many faces
// (the 185k sphere at 2 texels per voxel, four bands of equal rows: 50k, 56k, 54k and 24k faces).
// A face reaches rows floor(min y - 1 - margin) to floor(max y + margin) of its conservative
// raster (margin < 0), its thin-face points floor(min y - kUvRounding) to floor(max y +
// kUvRounding), all clamped onto the texture: the first and last bands take the faces beyond it.
// The faces are sorted into bands once, in shares of the faces (one per worker), each listing its
// faces band by band in order: a band reads its faces in order without looking at the others.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace voxelfair {

struct BakeBands {
    std::vector<int> start;  // band b holds rows start[b] .. start[b + 1] - 1 (y up); count() + 1 entries
    size_t faceCount = 0;
    size_t shares = 0;                         // 0 with one band: it takes every face
    std::vector<std::vector<uint32_t>> faces;  // [share * count() + band]: the share's faces reaching the band

    size_t count() const { return start.size() - 1; }
    int rowFrom(size_t band) const { return start[band]; }
    int rowTo(size_t band) const { return start[band + 1] - 1; }
    // visit(f) for every face the band takes, in face order.
    template <class Visit>
    void forEachFace(size_t band, Visit &&visit) const {
        if (shares == 0) {
            for (size_t f = 0; f < faceCount; ++f)
                visit(f);
            return;
        }
        for (size_t share = 0; share < shares; ++share)
            for (const uint32_t f : faces[share * count() + band])
                visit(size_t(f));
    }
};

// `bands` bands (at most `height`; 1: all rows, every face, nothing sorted) of a texture
// `height` rows high for the faces of `wedgeUv` (3 UVs per face, v up), sorted on up to `workers`
// threads.
BakeBands bakeBands(const std::vector<glm::vec2> &wedgeUv, int height, size_t bands, int workers);

}  // namespace voxelfair
