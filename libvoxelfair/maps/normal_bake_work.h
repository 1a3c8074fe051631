// The normal bake's work after its checks (normal_bake.h: set-up, bands, gutter), included twice
// by normal_bake.cpp: once as it is, once under GCC's target "avx2" (where the CPU has it, chosen
// at run time). The AVX2 copy uses the same operations in the same order (VEX encodings, AVX2
// broadcasts; no fused multiply-add: the target does not enable FMA), so both give the same map
// bit for bit; inline functions of other headers it calls keep their own out-of-line copies (a
// CPU without AVX2 never runs an AVX2 instruction). No include guard and no includes: it defines
// bakeNormalMapWork in the namespace it is included in, with normal_bake.cpp's headers.
// NOLINTBEGIN(misc-definitions-in-headers): included by normal_bake.cpp alone, in an anonymous namespace

constexpr int kBandRows = 32;

#if VOXELFAIR_SSE2
// SurfaceWalk::holds() and normalAt() on source face `face` for 4 texels of a row at once, lane k
// at weights (l1[k], l2[k]) on the target face (corner 0 at o, edges e1, e2, corner normals tn).
// Each lane repeats the scalar path's float operations in its order (p = o + l1 e1 + l2 e2,
// facing = l0 tn0 + l1 tn1 + l2 tn2, dot products summed x + y + z), so that the answers and the
// normals are the scalar build's bit for bit. holdsQuad: bit k of the result set when lane k
// holds; w gets the lanes' weights on the source face. quadNormals: lane k of n[a] gets the
// interpolated source normal at those weights (asked only for a quad that holds).
// The target face's corner 0, edges and corner normals, each coordinate in all 4 lanes.
struct QuadTarget {
    __m128 o[3], e1[3], e2[3], tn[3][3];
    QuadTarget(const glm::vec3 &origin, const glm::vec3 &edge1, const glm::vec3 &edge2, const glm::vec3 *normals) {
        for (int a = 0; a < 3; ++a) {
            o[a] = _mm_set1_ps(origin[a]), e1[a] = _mm_set1_ps(edge1[a]), e2[a] = _mm_set1_ps(edge2[a]);
            for (int k = 0; k < 3; ++k)
                tn[k][a] = _mm_set1_ps(normals[k][a]);
        }
    }
};
__attribute__((always_inline)) inline int holdsQuad(const SurfaceWalk &walk, uint32_t face, __m128 L1, __m128 L2,
                                                    const QuadTarget &t, __m128 w[3]) {
    const SurfaceWalk::Face &f = walk.record(face);
    auto all = [](float v) { return _mm_set1_ps(v); };
    const __m128 one = all(1.0f), zero = _mm_setzero_ps();
    const __m128 L0 = _mm_sub_ps(_mm_sub_ps(one, L1), L2);
    __m128 d[3], facing[3];
    for (int a = 0; a < 3; ++a) {
        const __m128 p = _mm_add_ps(_mm_add_ps(t.o[a], _mm_mul_ps(L1, t.e1[a])), _mm_mul_ps(L2, t.e2[a]));
        d[a] = _mm_sub_ps(p, all(f.origin[a]));
        facing[a] =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(L0, t.tn[0][a]), _mm_mul_ps(L1, t.tn[1][a])), _mm_mul_ps(L2, t.tn[2][a]));
    }
    auto dot = [&](const glm::vec3 &v) {  // dot(d, v)
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], all(v.x)), _mm_mul_ps(d[1], all(v.y))),
                          _mm_mul_ps(d[2], all(v.z)));
    };
    const __m128 w1 = dot(f.dual1), w2 = dot(f.dual2), height = dot(f.normal);
    const __m128 w0 = _mm_sub_ps(_mm_sub_ps(one, w1), w2);
    const __m128 faces =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(all(f.normal.x), facing[0]), _mm_mul_ps(all(f.normal.y), facing[1])),
                   _mm_mul_ps(all(f.normal.z), facing[2]));
    const __m128 inside =
        _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(w0, zero), _mm_cmpge_ps(w1, zero)), _mm_cmpge_ps(w2, zero));
    const __m128 ok = _mm_and_ps(_mm_and_ps(inside, _mm_cmple_ps(_mm_mul_ps(height, height), all(f.nearPlane))),
                                 _mm_cmpgt_ps(faces, zero));
    w[0] = w0, w[1] = w1, w[2] = w2;
    return _mm_movemask_ps(ok);
}
// The face across the edge lane `lane` of weights w (on `face`, holdsQuad's) leaves it by
// (SurfaceWalk::across on the lane's weights, which are holds()'s bit for bit).
inline uint32_t acrossLane(const SurfaceWalk &walk, uint32_t face, const __m128 w[3], int lane) {
    alignas(16) float w0[4], w1[4], w2[4];
    _mm_store_ps(w0, w[0]), _mm_store_ps(w1, w[1]), _mm_store_ps(w2, w[2]);
    return walk.across(face, glm::vec3(w0[lane], w1[lane], w2[lane]));
}
__attribute__((always_inline)) inline void quadNormals(const SurfaceWalk &walk, uint32_t face, const __m128 w[3],
                                                       __m128 n[3]) {
    const glm::vec3 *cn = walk.cornerNormals(face);
    for (int a = 0; a < 3; ++a)
        n[a] = _mm_add_ps(_mm_add_ps(_mm_mul_ps(w[0], _mm_set1_ps(cn[0][a])), _mm_mul_ps(w[1], _mm_set1_ps(cn[1][a]))),
                          _mm_mul_ps(w[2], _mm_set1_ps(cn[2][a])));
}
#endif

