// libvoxelfair/maps on generated families (fixed seeds): planes at random orientations with
// random affine (possibly mirrored) UV maps, where the MikkTSpace tangent is known in closed form,
// and normal fields baked from a fine grid onto a coarse one and read back as a shader does.
#include "maps/face_value_bake.h"
#include "maps/mikktspace.h"
#include "maps/normal_bake.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

using namespace voxelfair;

namespace {

glm::mat3 randomRotation(std::mt19937 &rng) {
    std::normal_distribution<float> g;
    glm::vec3 a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng));
    a = glm::normalize(a);
    b = glm::normalize(b - glm::dot(a, b) * a);
    return glm::mat3(a, b, glm::cross(a, b));
}

// An n x n vertex grid on the plane (s, t) in [0, 1]^2, placed by R and an offset, UVs A (s, t) + c.
struct PlaneGrid {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    glm::vec2 st(size_t v, int n) const { return glm::vec2(float(v % size_t(n)), float(v / size_t(n))) / float(n - 1); }
};

PlaneGrid planeGrid(int n, const glm::mat3 &R, glm::vec3 offset, const glm::mat2 &A, glm::vec2 c) {
    PlaneGrid g;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec2 st(float(i) / float(n - 1), float(j) / float(n - 1));
            g.positions.push_back(R * glm::vec3(st, 0.0f) + offset);
            g.normals.push_back(R[2]);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = uint32_t(j * n + i), b = a + 1, d = a + uint32_t(n), e = d + 1;
            for (uint32_t v : {a, b, e, a, e, d})
                g.triangles.push_back(v);
        }
    for (uint32_t v : g.triangles)
        g.wedgeUv.push_back(A * g.st(v, n) + c);
    return g;
}

std::vector<glm::vec4> tangentsOf(const PlaneGrid &g) {
    std::vector<glm::vec3> p, n;
    for (uint32_t v : g.triangles)
        p.push_back(g.positions[v]), n.push_back(g.normals[v]);
    TangentInput in;
    in.positions = p.data();
    in.normals = n.data();
    in.uvs = g.wedgeUv.data();
    in.triangleCount = g.triangles.size() / 3;
    return computeMikkTSpaceTangents(in);
}

// A UV map with a random rotation, scales in [0.2, 0.8] and a random mirror.
glm::mat2 randomUvMap(std::mt19937 &rng, bool mirror) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float angle = u(rng) * 6.2831853f, sx = 0.2f + 0.6f * u(rng), sy = 0.2f + 0.6f * u(rng);
    const glm::mat2 rot(std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle));
    return rot * glm::mat2(sx, 0.0f, 0.0f, mirror ? -sy : sy);
}

NormalBakeMesh view(const PlaneGrid &g) { return normalBakeMesh(g.positions, g.normals, g.triangles, g.wedgeUv); }

}  // namespace

TEST(MikkTSpace, PlanesAtRandomOrientationsGetDpDuAndTheHandednessOfTheirUvMap) {
    std::mt19937 rng(2008);
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE(trial);
        const glm::mat3 R = randomRotation(rng);
        const bool mirror = trial % 2 == 1;
        const glm::mat2 A = randomUvMap(rng, mirror);
        const PlaneGrid g = planeGrid(6, R, glm::vec3(float(trial), -3.0f, 7.5f), A, glm::vec2(0.1f, 0.1f));
        const std::vector<glm::vec4> t = tangentsOf(g);
        // (s, t) = A^-1 (uv - c): dP/du and dP/dv are R times A^-1's columns.
        const glm::mat2 inv = glm::inverse(A);
        const glm::vec3 dPdu = glm::normalize(R * glm::vec3(inv[0], 0.0f)), dPdv = R * glm::vec3(inv[1], 0.0f);
        const float sign = glm::dot(glm::cross(R[2], dPdu), dPdv) > 0.0f ? 1.0f : -1.0f;
        EXPECT_EQ(sign, mirror ? -1.0f : 1.0f);
        for (const glm::vec4 &c : t) {
            ASSERT_NEAR(c.x, dPdu.x, 1e-4f);
            ASSERT_NEAR(c.y, dPdu.y, 1e-4f);
            ASSERT_NEAR(c.z, dPdu.z, 1e-4f);
            ASSERT_EQ(c.w, sign);
        }
    }
}

