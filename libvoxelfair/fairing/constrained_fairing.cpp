// The second fairing mode (constrained_fairing.h). What makes it fast (about 14 ms on a
// 100k-vertex sphere, benchmarks/fairing_benchmark.cpp):
// - work arrays in two reused blocks (Arena), not a vector each: no page faults per call;
// - a vertex's corners with their next and previous vertices in one counting-sorted list, from
//   which the twins, the creases and the sweeps' order come in one pass;
// - step 3 on offsets from the input, with n . d kept per vertex, so that an update reads only
//   its neighbours' 16-byte offsets; the Gauss-Seidel order split into waves of independent
//   vertices, updated four at a time in SSE registers (same result as the plain order);
// - a specialization for quad meshes (the voxel surface), and the hot loops in their own
//   functions with locals, in SSE where glm's vec3 code compiles to stack round trips.
#include "fairing/constrained_fairing.h"

#include "fairing/voxel_size.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#if defined(__SSE2__) || defined(_M_X64) || defined(_M_AMD64)
#include <emmintrin.h>
#define VOXELFAIR_SSE2 1
#endif

namespace voxelfair {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

#if defined(__GNUC__)
#define VOXELFAIR_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define VOXELFAIR_NOINLINE __declspec(noinline)
#else
#define VOXELFAIR_NOINLINE
#endif

// Index of the bit of 1 << i (i < 8) from (1 << i) * 0x1D >> 5 & 7 (a de Bruijn sequence).
constexpr uint8_t kBitIndex[8] = {0, 1, 6, 2, 7, 5, 4, 3};

enum class VertexKind : uint8_t {
    Free,           // fitted along its normal to its neighbours (moveFreeBlock)
    FreeIrregular,  // the same through the general path: more than kRegularValence neighbours,
                    // an edge-line neighbour or an edge left out of the fit
    EdgeLine,       // on a line of sharp edges: fitted to the planes of its polygons
    Pinned,         // sharp edges end or meet here, or not selected, or no usable polygon
    Skipped,        // non-finite coordinates
};
bool isFree(VertexKind kind) { return kind <= VertexKind::FreeIrregular; }

// Step 1's verdict on the edge of each corner (both corners of a manifold edge agree).
enum EdgeFlag : uint8_t { kConvex = 1, kConcave = 2, kSharp = 4 };
constexpr uint8_t kCrease = kConvex | kConcave;

// Neighbours of a regular free vertex as the sweeps read them (voxel surfaces have 3 to 6), and
// the vertex-index tiles the sweeps are ordered in (see Fairing::buildSlots).
constexpr uint32_t kRegularValence = 6;
constexpr uint32_t kTileSize = 16384;

[[maybe_unused]] bool isFinite(const glm::vec3 &p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

glm::vec3 normalizedOrZero(const glm::vec3 &v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f && length2 <= std::numeric_limits<float>::max() ? v * (1.0f / std::sqrt(length2))
                                                                            : glm::vec3(0.0f);
}

// Unit normal of polygon [first, last) from its vector area (Newell), exact for non-planar
// polygons too; a quad's vector area is half the cross product of its diagonals. `at(i)` is the
// position of polygonIndices[i].
template <class Position>
glm::vec3 areaNormal(const Position &at, uint32_t first, uint32_t last) {
    if (last - first == 4)
        return normalizedOrZero(glm::cross(at(first + 2) - at(first), at(first + 3) - at(first + 1)));
    glm::vec3 n(0.0f);
    for (uint32_t i = first; i < last; ++i) {
        const glm::vec3 a = at(i), b = at(i + 1 < last ? i + 1 : first);
        n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return normalizedOrZero(n);
}

// Work arrays carved out of big blocks: many vectors would each be mapped and faulted in anew on
// every call (the allocator hands big blocks back to the system), a few blocks of the same sizes
// are kept and reused by the allocator. rewind() goes back to a mark(): the arrays taken since
// are dead and their room serves the next ones.
class Arena {
public:
    explicit Arena(size_t bytes) { addBlock(bytes); }
    // `count` default-initialized (trivial types: uninitialized) elements.
    template <class T>
    T *take(size_t count) {
        if (used_ + bytes<T>(count) > size_)
            addBlock(bytes<T>(count));  // more than expected: the arrays already taken stay where they are
        T *items = reinterpret_cast<T *>(block_ + used_);
        std::uninitialized_default_construct_n(items, count);
        used_ += bytes<T>(count);
        return items;
    }
    struct Mark {
        size_t block, used;
    };
    Mark mark() const { return {blocks_.size() - 1, used_}; }
    void rewind(Mark mark) {
        block_ = blockStart(mark.block);
        size_ = sizes_[mark.block];
        used_ = mark.used;
    }
    // Bytes taken by `count` elements of T.
    template <class T>
    static size_t bytes(size_t count) {
        return (sizeof(T) * count + 63) & ~size_t(63);
    }

private:
    // Arrays start on 64-byte lines (whole-register loads need 16). Plain new, aligned by hand:
    // the allocator reuses a freed block of the same size for it (not always so with aligned new).
    void addBlock(size_t bytes) {
        blocks_.emplace_back(new std::byte[bytes + 63]);  // not zeroed
        sizes_.push_back(bytes);
        const uintptr_t start = reinterpret_cast<uintptr_t>(blocks_.back().get());
        block_ = blocks_.back().get() + ((64 - start % 64) % 64);
        size_ = bytes;
        used_ = 0;
    }
    std::byte *blockStart(size_t block) const {
        const uintptr_t start = reinterpret_cast<uintptr_t>(blocks_[block].get());
        return blocks_[block].get() + ((64 - start % 64) % 64);
    }
    std::vector<std::unique_ptr<std::byte[]>> blocks_;
    std::vector<size_t> sizes_;
    std::byte *block_ = nullptr;
    size_t size_ = 0, used_ = 0;
};

#ifdef VOXELFAIR_SSE2
// glm::vec3 in a register (w = 0) and back, 12 bytes each way; dot and cross with glm's order of
// operations, so glm's results.
__m128 load3(const glm::vec3 &v) {
    const __m128 xy = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(&v.x)));  // unaligned
    return _mm_movelh_ps(xy, _mm_load_ss(&v.z));
}
void store3(glm::vec3 &v, __m128 x) {
    _mm_storel_epi64(reinterpret_cast<__m128i *>(&v.x), _mm_castps_si128(x));
    _mm_store_ss(&v.z, _mm_movehl_ps(x, x));
}
float dot3(__m128 a, __m128 b) {
    const __m128 p = _mm_mul_ps(a, b);
    return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(p, _mm_shuffle_ps(p, p, 1)), _mm_movehl_ps(p, p)));
}
__m128 cross3(__m128 a, __m128 b) {
    constexpr int yzx = _MM_SHUFFLE(3, 0, 2, 1), zxy = _MM_SHUFFLE(3, 1, 0, 2);
    return _mm_sub_ps(_mm_mul_ps(_mm_shuffle_ps(a, a, yzx), _mm_shuffle_ps(b, b, zxy)),
                      _mm_mul_ps(_mm_shuffle_ps(a, a, zxy), _mm_shuffle_ps(b, b, yzx)));
}

// normalizedOrZero of four vectors (lanes x, y, z; w = 0) at once, with the same operations, so
// the same results: length2 = (x x + y y) + z z, then v * (1 / sqrt(length2)).
void normalizeFour(__m128 &a, __m128 &b, __m128 &c, __m128 &d) {
    __m128 x = a, y = b, z = c, w = d;
    _MM_TRANSPOSE4_PS(x, y, z, w);
    const __m128 length2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
    const __m128 valid = _mm_and_ps(_mm_cmpgt_ps(length2, _mm_setzero_ps()),
                                    _mm_cmple_ps(length2, _mm_set1_ps(std::numeric_limits<float>::max())));
    const __m128 scale = _mm_and_ps(valid, _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(length2)));
    a = _mm_mul_ps(a, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(0, 0, 0, 0)));
    b = _mm_mul_ps(b, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(1, 1, 1, 1)));
    c = _mm_mul_ps(c, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(2, 2, 2, 2)));
    d = _mm_mul_ps(d, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(3, 3, 3, 3)));
}
#endif

