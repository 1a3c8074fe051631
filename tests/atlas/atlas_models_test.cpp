// The atlas at the texture filter's defaults (8 texels per voxel, texture sized from the
// density, 2:1 allowed, filled) through the whole chain (extraction, the paper's fairing,
// attributes; tools/pipeline_stages.h): on every shared model and on generated families of pixel
// art that make thin faces (thin plates, long diagonal slivers, many small parts, random
// orientations and sizes, fixed seeds). Every interior sample of every face reads its voxel
// colour (GL_NEAREST), no two charts share a texel, and the coverage is printed per model and
// held to the floor measured when it was written.
#include "pipeline/atlas_runs.h"
#include "shapes/analytic_shapes.h"
#include "shapes/shape_families.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <random>

using namespace voxelfair;

namespace {

struct Outcome {
    double coverage = 0;
    double chartsPerKiloFace = 0;
};

// The chain at the filter's defaults; the atlas' guarantees asserted.
Outcome checkModel(const pipeline::Model &model, AtlasOptions options = {}) {
    SCOPED_TRACE(model.name);
    options.pack.texelsPerUnit = 8.0f;  // the texture filter's default
    const std::optional<pipeline::AtlasRun> run = pipeline::runAtlas(model, options);
    if (!run)
        return {};
    const TextureAtlas &atlas = run->atlas;
    const AtlasMeasures &m = run->measures;
    const ColourFidelity &fid = run->fidelity;
    EXPECT_TRUE(atlas.crispGuaranteed);
    EXPECT_EQ(m.overlappingChartTexels, 0u);
    EXPECT_EQ(m.overlappingCentres, 0u);
    EXPECT_EQ(m.facesWithoutUvArea, 0u);
    EXPECT_EQ(fid.nearestMatches, fid.samples) << "interior samples that read another colour";
    EXPECT_TRUE(atlas.layout.width == atlas.layout.height || atlas.layout.width == 2 * atlas.layout.height);
    EXPECT_GE(atlas.layout.texelsPerUnit * run->mesh.voxelSize, 8.0 * 0.999);
    Outcome o{m.packingEfficiency, run->chartsPerKiloFace()};
    std::printf("  %-22s %7zu faces %5zu charts (%6.1f/kface) %5dx%-5d %6.2f texels/voxel coverage %5.1f%% crisp "
                "%zu/%zu, %zu separated\n",
                model.name.c_str(), run->faceCount(), atlas.charts.chartCount(), o.chartsPerKiloFace,
                atlas.layout.width, atlas.layout.height, atlas.layout.texelsPerUnit * run->mesh.voxelSize,
                100 * o.coverage, fid.nearestMatches, fid.samples, atlas.charts.separatedFaces);
    return o;
}

// Pixel art: each voxel one of eight colours, by a hash of its position and the seed.
std::function<Voxel(int, int, int)> pixelArt(uint32_t seed) {
    return [seed](int x, int y, int z) {
        uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u ^ seed * 2654435761u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return Voxel{uint8_t(1 + h % 8), 0};
    };
}

Palette eightColours() {
    Palette p;
    for (int i = 1; i <= 8; ++i)
        p.colours[size_t(i)] = {uint8_t(30 * i), uint8_t(255 - 25 * i), uint8_t((70 * i) % 256)};
    return p;
}

}  // namespace

