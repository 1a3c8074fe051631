// The paper's chain (sections 4.2-4.5) as separate stages on plain arrays, so each can be timed
// and its output counted: shared by tools/comparison_report and benchmarks/pipeline_benchmark.
//
//   load (VXL + HVA + palette, VOX, or a volume)  ->  VoxelScene
//   extract()            4.2  boundary quads with their voxel colours
//   fair()               4.3  modified-Lanczos fairing, in place
//   smoothAttributes()   4.4  face/vertex normals, vertex colours, quads -> triangles (a-c)
//   buildAtlas()         4.5  charts, packing, baked diffuse texture
//
// Header-only on voxelfair::core, so the benchmark needs no extra library.
#pragma once

#include "atlas/texture_atlas.h"
#include "attributes/face_normals.h"
#include "attributes/triangulate.h"
#include "attributes/vertex_colours.h"
#include "attributes/vertex_normals.h"
#include "base/parallel_bands.h"
#include "fairing/constrained_fairing.h"
#include "fairing/lanczos_fairing.h"
#include "fairing/voxel_size.h"
#include "formats/file_bytes.h"
#include "formats/hva.h"
#include "formats/palette.h"
#include "formats/vox.h"
#include "formats/vxl.h"
#include "scene/unit_scene.h"
#include "scene/vox_scene.h"
#include "scene/voxel_scene.h"
#include "scene/vxl_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/gtc/type_precision.hpp>
#include <glm/vec4.hpp>

namespace voxelfair::pipeline {

// A model ready for meshing. Owns what its scene points into, so it is neither copied nor moved.
struct Model {
    std::string name;
    std::string paletteSource;  // VXL: which palette coloured it
    VxlModel vxl;
    std::optional<HvaAnimation> hva;
    std::vector<UnitFile> unit;  // a whole unit: body, turret, barrel (empty for a single file)
    VoxFile vox;
    std::vector<VoxelVolume> volumes;  // for models built from volumes
    // What the chain runs on. VXL sections stay in their own voxel units, as the authors ran
    // them (doc/method.md §1): a model mixing section scales (subapc's HVA shrinks four of its five
    // sections to 0.01) would otherwise have no single voxel size for the fairing and the atlas.
    VoxelScene scene;
    // Per part: the chain's coordinates -> model space, for pictures (identity when equal).
    std::vector<glm::mat4> toDisplay;

    Model() = default;
    Model(const Model &) = delete;
    Model &operator=(const Model &) = delete;