// normalizedOrZero of `count` vectors in place, `stride` bytes apart.
void normalizeAll(glm::vec3 *vectors, size_t count, size_t stride = sizeof(glm::vec3)) {
    auto at = [&](size_t i) { return reinterpret_cast<glm::vec3 *>(reinterpret_cast<char *>(vectors) + i * stride); };
    size_t i = 0;
#ifdef VOXELFAIR_SSE2
    // Four square roots and divisions in one instruction each (one at a time, they are most of
    // the cost). 12-byte loads and stores: the vectors are packed.
    for (; i + 4 <= count; i += 4) {
        __m128 a = load3(*at(i)), b = load3(*at(i + 1)), c = load3(*at(i + 2)), d = load3(*at(i + 3));
        normalizeFour(a, b, c, d);
        store3(*at(i), a);
        store3(*at(i + 1), b);
        store3(*at(i + 2), c);
        store3(*at(i + 3), d);
    }
#endif
    for (; i < count; ++i)
        *at(i) = normalizedOrZero(*at(i));
}

// Polygon connectivity by corners: corner c is polygonIndices[c] and the edge from it to the next
// vertex of its polygon. With kQuads (the voxel surface) a corner's polygon, next corner and
// opposite corner follow from c itself.
template <bool kQuads>
struct Polygons {
    const uint32_t *offsets;
    const uint32_t *indices;
    const uint32_t *polygonTable;  // corner -> polygon (unused with kQuads)

    uint32_t polygonOf(uint32_t c) const {
        if constexpr (kQuads)
            return c >> 2;
        else
            return polygonTable[c];
    }
    uint32_t first(size_t p) const { return kQuads ? uint32_t(4 * p) : offsets[p]; }
    uint32_t last(size_t p) const { return kQuads ? uint32_t(4 * p + 4) : offsets[p + 1]; }
    uint32_t arity(size_t p) const { return last(p) - first(p); }
    bool inQuad(uint32_t c) const { return kQuads || arity(polygonOf(c)) == 4; }
    uint32_t nextCorner(uint32_t c) const {
        if constexpr (kQuads) {
            return (c & ~3u) | ((c + 1) & 3u);
        } else {
            const uint32_t p = polygonOf(c);
            return c + 1 < offsets[p + 1] ? c + 1 : offsets[p];
        }
    }
    uint32_t previousCorner(uint32_t c) const {
        if constexpr (kQuads) {
            return (c & ~3u) | ((c + 3) & 3u);
        } else {
            const uint32_t p = polygonOf(c);
            return c > offsets[p] ? c - 1 : offsets[p + 1] - 1;
        }
    }
    uint32_t nextVertex(uint32_t c) const { return indices[nextCorner(c)]; }
    uint32_t previousVertex(uint32_t c) const { return indices[previousCorner(c)]; }
    // The corner across the quad of corner c (its edge is opposite c's edge).
    uint32_t oppositeCorner(uint32_t c) const {
        if constexpr (kQuads) {
            return c ^ 2u;
        } else {
            const uint32_t first = offsets[polygonOf(c)];
            return first + (c - first + 2) % 4;
        }
    }
};

// Step 3's state per vertex, one 16-byte block: n . d and the offset d from the input position
// (n . d is 0 for vertices that are not free).
struct alignas(16) Offset {
    float alongNormal;
    glm::vec3 d;
};

// A vertex normal, padded to 16 bytes for whole-register loads and stores.
struct alignas(16) VertexNormal {
    glm::vec3 n;
    float unused;
};

// Step 3's fit for one pass of four free vertices (a block of slots, see Fairing::buildSlots),
// lane by lane: the sweeps update the four at once.
struct alignas(16) FitBlock {
    float stepScale[4];      // 2 / sum |s|^2
    float nx[4], ny[4], nz[4];  // vertex normal
    float base[4];           // sum of s . (input_u - input_v)
    float sx[4], sy[4], sz[4];  // sum of s

    glm::vec3 n(int lane) const { return {nx[lane], ny[lane], nz[lane]}; }
    glm::vec3 sumS(int lane) const { return {sx[lane], sy[lane], sz[lane]}; }
};

// One Gauss-Seidel step of a free vertex: along = base + n . sum d_u + sum n_u . d_u - sumS . d,
// then d += along * stepScale * n, clamped into the cell, and n . d.
void moveFreeVertex(const FitBlock &f, int lane, float along, float half, Offset &o) {
    const glm::vec3 n = f.n(lane);
    o.d = glm::clamp(o.d + (along * f.stepScale[lane]) * n, -half, half);
    o.alongNormal = glm::dot(n, o.d);
}

// The same for the four vertices of a block, each with exactly kRegularValence neighbours
// (padded with a zero offset): `neighbours` holds 4 * kRegularValence byte offsets into
// `offsets` (saving an instruction per neighbour).
#ifdef VOXELFAIR_SSE2
// In registers across the four: a few instructions per vertex where one at a time would need
// horizontal sums and shuffles (sweeps about 1.7 times faster).
void moveFreeBlock(const FitBlock &f, const uint32_t *neighbours, Offset *offsets, Offset *own, float half) {
    static_assert(kRegularValence == 6, "unrolled below");
    const char *const bytes = reinterpret_cast<const char *>(offsets);
    auto load = [&](uint32_t offset) { return _mm_load_ps(reinterpret_cast<const float *>(bytes + offset)); };
    __m128 sum[4];  // (sum n_u . d_u, sum d_u) per vertex
    for (int j = 0; j < 4; ++j, neighbours += kRegularValence)
        sum[j] = _mm_add_ps(_mm_add_ps(_mm_add_ps(load(neighbours[0]), load(neighbours[1])),
                                       _mm_add_ps(load(neighbours[2]), load(neighbours[3]))),
                            _mm_add_ps(load(neighbours[4]), load(neighbours[5])));
    _MM_TRANSPOSE4_PS(sum[0], sum[1], sum[2], sum[3]);
    __m128 a = _mm_load_ps(&own[0].alongNormal), dx = _mm_load_ps(&own[1].alongNormal),
           dy = _mm_load_ps(&own[2].alongNormal), dz = _mm_load_ps(&own[3].alongNormal);
    _MM_TRANSPOSE4_PS(a, dx, dy, dz);
    const __m128 nx = _mm_load_ps(f.nx), ny = _mm_load_ps(f.ny), nz = _mm_load_ps(f.nz);
    const __m128 along = _mm_sub_ps(
        _mm_add_ps(_mm_add_ps(sum[0], _mm_load_ps(f.base)),
                   _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, sum[1]), _mm_mul_ps(ny, sum[2])), _mm_mul_ps(nz, sum[3]))),
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_load_ps(f.sx), dx), _mm_mul_ps(_mm_load_ps(f.sy), dy)),
                   _mm_mul_ps(_mm_load_ps(f.sz), dz)));
    const __m128 step = _mm_mul_ps(along, _mm_load_ps(f.stepScale)), lo = _mm_set1_ps(-half), hi = _mm_set1_ps(half);
    dx = _mm_min_ps(_mm_max_ps(_mm_add_ps(dx, _mm_mul_ps(step, nx)), lo), hi);
    dy = _mm_min_ps(_mm_max_ps(_mm_add_ps(dy, _mm_mul_ps(step, ny)), lo), hi);
    dz = _mm_min_ps(_mm_max_ps(_mm_add_ps(dz, _mm_mul_ps(step, nz)), lo), hi);
    a = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy)), _mm_mul_ps(nz, dz));
    _MM_TRANSPOSE4_PS(a, dx, dy, dz);
    _mm_store_ps(&own[0].alongNormal, a);
    _mm_store_ps(&own[1].alongNormal, dx);
    _mm_store_ps(&own[2].alongNormal, dy);
    _mm_store_ps(&own[3].alongNormal, dz);
}
#else
void moveFreeBlock(const FitBlock &f, const uint32_t *neighbours, Offset *offsets, Offset *own, float half) {
    float along[4];
    for (int j = 0; j < 4; ++j, neighbours += kRegularValence) {
        glm::vec3 sumD(0.0f);
        float sumAlong = 0.0f;
        for (uint32_t i = 0; i < kRegularValence; ++i) {
            const Offset &o = offsets[neighbours[i] / sizeof(Offset)];
            sumD += o.d;
            sumAlong += o.alongNormal;
        }
        along[j] = sumAlong + f.base[j] + glm::dot(f.n(j), sumD) - glm::dot(f.sumS(j), own[j].d);
    }
    for (int j = 0; j < 4; ++j)
        moveFreeVertex(f, j, along[j], half, own[j]);
}
#endif

