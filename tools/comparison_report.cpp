// The comparison report: how our chain (paper sections 4.2-4.5) compares with MeshLab's Taubin
// Smooth on the shared real models and on voxelized analytic shapes, in numbers and pictures.
//
//   comparison_report [output folder] [--size N] [--only MODEL]   (default folder: <build>/report, N = 560)
//
// Writes <folder>/report.md (also printed) and, per model, PNG pictures seen from the same
// camera: raw voxels, Taubin (10 steps), ours (one pass of the paper's fairing), the constrained
// mode when libvoxelfair/fairing has it, and ours textured with the baked atlas; plus the atlas
// texture and all panels side by side (<model>_strip.png).
//
// Tables:
//   * fidelity against the true surface of analytic shapes (testkit/smoothers/smoothing_comparison.h);
//   * the paper's Table 1 (time per stage) and Table 2 (counts per stage) for every input;
//   * the Taubin chain's times beside ours;
//   * on real models, where no true surface is known: volume change and vertex displacement.
// Times are the best of a few runs in this process, single-threaded; benchmarks/pipeline_benchmark
// measures the same stages with Google Benchmark.
#include "pipeline/pipeline_stages.h"
#include "shapes/synthetic_tank.h"
#include "render/mesh_renderer.h"
#include "render/png_writer.h"

#include "smoothers/smoothing_comparison.h"
#include "smoothers/vcg_taubin.h"
#include "smoother_lineup.h"
#include "shapes/analytic_shapes.h"
#include "checks/surface_error.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using namespace voxelfair;

namespace {

std::string format(const char *fmt, ...) {
    char buffer[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buffer, sizeof buffer, fmt, args);
    va_end(args);
    return buffer;
}

// Best of `repeats` timed runs of run(input) with input = make() (making it is not timed), so a
// stage that works in place always starts from the same data.
template <class Make, class Run>
double bestMs(int repeats, Make make, Run run) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < repeats; ++i) {
        auto input = make();
        const auto t0 = std::chrono::steady_clock::now();
        run(input);
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

// Best of `repeats` timed runs of a stage that needs no fresh input.
template <class Run>
double bestMs(int repeats, Run run) {
    return bestMs(repeats, [] { return 0; }, [&](int) { run(); });
}

// A Markdown table: the first `textColumns` columns left-aligned, the figures right-aligned.
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    size_t textColumns = 1;

    std::string markdown() const {
        std::ostringstream out;
        auto line = [&out](const std::vector<std::string> &cells) {
            out << "|";
            for (const std::string &c : cells)
                out << " " << c << " |";
            out << "\n";
        };
        line(header);
        out << "|";
        for (size_t i = 0; i < header.size(); ++i)
            out << (i < textColumns ? "---|" : "---:|");
        out << "\n";
        for (const auto &row : rows)
            line(row);
        return out.str();
    }
};

// One smoothing of the extracted surface and what the later stages made of it.
struct Variant {
    std::string name;
    pipeline::QuadMesh mesh;  // positions after smoothing (raw: as extracted)
    pipeline::Attributes attributes;
    double smoothMs = 0, attributesMs = 0, atlasMs = 0;
    TextureAtlas atlas;
    size_t atlasVertices = 0;
    bool hasAtlas = false;
    std::vector<glm::vec3> displayPositions, displayNormals;  // model space, for pictures
};

struct ModelRun {
    std::string name;
    std::string kind;  // "VXL", "VOX", "shape"
    std::string palette;
    size_t boxVoxels = 0, solidVoxels = 0, parts = 0;
    double extractMs = 0;
    double taubinToVcgMs = 0;  // building vcglib's mesh, which MeshLab already holds
    Variant raw, ours, taubin, constrained, hc, twoStep;  // hc, twoStep: MeshLab's (smoother_lineup.h)
    bool hasTaubin = false, hasConstrained = false, hasOtherMeshLab = false, hasVtk = false;
    lineup::TriangleSurface vtk;
    const shapes::Shape *shape = nullptr;
};

constexpr int kRepeats = 3;