TEST(MikkTSpace, DegenerateAndUnmappedTrianglesTakeTheirVertexNeighboursSpace) {
    std::mt19937 rng(7);
    const PlaneGrid g = planeGrid(3, randomRotation(rng), glm::vec3(0.0f), glm::mat2(0.5f), glm::vec2(0.25f));
    std::vector<glm::vec3> p, n;
    std::vector<glm::vec2> uv = g.wedgeUv;
    for (uint32_t v : g.triangles)
        p.push_back(g.positions[v]), n.push_back(g.normals[v]);
    // A degenerate triangle on vertex 4's corner (position, normal, UV equal to a healthy corner).
    size_t corner4 = 0;
    while (g.triangles[corner4] != 4)
        ++corner4;
    for (int k = 0; k < 3; ++k)
        p.push_back(p[corner4]), n.push_back(n[corner4]), uv.push_back(uv[corner4]);
    TangentInput in{p.data(), n.data(), uv.data(), p.size() / 3};
    const std::vector<glm::vec4> t = computeMikkTSpaceTangents(in);
    for (size_t c = p.size() - 3; c < p.size(); ++c)
        EXPECT_EQ(t[c], t[corner4]);
    // Every corner of a triangle without UV area still gets a unit tangent from its neighbours.
    for (int k = 0; k < 3; ++k)
        uv[k] = uv[0];
    const std::vector<glm::vec4> u = computeMikkTSpaceTangents(in);
    for (int k = 1; k < 3; ++k)
        EXPECT_NEAR(glm::length(glm::vec3(u[size_t(k)])), 1.0f, 1e-5f);
}