// Step 1 of the header: which edges stay sharp, into `flags` (zeroed by the caller), given the
// creases (one corner per edge, edges whose polygons meet at more than creaseAngle) and the
// corners without twin (`sharpBoundary`: boundary, non-manifold, misoriented edges, all sharp).
// The genuine creases kept sharp go to `sharpCreases` (one corner per edge); counts into the
// report. Any order of the lists gives the same verdicts.
template <bool kQuads>
VOXELFAIR_NOINLINE void classifyEdges(const Polygons<kQuads> &k, const uint32_t *twin, const glm::vec3 *positions,
                                      const glm::vec3 *unitNormal, const ConstrainedFairingOptions &options,
                                      size_t vertexCount, const uint32_t *creases, size_t creaseCount, uint8_t *flags,
                                      std::vector<uint32_t> &sharpBoundary, std::vector<uint32_t> &sharpCreases,
                                      ConstrainedFairingReport &report) {
    // Convex or concave: the far end of the other polygon's next edge lies below this polygon's
    // plane, or not.
    for (const uint32_t *crease = creases; crease != creases + creaseCount; ++crease) {
        const uint32_t c = *crease, t = twin[c];  // t runs b -> a
        const uint32_t a = k.indices[c], far = k.nextVertex(k.nextCorner(t));
        flags[c] = flags[t] =
            glm::dot(unitNormal[k.polygonOf(c)], positions[far] - positions[a]) < 0.0f ? kConvex : kConcave;
    }
    report.creaseEdges = creaseCount;
    for (uint32_t c : sharpBoundary)
        flags[c] |= kSharp;
    report.sharpEdges = sharpBoundary.size();
    if (!options.keepSharpEdges)
        return;

    // Walks across quads away from the edge of corner c, through flat edges, to the next crease:
    // its corner and how many quads were crossed (kNone past maxSteps, at a boundary or at a
    // polygon that is not a quad).
    struct WalkEnd {
        uint32_t corner = kNone;
        int steps = 0;
    };
    auto walk = [&](uint32_t c, int maxSteps) {
        for (int step = 1; step <= maxSteps && k.inQuad(c); ++step) {
            const uint32_t opposite = k.oppositeCorner(c);
            if (flags[opposite] & kCrease)
                return WalkEnd{opposite, step};
            if (twin[opposite] == kNone)
                break;
            c = twin[opposite];
        }
        return WalkEnd{};
    };
    auto turn = [&](uint32_t c) { return flags[c] & kCrease; };

    struct Candidate {
        uint32_t corner;
        bool thin;
    };
    std::vector<Candidate> candidates;
    for (const uint32_t *crease = creases; crease != creases + creaseCount; ++crease) {
        const uint32_t c = *crease, t = twin[c];
        // Most creases of a staircase turn back one quad away on either side: a step, whatever
        // the walks find further (the nearest crease decides below).
        if (k.inQuad(c) && (flags[k.oppositeCorner(c)] & kCrease) && turn(k.oppositeCorner(c)) != turn(c))
            continue;
        if (k.inQuad(t) && (flags[k.oppositeCorner(t)] & kCrease) && turn(k.oppositeCorner(t)) != turn(c))
            continue;
        const WalkEnd side[2] = {walk(c, options.stepReach), walk(t, options.stepReach)};
        // The nearest crease within stepReach decides: turning back = a riser (staircase);
        // turning the same way one quad away = a 1-voxel plate or rod (genuine).
        int nearest = options.stepReach + 1;
        for (const WalkEnd &s : side)
            if (s.corner != kNone)
                nearest = std::min(nearest, s.steps);
        bool step = false, sameAtNearest = false;
        for (const WalkEnd &s : side)
            if (s.corner != kNone && s.steps == nearest)
                (turn(s.corner) != turn(c) ? step : sameAtNearest) = true;
        const bool isThin = !step && sameAtNearest && nearest == 1;
        if (!step && !isThin)
            for (const WalkEnd &s : side)
                if (s.corner != kNone && turn(s.corner) != turn(c))
                    step = true;
        if (step)
            continue;
        flags[c] |= kSharp;
        flags[t] |= kSharp;
        candidates.push_back({c, isThin});
    }
    if (candidates.empty())
        return;
    auto unsharpen = [&](uint32_t c) {
        flags[c] &= uint8_t(~kSharp);
        flags[twin[c]] &= uint8_t(~kSharp);
    };
    // A straight edge whose faces end, both ways, on staircase steps is a flat run of a rounded
    // part (a circle of radius 3 voxelizes with a 5-voxel straight corner).
    std::vector<uint32_t> demoted;
    if (options.featureReach > 0)
        for (const Candidate &candidate : candidates) {
            const uint32_t c = candidate.corner;
            if (candidate.thin)
                continue;
            const uint32_t a = walk(c, options.featureReach).corner, b = walk(twin[c], options.featureReach).corner;
            if (a != kNone && b != kNone && !(flags[a] & kSharp) && !(flags[b] & kSharp))
                demoted.push_back(c);
        }
    for (uint32_t c : demoted)
        unsharpen(c);
    // A single sharp edge touching no other is a corner of a small pole terrace, not a feature.
    std::vector<uint8_t> degree(vertexCount, 0);
    for (const Candidate &candidate : candidates)
        if (flags[candidate.corner] & kSharp)
            for (uint32_t v : {k.indices[candidate.corner], k.nextVertex(candidate.corner)})
                degree[v] = uint8_t(std::min(degree[v] + 1, 2));
    for (const Candidate &candidate : candidates) {
        const uint32_t c = candidate.corner;
        if ((flags[c] & kSharp) && degree[k.indices[c]] == 1 && degree[k.nextVertex(c)] == 1)
            unsharpen(c);
    }
    for (const Candidate &candidate : candidates)
        if (flags[candidate.corner] & kSharp)
            sharpCreases.push_back(candidate.corner);
    report.sharpEdges += sharpCreases.size();
}

// Everything after the checks, stage by stage (separate functions keep each hot loop's registers
// to itself); kQuads when every polygon is a quad. Member pointers used in hot loops are copied
// to locals: stores through the byte arrays could alias any member, so the compiler would reload
// them after each store.
template <bool kQuads>
class Fairing {
public:
    Fairing(glm::vec3 *positions, size_t vertexCount, const uint32_t *polygonOffsets, const uint32_t *polygonIndices,
            size_t polygonCount, const uint8_t *vertexSelected, const ConstrainedFairingOptions &options,
            ConstrainedFairingReport &report)
        : positions_(positions), input_(positions), V_(vertexCount), P_(polygonCount),
          cornerCount_(polygonOffsets[polygonCount]), offsets_(polygonOffsets), indices_(polygonIndices),
          selected_(vertexSelected), options_(options), report_(report),
          storedLevels_(std::max(options.normalLevels - 1, 1)), scratch_(scratchBytes()), arrays_(arraysBytes()) {}

