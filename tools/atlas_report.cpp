// Prints the measures of the section 4.5 texture atlas on test meshes, both packers:
// packing efficiency, overlaps, UV areas, stretch, crisp colour fidelity, faces separated for
// crisp colours (crowded_faces.h) and the whole atlas' time (buildTextureAtlas).
//
//   atlas_report                  the reference mesh: Taubin-smoothed voxel sphere r 20, 1024^2
//   atlas_report --all            also boxes, a torus, blobs, raw voxel spheres
//   atlas_report --models         also real VXL models from VOXELFAIR_MODELS_DIR (sections side by
//                                 side, boundary quads of section 4.2, Taubin-smoothed)
//   atlas_report --shared         only every shared model (vxl/, vox/) through the whole chain at
//                                 the atlas filter's defaults: coverage, charts per thousand faces,
//                                 crispness per model
//   atlas_report --ppm DIR        also writes each texture as DIR/<mesh>_<mode>.ppm
//   atlas_report --gutter N       texels between charts (default 2 on 2 x 2 blocks; the bake fills
//                                 N/2 of them, then the blocks), --shared too
//   atlas_report --shared --counts  also interior samples matching, all and on sure faces
#include "atlas/atlas_measures.h"
#include "atlas/texture_atlas.h"
#include "base/error.h"
#include "pipeline/atlas_runs.h"
#include "extraction/boundary_surface.h"
#include "formats/file_bytes.h"
#include "formats/format_error.h"
#include "formats/palette.h"
#include "formats/vxl.h"
#include "shapes/atlas_test_meshes.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void writePpm(const std::string &path, const AtlasTexture &t) {
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f)
        return;
    std::fprintf(f, "P6\n%d %d\n255\n", t.width, t.height);
    for (size_t i = 0; i < t.rgba.size(); i += 4)
        std::fwrite(&t.rgba[i], 1, 3, f);
    std::fclose(f);
}

int gutter = PackOptions().gutter;
bool noFill = false, square = false, counts = false;
const char *only = nullptr;  // --only NAME: one shared model
float cone = ChartOptions().minSeedCosine;

void report(const TestMesh &mesh, int textureSize, float texelsPerUnit, const char *ppmDir) {
    const AtlasMesh view = mesh.view();
    auto t0 = std::chrono::steady_clock::now();
    const AtlasCharts charts = computeCharts(view);
    const double chartMs = msSince(t0);
    size_t degenerateCharts = 0;
    for (size_t c = 0; c < charts.chartCount(); ++c)
        degenerateCharts += charts.isDegenerate(c);
    std::printf("\n%s: %zu faces, %zu charts (%zu degenerate faces), %zu non-manifold edges, charts %.1f ms\n",
                mesh.name.c_str(), mesh.faceCount(), charts.chartCount(), degenerateCharts, charts.nonManifoldEdges,
                chartMs);
    std::printf("  %-8s %6s %8s %7s %6s %6s %8s %8s %9s %9s %7s %7s %6s %8s\n", "mode", "size", "texel/u", "eff%",
                "ctr%", "over", "overCtr", "noArea", "maxStr", "max1/cos", "near%", "bilin%", "sep", "atlas ms");
    for (PackMode mode : {PackMode::Paper, PackMode::Tight}) {
        AtlasOptions options;
        options.pack.mode = mode;
        options.pack.textureSize = textureSize;
        options.pack.texelsPerUnit = texelsPerUnit;
        options.pack.gutter = gutter;
        t0 = std::chrono::steady_clock::now();
        TextureAtlas atlas;
        try {
            atlas = buildTextureAtlas(view, options);
        } catch (const Error &e) {
            std::printf("  %-8s failed: %s\n", toString(mode), e.what());
            continue;
        }
        const double atlasMs = msSince(t0);
        const AtlasLayout &layout = atlas.layout;
        const AtlasTexture &texture = atlas.texture;
        const AtlasMeasures m = measureAtlas(view, atlas.charts, layout);
        const ColourFidelity fid = measureColourFidelity(view, layout, texture);
        std::printf("  %-8s %6d %8.3f %7.2f %6.2f %6zu %8zu %8zu %9.5f %9.4f %7.3f %7.3f %6zu %8.1f\n", toString(mode),
                    layout.size, layout.texelsPerUnit, 100 * m.packingEfficiency, 100 * m.centreEfficiency,
                    m.overlappingChartTexels, m.overlappingCentres, m.facesWithoutUvArea, m.maxStretch,
                    m.maxInverseStretch, 100 * fid.nearest(), 100 * fid.bilinear(), atlas.charts.separatedFaces,
                    atlasMs);
        std::printf(
            "           packings tried %zu, min UV inradius %.2f texels, guaranteed faces' samples: "
            "nearest %zu/%zu, bilinear %zu/%zu, mean 1/cos %.4f, crisp guaranteed: %s (%zu thin, %zu crowded)\n",
            layout.packAttempts, fid.minInradius, fid.guaranteedNearestMatches, fid.guaranteedNearest,
            fid.guaranteedBilinearMatches, fid.guaranteedBilinear, m.meanInverseStretch,
            atlas.crispGuaranteed ? "yes" : "no", atlas.crowded.thinFaces, atlas.crowded.crowdedFaces);
        if (ppmDir) {
            std::string name = mesh.name + "_" + toString(mode) + ".ppm";
            for (char &ch : name)
                if (ch == ' ' || ch == '/')
                    ch = '_';
            writePpm(std::string(ppmDir) + "/" + name, texture);
        }
    }
}