// Attribute smoothing and, when asked, the atlas for a smoothed surface, timed; then the surface
// placed in model space for the pictures.
void finishVariant(Variant &v, const pipeline::Model &model, bool atlas) {
    v.attributesMs = bestMs(kRepeats, [&] { v.attributes = pipeline::smoothAttributes(v.mesh); });
    v.displayPositions = pipeline::displayPositions(v.mesh, model);
    v.displayNormals = pipeline::displayNormals(v.mesh, model, v.attributes.vertexNormals);
    if (!atlas)
        return;
    v.atlasMs = bestMs(kRepeats, [&] { v.atlas = pipeline::buildAtlas(v.mesh, v.attributes); });
    v.hasAtlas = v.atlas.status() == AtlasStatus::Ok;
    if (v.hasAtlas)
        v.atlasVertices = pipeline::atlasVertexCount(v.atlas, v.attributes);
}

ModelRun runChain(const pipeline::Model &model, const std::string &kind) {
    ModelRun run;
    run.name = model.name;
    run.kind = kind;
    run.palette = model.paletteSource;
    run.boxVoxels = model.boxVoxels();
    run.solidVoxels = model.solidVoxels();
    run.parts = model.scene.parts.size();

    run.extractMs = bestMs(kRepeats, [&] { run.raw.mesh = pipeline::extract(model.scene); });
    run.raw.name = "raw voxels";
    finishVariant(run.raw, model, false);

    run.ours.name = "ours (paper, 1 pass)";
    run.ours.smoothMs = bestMs(kRepeats, [&] { return run.raw.mesh; }, [&](pipeline::QuadMesh &m) {
        pipeline::fair(m);
        run.ours.mesh = std::move(m);
    });
    finishVariant(run.ours, model, true);

    run.hasConstrained = true;
    run.constrained.name = "constrained";
    run.constrained.smoothMs = bestMs(kRepeats, [&] { return run.raw.mesh; }, [&](pipeline::QuadMesh &m) {
        pipeline::fairConstrainedMode(m);
        run.constrained.mesh = std::move(m);
    });
    finishVariant(run.constrained, model, true);

#ifdef VOXELFAIR_HAVE_VCGLIB
    // MeshLab holds the a-c triangulation; its Taubin Smooth runs on that (testkit/smoothers/vcg_taubin.h).
    run.hasTaubin = true;
    run.taubin.name = "Taubin (10 steps)";
    run.taubin.mesh = run.raw.mesh;
    run.taubinToVcgMs = bestMs(kRepeats, [] { return std::make_unique<vcgtaubin::Mesh>(); },
                               [&](std::unique_ptr<vcgtaubin::Mesh> &m) {
                                   vcgtaubin::build(*m, run.raw.mesh.positions, run.raw.attributes.triangles);
                               });
    std::unique_ptr<vcgtaubin::Mesh> smoothed;
    run.taubin.smoothMs = bestMs(kRepeats, [&] {
        auto m = std::make_unique<vcgtaubin::Mesh>();
        vcgtaubin::build(*m, run.raw.mesh.positions, run.raw.attributes.triangles);
        return m;
    }, [&](std::unique_ptr<vcgtaubin::Mesh> &m) {
        vcgtaubin::taubinLikeMeshLab(*m);
        smoothed = std::move(m);
    });
    for (size_t i = 0; i < run.taubin.mesh.positions.size(); ++i) {
        const vcg::Point3f &p = smoothed->vert[i].cP();
        run.taubin.mesh.positions[i] = glm::vec3(p[0], p[1], p[2]);
    }
    finishVariant(run.taubin, model, true);
    // MeshLab's HC Laplacian and TwoStep Smooth, the same way (testkit/smoothers/vcg_smoothers.h).
    run.hasOtherMeshLab = true;
    run.hc.name = "HC Laplacian";
    run.hc.mesh = run.raw.mesh;
    run.hc.smoothMs = bestMs(1, [&] { vcgsmooth::hcLaplacian(run.hc.mesh.positions, run.raw.attributes.triangles); });
    finishVariant(run.hc, model, false);
    run.twoStep.name = "TwoStep";
    run.twoStep.mesh = run.raw.mesh;
    run.twoStep.smoothMs =
        bestMs(1, [&] { vcgsmooth::twoStep(run.twoStep.mesh.positions, run.raw.attributes.triangles); });
    finishVariant(run.twoStep, model, false);
#endif
#ifdef VOXELFAIR_HAVE_VTK
    run.hasVtk = true;
    run.vtk = lineup::vtkSurface(model);
#endif
    return run;
}