    void run() {
        takeArrays();
        if (!findNormals())
            return;
        buildCorners();
        std::fill(edgeFlags_, edgeFlags_ + cornerCount_, uint8_t(0));
        classifyEdges(k_, twin_, input_, normal_, options_, V_, creases_, creaseCount_, edgeFlags_, sharpBoundary_,
                      sharpCreases_, report_);
        findVertexKinds();
        buildLevels();
        buildSlots();
        for (int pass = 0; pass < options_.passes; ++pass) {
            if (pass > 0)
                findFairedNormals();
            // Later passes start from the faired surface, whose normals need one level less
            // (measured: smaller errors on spheres, tori and cylinders than with all levels again).
            const int levels = options_.normalLevels;
            filterNormals(pass == 0 ? levels : std::max(levels - 1, std::min(levels, 1)));
            fitFreeVertices();
            for (int i = 0; i < options_.positionSweeps; ++i)
                sweep(i % 2 == 0);
            ++report_.passes;
        }
        finish();
    }

private:
    // The arrays that live through the call, in one block.
    size_t arraysBytes() const {
        return Arena::bytes<VertexKind>(V_) + Arena::bytes<uint8_t>(P_) + Arena::bytes<glm::vec3>(P_ + 2) +
               Arena::bytes<uint32_t>(kQuads ? 0 : cornerCount_) + Arena::bytes<uint32_t>(V_ + 2) +
               Arena::bytes<uint32_t>(cornerCount_ + 8) + Arena::bytes<uint32_t>(size_t(storedLevels_) * cornerCount_) +
               Arena::bytes<uint32_t>(V_);
    }
    // The block for buildCorners' and classifyEdges' temporaries, then for step 3's arrays (see
    // buildSlots; more if the waves need more padding than an eighth of the vertices).
    size_t scratchBytes() const {
        const size_t setup = Arena::bytes<uint32_t>(cornerCount_) + Arena::bytes<uint32_t>(cornerCount_ + 8) +
                             Arena::bytes<uint8_t>(cornerCount_) + Arena::bytes<uint32_t>(cornerCount_ / 2 + 1);
        return std::max(setup, passesBytes(V_ + V_ / 8 + 4));
    }
    size_t passesBytes(size_t freeSlots) const {
        return Arena::bytes<glm::vec3>(P_ + 2) + Arena::bytes<VertexNormal>(V_) + Arena::bytes<uint32_t>(freeSlots) +
               Arena::bytes<uint32_t>(kRegularValence * freeSlots) + Arena::bytes<Offset>(freeSlots + V_ + 1) +
               Arena::bytes<FitBlock>(freeSlots / 4) + Arena::bytes<uint8_t>(freeSlots / 4);
    }
    void takeArrays() {
        kind_ = arrays_.take<VertexKind>(V_);
        live_ = arrays_.take<uint8_t>(P_);
        normal_ = arrays_.take<glm::vec3>(P_ + 2);
        uint32_t *polygonTable = arrays_.take<uint32_t>(kQuads ? 0 : cornerCount_);
        for (uint32_t p = 0; !kQuads && p < P_; ++p)
            std::fill(polygonTable + offsets_[p], polygonTable + offsets_[p + 1], p);
        k_ = Polygons<kQuads>{offsets_, indices_, polygonTable};
        vertexStart_ = arrays_.take<uint32_t>(V_ + 2);
        vertexNext_ = arrays_.take<uint32_t>(cornerCount_ + 8);
        twin_ = arrays_.take<uint32_t>(size_t(storedLevels_) * cornerCount_);
        rank_ = arrays_.take<uint32_t>(V_);
        vertexCorners_ = scratch_.take<uint32_t>(cornerCount_);
        vertexPrevious_ = scratch_.take<uint32_t>(cornerCount_ + 8);
        edgeFlags_ = scratch_.take<uint8_t>(cornerCount_);
        creases_ = scratch_.take<uint32_t>(cornerCount_ / 2 + 1);
    }

    auto currentAt() const {
        return [this](uint32_t i) { return input_[indices_[i]] + offset_[rank_[indices_[i]]].d; };
    }

    // Vertex finiteness, polygon normals and liveness, the voxel size. False: nothing to do.
    VOXELFAIR_NOINLINE bool findNormals() {
        VertexKind *const kind = kind_;
        const glm::vec3 *const input = input_;
        size_t skipped = 0;
        for (size_t v = 0; v < V_; ++v) {
#ifdef VOXELFAIR_SSE2
            const __m128 x = load3(input[v]);  // x - x is 0 when finite, NaN otherwise
            const bool finite = (_mm_movemask_ps(_mm_cmpeq_ps(_mm_sub_ps(x, x), _mm_setzero_ps())) & 7) == 7;
#else
            const bool finite = isFinite(input[v]);
#endif
            kind[v] = finite ? VertexKind::Free : VertexKind::Skipped;
            skipped += !finite;
        }
        report_.skippedVertices = skipped;
        // Live polygons: 3+ corners, finite vertices, non-zero area. The others are holes, with a
        // zero normal like entry P, which stands for "no polygon". On the way, whether every
        // polygon edge has one length: then that is the voxel size (what detectVoxelSize would
        // find, without its sampling and sorting).
        normal_[P_] = normal_[P_ + 1] = glm::vec3(0.0f);
        float edgeLength2 = -1.0f;  // -1: none seen yet
        bool oneLength = true;
        const uint32_t *const indices = indices_;
        glm::vec3 *const normal = normal_;
        uint8_t *const live = live_;
        const Polygons<kQuads> k = k_;
        auto at = [input, indices](uint32_t i) { return input[indices[i]]; };
        for (size_t p = 0; p < P_; ++p) {
            const uint32_t first = k.first(p), last = k.last(p);
            bool finite = last - first >= 3;
            if (skipped > 0)
                for (uint32_t i = first; finite && i < last; ++i)
                    finite = kind[indices[i]] != VertexKind::Skipped;
            normal[p] = glm::vec3(0.0f);
            live[p] = 0;
            if (!finite) {
                oneLength = oneLength && last - first < 2;
                continue;
            }
#ifdef VOXELFAIR_SSE2
            if constexpr (kQuads) {
                // (glm's vec3 code here compiles to stack round trips that stall.)
                const __m128 x0 = load3(at(first)), x1 = load3(at(first + 1)), x2 = load3(at(first + 2)),
                             x3 = load3(at(first + 3));
                if (oneLength) {
                    const __m128 e0 = _mm_sub_ps(x1, x0), e1 = _mm_sub_ps(x2, x1), e2 = _mm_sub_ps(x3, x2),
                                 e3 = _mm_sub_ps(x0, x3);
                    const float length2 = dot3(e0, e0);
                    oneLength = (edgeLength2 == length2 || edgeLength2 < 0.0f) && dot3(e1, e1) == length2 &&
                                dot3(e2, e2) == length2 && dot3(e3, e3) == length2;
                    edgeLength2 = length2;
                }
                const __m128 area = cross3(_mm_sub_ps(x2, x0), _mm_sub_ps(x3, x1));
                store3(normal[p], area);  // normalized below, to zero exactly when this fails:
                const float length2 = dot3(area, area);
                live[p] = length2 > 0.0f && length2 <= std::numeric_limits<float>::max();
                continue;
            }
#endif
            if (oneLength) {
                for (uint32_t i = first; i < last; ++i) {
                    const glm::vec3 e = at(i + 1 < last ? i + 1 : first) - at(i);
                    const float length2 = glm::dot(e, e);
                    oneLength = oneLength && (edgeLength2 == length2 || edgeLength2 < 0.0f);
                    edgeLength2 = length2;
                }
            }
            normal[p] = areaNormal(at, first, last);
            live[p] = 1;
        }
        normalizeAll(normal, P_);  // no-op on the normalized ones
#ifdef VOXELFAIR_SSE2
        if constexpr (!kQuads)
#endif
            for (size_t p = 0; p < P_; ++p)
                live[p] = live[p] && normal[p] != glm::vec3(0.0f);
        if (options_.voxelSize > 0.0f)
            report_.voxelSize = options_.voxelSize;
        else if (oneLength && edgeLength2 > 0.0f && std::isfinite(std::sqrt(edgeLength2)))
            report_.voxelSize = std::sqrt(edgeLength2);
        else
            report_.voxelSize = detectVoxelSize(input_, V_, offsets_, indices_, P_);
        if (!(report_.voxelSize > 0.0f)) {
            report_.status = FairingStatus::NothingToDo;
            report_.message = "no polygon edge of non-zero finite length to take the voxel size from";
            return false;
        }
        half_ = options_.cellHalfWidth * report_.voxelSize;
        return true;
    }

    // The live polygons' normals from the current positions (the dead ones keep a zero normal).
    VOXELFAIR_NOINLINE void findFairedNormals() {
        const uint8_t *const live = live_;
        glm::vec3 *const normal = normal_;
#ifdef VOXELFAIR_SSE2
        if constexpr (kQuads) {
            const glm::vec3 *const input = input_;
            const Offset *const offset = offset_;
            const uint32_t *const indices = indices_, *const rank = rank_;
            auto at = [&](uint32_t i) {
                const uint32_t v = indices[i];
                return _mm_add_ps(load3(input[v]), load3(offset[rank[v]].d));
            };
            for (uint32_t p = 0; p < P_; ++p)
                if (live[p])
                    store3(normal[p], cross3(_mm_sub_ps(at(4 * p + 2), at(4 * p)),
                                             _mm_sub_ps(at(4 * p + 3), at(4 * p + 1))));
            normalizeAll(normal, P_);
            return;
        }
#endif
        const auto at = currentAt();
        for (size_t p = 0; p < P_; ++p)
            if (live[p])
                normal[p] = areaNormal(at, k_.first(p), k_.last(p));
    }

