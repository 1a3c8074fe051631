// The bake (bake.h) paints bands of rows on threads, each band taking the faces that reach its
// rows (sorted once, a share of the faces per worker): the texture must be the same for any
// thread count, on layouts where the order of the faces decides texels (overlapping triangles,
// thin faces painting over their neighbours, faces beyond the texture whose thin points are
// clamped onto its border rows), for every colour source.
#include "atlas/bake.h"
#include "atlas/texture_atlas.h"
#include "shapes/atlas_test_meshes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

// A mesh of `faces` separate triangles whose UVs are random: most a few texels wide (thin at
// these sizes), some a few percent of the texture, some a third of it, every eleventh a sliver;
// corners up to 5% beyond the texture on every side. Random face and vertex colours.
struct RandomLayout {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;
    std::vector<glm::u8vec3> faceColours, vertexColours;
    AtlasLayout layout;
    AtlasMesh mesh() const {
        AtlasMesh m;
        m.positions = positions.data();
        m.vertexCount = positions.size();
        m.triangles = triangles.data();
        m.faceCount = triangles.size() / 3;
        m.faceColours = faceColours.data();
        m.vertexColours = vertexColours.data();
        return m;
    }
};

RandomLayout randomLayout(size_t faces, int width, int height, int gutter, int block, uint32_t seed) {
    RandomLayout r;
    r.layout.width = r.layout.size = width;
    r.layout.height = height;
    r.layout.gutter = gutter;
    r.layout.block = block;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> corner(-0.05f, 1.05f), unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> channel(0, 255);
    auto colour = [&] { return glm::u8vec3(channel(rng), channel(rng), channel(rng)); };
    for (size_t f = 0; f < faces; ++f) {
        const float scale = f % 7 == 0 ? 0.3f : f % 3 == 0 ? 0.02f : 3.0f / float(width);
        const glm::vec2 origin(corner(rng), corner(rng));
        for (int k = 0; k < 3; ++k) {
            glm::vec2 uv = origin + scale * glm::vec2(unit(rng), unit(rng));
            if (f % 11 == 0 && k == 2)  // nearly on the line of the other two
                uv = origin + 0.5f * (r.layout.wedgeUv.back() - origin) + glm::vec2(1e-4f, 0);
            r.layout.wedgeUv.push_back(uv);
            r.triangles.push_back(uint32_t(r.positions.size()));
            r.positions.emplace_back(uv, 0.0f);
            r.vertexColours.push_back(colour());
        }
        r.faceColours.push_back(colour());
    }
    return r;
}

// Bakes with 1, 2, 3 and 7 threads; every texture must equal the one-thread one. Returns the
// one-thread texture.
AtlasTexture expectSameOnAnyThreads(const AtlasMesh &mesh, const AtlasLayout &layout, BakeOptions options) {
    options.threads = 1;
    const AtlasTexture reference = bakeTexture(mesh, layout, options);
    for (int threads : {2, 3, 7}) {
        options.threads = threads;
        const AtlasTexture texture = bakeTexture(mesh, layout, options);
        EXPECT_EQ(texture.rgba, reference.rgba) << threads << " threads";
        EXPECT_EQ(texture.source, reference.source);
        EXPECT_EQ(texture.dilation, reference.dilation);
    }
    return reference;
}

}  // namespace

TEST(Bake, AnyThreadCountPaintsTheSameTextureOnRandomLayouts) {
    const int sizes[][2] = {{64, 64}, {128, 64}, {256, 128}, {512, 512}};
    for (int trial = 0; trial < 8; ++trial) {
        const int width = sizes[trial % 4][0], height = sizes[trial % 4][1];
        const RandomLayout random = randomLayout(trial < 4 ? 5000 : 9000, width, height, 2 * (trial % 3),
                                                 trial % 2 ? 2 : 1, uint32_t(1234 + trial));
        const AtlasMesh mesh = random.mesh();
        ASSERT_GE(mesh.faceCount, 4096u);  // above the bake's parallel threshold
        for (BakeSource source : {BakeSource::FaceColours, BakeSource::VertexColours, BakeSource::FlatColour}) {
            SCOPED_TRACE("trial " + std::to_string(trial) + ", " + toString(source));
            BakeOptions options;
            options.source = source;
            options.dilation = trial % 4 == 3 ? 2 : -1;
            if (trial % 5 == 0)
                options.background = glm::u8vec4(1, 2, 3, 4);
            const AtlasTexture texture = expectSameOnAnyThreads(mesh, random.layout, options);
            // Faces cover the texture from its first row to its last (the bands all paint).
            for (int y : {0, height - 1}) {
                int painted = 0;
                for (int x = 0; x < width; ++x)
                    painted += texture.texel(x, y).a == 255;
                EXPECT_GT(painted, 0) << "row " << y;
            }
        }
    }
}

// A smoothed sphere at 2 texels per voxel: nearly every face thin (its interior points painted
// after the centres and overlaps), charts on 2 x 2 blocks.
TEST(Bake, AnyThreadCountPaintsTheSameTextureOnThinFaces) {
    const TestMesh mesh = smoothed(voxelSphere(20));
    ASSERT_GE(mesh.faceCount(), 4096u);
    AtlasOptions options;
    options.pack.texelsPerUnit = 2;
    options.alwaysCrisp = false;
    const TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
    for (BakeSource source : {BakeSource::FaceColours, BakeSource::VertexColours, BakeSource::FlatColour}) {
        SCOPED_TRACE(toString(source));
        BakeOptions bake;
        bake.source = source;
        expectSameOnAnyThreads(mesh.view(), atlas.layout, bake);
    }
}