TEST(NormalBake, NormalFieldsOnRandomPlanesReadBackThroughTheShaderFrame) {
    std::mt19937 rng(185);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int trial = 0; trial < 12; ++trial) {
        SCOPED_TRACE(trial);
        const glm::mat3 R = randomRotation(rng);
        const glm::mat2 A = randomUvMap(rng, trial % 2 == 1);
        const glm::vec2 c(0.5f, 0.5f);
        PlaneGrid fine = planeGrid(33, R, glm::vec3(2.0f), A, c - A * glm::vec2(0.5f));
        PlaneGrid coarse = planeGrid(4, R, glm::vec3(2.0f), A, c - A * glm::vec2(0.5f));
        // A bumpy normal field on the source; the target's vertex normals tilted at random too.
        const float fx = 2.0f + 3.0f * std::abs(u(rng)), fy = 2.0f + 3.0f * std::abs(u(rng));
        for (size_t v = 0; v < fine.positions.size(); ++v) {
            const glm::vec2 st = fine.st(v, 33);
            fine.normals[v] =
                glm::normalize(R * glm::vec3(0.4f * std::sin(fx * st.x), 0.4f * std::cos(fy * st.y), 1.0f));
        }
        for (glm::vec3 &n : coarse.normals)
            n = glm::normalize(n + 0.2f * R * glm::vec3(u(rng), u(rng), 0.0f));
        NormalBakeOptions options;
        // Square maps, and 2:1 ones (a wide atlas: UVs normalised per axis).
        options.width = 256;
        options.height = trial % 3 == 2 ? 128 : 256;
        options.level = trial / 6;  // the last six at level 1: one texel per 2 x 2 block
        // At level 0, half the trials at the atlas' size, half 4x finer (the default for a
        // 256-texel atlas, NormalBakeOptions::minSide).
        if (trial % 2 == 1)
            options.minSide = 0;
        const int scale = options.level == 0 && trial % 2 == 0 ? 4 : 1;
        EXPECT_EQ(normalMapScale(options), scale);
        const NormalMap map = bakeNormalMap(view(fine), view(coarse), options);
        EXPECT_EQ(map.width, (256 >> options.level) * scale);
        EXPECT_EQ(map.height, (options.height >> options.level) * scale);
        EXPECT_EQ(map.texelsWithoutSource, 0u);
        // Texel centres inside coarse triangles: the decoded normal is the fine one there.
        double worst = 0;
        int checked = 0;
        for (size_t f = 0; f < coarse.triangles.size() / 3; ++f) {
            for (int s = 0; s < 6; ++s) {
                float l1 = std::abs(u(rng)), l2 = std::abs(u(rng));
                if (l1 + l2 > 1)
                    l1 = 1 - l1, l2 = 1 - l2;
                const float l[3] = {1 - l1 - l2, l1, l2};
                glm::vec2 uv(0.0f);
                glm::vec3 n(0.0f), t(0.0f);
                float w = 0;
                for (int k = 0; k < 3; ++k)
                    uv += l[k] * coarse.wedgeUv[3 * f + size_t(k)];
                // Snap to the texel centre, and interpolate there.
                const glm::vec2 side(float(map.width), float(map.height));
                const glm::vec2 texel = glm::floor(uv * side) + 0.5f;
                uv = texel / side;
                const glm::vec2 *q = &coarse.wedgeUv[3 * f];
                const float d = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
                const float b1 = ((uv.x - q[0].x) * (q[2].y - q[0].y) - (uv.y - q[0].y) * (q[2].x - q[0].x)) / d;
                const float b2 = ((q[1].x - q[0].x) * (uv.y - q[0].y) - (q[1].y - q[0].y) * (uv.x - q[0].x)) / d;
                const float b[3] = {1 - b1 - b2, b1, b2};
                if (b[0] < 0.01f || b[1] < 0.01f || b[2] < 0.01f)
                    continue;
                for (int k = 0; k < 3; ++k) {
                    n += b[k] * coarse.normals[coarse.triangles[3 * f + size_t(k)]];
                    t += b[k] * glm::vec3(map.cornerTangents[3 * f + size_t(k)]);
                    w += b[k] * map.cornerTangents[3 * f + size_t(k)].w;
                }
                const int x = int(texel.x), y = int(texel.y);
                const uint8_t *p = &map.rgba[(size_t(map.height - 1 - y) * size_t(map.width) + size_t(x)) * 4];
                const glm::vec3 decoded(p[0] / 255.0f * 2 - 1, p[1] / 255.0f * 2 - 1, p[2] / 255.0f * 2 - 1);
                const glm::vec3 shaded = applyNormalMapTexel(decoded, n, glm::vec4(t, w));
                // The fine grid's normal at the same point (its UV map is the same).
                const glm::vec2 st = glm::inverse(A) * (uv - (c - A * glm::vec2(0.5f)));
                const float gx = st.x * 32.0f, gy = st.y * 32.0f;
                const int i0 = std::min(int(gx), 31), j0 = std::min(int(gy), 31);
                const float ax = gx - float(i0), ay = gy - float(j0);
                auto N = [&](int i, int j) { return fine.normals[size_t(j * 33 + i)]; };
                // The fine quads are split along (i, j)-(i+1, j+1).
                const glm::vec3 expected =
                    ax >= ay ? (1 - ax) * N(i0, j0) + (ax - ay) * N(i0 + 1, j0) + ay * N(i0 + 1, j0 + 1)
                             : (1 - ay) * N(i0, j0) + (ay - ax) * N(i0, j0 + 1) + ax * N(i0 + 1, j0 + 1);
                const double angle =
                    std::acos(std::clamp(double(glm::dot(shaded, glm::normalize(expected))), -1.0, 1.0)) * 180 / M_PI;
                worst = std::max(worst, angle);
                ++checked;
            }
        }
        EXPECT_GT(checked, 20);
        EXPECT_LT(worst, 1.0) << "degrees";  // 8-bit quantisation: about 0.45 degrees
    }
}

// The thrown error's message, "" when nothing was thrown.
template <class ErrorType>
std::string thrown(const NormalBakeMesh &source, const NormalBakeMesh &target, const NormalBakeOptions &options) {
    try {
        bakeNormalMap(source, target, options);
    } catch (const ErrorType &e) {
        return e.what();
    }
    return "";
}