    // The corners of live polygons at each vertex (CSR) with the next and previous vertex of
    // each, the twins, and each vertex's wave (see buildSlots).
    VOXELFAIR_NOINLINE void buildCorners() {
        // Counting sort by vertex: count into start[v + 2], then fill through start[v + 1], which
        // leaves every start in place.
        const uint32_t cornerCount = cornerCount_, *const indices = indices_;
        const uint8_t *const live = live_;
        uint32_t *const start = vertexStart_, *const corners = vertexCorners_, *const next = vertexNext_,
                       *const previous = vertexPrevious_;
        std::fill(start, start + V_ + 2, 0u);
        for (uint32_t c = 0; c < cornerCount; ++c)
            start[indices[c] + 2] += live[k_.polygonOf(c)];
        for (size_t v = 1; v < V_ + 1; ++v)
            start[v + 1] += start[v];
        for (uint32_t c = 0; c < cornerCount; ++c)
            if (live[k_.polygonOf(c)]) {
                const uint32_t slot = start[indices[c] + 1]++;
                corners[slot] = c;
                next[slot] = k_.nextVertex(c);
                previous[slot] = k_.previousVertex(c);
            }
        std::fill(next + start[V_], next + start[V_] + 8, kNone);  // read past by the 8-lane loads
        std::fill(previous + start[V_], previous + start[V_] + 8, kNone);

        // Twins: a -> b and the one edge b -> a, when no other polygon has either direction.
        // Anything else (a boundary, a non-manifold or misoriented edge) stays without twin and
        // counts as sharp. Both directions show at a: a -> b as a corner at a whose next vertex is
        // b, b -> a as a corner at a whose previous vertex is b; so a's own list decides.
        uint32_t *const twin = twin_, *const wave = rank_;
        std::fill(twin, twin + cornerCount, kNone);
        // On the way: the creases (step 1; listed without branching on the test, whose outcome
        // follows no pattern) and the corners without twin.
        const glm::vec3 *const normal = normal_;
        const float creaseCos = std::cos(options_.creaseAngleDegrees * 3.14159265f / 180.0f);
        uint32_t *const creases = creases_;
        size_t creaseCount = 0;
        auto noTwin = [&](uint32_t c, bool edge) {
            if (edge)
                sharpBoundary_.push_back(c);
        };
        auto foundTwin = [&](uint32_t c, uint32_t t) {
            twin[c] = t;
            creases[creaseCount] = c;
#ifdef VOXELFAIR_SSE2
            creaseCount += t > c && dot3(load3(normal[k_.polygonOf(c)]), load3(normal[k_.polygonOf(t)])) < creaseCos;
#else
            creaseCount += t > c && glm::dot(normal[k_.polygonOf(c)], normal[k_.polygonOf(t)]) < creaseCos;
#endif
        };
        std::fill(wave, wave + V_, 0u);
        for (size_t a = 0; a < V_; ++a) {
            const uint32_t first = start[a], count = start[a + 1] - first;
            const size_t tileStart = a - a % kTileSize;
            uint32_t w = 0;
            // (Next vertices are enough: a free vertex has no sharp edge, so every edge a -> u
            // has its twin u -> a, and only free vertices are ordered.)
            for (uint32_t i = first; i < first + count; ++i) {
                // Masked, not branched on: half the neighbours come before, in no pattern.
                const uint32_t u = next[i], before = 0u - uint32_t(u < a && u >= tileStart);
                w = std::max(w, (wave[u] + 1) & before);
            }
            wave[a] = w;
#ifdef VOXELFAIR_SSE2
            if (count <= 8) {
                // 8 lanes compared at once: where the match is varies, a branch on it would
                // mispredict for most corners. Lanes past `count` hold the next vertices'.
                auto load = [](const uint32_t *x) { return _mm_loadu_si128(reinterpret_cast<const __m128i *>(x)); };
                const __m128i next0 = load(next + first), next1 = load(next + first + 4),
                              previous0 = load(previous + first), previous1 = load(previous + first + 4);
                const unsigned lanes = (1u << count) - 1;
                auto matches = [lanes](__m128i b, __m128i low, __m128i high) {
                    return (unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(b, low)))) |
                            unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(b, high)))) << 4) &
                           lanes;
                };
                for (uint32_t i = 0; i < count; ++i) {
                    const uint32_t b = next[first + i];
                    const __m128i bb = _mm_set1_epi32(int(b));
                    const unsigned out = matches(bb, next0, next1), in = matches(bb, previous0, previous1);
                    // Exactly one each way (out holds i at least).
                    const uint32_t c = corners[first + i];
                    if (b == a || (out & (out - 1)) != 0 || in == 0 || (in & (in - 1)) != 0) {
                        noTwin(c, b != a);
                        continue;
                    }
                    const uint32_t back = kBitIndex[(in * 0x1Du) >> 5 & 7];  // in is a power of 2 below 256
                    const uint32_t t = k_.previousCorner(corners[first + back]);
                    if (k_.polygonOf(t) != k_.polygonOf(c))
                        foundTwin(c, t);
                    else
                        noTwin(c, true);
                }
                continue;
            }
