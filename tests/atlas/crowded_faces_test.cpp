// Crisp colours for every face (crowded_faces.h): on families of voxel meshes faired by the
// paper's operator (the slivers it squeezes are the hard case), smoothed by Taubin, or jittered
// into needles, every interior point of every face reads its face's colour (also from UVs
// rounded as text files store them: measureColourFidelity), at every density
// that the texture can resolve, in both packers and with a fixed texture size.
#include "atlas/atlas_measures.h"
#include "atlas_checks.h"
#include "shapes/atlas_test_meshes.h"
#include "atlas/texture_atlas.h"
#include "base/error.h"
#include "fairing/lanczos_fairing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

// The paper's fairing (one pass, lambda 4/3) on a voxel surface: quad k is triangles 2k, 2k+1.
TestMesh paperFaired(TestMesh m, int passes = 1) {
    const size_t quads = m.faceCount() / 2;
    std::vector<uint32_t> offsets(quads + 1), indices(4 * quads);
    for (size_t q = 0; q < quads; ++q) {
        offsets[q] = uint32_t(4 * q);
        const uint32_t *t = &m.triangles[6 * q];  // (a, b, c), (a, c, d)
        indices[4 * q] = t[0], indices[4 * q + 1] = t[1], indices[4 * q + 2] = t[2], indices[4 * q + 3] = t[5];
    }
    offsets[quads] = uint32_t(4 * quads);
    LanczosFairingOptions options;
    options.passes = passes;
    options.voxelSize = 1.0f;
    const FairingReport report = fairModifiedLanczos(
        {m.positions.data(), m.positions.size(), offsets.data(), indices.data(), quads}, nullptr, options);
    EXPECT_EQ(report.status, FairingStatus::Ok) << report.message;
    m.name += " paper" + std::to_string(passes);
    return m;
}

// Every vertex moved by up to `amount` voxel on each axis: needles, slivers, faces at all angles.
TestMesh jittered(TestMesh m, float amount, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-amount, amount);
    for (glm::vec3 &p : m.positions)
        p += glm::vec3(unit(rng), unit(rng), unit(rng));
    m.name += " jittered";
    return m;
}

std::vector<TestMesh> families() {
    std::vector<TestMesh> out;
    out.push_back(paperFaired(voxelSphere(9)));
    out.push_back(paperFaired(voxelBox(6, 4, 3)));
    out.push_back(paperFaired(voxelTorus(8, 3)));
    out.push_back(paperFaired(voxelBlob(8, 3)));
    out.push_back(paperFaired(voxelBlob(7, 4), 3));
    out.push_back(smoothed(voxelSphere(8)));
    out.push_back(smoothed(voxelBlob(7, 1), 30));
    out.push_back(jittered(voxelSphere(6), 0.3f, 7));
    out.push_back(jittered(voxelBox(4, 4, 4), 0.45f, 8));
    return out;
}

size_t wrongSamples(const TestMesh &mesh, const TextureAtlas &atlas) {
    const ColourFidelity f = measureColourFidelity(mesh.view(), atlas.layout, atlas.texture);
    return f.samples - f.nearestMatches;
}

}  // namespace

TEST(CrowdedFaces, EveryInteriorPointKeepsItsColourOnEveryFamily) {
    for (const TestMesh &mesh : families())
        for (float density : {8.0f, 12.0f, 16.0f})
            for (PackMode mode : {PackMode::Tight, PackMode::Paper}) {
                SCOPED_TRACE(mesh.name + " at " + std::to_string(density) + " texels per voxel, " + toString(mode));
                AtlasOptions options;
                options.pack.mode = mode;
                const TextureAtlas atlas = atlasAt(mesh, density, options);
                EXPECT_TRUE(atlas.crispGuaranteed) << atlas.crowded.crowdedFaces << " crowded faces";
                EXPECT_EQ(wrongSamples(mesh, atlas), 0u) << atlas.charts.separatedFaces << " faces separated";
                if (density == 8.0f && mode == PackMode::Tight)
                    std::printf("%s: %zu of %zu faces thin at 8 texels per voxel, %zu separated\n", mesh.name.c_str(),
                                atlas.crowded.thinFaces, mesh.faceCount(), atlas.charts.separatedFaces);
                // The separation keeps what every atlas must satisfy.
                const AtlasMeasures m = measureAtlas(mesh.view(), atlas.charts, atlas.layout);
                EXPECT_EQ(m.overlappingChartTexels, 0u);
                EXPECT_EQ(m.overlappingCentres, 0u);
                EXPECT_EQ(m.facesWithoutUvArea, 0u);
                EXPECT_LE(m.maxStretch, 1.0 + 1e-3);
                EXPECT_LE(m.maxInverseStretch, 1.0 / ChartOptions().mergeCosine + 1e-3);
            }
}