TEST(NormalBake, RefusesEmptyOrBrokenInputWithAMessage) {
    NormalBakeMesh empty;
    NormalBakeOptions options;
    options.width = 16;
    EXPECT_NE(thrown<MeshError>(empty, empty, options).find("source mesh has no faces"), std::string::npos);
    const PlaneGrid g = planeGrid(3, glm::mat3(1.0f), glm::vec3(0.0f), glm::mat2(1.0f), glm::vec2(0.0f));
    std::vector<uint32_t> broken = g.triangles;
    broken[4] = 99;
    NormalBakeMesh bad = view(g);
    bad.triangles = broken.data();
    EXPECT_NE(thrown<MeshError>(view(g), bad, options).find("target mesh has a vertex index out of range (face 1)"),
              std::string::npos);
    options.width = 0;
    EXPECT_NE(thrown<OptionError>(view(g), view(g), options).find("between 1 and 16384"), std::string::npos);
    options.width = 16, options.height = 20000;
    EXPECT_NE(thrown<OptionError>(view(g), view(g), options).find("between 1 and 16384"), std::string::npos);
    options.height = 16, options.level = 2;
    EXPECT_NE(thrown<OptionError>(view(g), view(g), options).find("level must be 0"), std::string::npos);
    options.level = 1, options.width = 15;  // odd sides: a last half block
    EXPECT_EQ(bakeNormalMap(view(g), view(g), options).width, 8);
}

// The map's size rule (NormalBakeOptions::minSide): small atlases get a map 2x or 4x finer each
// side, the least whose long side reaches 1024 texels; atlases of 1024 or more stay 1:1, as do
// level 1 and minSide 0. Generated sides, square and not, either side the long one.
TEST(NormalBake, SmallAtlasesGetAFinerMapLargeOnesKeepTheirSize) {
    std::mt19937 rng(1313);
    std::uniform_int_distribution<int> side(1, 4096);
    for (int trial = 0; trial < 500; ++trial) {
        NormalBakeOptions options;
        options.width = side(rng), options.height = trial % 3 == 0 ? 0 : side(rng);
        const int longSide = std::max(options.width, options.height);
        const int scale = normalMapScale(options);
        SCOPED_TRACE(std::to_string(options.width) + " x " + std::to_string(options.height));
        if (longSide >= 1024)
            EXPECT_EQ(scale, 1);
        else if (longSide >= 512)
            EXPECT_EQ(scale, 2);
        else
            EXPECT_EQ(scale, 4);  // at most 4x, even when the long side stays under 1024
        options.minSide = 0;
        EXPECT_EQ(normalMapScale(options), 1);
        options.minSide = 1024, options.level = 1;
        EXPECT_EQ(normalMapScale(options), 1);
    }
    // The baked map has those sides.
    const PlaneGrid g = planeGrid(3, glm::mat3(1.0f), glm::vec3(0.0f), glm::mat2(1.0f), glm::vec2(0.0f));
    for (const auto &[w, h, mapW, mapH] : {std::array<int, 4>{300, 150, 1200, 600},
                                           {600, 0, 1200, 1200},
                                           {1024, 512, 1024, 512},
                                           {2048, 2048, 2048, 2048}}) {
        NormalBakeOptions options;
        options.width = w, options.height = h;
        const NormalMap map = bakeNormalMap(view(g), view(g), options);
        EXPECT_EQ(map.width, mapW);
        EXPECT_EQ(map.height, mapH);
    }
}

TEST(NormalBake, TheMapIsTheSameOnAnyNumberOfThreads) {
    std::mt19937 rng(1313);
    for (int trial = 0; trial < 4; ++trial) {
        SCOPED_TRACE(trial);
        const glm::mat3 R = randomRotation(rng);
        const glm::mat2 A = randomUvMap(rng, trial % 2 == 1);
        const glm::vec2 c(0.5f, 0.5f);
        PlaneGrid fine = planeGrid(41, R, glm::vec3(1.0f), A, c - A * glm::vec2(0.5f));
        const PlaneGrid coarse = planeGrid(5, R, glm::vec3(1.0f), A, c - A * glm::vec2(0.5f));
        for (size_t v = 0; v < fine.positions.size(); ++v) {
            const glm::vec2 st = fine.st(v, 41);
            fine.normals[v] = glm::normalize(R * glm::vec3(0.3f * std::sin(7 * st.x), 0.3f * std::cos(5 * st.y), 1.0f));
        }
        NormalBakeOptions options;
        options.width = 512;
        options.height = trial < 2 ? 512 : 256;
        options.level = trial % 2;
        options.minSide = trial == 0 ? 1024 : 0;  // one 2x finer map
        options.threads = 1;
        const NormalMap one = bakeNormalMap(view(fine), view(coarse), options);
        for (int threads : {2, 3, 8}) {
            options.threads = threads;
            const NormalMap many = bakeNormalMap(view(fine), view(coarse), options);
            EXPECT_EQ(many.texelsBaked, one.texelsBaked);
            EXPECT_GT(many.texelsBaked, size_t(many.width) * size_t(many.height) / 20);
            EXPECT_TRUE(many.rgba == one.rgba) << threads << " threads";
        }
    }
}