#endif
            for (uint32_t i = first; i < first + count; ++i) {
                const uint32_t b = next[i];
                if (b == a)
                    continue;  // no edge
                uint32_t out = 0, in = 0, back = 0;
                for (uint32_t j = first; j < first + count; ++j) {
                    out += next[j] == b;
                    if (previous[j] == b) {
                        back = j;
                        ++in;
                    }
                }
                const uint32_t c = corners[i], t = k_.previousCorner(corners[back]);
                if (out == 1 && in == 1 && k_.polygonOf(t) != k_.polygonOf(c))
                    foundTwin(c, t);
                else
                    noTwin(c, true);
            }
        }
        creaseCount_ = creaseCount;
    }

    // Vertex kinds from the sharp edges around them (each edge counted once per end); the
    // polygons of edge-line vertices.
    VOXELFAIR_NOINLINE void findVertexKinds() {
        VertexKind *const kind = kind_;
        const uint32_t *const start = vertexStart_, *const next = vertexNext_;
        const bool anySharp = !sharpBoundary_.empty() || !sharpCreases_.empty();
        std::vector<uint8_t> sharpDegree(anySharp ? V_ : 0, 0);
        for (const std::vector<uint32_t> *edges : {&sharpBoundary_, &sharpCreases_})
            for (uint32_t c : *edges)
                for (uint32_t v : {indices_[c], k_.nextVertex(c)})
                    sharpDegree[v] = uint8_t(std::min(sharpDegree[v] + 1, 3));
        size_t pinned = 0;
        for (size_t v = 0; v < V_; ++v) {
            if (kind[v] == VertexKind::Skipped || (!anySharp && !selected_ && start[v] < start[v + 1]))
                continue;  // (the common case: free)
            const uint8_t degree = anySharp ? sharpDegree[v] : 0;
            if ((selected_ && !selected_[v]) || start[v] == start[v + 1] || (degree != 0 && degree != 2)) {
                kind[v] = VertexKind::Pinned;
                ++pinned;
            } else if (degree == 2) {
                kind[v] = VertexKind::EdgeLine;
                lineVertices_.push_back(uint32_t(v));
            }
        }
        report_.pinnedVertices = pinned;
        report_.edgeLineVertices = lineVertices_.size();
        // Free vertices with more than kRegularValence neighbours or beside an edge line go
        // through the general path.
        const bool anyLine = !lineVertices_.empty();
        for (size_t v = 0; v < V_; ++v) {
            if (kind[v] != VertexKind::Free)
                continue;
            bool regular = start[v + 1] - start[v] <= kRegularValence;
            for (uint32_t i = start[v]; anyLine && regular && i < start[v + 1]; ++i)
                regular = kind[next[i]] != VertexKind::EdgeLine;
            if (!regular)
                kind[v] = VertexKind::FreeIrregular;
        }
        linePolygonStart_.push_back(0);
        for (uint32_t v : lineVertices_) {
            for (uint32_t i = start[v]; i < start[v + 1]; ++i)
                linePolygons_.push_back(k_.polygonOf(vertexCorners_[i]));
            linePolygonStart_.push_back(uint32_t(linePolygons_.size()));
        }
    }

    // Step 2's neighbours: level i of corner c is the polygon 2^i quads straight across c's edge,
    // none when a sharp edge, a hole or a non-quad is in the way (at level 0 any polygon across a
    // smooth edge). Stored as the corner by which the walk enters that polygon, so that level
    // i + 1 is level i taken twice (pointer doubling): level 0 is the twin across smooth edges.
    // One table per level but the last, which only the first pass uses and which is looked up
    // through the level below.
    VOXELFAIR_NOINLINE void buildLevels() {
        uint32_t *const twin = twin_;
        for (const std::vector<uint32_t> *edges : {&sharpBoundary_, &sharpCreases_})
            for (uint32_t c : *edges)
                if (twin[c] != kNone) {
                    twin[twin[c]] = kNone;
                    twin[c] = kNone;
                }
        for (int level = 1; level < storedLevels_; ++level) {
            const uint32_t *below = levelTable(level - 1);
            uint32_t *table = twin + size_t(level) * cornerCount_;
            for (uint32_t c = 0; c < cornerCount_; ++c)
                table[c] = doubled(below, c);
        }
    }
    const uint32_t *levelTable(int level) const { return twin_ + size_t(level) * cornerCount_; }
    // The corner entering the polygon twice as far across c's edge as `entry` does, both in quads.
    uint32_t doubled(const uint32_t *entry, uint32_t c) const {
        const uint32_t m = entry[c];
        if (m == kNone || !k_.inQuad(m))
            return kNone;
        const uint32_t m2 = entry[k_.oppositeCorner(m)];
        return m2 != kNone && k_.inQuad(m2) ? m2 : kNone;
    }

    // Step 3's layout. A sweep updates the free vertices in index order, and all that matters
    // for the result is, for each pair of neighbours, which goes first. In index order each
    // update mostly waits for the previous one (a neighbour); instead, within each tile of
    // kTileSize vertex indices, wave w holds the vertices whose neighbours of lower index in the
    // tile are in waves < w (buildCorners). Sweeping tile after tile and, in each, wave after
    // wave (or all in reverse) keeps the order of every pair, and the vertices of a wave never
    // depend on each other: they are updated four at a time (moveFreeBlock). So each vertex
    // gets a slot: the free vertices tile by tile, wave by wave, each wave padded to whole
    // blocks of four (empty slots), then the other vertices, then one slot that stays zero.
    // Step 3's arrays are stored by slot, so a sweep streams through memory.
    VOXELFAIR_NOINLINE void buildSlots() {
        const VertexKind *const kind = kind_;
        uint32_t *const rank = rank_, *const wave = rank_;  // a tile's waves are copied before its ranks are set
        // The temporaries are dead: step 3's arrays go in their place, first the slots' vertices
        // (room for each wave's padding: at most 3 empty slots per wave).
        scratch_.rewind({0, 0});
        size_t room = 0;
        for (size_t tileStart = 0; tileStart < V_; tileStart += kTileSize) {
            uint32_t waves = 0;
            for (size_t v = tileStart; v < std::min(V_, tileStart + kTileSize); ++v)
                if (isFree(kind[v])) {
                    waves = std::max(waves, wave[v] + 1);
                    ++room;
                }
            room += 3 * size_t(waves);
        }
        uint32_t *const vertexAt = vertexAt_ = scratch_.take<uint32_t>(room);
        std::vector<uint32_t> tileWave, waveStart;
        size_t slots = 0;
        for (size_t tileStart = 0; tileStart < V_; tileStart += kTileSize) {
            const size_t tileEnd = std::min(V_, tileStart + kTileSize);
            tileWave.assign(wave + tileStart, wave + tileEnd);
            uint32_t waves = 0;
            for (size_t v = tileStart; v < tileEnd; ++v)
                if (isFree(kind[v]))
                    waves = std::max(waves, tileWave[v - tileStart] + 1);
            waveStart.assign(waves + 1, 0);
            for (size_t v = tileStart; v < tileEnd; ++v)
                if (isFree(kind[v]))
                    ++waveStart[tileWave[v - tileStart] + 1];
            for (uint32_t w = 0; w < waves; ++w)
                waveStart[w + 1] = waveStart[w] + ((waveStart[w + 1] + 3) & ~3u);  // whole blocks
            std::fill(vertexAt + slots, vertexAt + slots + waveStart[waves], kNone);
            for (size_t v = tileStart; v < tileEnd; ++v)
                if (isFree(kind[v])) {
                    const uint32_t slot = uint32_t(slots + waveStart[tileWave[v - tileStart]]++);
                    vertexAt[slot] = uint32_t(v);
                    rank[v] = slot;
                }
            slots += waveStart[waves];
        }
        freeSlots_ = slots;
        uint32_t other = uint32_t(freeSlots_);
        for (size_t v = 0; v < V_; ++v)
            if (!isFree(kind[v]))
                rank[v] = other++;
        const uint32_t zeroSlot = other;

        filtered_ = scratch_.take<glm::vec3>(P_ + 2);
        filtered_[P_] = filtered_[P_ + 1] = glm::vec3(0.0f);
        vertexNormal_ = scratch_.take<VertexNormal>(V_);
        slotNeighbours_ = scratch_.take<uint32_t>(kRegularValence * freeSlots_);
        offset_ = scratch_.take<Offset>(zeroSlot + 1);
        std::fill(offset_, offset_ + zeroSlot + 1, Offset{0.0f, glm::vec3(0.0f)});
        fit_ = scratch_.take<FitBlock>(freeSlots_ / 4);
        regularBlock_ = scratch_.take<uint8_t>(freeSlots_ / 4);
        // (moveFreeBlock reads slotNeighbours as byte offsets, which must fit 32 bits: beyond
        // 2^28 slots every vertex goes through the general path.)
        const bool regularFits = zeroSlot < (1u << 28);
        std::fill(regularBlock_, regularBlock_ + freeSlots_ / 4, uint8_t(regularFits));  // see fitFreeVertices
        // Free vertices' neighbours by slot (as byte offsets), the zero slot where fewer (vertex by
        // vertex: the neighbours' ranks are near in memory); empty slots read the zero slot and
        // move by 0 (a zero fit).
        uint32_t *const slotNeighbours = slotNeighbours_;
        const uint32_t *const start = vertexStart_, *const next = vertexNext_;
        for (size_t v = 0; v < V_; ++v) {
            if (!isFree(kind[v]))
                continue;
            uint32_t *out = slotNeighbours + kRegularValence * size_t(rank[v]);
            const uint32_t count = kind[v] == VertexKind::Free ? start[v + 1] - start[v] : 0;
            for (uint32_t i = 0; i < kRegularValence; ++i) {
                // (Selected, not branched on: the count varies in no pattern.)
                const uint32_t neighbour = rank[next[start[v] + std::min(i, std::max(count, 1u) - 1)]];
                out[i] = uint32_t(sizeof(Offset)) * (i < count ? neighbour : zeroSlot);
            }
        }
        for (size_t slot = 0; slot < freeSlots_; ++slot) {
            if (vertexAt_[slot] != kNone)
                continue;
            std::fill(slotNeighbours + kRegularValence * slot, slotNeighbours + kRegularValence * (slot + 1),
                      uint32_t(sizeof(Offset)) * zeroSlot);
            FitBlock &f = fit_[slot / 4];
            const int lane = int(slot % 4);
            f.stepScale[lane] = f.nx[lane] = f.ny[lane] = f.nz[lane] = 0.0f;
            f.base[lane] = f.sx[lane] = f.sy[lane] = f.sz[lane] = 0.0f;
        }
    }

    // Step 2 (Jacobi, a trous): each polygon's normal becomes the mean of itself and the four
    // polygons 1, 2, 4, ... quads away, so each level doubles the reach (Holschneider et al., "A
    // real-time algorithm for signal analysis with the help of the wavelet transform", 1989). The
    // last level also sums each vertex's polygon normals into vertexNormal, polygon by polygon
    // (the order of its corner list), then normalizes them.
    VOXELFAIR_NOINLINE void filterNormals(int levels) {
        std::fill(vertexNormal_, vertexNormal_ + V_, VertexNormal{glm::vec3(0.0f), 0.0f});
        for (int level = 0; level < levels; ++level) {
            const bool composed = level == storedLevels_;  // the top level of the first pass
            const bool toVertices = level == levels - 1;
            const uint32_t *table = levelTable(composed ? level - 1 : level);
#ifdef VOXELFAIR_SSE2
            if constexpr (kQuads) {
                filterQuads(table, composed, toVertices);
                std::swap(normal_, filtered_);
                continue;
            }
#endif
            for (size_t p = 0; p < P_; ++p) {
                glm::vec3 sum = normal_[p];
                for (uint32_t c = k_.first(p); c < k_.last(p); ++c) {
                    const uint32_t e = composed ? doubled(table, c) : table[c];
                    sum += normal_[e != kNone ? k_.polygonOf(e) : uint32_t(P_)];
                }
                filtered_[p] = normalizedOrZero(sum);
                if (toVertices)
                    for (uint32_t c = k_.first(p); c < k_.last(p); ++c)
                        vertexNormal_[indices_[c]].n += filtered_[p];
            }
            std::swap(normal_, filtered_);
        }
        if (levels == 0)
            for (size_t p = 0; p < P_; ++p)
                for (uint32_t c = k_.first(p); c < k_.last(p); ++c)
                    vertexNormal_[indices_[c]].n += normal_[p];
        normalizeAll(&vertexNormal_[0].n, V_, sizeof(VertexNormal));
    }