    // The paper's Table 2 "Voxels": the parts' bounding boxes; "Opaque Voxels": the solid ones.
    size_t boxVoxels() const {
        size_t n = 0;
        for (const PlacedVolume &p : scene.parts)
            n += size_t(p.volume->sizeX) * size_t(p.volume->sizeY) * size_t(p.volume->sizeZ);
        return n;
    }
    size_t solidVoxels() const {
        size_t n = 0;
        for (const PlacedVolume &p : scene.parts)
            n += p.volume->voxelCount();
        return n;
    }
};

// A .vxl with the .hva beside it (same stem) when there is one, frame 0; with `wholeUnit`, a
// unit's body with its turret and barrel files (scene/unit_scene.h). When the embedded
// palette is all zeros (many community files), the game palette from `paletteDir` matching the
// model's normal type (ts_unittem.pal for Tiberian Sun, ra2_unittem.pal otherwise) colours it.
// Throws FormatError.
inline std::unique_ptr<Model> loadVxl(const std::string &path, const std::string &paletteDir, bool wholeUnit = false) {
    auto model = std::make_unique<Model>();
    model->name = std::filesystem::path(path).stem().string();
    const std::vector<uint8_t> bytes = readFileBytes(path);
    model->vxl = readVxl(bytes.data(), bytes.size());
    const std::filesystem::path hvaPath = std::filesystem::path(path).replace_extension(".hva");
    if (std::filesystem::exists(hvaPath)) {
        const std::vector<uint8_t> hvaBytes = readFileBytes(hvaPath.string());
        model->hva = readHva(hvaBytes.data(), hvaBytes.size());
    }
    VxlSceneOptions options;
    Palette external;
    if (model->vxl.embeddedPalette.allZero() && !paletteDir.empty()) {
        const bool tiberianSun = !model->vxl.sections.empty() &&
                                 model->vxl.sections.front().normalType == uint8_t(VxlNormalType::TiberianSun);
        const std::string palPath = paletteDir + (tiberianSun ? "/ts_unittem.pal" : "/ra2_unittem.pal");
        if (std::filesystem::exists(palPath)) {
            const std::vector<uint8_t> palBytes = readFileBytes(palPath);
            external = readPal(palBytes.data(), palBytes.size());
            options.externalPalette = &external;
            model->paletteSource = std::filesystem::path(palPath).filename().string();
        }
    }
    if (model->paletteSource.empty())
        model->paletteSource = chooseVxlPalette(model->vxl, options).source;
    const HvaAnimation *hva = model->hva ? &*model->hva : nullptr;
    // A unit's body brings its turret and barrel (NAMEtur.vxl, NAMEbarl.vxl beside it), as the
    // importer does: the whole tank, each file by its own .hva.
    if (wholeUnit && !isUnitCompanionStem(model->name)) {
        for (UnitRole role : {UnitRole::Turret, UnitRole::Barrel}) {
            const std::filesystem::path companion =
                std::filesystem::path(path).parent_path() / (unitCompanionStem(model->name, role) + ".vxl");
            if (!std::filesystem::exists(companion))
                continue;
            if (model->unit.empty())
                model->unit.push_back({UnitRole::Body, model->name, model->vxl, model->hva});
            UnitFile file{role, companion.filename().string(), {}, {}};
            const std::vector<uint8_t> b = readFileBytes(companion.string());
            file.model = readVxl(b.data(), b.size());
            const std::filesystem::path h = std::filesystem::path(companion).replace_extension(".hva");
            if (std::filesystem::exists(h)) {
                const std::vector<uint8_t> hb = readFileBytes(h.string());
                file.hva = readHva(hb.data(), hb.size());
            }
            model->unit.push_back(std::move(file));
        }
    }
    if (!model->unit.empty()) {
        UnitSceneOptions unitOptions;
        unitOptions.vxl = options;
        for (const PlacedVolume &part : unitScene(model->unit, unitOptions).scene.parts)
            model->toDisplay.push_back(part.toModel);
        unitOptions.vxl.applyTransforms = false;
        model->scene = unitScene(model->unit, unitOptions).scene;
        return model;
    }
    for (const PlacedVolume &part : vxlScene(model->vxl, hva, options).parts)
        model->toDisplay.push_back(part.toModel);
    options.applyTransforms = false;
    model->scene = vxlScene(model->vxl, hva, options);
    return model;
}

// A .vox, frame 0. Throws FormatError.
inline std::unique_ptr<Model> loadVox(const std::string &path) {
    auto model = std::make_unique<Model>();
    model->name = std::filesystem::path(path).stem().string();
    const std::vector<uint8_t> bytes = readFileBytes(path);
    model->vox = readVox(bytes.data(), bytes.size());
    model->paletteSource = "file";
    model->scene = voxScene(model->vox);  // instances turn and move, but keep one voxel per unit
    model->toDisplay.assign(model->scene.parts.size(), glm::mat4(1.0f));
    return model;
}

// Every shared model the readers accept, sorted by file (vxl/NAME.vxl with its .hva and the game
// palettes in pal/, vox/NAME.vox), or only the one named `only` (its file name without extension);
// `refused` collects "file: reason" for the others.
inline std::vector<std::unique_ptr<Model>>
sharedModels(const std::filesystem::path &dir, std::vector<std::string> *refused, const std::string &only = "") {
    std::vector<std::filesystem::path> files;
    for (const char *sub : {"vxl", "vox"})
        if (std::filesystem::is_directory(dir / sub))
            for (const auto &entry : std::filesystem::directory_iterator(dir / sub))
                if (entry.path().extension() == std::string(".") + sub && (only.empty() || entry.path().stem() == only))
                    files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::vector<std::unique_ptr<Model>> models;
    for (const auto &file : files) {
        try {
            models.push_back(file.extension() == ".vxl" ? loadVxl(file.string(), (dir / "pal").string())
                                                        : loadVox(file.string()));
        } catch (const std::exception &e) {
            if (refused)
                refused->push_back(file.filename().string() + ": " + e.what());
        }
    }
    return models;
}

// Volumes meshed in their own voxel units, shown placed by `toDisplay` (one matrix per volume),
// with `palette`: e.g. a voxelized analytic shape, or a synthetic multi-section model.
inline std::unique_ptr<Model> volumesModel(std::string name, std::vector<VoxelVolume> volumes,
                                           std::vector<glm::mat4> toDisplay, const Palette &palette) {
    auto model = std::make_unique<Model>();
    model->name = std::move(name);
    model->paletteSource = "given";
    model->volumes = std::move(volumes);
    model->toDisplay = std::move(toDisplay);
    model->toDisplay.resize(model->volumes.size(), glm::mat4(1.0f));
    model->scene.palette = palette;
    for (size_t i = 0; i < model->volumes.size(); ++i) {
        PlacedVolume part;
        part.volume = &model->volumes[i];
        part.part = int(i);
        part.name = model->name;
        model->scene.parts.push_back(part);
    }
    return model;
}

inline std::unique_ptr<Model> volumeModel(std::string name, VoxelVolume volume, const Palette &palette) {
    std::vector<VoxelVolume> volumes;
    volumes.push_back(std::move(volume));
    return volumesModel(std::move(name), std::move(volumes), {}, palette);
}

// Section 4.2's output: quads with their voxel's colour.
struct QuadMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> offsets;  // polygon offsets (4 * q), for the polygon-array units
    std::vector<uint32_t> quads;
    std::vector<glm::u8vec3> quadColours;
    std::vector<uint32_t> quadPart;         // index into the scene's parts
    std::vector<uint8_t> quadPaletteIndex;  // the palette index of each quad's voxel
    float voxelSize = 1.0f;                 // edge length of one voxel in the mesh's units