TEST(AtlasModels, EverySharedModelIsCrispWithoutOverlaps) {
    const std::string dir = VOXELFAIR_MODELS_DIR;
    if (!std::filesystem::is_directory(dir + "/vxl"))
        GTEST_SKIP() << "needs the shared models in " << dir;
    std::vector<std::string> refused;
    std::vector<double> coverage, charts;
    for (const auto &model : pipeline::sharedModels(dir, &refused)) {
        const Outcome o = checkModel(*model);
        if (o.coverage > 0) {
            coverage.push_back(o.coverage);
            charts.push_back(o.chartsPerKiloFace);
        }
    }
    for (const std::string &r : refused)
        std::printf("  not read: %s\n", r.c_str());
    ASSERT_GE(coverage.size(), 15u);
    std::printf("coverage: median %.1f%%, lowest %.1f%% over %zu models\n", 100 * pipeline::median(coverage),
                100 * *std::min_element(coverage.begin(), coverage.end()), coverage.size());
    // Measured 71.8%, lowest 54.9% (charts start just inside their first texel, small charts
    // packed by their shapes, a longer fill on models up to 32768 faces); 66.2% and 54.9%
    // before (small charts merged, a third fill try after two misses); 64.9% and 51.8% before
    // those (2 x 2 blocks with a gutter of 2, holes inside large charts reused, small textures
    // stepped up); 57.4% and 4.7% before those (2:1 textures, the fill), 31.7% before that.
    // The goal: a 70% median, 50% on every model.
    EXPECT_GE(pipeline::median(coverage), 0.70);
    EXPECT_GE(*std::min_element(coverage.begin(), coverage.end()), 0.54);
    // Charts per thousand faces: median 45.1 with the paper's charts alone, 27.3 with small
    // charts merged into their neighbours (chart_merge.h).
    std::printf("charts per thousand faces: median %.1f\n", pipeline::median(charts));
    EXPECT_LE(pipeline::median(charts), 30.0);
}

TEST(AtlasModels, GeneratedFamiliesAreCrispWithoutOverlaps) {
    std::mt19937_64 random(20261125);
    const Palette palette = eightColours();
    std::vector<double> coverage;
    for (int i = 0; i < 3; ++i) {
        // A thin plate (1 to 2 voxels) at a random orientation.
        const glm::dvec3 half(shapes::uniformIn(random, 6, 14), shapes::uniformIn(random, 5, 12),
                              shapes::uniformIn(random, 0.55, 1.1));
        const shapes::Shape plate = shapes::atOffset(shapes::orientedBox("plate", half, shapes::randomRotation(random)),
                                                     shapes::randomFraction(random));
        coverage.push_back(checkModel(*pipeline::volumeModel("thin plate " + std::to_string(i),
                                                             shapes::voxelize(plate, pixelArt(uint32_t(i))), palette))
                               .coverage);
        // A long diagonal sliver: a thin capsule across the lattice.
        const double radius = shapes::uniformIn(random, 0.6, 1.2), length = shapes::uniformIn(random, 20, 40);
        const glm::dmat3 r = shapes::randomRotation(random);
        const glm::dvec3 a = -0.5 * length * r[2], b = 0.5 * length * r[2];
        shapes::Shape sliver;
        sliver.name = "sliver";
        sliver.sdf = [=](const glm::dvec3 &p) { return shapes::capsuleDistance(p, a, b, radius); };
        sliver.boundsMin = glm::min(a, b) - radius;
        sliver.boundsMax = glm::max(a, b) + radius;
        sliver = shapes::atOffset(sliver, shapes::randomFraction(random));
        coverage.push_back(
            checkModel(*pipeline::volumeModel("diagonal sliver " + std::to_string(i),
                                              shapes::voxelize(sliver, pixelArt(uint32_t(10 + i))), palette))
                .coverage);
        // Many small parts: 40 spheres and boxes of 1 to 3 voxels, each its own part.
        std::vector<VoxelVolume> parts;
        for (int k = 0; k < 40; ++k) {
            const double s = shapes::uniformIn(random, 0.8, 2.5);
            const shapes::Shape part =
                k % 2 ? shapes::atOffset(shapes::sphere(glm::dvec3(s + 1), s), shapes::randomFraction(random))
                      : shapes::atOffset(
                            shapes::orientedBox("box", glm::dvec3(s, 0.8 * s, 0.6 * s), shapes::randomRotation(random)),
                            shapes::randomFraction(random));
            parts.push_back(shapes::voxelize(part, pixelArt(uint32_t(100 * i + k))));
        }
        coverage.push_back(
            checkModel(*pipeline::volumesModel("small parts " + std::to_string(i), std::move(parts), {}, palette))
                .coverage);
    }
    std::printf("coverage: median %.1f%% over %zu generated models\n", 100 * pipeline::median(coverage),
                coverage.size());
}