#ifdef VOXELFAIR_SSE2
    // One level of filterNormals on quads, a normal per register and four normalized at once (a
    // square root and a division each otherwise make up most of the time): the same sums and
    // products, so the same results. Loads and stores of 16 bytes at the 12-byte normals read
    // one float past (arrays of P + 2) and write 0 into the next normal's x (its own turn comes
    // next; [P] stays 0).
    VOXELFAIR_NOINLINE void filterQuads(const uint32_t *table, bool composed, bool toVertices) {
        const glm::vec3 *const normal = normal_;
        glm::vec3 *const filtered = filtered_;
        VertexNormal *const vertexNormal = vertexNormal_;
        const uint32_t *const indices = indices_;
        const uint32_t none = uint32_t(P_);
        const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
        auto load = [&](uint32_t p) { return _mm_loadu_ps(&normal[p].x); };
        auto sumAround = [&](size_t p) {
            const uint32_t *entry = table + 4 * p;
            __m128 sum = load(uint32_t(p));
            for (uint32_t i = 0; i < 4; ++i) {
                uint32_t e = entry[i];
                if (composed && e != kNone)
                    e = table[e ^ 2u];
                sum = _mm_add_ps(sum, load(e != kNone ? e >> 2 : none));
            }
            return _mm_and_ps(sum, xyz);
        };
        auto store = [&](size_t p, __m128 unit) {
            _mm_storeu_ps(&filtered[p].x, unit);
            if (!toVertices)
                return;
            for (uint32_t i = 0; i < 4; ++i) {
                float *n = &vertexNormal[indices[4 * p + i]].n.x;
                _mm_store_ps(n, _mm_add_ps(_mm_load_ps(n), unit));
            }
        };
        size_t p = 0;
        for (; p + 4 <= P_; p += 4) {
            __m128 a = sumAround(p), b = sumAround(p + 1), c = sumAround(p + 2), d = sumAround(p + 3);
            normalizeFour(a, b, c, d);
            store(p, a);
            store(p + 1, b);
            store(p + 2, c);
            store(p + 3, d);
        }
        for (; p < P_; ++p) {
            __m128 a = sumAround(p), b = a, c = a, d = a;
            normalizeFour(a, b, c, d);
            store(p, a);
        }
    }
#endif

    // Step 3's least squares for a free vertex v with normal n: each edge v-u wants to be
    // perpendicular to s = n + n_u (to the bisector of the two normals, which holds exactly on a
    // sphere); v moves along n by 2 sum s.(x_u - x_v) / sum |s|^2. A neighbour that is not free
    // lends n (s = 2n); one more than 90 degrees away (another sheet) is left out (an edge is
    // used when |s|^2 > 2). With x = input + d and n_u . d_u kept per vertex,
    // sum s.(x_u - x_v) = base + n . sum d_u + sum n_u . d_u - sumS . d_v, so a sweep reads only
    // the neighbours' offsets; lending neighbours that never move read as zero. A vertex with an
    // edge left out goes through the general path from then on.
    glm::vec3 edgeTerm(const glm::vec3 &n, uint32_t u) const {
        return n + (isFree(kind_[u]) ? vertexNormal_[u].n : n);
    }
    VOXELFAIR_NOINLINE void fitFreeVertices() {
        // Vertex by vertex (neighbours' data are near in memory), into the slots' blocks; the
        // empty slots' lanes were zeroed in buildSlots.
        VertexKind *const kind = kind_;
        const VertexNormal *const vertexNormal = vertexNormal_;
        const glm::vec3 *const input = input_;
        const uint32_t *const rank = rank_, *const start = vertexStart_, *const next = vertexNext_;
        FitBlock *const fit = fit_;
        uint8_t *const regularBlock = regularBlock_;
        for (size_t v = 0; v < V_; ++v) {
            if (!isFree(kind[v]))
                continue;
            float sum2 = 0.0f, base = 0.0f;
            bool allUsed = true;
#ifdef VOXELFAIR_SSE2
            // (glm's vec3 code here compiles to stack round trips that stall.)
            // (Vertex normals are 16-byte blocks with a zero fourth float: whole loads.)
            auto normalOf = [vertexNormal](uint32_t u) { return _mm_load_ps(&vertexNormal[u].n.x); };
            const __m128 n = normalOf(uint32_t(v)), x = load3(input[v]);
            __m128 sumS = _mm_setzero_ps(), products = sumS;  // base: the sum of products' lanes
            for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
                const uint32_t u = next[i];
                const __m128 s = _mm_add_ps(n, isFree(kind[u]) ? normalOf(u) : n);
                const float s2 = dot3(s, s);
                if (!(s2 > 2.0f)) {
                    allUsed = false;
                    continue;
                }
                sum2 += s2;
                sumS = _mm_add_ps(sumS, s);
                products = _mm_add_ps(products, _mm_mul_ps(s, _mm_sub_ps(load3(input[u]), x)));
            }
            base = dot3(products, _mm_set1_ps(1.0f));
            alignas(16) float nOut[4], sOut[4];
            _mm_store_ps(nOut, n);
            _mm_store_ps(sOut, sumS);
#else
            const glm::vec3 n = vertexNormal[v].n;
            glm::vec3 sumS(0.0f);
            for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
                const uint32_t u = next[i];
                const glm::vec3 s = edgeTerm(n, u);
                const float s2 = glm::dot(s, s);
                if (!(s2 > 2.0f)) {
                    allUsed = false;
                    continue;
                }
                sum2 += s2;
                sumS += s;
                base += glm::dot(s, input[u] - input[v]);
            }
            const float nOut[3] = {n.x, n.y, n.z}, sOut[3] = {sumS.x, sumS.y, sumS.z};