// Without the separation the same atlases lose samples: the test above is not vacuous.
TEST(CrowdedFaces, WithoutSeparationFairedMeshesLoseSamples) {
    size_t lost = 0, separated = 0;
    for (const TestMesh &mesh : families()) {
        AtlasOptions options;
        options.pack.fillTexture = false;  // exactly 8: the fill's higher density may spare them
        options.maxSeparatedShare = 0;
        const TextureAtlas plain = atlasAt(mesh, 8, options);
        EXPECT_EQ(plain.charts.separatedFaces, 0u);
        EXPECT_FALSE(plain.crispGuaranteed);
        lost += wrongSamples(mesh, plain);
        options.maxSeparatedShare = 0.1;
        separated += atlasAt(mesh, 8, options).charts.separatedFaces;
    }
    EXPECT_GT(lost, 0u);
    EXPECT_GT(separated, 0u);
}

// A fixed texture size sets the density while packing: the charts are separated for the
// density found, and the guarantee still holds.
TEST(CrowdedFaces, FixedTextureSizeIsSeparatedForTheDensityFound) {
    for (const TestMesh &mesh : {paperFaired(voxelSphere(9)), jittered(voxelBox(4, 4, 4), 0.45f, 8)}) {
        SCOPED_TRACE(mesh.name);
        AtlasOptions options;
        options.pack.textureSize = 512;
        const TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
        EXPECT_EQ(atlas.layout.size, 512);
        EXPECT_TRUE(atlas.crispGuaranteed);
        EXPECT_EQ(wrongSamples(mesh, atlas), 0u);
    }
}

// The charts are searched on threads and summed in chart order, and rebuilt on threads: any thread
// count separates the same faces into the same charts and counts the same, also where the search
// stops over the budget.
TEST(CrowdedFaces, AnyThreadCountSeparatesTheSameFaces) {
    const TestMesh mesh = paperFaired(voxelSphere(16));
    ASSERT_GE(mesh.faceCount(), 4096u);  // enough faces to be searched on threads
    const AtlasCharts start = computeCharts(mesh.view());
    bool sawSeparated = false, sawOverBudget = false;
    for (const CrowdedFaceOptions &o : {CrowdedFaceOptions{8.0, 0.1}, CrowdedFaceOptions{2.0, 0.1},
                                        CrowdedFaceOptions{2.0, 0.02}, CrowdedFaceOptions{3.0, 0.5}}) {
        AtlasCharts one = start;
        CrowdedFaceOptions serial = o;
        serial.threads = 1;
        const CrowdedFaces expected = separateCrowdedFaces(mesh.view(), one, serial);
        sawSeparated = sawSeparated || expected.separatedFaces > 0;
        sawOverBudget = sawOverBudget || expected.overBudget();
        for (int threads : {2, 3}) {
            AtlasCharts many = start;
            CrowdedFaceOptions parallel = o;
            parallel.threads = threads;
            const CrowdedFaces got = separateCrowdedFaces(mesh.view(), many, parallel);
            EXPECT_EQ(got.thinFaces, expected.thinFaces) << o.texelsPerUnit << " " << threads;
            EXPECT_EQ(got.crowdedFaces, expected.crowdedFaces) << o.texelsPerUnit << " " << threads;
            EXPECT_EQ(got.separatedFaces, expected.separatedFaces) << o.texelsPerUnit << " " << threads;
            expectSameCharts(many, one, threads);
        }
    }
    EXPECT_TRUE(sawSeparated);
    EXPECT_TRUE(sawOverBudget);
}