// A VXL model as one mesh: each section's boundary quads (section 4.2), split along a-c, placed
// side by side along x, coloured from the embedded palette (the Red Alert 2 unit palette when
// the file's is all zeros), then smoothed like MeshLab's Taubin filter.
bool loadVxl(const std::string &name, TestMesh &mesh) {
    const std::string dir = VOXELFAIR_MODELS_DIR;
    try {
        const std::vector<uint8_t> bytes = readFileBytes(dir + "/vxl/" + name + ".vxl");
        const VxlModel model = readVxl(bytes.data(), bytes.size());
        Palette palette = model.embeddedPalette;
        if (palette.allZero()) {
            const std::vector<uint8_t> pal = readFileBytes(dir + "/pal/ra2_unittem.pal");
            palette = readPal(pal.data(), pal.size());
        }
        mesh = TestMesh{};
        mesh.name = name + ".vxl";
        float offset = 0;
        for (const VxlSection &section : model.sections) {
            const BoundarySurface surface = extractBoundarySurface(section.volume);
            const uint32_t base = uint32_t(mesh.positions.size());
            for (const glm::vec3 &p : surface.positions)
                mesh.positions.push_back(p + glm::vec3(offset, 0, 0));
            for (size_t q = 0; q < surface.quadCount(); ++q) {
                const uint32_t *v = &surface.quads[4 * q];
                mesh.triangles.insert(mesh.triangles.end(),
                                      {base + v[0], base + v[1], base + v[2], base + v[0], base + v[2], base + v[3]});
                const Rgb c = palette.colours[surface.quadVoxels[q].colour];
                mesh.faceColours.insert(mesh.faceColours.end(), 2, glm::u8vec3(c.r, c.g, c.b));
            }
            offset += float(section.volume.sizeX) + 4;
        }
        computeVertexColours(mesh);
        taubinSmooth(mesh);
        mesh.name += " taubin10";
        return !mesh.triangles.empty();
    } catch (const std::exception &e) {
        std::printf("\n%s: skipped (%s; models folder %s)\n", name.c_str(), e.what(), dir.c_str());
        return false;
    }
}