    size_t quadCount() const { return quads.size() / 4; }
    size_t vertexCount() const { return positions.size(); }
    PolygonMesh view() const { return polygonMesh(positions, offsets, quads); }
    MutablePolygonMesh mutableView() { return mutablePolygonMesh(positions, offsets, quads); }
};

inline QuadMesh extract(const VoxelScene &scene) {
    SceneSurface surface = extractSceneSurface(scene);
    QuadMesh mesh;
    mesh.positions = std::move(surface.positions);
    mesh.quads = std::move(surface.quads);
    mesh.offsets.resize(mesh.quadCount() + 1);
    for (size_t q = 0; q < mesh.offsets.size(); ++q)
        mesh.offsets[q] = uint32_t(4 * q);
    mesh.quadColours.reserve(surface.quadColours.size());
    for (const Rgb &c : surface.quadColours)
        mesh.quadColours.emplace_back(c.r, c.g, c.b);
    mesh.quadPaletteIndex.reserve(surface.quadVoxels.size());
    for (const Voxel &v : surface.quadVoxels)
        mesh.quadPaletteIndex.push_back(v.colour);
    for (size_t part = 0; part < surface.partQuadCounts.size(); ++part)
        mesh.quadPart.insert(mesh.quadPart.end(), surface.partQuadCounts[part], uint32_t(part));
    const float size = detectVoxelSize(mesh.view(), 0.0f, 0);
    mesh.voxelSize = size > 0.0f ? size : 1.0f;
    return mesh;
}

// One pass of the paper's fairing (default options), in the extracted mesh's voxel units.
inline FairingReport fair(QuadMesh &mesh, LanczosFairingOptions options = {}) {
    if (options.voxelSize == 0.0f)
        options.voxelSize = mesh.voxelSize;
    return fairModifiedLanczos(mesh.mutableView(), nullptr, options);
}

// The constrained mode (default options) in place of the paper's fairing.
inline ConstrainedFairingReport fairConstrainedMode(QuadMesh &mesh, ConstrainedFairingOptions options = {}) {
    if (options.voxelSize == 0.0f)
        options.voxelSize = mesh.voxelSize;
    return fairConstrained(mesh.mutableView(), nullptr, options);
}

// Section 4.4's output, on the (faired) quad mesh's vertices.
struct Attributes {
    std::vector<glm::vec3> quadNormals;
    std::vector<glm::vec3> vertexNormals;    // distinct adjacent face normals
    std::vector<glm::u8vec3> vertexColours;  // mean of the adjacent quads' colours
    std::vector<uint32_t> triangles;         // a-c fan: quad q -> triangles 2q, 2q + 1
    std::vector<uint32_t> triangleQuad;
    std::vector<glm::u8vec3> triangleColours;

    size_t triangleCount() const { return triangleQuad.size(); }
};