// The bake of a map of width x height texels, `scale` map texels per atlas texel (the options
// checked).
NormalMap bakeNormalMapWork(const NormalBakeMesh &source, const NormalBakeMesh &target,
                            const NormalBakeOptions &options, int width, int height, int scale) {
    NormalMap out;
    const size_t texels = size_t(width) * size_t(height);
    out.width = width;
    out.height = height;

    // Set-up as tasks the threads take in turn (the sorted source first: the walk, the source's
    // bands and its UV grid wait for it); each builds its own structure.
    std::unique_ptr<SortedSource> sorted;
    std::unique_ptr<UvFaceGrid> grid;
    std::unique_ptr<SurfaceWalk> walk;
    FaceBands bands, sourceBands;
    ByteBuffer state;  // each band clears its own rows (the pages' first touch on its thread)
    {
        std::promise<void> sortedDone;
        const std::shared_future<void> sortedReady = sortedDone.get_future().share();
        runBands(7, options.threads, [&](size_t task) {
            switch (task) {
            case 0:
                sorted = std::make_unique<SortedSource>(source, width, height);
                sortedDone.set_value();
                break;
            case 1: out.cornerTangents = targetTangents(target); break;
            case 2: {
                // The adjacency of the source in its own order (its vertices' order, near in
                // memory: twice as fast as in the atlas' order), renumbered.
                const std::vector<uint32_t> original =
                    buildEdgeAdjacency(source.triangles, source.faceCount, source.vertexCount).opposite;
                sortedReady.wait();
                std::vector<uint32_t, DefaultInitAllocator<uint32_t>> opposite(original.size());  // written in full
                const uint32_t *const to = sorted->sortedFace.data();
                for (size_t f = 0; f < source.faceCount; ++f)
                    for (size_t k = 0; k < 3; ++k) {
                        const uint32_t h = original[3 * f + k];
                        opposite[3 * size_t(to[f]) + k] = h == kNoOpposite ? kNoOpposite : 3 * to[h / 3] + h % 3;
                    }
                walk = std::make_unique<SurfaceWalk>(source.positions, source.normals, sorted->triangles.data(),
                                                     source.faceCount, source.vertexCount, opposite.data());
                break;
            }
            case 3: out.rgba.resize(texels * 4); break;  // unwritten: the bands write every texel
            case 4:
                sortedReady.wait();
                sourceBands = faceBands(sorted->mesh, width, height, kBandRows);
                break;
            case 5:
                state.resize(texels);
                bands = faceBands(target, width, height, kBandRows);
                break;
            default:
                sortedReady.wait();
                grid = std::make_unique<UvFaceGrid>(*sorted, width, height);
                break;
            }
        });
    }
    const size_t bandCount = bands.start.size() - 1;
    std::vector<size_t> baked(bandCount, 0), flat(bandCount, 0);
    // A row's texels a triangle only overlaps, left for the band's second pass: cl..cr but the
    // centres zl..zr (zl > zr: none), the walk starting from `left` before the centres and from
    // `right` after them (the source faces of the first pass' texels there).
    struct OverlapRow {
        uint32_t face;  // the index in the band's faces
        int y, cl, cr, zl, zr;
        uint32_t left, right;
    };
    // Per thread: the band's source faces under the texel centres, a triangle's texels, the faces
    // the walk's closest-point refinement has measured, the rows of overlapped texels.
    struct Scratch {
        std::vector<uint32_t> under;
        TexelBatch batch;
        SurfaceWalk::Marks marks;
        std::vector<OverlapRow> overlaps;
    };
    std::vector<Scratch> scratch(size_t(bandThreads(options.threads, bandCount)));
    runWorkerBands(bandCount, options.threads, [&](size_t band, int worker) {
        const int r0 = int(band) * kBandRows, r1 = std::min(height, r0 + kBandRows);
        uint32_t *const rgba = reinterpret_cast<uint32_t *>(out.rgba.data());
        uint8_t *const states = state.data();
        std::memset(states + size_t(r0) * size_t(width), 0, size_t(r1 - r0) * size_t(width));
        // Flat normal (128, 128, 255) on the band's rows (image rows height - r1 .. height - 1 - r0).
        std::fill(rgba + size_t(height - r1) * size_t(width), rgba + size_t(height - r0) * size_t(width),
                  0xFFFF8080u);  // bytes 128, 128, 255, 255
        glm::dvec2 q[3];
        // The source face under each texel centre of the band (its UV triangle holds the centre).
        std::vector<uint32_t> &under = scratch[size_t(worker)].under;
        TexelBatch &batch = scratch[size_t(worker)].batch;
        SurfaceWalk::Marks &marks = scratch[size_t(worker)].marks;
        under.assign(size_t(r1 - r0) * size_t(width), UINT32_MAX);
        for (uint32_t i = sourceBands.start[band]; i < sourceBands.start[band + 1]; ++i)
            fillFacesUnder(sorted->mesh, sourceBands.faces[i], width, height, r0, r1, under.data());
        // Two passes over the band's triangles: their texel centres first, then the texels they
        // merely overlap that no centre claimed (the first triangle in the band's order that
        // overlaps one claims it, as in a single pass, but no overlap is baked only to be
        // overwritten by a later triangle's centre: three in four were, on the benchmark mesh).
        std::vector<OverlapRow> &overlapRows = scratch[size_t(worker)].overlaps;
        overlapRows.clear();
        size_t nextOverlap = 0;  // the second pass' next row
        const uint32_t firstFace = bands.start[band], endFace = bands.start[band + 1];
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) {
                // Only the rows with an overlapped texel no centre claimed.
                auto unclaimed = [&](const OverlapRow &row) {
                    const uint8_t *const s = states + size_t(row.y) * size_t(width);
                    const bool centres = row.zl <= row.zr;
                    for (int x = row.cl; x <= (centres ? std::min(row.zl - 1, row.cr) : row.cr); ++x)
                        if (s[x] == 0)
                            return true;
                    for (int x = std::max(row.zr + 1, row.cl); centres && x <= row.cr; ++x)
                        if (s[x] == 0)
                            return true;
                    return false;
                };
                overlapRows.erase(std::remove_if(overlapRows.begin(), overlapRows.end(),
                                                 [&](const OverlapRow &row) { return !unclaimed(row); }),
                                  overlapRows.end());
            }
            for (uint32_t i = firstFace; i < endFace; ++i) {
                if (pass == 1 && (nextOverlap == overlapRows.size() || overlapRows[nextOverlap].face != i))
                    continue;
                const size_t f = bands.faces[i];
                loadUv(target, f, width, height, q);
                const double d = doubleArea(q[0], q[1], q[2]);
                if (!(d != 0) || !std::isfinite(d))
                    continue;
                // Barycentric weights as affine functions of the texel centre: l = l0 + lx x + ly y.
                const double a1 = (q[2].y - q[0].y) / d, b1 = -(q[2].x - q[0].x) / d;
                const double a2 = -(q[1].y - q[0].y) / d, b2 = (q[1].x - q[0].x) / d;
                glm::vec3 tp[3], tn[3], tt[3];
                float w = 0.0f;
                for (int k = 0; k < 3; ++k) {
                    const uint32_t v = target.triangles[3 * f + size_t(k)];
                    tp[k] = target.positions[v];
                    tn[k] = target.normals[v];
                    tt[k] = glm::vec3(out.cornerTangents[3 * f + size_t(k)]);
                    w += out.cornerTangents[3 * f + size_t(k)].w;
                }
                const glm::vec3 e1 = tp[1] - tp[0], e2 = tp[2] - tp[0];
                const float sign = w < 0.0f ? -1.0f : 1.0f;
                TargetFrame targetFrame;
                for (int k = 0; k < 3; ++k)
                    for (int a = 0; a < 3; ++a)
                        targetFrame.n[k][a] = tn[k][a], targetFrame.t[k][a] = tt[k][a];
                targetFrame.sign = sign;
#if VOXELFAIR_SSE2
                const QuadTarget quadTarget(tp[0], e1, e2, tn);
#endif
                // The texels are visited row by row, left to right. A texel's source point is most
                // often on the face of the texel before it (checked first), else on the face across
                // the edge it left that face by (the walk's first step: rows cross a source face every
                // few texels), else on the source face under its UV (the atlas' correspondence);
                // failing all, the walk starts from the texel before it (a step or two away on the
                // same sheet), or, for a row's first texel, from the previous row's first answer, for
                // the triangle's first texel from the face under its UV (the UV grid's nearest where
                // none is).
                uint32_t hitFace = UINT32_MAX, rowFace = UINT32_MAX;
                // The source normal at texel (x, y) with weights l1, l2; false when no source face is
                // near. `tried`: the texel is known not to be on hitFace (holdsQuad said so) and left
                // it for `next` (SurfaceWalk::across); `both`: nor on `next` and the face under its UV.
                auto sourceNormal = [&](int x, int y, float l1, float l2, glm::vec3 &n, bool tried, bool both,
                                        uint32_t next) {
                    const glm::vec3 p = tp[0] + l1 * e1 + l2 * e2;
                    const float l0 = 1.0f - l1 - l2;
                    const glm::vec3 facing = l0 * tn[0] + l1 * tn[1] + l2 * tn[2];
                    glm::vec3 weights;
                    if (!tried && hitFace != UINT32_MAX) {
                        if (walk->holds(p, hitFace, facing, weights)) {
                            n = walk->normalAt(hitFace, weights);
                            return true;
                        }
                        next = walk->across(hitFace, weights);
                    }
                    if (!both && next != UINT32_MAX && walk->holds(p, next, facing, weights)) {
                        hitFace = next;
                        n = walk->normalAt(hitFace, weights);
                        return true;
                    }
                    const uint32_t start = under[size_t(y - r0) * size_t(width) + size_t(x)];
                    if (!both && start != UINT32_MAX && start != hitFace && start != next &&
                        walk->holds(p, start, facing, weights)) {
                        hitFace = start;
                        n = walk->normalAt(hitFace, weights);
                        return true;
                    }
                    uint32_t from = hitFace != UINT32_MAX ? hitFace : start;
                    if (from == UINT32_MAX &&
                        (from = grid->find(double(l0) * q[0] + double(l1) * q[1] + double(l2) * q[2])) == UINT32_MAX)
                        return false;
                    const SurfaceWalk::Hit hit = walk->project(p, from, facing, marks, 64);
                    hitFace = hit.face;
                    n = walk->normalAt(hit);
                    return true;
                };
                // Rows outside the band belong to the bands that hold them.
                auto visitRow = [&](int y, int cl, int cr, int zl, int zr) {
                    const uint32_t stateRow = uint32_t(y) * uint32_t(width),
                                   imageRow = uint32_t(height - 1 - y) * uint32_t(width);
                    const double py = y + 0.5 - q[0].y;
                    hitFace = rowFace;
                    bool first = true;
                    // The row's texels are gathered, the triangle's rows solved and written at once
                    // (its texels are distinct, one row each: a row reads only the states of its own
                    // texels, which no other row of the triangle writes, so the order of claims is
                    // kept).
                    const bool centres = zl <= zr;
                    const bool overlaps = centres ? cl < zl || cr > zr : cl <= cr;
                    const uint32_t leftStart = hitFace;
                    if (pass == 0 && !centres) {
                        overlapRows.push_back({i, y, cl, cr, zl, zr, leftStart, leftStart});
                        return;
                    }
                    if (pass == 0)
                        batch.startRow(stateRow, imageRow, zl, zr - zl + 1);
                    auto visit = [&](int x, float l1, float l2, bool tried = false, bool both = false,
                                     uint32_t next = UINT32_MAX) {
                        glm::vec3 n(0.0f);
                        if (!sourceNormal(x, y, l1, l2, n, tried, both, next))
                            n = glm::vec3(0.0f);
                        if (first)
                            rowFace = hitFace, first = false;
                        batch.set(x, l1, l2, n);
                    };
                    // Texels the triangle only overlaps, if no centre claimed them (no centre of this
                    // face lies among them, so their order among the centres keeps the order of
                    // claims): weights clamped onto it.
                    auto overlap = [&](int x) {
                        if (states[stateRow + uint32_t(x)] != 0)
                            return;
                        const double px = x + 0.5 - q[0].x;
                        float l1 = float(a1 * px + b1 * py), l2 = float(a2 * px + b2 * py), l0 = 1.0f - l1 - l2;
                        l0 = std::max(l0, 0.0f), l1 = std::max(l1, 0.0f), l2 = std::max(l2, 0.0f);
                        const float sum = l0 + l1 + l2;
                        if (sum > 0)
                            l1 /= sum, l2 /= sum;
                        visit(x, l1, l2);
                    };
                    if (pass == 1) {  // the overlapped texels left of the centres, then right of them
                        const OverlapRow &row = overlapRows[nextOverlap++];
                        const int leftEnd = centres ? std::min(zl - 1, cr) : cr, rightBegin = std::max(zr + 1, cl);
                        hitFace = row.left;
                        if (cl <= leftEnd) {
                            batch.startRow(stateRow, imageRow, cl, leftEnd - cl + 1);
                            for (int x = cl; x <= leftEnd; ++x)
                                overlap(x);
                        }
                        hitFace = row.right;
                        if (centres && rightBegin <= cr) {
                            batch.startRow(stateRow, imageRow, rightBegin, cr - rightBegin + 1);
                            for (int x = rightBegin; x <= cr; ++x)
                                overlap(x);
                        }
                        return;
                    }
                    // Centres inside: the weights step along the row.
                    if (centres) {
                        const double px = zl + 0.5 - q[0].x;
                        double l1 = a1 * px + b1 * py, l2 = a2 * px + b2 * py;
                        bool tried = false;          // texel x is known not to be on hitFace,
                        uint32_t next = UINT32_MAX;  // and left it for this face
                        for (int x = zl; x <= zr;) {
#if VOXELFAIR_SSE2
                            // 4 texels at once (those past zr ignored) against the face of the texel
                            // before them (the fast path), else, when the first is not on it, against
                            // the face it left that one by, then the face under the first's UV, as
                            // sourceNormal tries them: the texels up to the first that is not on the
                            // face that holds the first are done.
                            if (hitFace != UINT32_MAX) {
                                // The weights of the 4 texels, stepped in doubles as one texel at a
                                // time does it (l1 and l2 side by side), then rounded to float.
                                __m128d m = _mm_set_pd(l2, l1);
                                const __m128d step = _mm_set_pd(a2, a1);
                                __m128 w[4];
                                for (__m128 &wk : w)
                                    wk = _mm_cvtpd_ps(m), m = _mm_add_pd(m, step);
                                const __m128 w01 = _mm_unpacklo_ps(w[0], w[1]), w23 = _mm_unpacklo_ps(w[2], w[3]);
                                const __m128 L1 = _mm_movelh_ps(w01, w23), L2 = _mm_movehl_ps(w23, w01);
                                __m128 weights[3];
                                const int lanes = (1 << std::min(4, zr - x + 1)) - 1;
                                int held = 0;
                                if (!tried) {
                                    held = holdsQuad(*walk, hitFace, L1, L2, quadTarget, weights) & lanes;
                                    if ((held & 1) == 0)
                                        next = acrossLane(*walk, hitFace, weights, 0);
                                }
                                if ((held & 1) == 0 && next != UINT32_MAX &&
                                    ((held = holdsQuad(*walk, next, L1, L2, quadTarget, weights) & lanes) & 1) != 0)
                                    hitFace = next;
                                if ((held & 1) == 0) {
                                    const uint32_t start = under[size_t(y - r0) * size_t(width) + size_t(x)];
                                    if (start != UINT32_MAX && start != hitFace && start != next &&
                                        ((held = holdsQuad(*walk, start, L1, L2, quadTarget, weights) & lanes) & 1) !=
                                            0)
                                        hitFace = start;
                                }
                                if ((held & 1) != 0) {
                                    __m128 n[3];
                                    quadNormals(*walk, hitFace, weights, n);
                                    if (first)
                                        rowFace = hitFace, first = false;
                                    int k = 0;  // the lanes held, up to the first that is not
                                    while (k < 4 && (held >> k & 1) != 0)
                                        ++k;
                                    batch.setQuad(x, L1, L2, n, k);
                                    if (k < 4)  // lane k is not on hitFace: the face it left it for
                                        next = acrossLane(*walk, hitFace, weights, k);
                                    x += k;
                                    if (k == 4)
                                        l1 = _mm_cvtsd_f64(m), l2 = _mm_cvtsd_f64(_mm_unpackhi_pd(m, m));
                                    else
                                        for (int j = 0; j < k; ++j)
                                            l1 += a1, l2 += a2;
                                    tried = k < 4;
                                    continue;
                                }
                                // Neither: the walk.
                                visit(x, _mm_cvtss_f32(L1), _mm_cvtss_f32(L2), true, true);
                                ++x, l1 += a1, l2 += a2;
                                tried = false;
                                continue;
                            }
#endif
                            visit(x, float(l1), float(l2), tried, false, next);
                            ++x, l1 += a1, l2 += a2;
                            tried = false;
                        }
                        if (overlaps)
                            overlapRows.push_back({i, y, cl, cr, zl, zr, leftStart, hitFace});
                    }
                };
                batch.clear();
                if (pass == 0) {
                    rasterRows(q[0], q[1], q[2], kMargin, width, height, visitRow, r0, r1 - 1);
                } else {
                    for (; nextOverlap < overlapRows.size() && overlapRows[nextOverlap].face == i;) {
                        const OverlapRow &row = overlapRows[nextOverlap];
                        hitFace = rowFace = row.left;
                        visitRow(row.y, row.cl, row.cr, row.zl, row.zr);
                    }
                }
                writeTexelBatch(targetFrame, batch, states, rgba);
            }
        }

        uint32_t fromSource = 0, painted = 0;  // local: the bands' counters share cache lines
        for (size_t t = size_t(r0) * size_t(width); t < size_t(r1) * size_t(width); ++t) {
            fromSource += states[t] >> 1;
            painted += states[t] & 1;
        }
        baked[band] = fromSource;
        flat[band] = painted - fromSource;
    });
    for (size_t b = 0; b < bandCount; ++b)
        out.texelsBaked += baked[b], out.texelsWithoutSource += flat[b];

    fillNormalGutter(width, height, state.data(), out.rgba.data(), options.dilation * scale,
                     options.blocks && options.level == 0 ? 2 * scale : 0, options.threads);
    return out;
}

// NOLINTEND(misc-definitions-in-headers)