// Each separated face is a chart of its own, projected onto its own plane (stretch 1), and the
// charts it left still hold all their other faces.
TEST(CrowdedFaces, SeparatedFacesAreOneFaceChartsOnTheirOwnPlane) {
    const TestMesh mesh = paperFaired(voxelBlob(7, 4), 3);
    AtlasCharts charts = computeCharts(mesh.view());
    const AtlasCharts before = charts;
    const CrowdedFaces crowded = separateCrowdedFaces(mesh.view(), charts, {8.0, 0.1});
    ASSERT_GT(crowded.separatedFaces, 0u);
    EXPECT_LE(crowded.separatedFaces, crowded.thinFaces);
    EXPECT_EQ(charts.separatedFaces, crowded.separatedFaces);
    EXPECT_EQ(charts.faceCount(), mesh.faceCount());
    EXPECT_EQ(charts.chartFaces.size(), mesh.faceCount());
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
        ASSERT_LT(first, end) << "empty chart " << c;
        for (uint32_t i = first; i < end; ++i)
            EXPECT_EQ(charts.faceChart[charts.chartFaces[i]], c);
    }
    // The separated faces' charts come after the others (and before degenerate faces', none here).
    ASSERT_EQ(charts.degenerateFaces, 0u);
    for (size_t c = charts.chartCount() - crowded.separatedFaces; c < charts.chartCount(); ++c) {
        ASSERT_EQ(charts.chartFirstFace[c + 1] - charts.chartFirstFace[c], 1u);
        const uint32_t f = charts.chartFaces[charts.chartFirstFace[c]];
        EXPECT_GT(before.chartFirstFace[before.faceChart[f] + 1] - before.chartFirstFace[before.faceChart[f]], 1u)
            << "a face alone in its chart is never crowded";
        const glm::vec3 a = mesh.positions[mesh.triangles[3 * f]], b = mesh.positions[mesh.triangles[3 * f + 1]],
                        d = mesh.positions[mesh.triangles[3 * f + 2]];
        EXPECT_NEAR(glm::dot(glm::normalize(glm::cross(b - a, d - a)), charts.chartAxis[c]), 1.0f, 1e-4f);
    }
    EXPECT_GT(charts.chartCount(), before.chartCount());
    EXPECT_LE(charts.chartCount(), before.chartCount() + crowded.separatedFaces);
}

// 2 texels per voxel cannot keep pixel art: nearly every face is crowded, far over the budget.
// By default the density is raised until few are, and every face keeps its colour.
TEST(CrowdedFaces, TooCoarseADensityIsRaisedNotShredded) {
    for (const TestMesh &mesh : families()) {
        SCOPED_TRACE(mesh.name);
        const TextureAtlas atlas = atlasAt(mesh, 2);
        EXPECT_TRUE(atlas.crispGuaranteed);
        EXPECT_EQ(wrongSamples(mesh, atlas), 0u);
        EXPECT_LE(double(atlas.charts.separatedFaces), 0.1 * double(mesh.faceCount()));
        EXPECT_GE(atlas.crispDensity, 2.0);
    }
}

// A fixed texture too small for the pixel art: separating the crowded faces lowers the density
// it can hold, which crowds more (a fixed size cannot raise it). Whatever the size, the atlas is
// made, and where it cannot promise every colour it says so; from some size on it promises.
TEST(CrowdedFaces, AFixedTextureSizeEitherKeepsEveryColourOrSaysSo) {
    const TestMesh mesh = paperFaired(voxelSphere(9));
    bool promised = false;
    for (int size : {128, 256, 320, 384, 512}) {
        SCOPED_TRACE(size);
        AtlasOptions options;
        options.pack.textureSize = size;
        const TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
        EXPECT_EQ(atlas.layout.width, size);
        if (atlas.crispGuaranteed) {
            EXPECT_EQ(wrongSamples(mesh, atlas), 0u);
        }
        promised = promised || atlas.crispGuaranteed;
    }
    EXPECT_TRUE(promised);
}

// Without alwaysCrisp nothing is separated past the budget and the atlas says so.
TEST(CrowdedFaces, TooCoarseATextureIsReportedNotShredded) {
    const TestMesh mesh = paperFaired(voxelSphere(9));
    AtlasOptions options;
    options.pack.texelsPerUnit = 2;
    options.alwaysCrisp = false;
    const TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
    EXPECT_TRUE(atlas.crowded.overBudget());
    EXPECT_GT(atlas.crowded.crowdedFaces, mesh.faceCount() / 10);
    EXPECT_EQ(atlas.charts.separatedFaces, 0u);
    EXPECT_EQ(atlas.charts.chartCount(), computeCharts(mesh.view()).chartCount());
    EXPECT_FALSE(atlas.crispGuaranteed);
}

// One colour crowds nothing, however coarse; smoothed (vertex) colours are not crisp at all.
TEST(CrowdedFaces, OneColourOrASmoothedBakeSeparatesNothing) {
    TestMesh mesh = paperFaired(voxelSphere(9));
    for (glm::u8vec3 &c : mesh.faceColours)
        c = {90, 120, 30};
    AtlasOptions options;
    options.pack.texelsPerUnit = 2;
    TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
    EXPECT_EQ(atlas.charts.separatedFaces, 0u);
    EXPECT_TRUE(atlas.crispGuaranteed);
    EXPECT_EQ(wrongSamples(mesh, atlas), 0u);

    const TestMesh art = paperFaired(voxelSphere(9));
    options.pack.texelsPerUnit = 8;
    options.bake.source = BakeSource::VertexColours;
    atlas = buildTextureAtlas(art.view(), options);
    EXPECT_EQ(atlas.charts.separatedFaces, 0u);
    EXPECT_EQ(atlas.crowded.thinFaces, 0u);
    EXPECT_FALSE(atlas.crispGuaranteed);
}