#endif
            const uint32_t slot = rank[v];
            if (!allUsed)
                kind[v] = VertexKind::FreeIrregular;
            if (kind[v] != VertexKind::Free)
                regularBlock[slot / 4] = 0;
            FitBlock &f = fit[slot / 4];
            const int lane = int(slot % 4);
            f.stepScale[lane] = sum2 > 0.0f ? 2.0f / sum2 : 0.0f;
            f.nx[lane] = nOut[0];
            f.ny[lane] = nOut[1];
            f.nz[lane] = nOut[2];
            f.base[lane] = base;
            f.sx[lane] = sOut[0];
            f.sy[lane] = sOut[1];
            f.sz[lane] = sOut[2];
        }
        // n . d with this pass's normals, slot by slot.
        for (size_t slot = 0; slot < freeSlots_; ++slot)
            offset_[slot].alongNormal = glm::dot(fit[slot / 4].n(int(slot % 4)), offset_[slot].d);
    }

    // One Gauss-Seidel sweep, each vertex clamped into its cell (step 4) as it moves: edge-line
    // vertices, then the free ones.
    VOXELFAIR_NOINLINE void sweep(bool forward) {
        // On a sharp edge line: towards the plane of each polygon through its centroid.
        const auto at = currentAt();
        for (size_t line = 0; line < lineVertices_.size(); ++line) {
            const uint32_t v = lineVertices_[line];
            Offset &o = offset_[rank_[v]];
            const glm::vec3 x = input_[v] + o.d;
            glm::vec3 move(0.0f);
            for (uint32_t j = linePolygonStart_[line]; j < linePolygonStart_[line + 1]; ++j) {
                const uint32_t p = linePolygons_[j];
                glm::vec3 centroid(0.0f);
                for (uint32_t c = k_.first(p); c < k_.last(p); ++c)
                    centroid += at(c);
                centroid /= float(k_.arity(p));
                move += normal_[p] * glm::dot(normal_[p], centroid - x);
            }
            move /= float(linePolygonStart_[line + 1] - linePolygonStart_[line]);
            o.d = glm::clamp(o.d + move, -half_, half_);
        }
        // Free vertices, alternating direction so that no side of the mesh leads.
        const FitBlock *const fit = fit_;
        const uint32_t *const neighbours = slotNeighbours_;
        const uint8_t *const regular = regularBlock_;
        Offset *const offset = offset_;
        const size_t blocks = freeSlots_ / 4;
        const float half = half_;
        for (size_t i = 0; i < blocks; ++i) {
            const size_t block = forward ? i : blocks - 1 - i;
            if (regular[block])
                moveFreeBlock(fit[block], neighbours + 4 * kRegularValence * block, offset, offset + 4 * block, half);
            else
                moveIrregularBlock(block);
        }
    }
    // Each vertex of the block on its own, from its corner list.
    VOXELFAIR_NOINLINE void moveIrregularBlock(size_t block) {
        const FitBlock &f = fit_[block];
        for (int lane = 0; lane < 4; ++lane) {
            const uint32_t v = vertexAt_[4 * block + lane];
            if (v == kNone)
                continue;
            Offset &o = offset_[4 * block + lane];
            const glm::vec3 n = f.n(lane);
            float along = f.base[lane] - glm::dot(f.sumS(lane), o.d);
            for (uint32_t i = vertexStart_[v]; i < vertexStart_[v + 1]; ++i) {
                const uint32_t u = vertexNext_[i];
                const glm::vec3 s = edgeTerm(n, u);
                if (glm::dot(s, s) > 2.0f)
                    along += glm::dot(s, offset_[rank_[u]].d);
            }
            moveFreeVertex(f, lane, along, half_, o);
        }
    }

    // The faired positions and the report's counts.
    VOXELFAIR_NOINLINE void finish() {
        const float moved2 = 1e-12f * report_.voxelSize * report_.voxelSize, wall = half_ * (1.0f - 1e-5f);
        float maxMove2 = 0.0f;
        size_t moved = 0, clamped = 0;
        for (size_t v = 0; v < V_; ++v) {
            if (!isFree(kind_[v]) && kind_[v] != VertexKind::EdgeLine)
                continue;
            const glm::vec3 d = offset_[rank_[v]].d;
            positions_[v] = input_[v] + d;
            const float d2 = glm::dot(d, d);
            maxMove2 = std::max(maxMove2, d2);
            moved += d2 > moved2;
            clamped += std::max(std::abs(d.x), std::max(std::abs(d.y), std::abs(d.z))) >= wall;
        }
        report_.movedVertices = moved;
        report_.clampedVertices = clamped;
        report_.maxDisplacement = std::sqrt(maxMove2);
    }

    glm::vec3 *const positions_;
    const glm::vec3 *const input_;  // positions stay the input until finish()
    const size_t V_, P_;
    const uint32_t cornerCount_;
    const uint32_t *const offsets_, *const indices_;
    const uint8_t *const selected_;
    const ConstrainedFairingOptions &options_;
    ConstrainedFairingReport &report_;
    const int storedLevels_;  // step 2's tables
    float half_ = 0.0f;       // the cells' half-width

    Arena scratch_, arrays_;  // the temporaries, then step 3's arrays; the call's arrays
    Polygons<kQuads> k_{};
    VertexKind *kind_ = nullptr;
    uint8_t *live_ = nullptr;
    glm::vec3 *normal_ = nullptr, *filtered_ = nullptr;  // P + 2: [P] (and [P + 1]) stay zero
    uint32_t *vertexStart_ = nullptr;  // CSR of the corners of live polygons at each vertex:
    uint32_t *vertexNext_ = nullptr;   // their next vertices (8 more entries: see buildCorners),
    uint32_t *vertexCorners_ = nullptr, *vertexPrevious_ = nullptr;  // and, while building, the rest
    uint32_t *twin_ = nullptr;  // then step 2's level 0, and the tables of levels 1.. after it
    uint8_t *edgeFlags_ = nullptr;
    uint32_t *creases_ = nullptr;  // one corner per edge (the lower), creaseCount_ of them
    size_t creaseCount_ = 0;
    std::vector<uint32_t> sharpBoundary_, sharpCreases_, lineVertices_, linePolygonStart_, linePolygons_;
    uint32_t *rank_ = nullptr;  // vertex -> slot (first the waves)

    // Step 3, by slot (see buildSlots).
    size_t freeSlots_ = 0;                // slots of free vertices (and empty ones): whole blocks
    VertexNormal *vertexNormal_ = nullptr;  // by vertex
    uint32_t *vertexAt_ = nullptr;        // free slot -> vertex, kNone when empty
    uint32_t *slotNeighbours_ = nullptr;  // kRegularValence byte offsets per free slot (see buildSlots)
    Offset *offset_ = nullptr;
    FitBlock *fit_ = nullptr;             // per block of four free slots
    uint8_t *regularBlock_ = nullptr;     // per block: all its vertices Free (moveFreeBlock)
};

}  // namespace

ConstrainedFairingReport fairConstrained(glm::vec3 *positions, size_t vertexCount, const uint32_t *polygonOffsets,
                                         const uint32_t *polygonIndices, size_t polygonCount,
                                         const uint8_t *vertexSelected, const ConstrainedFairingOptions &options) {
    ConstrainedFairingReport report;
    auto finish = [&](FairingStatus status, const char *message) {
        report.status = status;
        report.message = message;
        return report;
    };
    if (options.passes < 0 || options.normalLevels < 0 || options.normalLevels > 8 || options.positionSweeps < 0 ||
        options.stepReach < 1 || options.featureReach < 0 || !(options.cellHalfWidth > 0.0f) ||
        !std::isfinite(options.cellHalfWidth) ||
        !(options.creaseAngleDegrees > 0.0f && options.creaseAngleDegrees < 180.0f) ||
        !std::isfinite(options.voxelSize) || options.voxelSize < 0.0f)
        return finish(FairingStatus::InvalidOptions,
                      "passes, positionSweeps >= 0, normalLevels in [0, 8], stepReach >= 1, featureReach >= 0, "
                      "cellHalfWidth > 0, creaseAngle in (0, 180), voxelSize finite and >= 0");
    if (const auto [status, message] = checkFairingInput(positions, vertexCount, polygonOffsets, polygonIndices,
                                                         polygonCount, options.passes);
        status != FairingStatus::Ok)
        return finish(status, message);

    bool allQuads = polygonOffsets[polygonCount] == 4 * polygonCount;
    for (size_t p = 0; allQuads && p < polygonCount; ++p)
        allQuads = polygonOffsets[p + 1] - polygonOffsets[p] == 4;
    if (allQuads)
        Fairing<true>(positions, vertexCount, polygonOffsets, polygonIndices, polygonCount, vertexSelected, options,
                      report)
            .run();
    else
        Fairing<false>(positions, vertexCount, polygonOffsets, polygonIndices, polygonCount, vertexSelected, options,
                       report)
            .run();
    return report;
}

}  // namespace voxelfair