// Every shared model (vxl/ and vox/), through the chain as the plugins run it (extraction,
// the paper's fairing, attributes, atlas) at the atlas filter's defaults: one row per model.
void reportShared(const char *ppmDir) {
    const std::string dir = VOXELFAIR_MODELS_DIR;
    std::vector<std::string> refused;
    const auto models = pipeline::sharedModels(dir, &refused, only ? only : "");
    if (models.empty() && refused.empty()) {
        std::printf("\n--shared: no models in %s\n", dir.c_str());
        return;
    }
    AtlasOptions options;
    options.pack.texelsPerUnit = 8.0f;  // the filter's default
    options.pack.fillTexture = !noFill;
    options.pack.allowWide = !square;
    options.pack.gutter = gutter;
    options.charts.minSeedCosine = cone;
    std::printf("\nShared models, chain at the filter's defaults (%g texels per voxel, max %d):\n",
                double(options.pack.texelsPerUnit), options.pack.maxTextureSize);
    std::printf("  %-14s %7s %6s %11s %8s %7s %6s %8s %7s %7s %6s %5s %8s\n", "model", "faces", "charts", "texture",
                "texel/v", "cover%", "ctr%", "ch/kface", "near%", "bilin%", "sep", "over", "atlas ms");
    for (const std::string &r : refused)
        std::printf("  skipped: %s\n", r.c_str());
    std::vector<double> covers;
    for (const auto &model : models) {
        std::optional<pipeline::AtlasRun> run;
        try {
            run = pipeline::runAtlas(*model, options);
        } catch (const Error &e) {
            std::printf("  %-14s failed: %s\n", model->name.c_str(), e.what());
            continue;
        }
        if (!run) {
            std::printf("  %-14s skipped: no surface\n", model->name.c_str());
            continue;
        }
        const TextureAtlas &atlas = run->atlas;
        const AtlasMeasures &m = run->measures;
        const ColourFidelity &fid = run->fidelity;
        covers.push_back(m.packingEfficiency);
        const std::string texture = std::to_string(atlas.layout.width) + "x" + std::to_string(atlas.layout.height);
        std::printf("  %-14s %7zu %6zu %11s %8.3f %7.2f %6.2f %8.2f %7.3f %7.3f %6zu %5zu %8.1f\n", model->name.c_str(),
                    run->faceCount(), atlas.charts.chartCount(), texture.c_str(),
                    atlas.layout.texelsPerUnit * run->mesh.voxelSize, 100 * m.packingEfficiency,
                    100 * m.centreEfficiency, run->chartsPerKiloFace(), 100 * fid.nearest(), 100 * fid.bilinear(),
                    atlas.charts.separatedFaces, m.overlappingChartTexels + m.overlappingCentres, run->atlasMs);
        if (counts)
            std::printf("    nearest %zu/%zu, sure %zu/%zu\n", fid.nearestMatches, fid.samples,
                        fid.guaranteedNearestMatches, fid.guaranteedNearest);
        if (ppmDir)
            writePpm(std::string(ppmDir) + "/" + model->name + "_shared.ppm", atlas.texture);
    }
    if (!covers.empty())
        std::printf("  coverage over %zu models: median %.2f%%, lowest %.2f%%\n", covers.size(),
                    100 * pipeline::median(covers), 100 * *std::min_element(covers.begin(), covers.end()));
}

}  // namespace

int main(int argc, char **argv) {
    bool all = false, models = false, shared = false;
    const char *ppmDir = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--all"))
            all = true;
        else if (!std::strcmp(argv[i], "--models"))
            models = true;
        else if (!std::strcmp(argv[i], "--shared"))
            shared = true;
        else if (!std::strcmp(argv[i], "--no-fill"))
            noFill = true;
        else if (!std::strcmp(argv[i], "--square"))
            square = true;
        else if (!std::strcmp(argv[i], "--counts"))
            counts = true;
        else if (!std::strcmp(argv[i], "--cone") && i + 1 < argc)
            cone = float(std::atof(argv[++i]));
        else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
            only = argv[++i];
        else if (!std::strcmp(argv[i], "--ppm") && i + 1 < argc)
            ppmDir = argv[++i];
        else if (!std::strcmp(argv[i], "--gutter") && i + 1 < argc)
            gutter = std::atoi(argv[++i]);
        else {
            std::fprintf(
                stderr,
                "usage: %s [--all] [--models] [--shared [--only NAME] [--no-fill] [--square] [--counts] [--cone COS]] "
                "[--ppm DIR] [--gutter N]\n",
                argv[0]);
            return 2;
        }
    }
    std::printf("Texture atlas (paper 4.5): cone cos >= 0.7, gutter %d, dilation %d (defaults 4, 2).\n"
                "eff%%: texels the charts overlap / all texels; ctr%%: texel centres inside charts / all;\n"
                "over/overCtr: texels shared by two charts / centres inside two triangles; noArea: faces\n"
                "without positive UV area; maxStr, max1/cos: singular values of surface->UV over the\n"
                "density; near%%/bilin%%: crisp fidelity, 4 interior samples per face.\n",
                gutter + (gutter & 1), (gutter + (gutter & 1)) / 2);
    report(smoothed(voxelSphere(20)), 1024, 0, ppmDir);
    if (all) {
        report(voxelSphere(20), 1024, 0, ppmDir);
        report(smoothed(voxelSphere(8)), 256, 0, ppmDir);
        report(smoothed(voxelTorus(16, 6)), 1024, 0, ppmDir);
        report(smoothed(voxelBlob(16, 7)), 1024, 0, ppmDir);
        report(voxelBox(12, 7, 3), 256, 0, ppmDir);
        report(smoothed(voxelSphere(20)), 0, 8, ppmDir);
        report(smoothed(voxelSphere(70), 4), 0, 2, ppmDir);
    }
    if (shared) {
        reportShared(ppmDir);
        return 0;
    }
    if (models) {
        for (const char *name : {"3tnk", "jeep", "hmec", "subapc", "cc"}) {
            TestMesh mesh;
            if (loadVxl(name, mesh)) {
                report(mesh, 1024, 0, ppmDir);
                report(mesh, 0, 8, ppmDir);
            }
        }
    }
    return 0;
}