// ---------------------------------------------------------------------------------------------
// Pictures

struct Pictures {
    std::vector<std::string> files;   // panel files, in panel order
    std::vector<std::string> labels;
    std::string strip, texture, wireframe;
};

constexpr size_t kMaxWireframeQuads = 15000;

Pictures renderPictures(const ModelRun &run, const fs::path &folder, int size) {
    using namespace voxelfair::render;
    Pictures out;
    std::string stem = run.name;
    for (char &c : stem)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
            c = '_';

    // One camera for every panel, framed on the raw voxels: a 3/4 view from above the front.
    const View view = fitView(run.raw.displayPositions.data(), run.raw.displayPositions.size(), Camera{}, 1.0f);
    RenderOptions options;
    options.width = options.height = size;

    auto meshOf = [](const Variant &v) {
        RenderMesh m;
        m.positions = v.displayPositions.data();
        m.vertexCount = v.displayPositions.size();
        m.triangles = v.attributes.triangles.data();
        m.triangleCount = v.attributes.triangleCount();
        m.faceColours = v.attributes.triangleColours.data();
        return m;
    };
    std::vector<Image> panels;
    auto add = [&](const Image &image, const std::string &suffix, const std::string &label) {
        const std::string file = stem + "_" + suffix + ".png";
        std::string error;
        if (!writePng((folder / file).string(), image.rgb.data(), image.width, image.height, 3, &error))
            std::fprintf(stderr, "%s\n", error.c_str());
        panels.push_back(image);
        out.files.push_back(file);
        out.labels.push_back(label);
    };

    // Geometry panels: crisp voxel colours and faceted shading, so only the shapes differ.
    add(renderMesh(meshOf(run.raw), view, options), "raw", "raw voxels");
    if (run.hasTaubin)
        add(renderMesh(meshOf(run.taubin), view, options), "taubin", "Taubin, 10 steps");
    add(renderMesh(meshOf(run.ours), view, options), "ours", "ours (paper, 1 pass)");
    if (run.hasConstrained)
        add(renderMesh(meshOf(run.constrained), view, options), "constrained", "constrained mode");
    if (run.hasOtherMeshLab) {
        add(renderMesh(meshOf(run.hc), view, options), "hc", "HC Laplacian");
        add(renderMesh(meshOf(run.twoStep), view, options), "twostep", "TwoStep");
    }
    if (run.hasVtk) {
        RenderMesh vtk;
        vtk.positions = run.vtk.displayPositions.data();
        vtk.vertexCount = run.vtk.displayPositions.size();
        vtk.triangles = run.vtk.triangles.data();
        vtk.triangleCount = run.vtk.triangles.size() / 3;
        add(renderMesh(vtk, view, options), "vtk", "VTK windowed sinc (no colours)");
    }
    // The product: the faired mesh with its smoothed normals and the baked texture.
    if (run.ours.hasAtlas) {
        RenderMesh textured = meshOf(run.ours);
        textured.vertexNormals = run.ours.displayNormals.data();
        textured.wedgeUv = run.ours.atlas.layout.wedgeUv.data();
        textured.texture = {run.ours.atlas.texture.width, run.ours.atlas.texture.height, run.ours.atlas.texture.rgba.data()};
        add(renderMesh(textured, view, options), "textured", "ours + atlas texture, smooth normals");
        out.texture = stem + "_texture.png";
        const AtlasTexture &t = run.ours.atlas.texture;
        writePng((folder / out.texture).string(), t.rgba.data(), t.width, t.height, 4);
    }
    // The paper's Figure 9: the faired quads in wireframe, where the edges are not too dense to see.
    if (run.ours.mesh.quadCount() <= kMaxWireframeQuads) {
        const std::vector<uint8_t> quadEdges = fanEdgeMask(run.ours.mesh.offsets.data(), run.ours.mesh.quadCount());
        RenderMesh wire = meshOf(run.ours);
        wire.edgeMask = quadEdges.data();
        RenderOptions wireOptions = options;
        wireOptions.wireOpacity = 0.55f;
        out.wireframe = stem + "_ours_wire.png";
        const Image image = renderMesh(wire, view, wireOptions);
        writePng((folder / out.wireframe).string(), image.rgb.data(), image.width, image.height, 3);
    }
    const Image strip = sideBySide(panels, size / 40, options.background);
    out.strip = stem + "_strip.png";
    writePng((folder / out.strip).string(), strip.rgb.data(), strip.width, strip.height, 3);
    return out;
}