// Aligned 2 x 2 blocks of a width x height image (rows top down, RGBA) that mix texels `filled`
// says are painted with texels it says are not.
template <class Bytes, class Filled>
int mixedBlocks(const Bytes &rgba, int width, int height, Filled &&filled, int side = 2) {
    int mixed = 0;
    for (int y = 0; y + side - 1 < height; y += side)
        for (int x = 0; x + side - 1 < width; x += side) {
            int n = 0;
            for (int k = 0; k < side * side; ++k)
                n += filled(&rgba[(size_t(y + k / side) * size_t(width) + size_t(x + k % side)) * 4]) ? 1 : 0;
            mixed += n > 0 && n < side * side ? 1 : 0;
        }
    return mixed;
}

TEST(NormalBake, OnABlockAtlasEveryBlockAChartTouchesIsFilledAsTheBaseColoursIs) {
    std::mt19937 rng(2222);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int trial = 0; trial < 6; ++trial) {
        SCOPED_TRACE(trial);
        const glm::mat3 R = randomRotation(rng);
        const glm::mat2 A = randomUvMap(rng, trial % 2 == 1);
        const glm::vec2 c(0.5f, 0.5f);
        const PlaneGrid fine = planeGrid(17, R, glm::vec3(1.0f), A, c - A * glm::vec2(0.5f));
        PlaneGrid coarse = planeGrid(3, R, glm::vec3(1.0f), A, c - A * glm::vec2(0.5f));
        for (glm::vec3 &n : coarse.normals)  // tilted: no baked texel is the flat background
            n = glm::normalize(n + 0.3f * R * glm::vec3(0.5f + 0.5f * std::abs(u(rng)), 0.5f, 0.0f));
        NormalBakeOptions options;
        options.width = 97 + trial;  // odd sides too: a last half block
        options.height = 64;
        auto painted = [](const uint8_t *p) { return !(p[0] == 128 && p[1] == 128 && p[2] == 255); };
        // Flipped rows keep blocks aligned only on even heights; the height is even.
        // At the atlas' size and 4x finer (the default for so small an atlas): the atlas' blocks
        // are 2 x 2 texels of the one, 8 x 8 of the other.
        for (const int minSide : {0, 1024}) {
            options.minSide = minSide, options.blocks = true;
            const int side = 2 * normalMapScale(options);
            const NormalMap filled = bakeNormalMap(view(fine), view(coarse), options);
            EXPECT_EQ(filled.width, options.width * side / 2);
            EXPECT_EQ(mixedBlocks(filled.rgba, filled.width, filled.height, painted, side), 0);
            options.blocks = false;
            const NormalMap rings = bakeNormalMap(view(fine), view(coarse), options);
            EXPECT_GT(mixedBlocks(rings.rgba, rings.width, rings.height, painted, side), 0);  // the test can tell
        }

        // The per-face value maps (house mask, material maps) too: alpha 255 on charts and gutter.
        FaceValueMesh mesh;
        static_cast<TriangleMesh &>(mesh) = triangleMesh(fine.positions, fine.triangles);
        mesh.wedgeUv = fine.wedgeUv.data();
        const std::vector<glm::u8vec3> values(fine.triangles.size() / 3, glm::u8vec3(200, 100, 50));
        auto opaque = [](const uint8_t *p) { return p[3] == 255; };
        const FaceValueImage blocks = bakeFaceValues(mesh, values.data(), options.width, 64, 1, {0, 0, 0}, true);
        EXPECT_EQ(mixedBlocks(blocks.rgba, blocks.width, blocks.height, opaque), 0);
        const FaceValueImage plain = bakeFaceValues(mesh, values.data(), options.width, 64, 1, {0, 0, 0}, false);
        EXPECT_GT(mixedBlocks(plain.rgba, plain.width, plain.height, opaque), 0);
    }
}