// A section an HVA frame shrinks to 1% (shared model subapc has four): with one density its
// voxels would get 0.08 texels and could not keep their colours; faceTexelScale gives each
// part's voxels the same texels, and the guarantee holds for both parts.
TEST(CrowdedFaces, APartShrunkToOnePercentKeepsEveryVoxelWithItsTexelScale) {
    const TestMesh big = paperFaired(voxelSphere(7));
    TestMesh mesh = big;
    mesh.name = "sphere and its 1% copy";
    const uint32_t offset = uint32_t(mesh.positions.size());
    for (const glm::vec3 &p : big.positions)
        mesh.positions.push_back(p * 0.01f + glm::vec3(30.0f, 0.0f, 0.0f));
    for (uint32_t v : big.triangles)
        mesh.triangles.push_back(v + offset);
    mesh.faceColours.insert(mesh.faceColours.end(), big.faceColours.begin(), big.faceColours.end());
    std::vector<float> scale(mesh.faceCount(), 1.0f);
    std::fill(scale.begin() + long(big.faceCount()), scale.end(), 100.0f);

    AtlasOptions options;
    options.pack.texelsPerUnit = 8;
    // One density: the 1% copy's faces are all crowded; the atlas still keeps them (density
    // raised, or the faces separated), at the price of a larger texture or many more charts.
    const TextureAtlas single = buildTextureAtlas(mesh.view(), options);
    EXPECT_TRUE(single.crispGuaranteed);
    EXPECT_EQ(wrongSamples(mesh, single), 0u);

    AtlasMesh view = mesh.view();
    view.faceTexelScale = scale.data();
    const TextureAtlas atlas = buildTextureAtlas(view, options);
    EXPECT_TRUE(atlas.crispGuaranteed);
    EXPECT_EQ(wrongSamples(mesh, atlas), 0u);
    EXPECT_LT(atlas.charts.separatedFaces, single.charts.separatedFaces);
    for (size_t c = 0; c < atlas.charts.chartCount(); ++c)
        for (uint32_t i = atlas.charts.chartFirstFace[c]; i < atlas.charts.chartFirstFace[c + 1]; ++i)
            EXPECT_EQ(scale[atlas.charts.chartFaces[i]],
                      scale[atlas.charts.chartFaces[atlas.charts.chartFirstFace[c]]]);
    // Stretch against each face's own density: the usual bounds.
    const AtlasMeasures m = measureAtlas(view, atlas.charts, atlas.layout);
    EXPECT_EQ(m.overlappingChartTexels, 0u);
    EXPECT_LE(m.maxStretch, 1.0 + 1e-3);
    EXPECT_LE(m.maxInverseStretch, 1.0 / ChartOptions().mergeCosine + 1e-3);

    scale[0] = -1.0f;
    EXPECT_THROW(buildTextureAtlas(view, options), MeshError);
    scale[0] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(buildTextureAtlas(view, options), MeshError);
}

// A sliver thinner than 0.01 texel may lose its UV area to float rounding once packed (then it
// is given a tiny triangle at a corner, away from where this search looked): in a chart with
// another colour it is separated even with no other colour near it.
TEST(CrowdedFaces, AFloatThinSliverInAMixedChartIsSeparated) {
    TestMesh plate;
    plate.name = "plate with a sliver";
    plate.positions = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {5, 1e-4f, 0}};
    plate.triangles = {0, 1, 4, 4, 1, 2, 4, 2, 3, 0, 4, 3};  // counter-clockwise seen from +Z
    plate.faceColours = {{200, 0, 0}, {200, 0, 0}, {0, 0, 200}, {200, 0, 0}};
    AtlasCharts charts = computeCharts(plate.view());
    ASSERT_EQ(charts.chartCount(), 1u);
    const CrowdedFaces crowded = separateCrowdedFaces(plate.view(), charts, {8.0, 0.5});
    EXPECT_EQ(crowded.separatedFaces, 1u);
    ASSERT_EQ(charts.chartCount(), 2u);
    EXPECT_EQ(charts.chartFaces[charts.chartFirstFace[1]], 0u) << "the sliver is the face separated";
}