// ---------------------------------------------------------------------------------------------
// Inputs

struct Input {
    std::unique_ptr<pipeline::Model> model;
    std::string kind;
    const shapes::Shape *shape = nullptr;
};

// Two-colour 3D checker of 4-voxel blocks, so the pictures show whether the texture stays crisp.
Palette shapePalette() {
    Palette p;
    p.colours[1] = {214, 128, 64};
    p.colours[2] = {72, 132, 190};
    return p;
}

std::vector<std::string> sortedFiles(const fs::path &folder, const std::string &extension) {
    std::vector<std::string> files;
    if (fs::is_directory(folder))
        for (const auto &entry : fs::directory_iterator(folder))
            if (entry.path().extension() == extension)
                files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

constexpr size_t kMinSolidVoxels = 500;  // smaller models (1x1x1, 3x3x3 test files) say nothing here

std::string machine() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, cpu = "unknown CPU";
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    // Other work on the machine slows the timings down: say how busy it was.
    std::string load = "?";
    std::ifstream("/proc/loadavg") >> load;
    return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads, load average " + load;
}

std::string ms(double v) { return v < 10 ? format("%.2f", v) : format("%.1f", v); }

}  // namespace

int main(int argc, char **argv) {
    fs::path folder = VOXELFAIR_DEFAULT_REPORT_DIR;
    int size = 560;
    std::string only;  // --only NAME: that model's pictures and rows alone (e.g. to refresh one strip)
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc)
            size = std::max(64, std::atoi(argv[++i]));
        else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            only = argv[++i];
        else if (argv[i][0] == '-') {
            std::fprintf(stderr, "usage: %s [output folder] [--size pixels] [--only MODEL]\n", argv[0]);
            return 2;
        } else
            folder = argv[i];
    }
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) {
        std::fprintf(stderr, "%s: %s\n", folder.string().c_str(), ec.message().c_str());
        return 1;
    }

    const fs::path models = VOXELFAIR_MODELS_DIR;
    std::vector<Input> inputs;
    std::vector<std::string> skipped;
    for (const std::string &path : sortedFiles(models / "vxl", ".vxl")) {
        // A unit is shown whole under its body's name: its turret and barrel files not again.
        const std::string stem = fs::path(path).stem().string();
        bool companion = false;
        for (const char *suffix : {"tur", "barl"}) {
            const size_t n = std::strlen(suffix);
            companion = companion || (stem.size() > n && stem.compare(stem.size() - n, n, suffix) == 0 &&
                                      fs::exists(fs::path(path).parent_path() / (stem.substr(0, stem.size() - n) + ".vxl")));
        }
        if (companion) continue;
        try {
            Input in{pipeline::loadVxl(path, (models / "pal").string(), true), "VXL"};
            if (in.model->solidVoxels() < kMinSolidVoxels)
                skipped.push_back(format("%s (%zu voxels)", in.model->name.c_str(), in.model->solidVoxels()));
            else
                inputs.push_back(std::move(in));
        } catch (const std::exception &e) {
            skipped.push_back(fs::path(path).filename().string() + " (" + e.what() + ")");
        }
    }
    for (const char *name : {"crabby", "robo", "8ontop"}) {
        try {
            inputs.push_back({pipeline::loadVox((models / "vox" / (std::string(name) + ".vox")).string()), "VOX"});
        } catch (const std::exception &e) {
            skipped.push_back(std::string(name) + ".vox (" + e.what() + ")");
        }
    }
    inputs.push_back({pipeline::syntheticTankModel(), "synthetic"});
    const std::vector<shapes::Shape> shapeList = comparison::comparisonShapes();
    for (const shapes::Shape &shape : shapeList) {
        VoxelVolume volume = shapes::voxelize(shape, [](int x, int y, int z) {
            return Voxel{uint8_t(1 + (x / 4 + y / 4 + z / 4) % 2), 0};
        });
        inputs.push_back({pipeline::volumeModel(shape.name, std::move(volume), shapePalette()), "shape", &shape});
    }

    if (!only.empty())
        inputs.erase(std::remove_if(inputs.begin(), inputs.end(), [&](const Input &in) { return in.model->name != only; }),
                     inputs.end());
    std::vector<ModelRun> runs;
    std::vector<Pictures> pictures;
    for (const Input &in : inputs) {
        std::fprintf(stderr, "%s...\n", in.model->name.c_str());
        runs.push_back(runChain(*in.model, in.kind));
        runs.back().shape = in.shape;
        pictures.push_back(renderPictures(runs.back(), folder, size));
    }

    std::ostringstream md;
    md << "# voxelfair comparison report\n\n"
       << "Our chain (paper sections 4.2-4.5: extraction, one pass of the modified-Lanczos fairing, attribute "
          "smoothing, texture atlas) against MeshLab 2020.09's Taubin Smooth (vcglib, 10 steps, lambda 0.5, "
          "mu -0.53, on the a-c triangulation MeshLab holds).\n\n"
       << "Machine: " << machine() << ". Times: best of " << kRepeats
       << " runs in one process, one thread, Release build. Distances in voxels.\n\n";