// On two threads (`threads`: 0, one per hardware thread; 1, one), each step writing its own
// arrays: the quads' normals, then the vertex normals, beside the vertex polygons, the vertex
// colours and the triangles. The same attributes for any count.
inline Attributes smoothAttributes(const QuadMesh &mesh, int threads = 0) {
    const size_t quads = mesh.quadCount(), vertices = mesh.vertexCount();
    Attributes a;
    a.quadNormals.resize(quads);
    a.vertexNormals.resize(vertices);
    a.vertexColours.resize(vertices);
    CsrAdjacency polygonsOf;  // for the normals and the colours
    const int workers = bandThreads(threads, 2);
    // The units throw MeshError on invalid polygons: caught in their band, rethrown here.
    std::exception_ptr failed[2];
    auto guarded = [&](auto &&step) {
        return [&failed, &step](size_t band) {
            try {
                step(band);
            } catch (...) {
                failed[band] = std::current_exception();
            }
        };
    };
    auto rethrow = [&failed] {
        for (const std::exception_ptr &e : failed)
            if (e)
                std::rethrow_exception(e);
    };
    runBands(2, workers, guarded([&](size_t band) {
                 const PolygonMesh view = mesh.view();
                 if (band == 1) {
                     computePolygonNormals(view, a.quadNormals.data());
                     return;
                 }
                 polygonsOf = buildVertexPolygons(view);
                 std::vector<glm::vec4> quadColours(quads), vertexColours(vertices);
                 for (size_t q = 0; q < quads; ++q)
                     quadColours[q] = glm::vec4(glm::vec3(mesh.quadColours[q]), 255.0f);
                 PolygonMesh coloured = view;
                 coloured.polygonColours = quadColours.data();
                 computeVertexColours(coloured, polygonsOf, vertexColours.data());
                 for (size_t v = 0; v < vertices; ++v)
                     a.vertexColours[v] =
                         glm::u8vec3(glm::clamp(glm::round(glm::vec3(vertexColours[v])), 0.0f, 255.0f));
             }));
    rethrow();
    runBands(2, workers, guarded([&](size_t band) {
                 const PolygonMesh view = mesh.view();
                 if (band == 0) {
                     computeVertexNormals(view, polygonsOf, a.quadNormals.data(), a.vertexNormals.data());
                     return;
                 }
                 const size_t triangles = countFanTriangles(view);  // on polygons checked by the first step
                 a.triangles.resize(3 * triangles);
                 a.triangleQuad.resize(triangles);
                 a.triangleColours.resize(triangles);
                 triangulatePolygons(view, a.triangles.data(), a.triangleQuad.data());
                 for (size_t t = 0; t < triangles; ++t)
                     a.triangleColours[t] = mesh.quadColours[a.triangleQuad[t]];
             }));
    rethrow();
    return a;
}

// The atlas' view of the mesh: crisp voxel colours per triangle, smoothed ones per vertex.
inline AtlasMesh atlasMesh(const QuadMesh &mesh, const Attributes &a) {
    AtlasMesh m;
    m.positions = mesh.positions.data();
    m.vertexCount = mesh.vertexCount();
    m.triangles = a.triangles.data();
    m.faceCount = a.triangleCount();
    m.faceColours = a.triangleColours.data();
    m.vertexColours = a.vertexColours.data();
    return m;
}

// Density in texels per voxel edge whatever the model's scale.
inline TextureAtlas buildAtlas(const QuadMesh &mesh, const Attributes &a, AtlasOptions options = {}) {
    options.pack.texelsPerUnit /= mesh.voxelSize;
    return buildTextureAtlas(atlasMesh(mesh, a), options);
}

// Vertices of the textured mesh: a vertex on faces of k charts is cloned k times (section 4.5).
inline size_t atlasVertexCount(const TextureAtlas &atlas, const Attributes &a) {
    std::vector<uint64_t> keys;
    keys.reserve(a.triangles.size());
    for (size_t t = 0; t < atlas.charts.faceChart.size(); ++t)
        for (int k = 0; k < 3; ++k)
            keys.push_back(uint64_t(a.triangles[3 * t + size_t(k)]) << 32 | atlas.charts.faceChart[t]);
    std::sort(keys.begin(), keys.end());
    return size_t(std::unique(keys.begin(), keys.end()) - keys.begin());
}

// The mesh's vertices (and optionally unit normals) in model space, for pictures: each vertex
// moved with its part (every vertex belongs to the quads of one part).
inline std::vector<glm::vec3> displayPositions(const QuadMesh &mesh, const Model &model) {
    std::vector<glm::vec3> out = mesh.positions;
    for (size_t q = 0; q < mesh.quadCount(); ++q) {
        const glm::mat4 &m = model.toDisplay[mesh.quadPart[q]];
        for (size_t k = 4 * q; k < 4 * q + 4; ++k)
            out[mesh.quads[k]] = glm::vec3(m * glm::vec4(mesh.positions[mesh.quads[k]], 1.0f));
    }
    return out;
}

inline std::vector<glm::vec3> displayNormals(const QuadMesh &mesh, const Model &model,
                                             const std::vector<glm::vec3> &normals) {
    std::vector<glm::mat3> normalMatrix;
    for (const glm::mat4 &m : model.toDisplay)
        normalMatrix.push_back(glm::transpose(glm::inverse(glm::mat3(m))));
    std::vector<glm::vec3> out = normals;
    for (size_t q = 0; q < mesh.quadCount(); ++q) {
        const glm::mat3 &m = normalMatrix[mesh.quadPart[q]];
        for (size_t k = 4 * q; k < 4 * q + 4; ++k) {
            const glm::vec3 n = m * normals[mesh.quads[k]];
            const float length = glm::length(n);
            out[mesh.quads[k]] = length > 0.0f ? n / length : n;
        }
    }
    return out;
}

}  // namespace voxelfair::pipeline