// Frames of thin bars (a window, a fence, a scaffold): the paper's growth makes each side of a
// wire cube one ring-shaped chart whose box is nearly all hole, and equal rings cannot nest in
// each other's holes; before sparse charts were cut (chart_split.h) a 256-voxel wire cube's atlas
// fell to 2.5 texels per voxel in a 4096^2 texture 1.2% full. Wire cubes of random sides and bar
// thicknesses, on the lattice and turned, at sub-voxel offsets: the atlas keeps the asked density
// (checkModel), crisp and without overlaps, and fills a fair share of its texture.
TEST(AtlasModels, WireFramesKeepTheirDensity) {
    std::mt19937_64 random(20261126);
    const Palette palette = eightColours();
    for (int i = 0; i < 4; ++i) {
        const double side = shapes::uniformIn(random, 40, 90), bar = shapes::uniformIn(random, 1.0, 2.6);
        const double h = 0.5 * side, hb = 0.5 * bar;
        auto frame = [h, hb](const glm::dvec3 &p) {
            double d = 1e30;
            for (int axis = 0; axis < 3; ++axis)
                for (int a = -1; a <= 1; a += 2)
                    for (int b = -1; b <= 1; b += 2) {
                        glm::dvec3 centre(0.0), half(hb);
                        centre[(axis + 1) % 3] = a * (h - hb);
                        centre[(axis + 2) % 3] = b * (h - hb);
                        half[axis] = h;
                        d = std::min(d, shapes::boxDistance(p - centre, half));
                    }
            return d;
        };
        const glm::dmat3 turn = i % 2 ? shapes::randomRotation(random) : glm::dmat3(1.0);
        const shapes::Shape cube =
            shapes::atOffset(shapes::placed("wire cube", frame, glm::dvec3(h), 0.0, turn, glm::dvec3(0.0)),
                             shapes::randomFraction(random));
        const Outcome o = checkModel(*pipeline::volumeModel(
            "wire cube " + std::to_string(i), shapes::voxelize(cube, pixelArt(uint32_t(200 + i))), palette));
        // Measured 49.8%, 48.4%, 34.4%, 53.0% (long bars that fit a 1024^2 texture only side by
        // side); without the cut the cubes on the lattice took 2048 x 1024 textures 13.9% and 16.8%
        // full, the turned ones 44.4% and 53.0%.
        EXPECT_GE(o.coverage, 0.30) << "wire cube " << i;
    }
}

// Fewer, larger charts where that costs no crispness (chart_merge.h): smooth solids at random
// sizes, orientations and sub-voxel offsets, whose rounded corners leave the paper's growth
// many tiny charts. Merging them at least a third fewer charts on every one, still crisp.
TEST(AtlasModels, MergingSmallChartsKeepsEveryShapeCrisp) {
    std::mt19937_64 random(20261126);
    const Palette palette = eightColours();
    AtlasOptions paper;
    paper.charts.mergeFaces = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 half(shapes::uniformIn(random, 4, 10), shapes::uniformIn(random, 4, 10),
                              shapes::uniformIn(random, 3, 8));
        const glm::dmat3 turn = shapes::randomRotation(random);
        const shapes::Shape shape =
            i % 2 ? shapes::placed(
                        "ellipsoid", [half](const glm::dvec3 &p) { return shapes::ellipsoidDistance(p, half); }, half,
                        4.18879 * half.x * half.y * half.z, turn, glm::dvec3(0.0))
                  : shapes::orientedRoundedBox("rounded box", half, shapes::uniformIn(random, 1.5, 3), turn);
        const auto model = pipeline::volumeModel(
            shape.name + " " + std::to_string(i),
            shapes::voxelize(shapes::atOffset(shape, shapes::randomFraction(random)), pixelArt(uint32_t(200 + i))),
            palette);
        const Outcome merged = checkModel(*model), alone = checkModel(*model, paper);
        EXPECT_LE(merged.chartsPerKiloFace, alone.chartsPerKiloFace * 2 / 3) << model->name;
    }
}