#ifndef VOXELFAIR_HAVE_VCGLIB
    md << "Built without vcglib: no Taubin columns.\n\n";
#endif
#ifndef VOXELFAIR_HAVE_VTK
    md << "Built without VTK: no VTK columns.\n\n";
#endif
    if (!skipped.empty()) {
        md << "Not shown: ";
        for (size_t i = 0; i < skipped.size(); ++i)
            md << (i ? ", " : "") << skipped[i];
        md << ".\n\n";
    }

    // Fidelity on analytic shapes.
    md << "## Fidelity to the true surface (voxelized analytic shapes)\n\n"
       << "Distances from 200k area-uniform samples of each triangulated mesh to the shape's exact SDF "
          "(testkit/smoothers/smoothing_comparison.h). Bias > 0: the mesh lies outside on average. Volume: "
          "enclosed volume against the true solid's.\n\n";
    Table fidelity{{"shape", "method", "RMS", "max", "bias", "volume %"}, {}, 2};
    for (const ModelRun &run : runs) {
        if (!run.shape)
            continue;
        // Every smoother the comparison knows (the second mode included, once it exists).
        for (const comparison::Row &r : comparison::compare(*run.shape))
            fidelity.rows.push_back({r.shape, r.method, format("%.4f", r.error.rms), format("%.4f", r.error.max),
                                     format("%+.4f", r.error.bias), format("%+.2f", r.error.volumeChangePercent)});
    }
    md << fidelity.markdown() << "\n";

    // Table 1: time per stage.
    md << "## Time per stage (the paper's Table 1)\n\n"
       << "Milliseconds. Extraction: section 4.2 over every part (VXL sections in their own voxel units, as the "
          "authors ran them; their HVA placement is applied only for the pictures). Fairing: one pass, adjacency "
          "included. Attributes: face and vertex normals, vertex colours, quads to triangles. Atlas: charts, "
          "packing and the baked texture (4 texels per voxel edge). Taubin: the filter body on vcglib's mesh "
          "(building that mesh, which MeshLab already holds, is the last column).\n\n";
    md << "The paper's Table 1 (ms; HP TX1120 tablet, dual-core 1.8 GHz, 2010):\n\n"
       << Table{{"model", "opaque voxels", "extraction", "fairing", "attributes", "atlas", "Taubin"},
                {{"Demo Truck", "7893", "35", "11", "14", "316", "47"},
                 {"Kirov", "35841", "397", "52", "56", "1237", "203"},
                 {"Yuri Head", "42733", "327", "124", "131", "5522", "485"},
                 {"Warhammer", "63150", "359", "186", "201", "6393", "735"}}}
              .markdown()
       << "\nOurs:\n\n";
    Table times{{"model", "opaque voxels", "extraction", "fairing", "attributes", "atlas", "ours total"}, {}};
    if (!runs.empty() && runs.front().hasConstrained)
        times.header.push_back("constrained fairing");
    if (!runs.empty() && runs.front().hasTaubin)
        for (const char *h : {"Taubin 10", "Taubin chain total", "vcg mesh build"})
            times.header.push_back(h);
    for (const ModelRun &r : runs) {
        const double total = r.extractMs + r.ours.smoothMs + r.ours.attributesMs + r.ours.atlasMs;
        std::vector<std::string> row = {r.name, std::to_string(r.solidVoxels), ms(r.extractMs), ms(r.ours.smoothMs),
                                        ms(r.ours.attributesMs), ms(r.ours.atlasMs), ms(total)};
        if (r.hasConstrained)
            row.push_back(ms(r.constrained.smoothMs));
        if (r.hasTaubin) {
            row.push_back(ms(r.taubin.smoothMs));
            row.push_back(ms(r.extractMs + r.taubin.smoothMs + r.taubin.attributesMs + r.taubin.atlasMs));
            row.push_back(ms(r.taubinToVcgMs));
        }
        times.rows.push_back(row);
    }
    md << times.markdown() << "\n";

    // Table 2: counts per stage.
    md << "## Counts per stage (the paper's Table 2)\n\n"
       << "Voxels: the parts' bounding boxes; opaque: solid voxels. Fairing keeps the extracted mesh's counts. "
          "After the atlas a vertex is cloned once per chart it touches (section 4.5).\n\n";
    md << "The paper's Table 2 (after texture extraction):\n\n"
       << Table{{"model", "voxels", "opaque voxels", "vertices", "triangles"},
                {{"Demo Truck", "21168", "7893", "8987", "13624"},
                 {"Kirov", "554880", "35841", "36005", "52620"},
                 {"Yuri Head", "391680", "42733", "98324", "121468"},
                 {"Warhammer", "429900", "63150", "89750", "185552"}}}
              .markdown()
       << "\nOurs:\n\n";
    Table counts{{"model", "kind", "parts", "voxels", "opaque voxels", "extracted vertices", "quads",
                  "triangles (4.4)", "atlas vertices", "atlas triangles", "charts", "texture"},
                 {},
                 2};
    for (const ModelRun &r : runs) {
        const Variant &o = r.ours;
        counts.rows.push_back({r.name, r.kind, std::to_string(r.parts), std::to_string(r.boxVoxels),
                               std::to_string(r.solidVoxels), std::to_string(r.raw.mesh.vertexCount()),
                               std::to_string(r.raw.mesh.quadCount()), std::to_string(o.attributes.triangleCount()),
                               o.hasAtlas ? std::to_string(o.atlasVertices) : "-",
                               o.hasAtlas ? std::to_string(o.atlas.layout.wedgeUv.size() / 3) : "-",
                               o.hasAtlas ? std::to_string(o.atlas.charts.chartCount()) : "-",
                               o.hasAtlas ? format("%dx%d", o.atlas.texture.width, o.atlas.texture.height) : o.atlas.message()});
    }
    md << counts.markdown() << "\n";

    // The Taubin chain stage by stage, and the atlas on its surface.
    if (!runs.empty() && runs.front().hasTaubin) {
        md << "## Taubin chain, stage by stage\n\n"
           << "The same stages after Taubin Smooth instead of our fairing (extraction is shared), and how "
              "many charts the atlas makes of each smoothed surface.\n\n";
        Table taubin{{"model", "extraction", "Taubin 10", "attributes", "atlas", "total", "charts (Taubin)",
                      "charts (ours)"},
                     {}};
        for (const ModelRun &r : runs)
            taubin.rows.push_back({r.name, ms(r.extractMs), ms(r.taubin.smoothMs), ms(r.taubin.attributesMs),
                                   ms(r.taubin.atlasMs),
                                   ms(r.extractMs + r.taubin.smoothMs + r.taubin.attributesMs + r.taubin.atlasMs),
                                   r.taubin.hasAtlas ? std::to_string(r.taubin.atlas.charts.chartCount()) : "-",
                                   r.ours.hasAtlas ? std::to_string(r.ours.atlas.charts.chartCount()) : "-"});
        md << taubin.markdown() << "\n";
    }

    // Real models: no true surface, so how much each smoother changed the voxel surface.
    md << "## Change from the voxel surface (all inputs)\n\n"
       << "Enclosed volume against the raw voxel surface's, and vertex displacement from the lattice (voxels).\n\n";
    Table change{{"model", "method", "volume %", "mean move", "max move"}, {}, 2};
    for (const ModelRun &r : runs) {
        const double rawVolume = shapes::enclosedVolume(r.raw.mesh.positions, r.raw.attributes.triangles);
        for (const Variant *v : {&r.ours, &r.constrained, &r.taubin, &r.hc, &r.twoStep}) {
            if (v->mesh.positions.size() != r.raw.mesh.positions.size() || v->mesh.positions.empty())
                continue;
            double sum = 0, maxMove = 0;
            for (size_t i = 0; i < v->mesh.positions.size(); ++i) {
                const double d = glm::length(v->mesh.positions[i] - r.raw.mesh.positions[i]) / r.raw.mesh.voxelSize;
                sum += d;
                maxMove = std::max(maxMove, d);
            }
            const double volume = shapes::enclosedVolume(v->mesh.positions, r.raw.attributes.triangles);
            change.rows.push_back({r.name, v->name, format("%+.2f", (volume - rawVolume) / rawVolume * 100.0),
                                   format("%.3f", sum / double(v->mesh.positions.size())), format("%.3f", maxMove)});
        }
        if (r.hasVtk) {  // its own vertices: no displacement
            const double volume = shapes::enclosedVolume(r.vtk.positions, r.vtk.triangles);
            change.rows.push_back({r.name, "VTK windowed sinc", format("%+.2f", (volume - rawVolume) / rawVolume * 100.0),
                                   "-", "-"});
        }
    }
    md << change.markdown() << "\n";

    // The shape families at random orientations and offsets.
    md << "## Shape families (random orientations and sub-voxel offsets)\n\n"
       << "Worst RMS distance to the true surface over 4 shapes of each family of testkit/shapes/shape_families.h "
          "(20k samples each), worst |volume change| in brackets; best smoothed value in bold.\n\n"
       << lineup::familyTable(4, 20000) << "\n" << lineup::familyPictures(folder, size / 2);

    // Pictures.
    md << "## Pictures\n\nSame camera for every panel of a model (3/4 view from above the front, z up). Geometry "
          "panels use the voxel colours and faceted shading, so only the shape differs; the last panel is the "
          "product: the faired mesh with its smoothed vertex normals and the baked atlas texture.\n\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        const Pictures &p = pictures[i];
        md << "### " << runs[i].name << "\n\n";
        for (size_t k = 0; k < p.labels.size(); ++k)
            md << (k ? ", " : "Panels: ") << "[" << p.labels[k] << "](" << p.files[k] << ")";
        if (!p.wireframe.empty())
            md << ", [ours in wireframe](" << p.wireframe << ")";
        if (!p.texture.empty())
            md << "; [atlas texture](" << p.texture << ")";
        md << ".\n\n![" << runs[i].name << "](" << p.strip << ")\n\n";
    }

    const std::string text = md.str();
    std::ofstream((folder / "report.md").string()) << text;
    std::fputs(text.c_str(), stdout);
    std::fprintf(stderr, "wrote %s\n", (folder / "report.md").string().c_str());
    return 0;
}
