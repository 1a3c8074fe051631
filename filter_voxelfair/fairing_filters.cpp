// The smoothing filters: sections 4.3 (fairing) and 4.4 (attribute smoothing).
#include "filter_voxelfair_plugin.h"
#include "meshlab_arrays.h"

#include "../io_vxl/scene_to_meshlab.h"

#include "attributes/face_normals.h"
#include "base/error.h"
#include "attributes/vertex_colours.h"
#include "attributes/vertex_normals.h"
#include "fairing/constrained_fairing.h"
#include "fairing/lanczos_fairing.h"
#include "fairing/voxel_size.h"

#include <QElapsedTimer>

#include <glm/common.hpp>

#include <algorithm>
#include <future>

using namespace voxelfair;

namespace {

// What one fairing run did, whichever mode; summed over parts.
struct FairingSummary {
    size_t moved = 0, skipped = 0, parts = 0;
    float maxMove = 0.0f, minVoxel = 0.0f, maxVoxel = 0.0f;
    std::string extra;  // the constrained mode's edge classes

    void add(size_t movedVertices, size_t skippedVertices, float move, float voxel) {
        moved += movedVertices;
        skipped += skippedVertices;
        maxMove = std::max(maxMove, move);
        minVoxel = parts == 0 ? voxel : std::min(minVoxel, voxel);
        maxVoxel = std::max(maxVoxel, voxel);
        ++parts;
    }
};

// Runs the chosen mode on one set of polygon arrays; throws voxelfair::Error on bad input.
// `imported`: the voxel size the importer measured for these polygons (0: none), taken while
// the mesh still has edges of that length (a mesh faired once already may not say it itself).
void fairArrays(bool constrained, const RichParameterList &parameters, std::vector<glm::vec3> &positions,
                const std::vector<uint32_t> &offsets, const std::vector<uint32_t> &indices, const uint8_t *selected,
                float imported, FairingSummary &summary) {
    const MutablePolygonMesh mesh = mutablePolygonMesh(positions, offsets, indices);
    float voxelSize = parameters.getFloat("voxelSize");
    if (voxelSize <= 0.0f && imported > 0.0f)
        voxelSize = detectVoxelSize(mesh, imported);
    if (constrained) {
        ConstrainedFairingOptions options;
        options.voxelSize = voxelSize;
        const ConstrainedFairingReport r = fairConstrained(mesh, selected, options);
        if (r.status == FairingStatus::Ok) {
            summary.add(r.movedVertices, r.skippedVertices, r.maxDisplacement, r.voxelSize);
            summary.extra = QString("%1 sharp edges kept, %2 vertices pinned, %3 held by their voxel cell")
                                .arg(r.sharpEdges)
                                .arg(r.pinnedVertices)
                                .arg(r.clampedVertices)
                                .toStdString();
        }
        return;
    }
    LanczosFairingOptions options;
    options.lambda = parameters.getFloat("lambda");
    options.passes = parameters.getInt("passes");
    options.voxelSize = voxelSize;
    const FairingReport r = fairModifiedLanczos(mesh, selected, options);
    if (r.status == FairingStatus::Ok)
        summary.add(r.movedVertices, r.skippedVertices, r.maxDisplacement, r.voxelSize);
}

}  // namespace

bool FilterVoxelfairPlugin::applyLanczosFairing(MeshModel &m, const RichParameterList &parameters,
                                                vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    if (m.cm.fn == 0)
        return fail("Voxel Fairing: the mesh has no faces to smooth");
    const bool constrained = parameters.getEnum("mode") == 1;
    const bool selectedOnly = parameters.getBool("Selected");

    if (cb)
        cb(10, "Reading polygons");
    // Kept between runs (see polygonArrays); each run overwrites it.
    thread_local PolygonArrays arrays;
    polygonArrays(m.cm, arrays);
    if (cb)
        cb(40, "Fairing");
    FairingSummary summary;
    // Parts of an import may have different voxel sizes: detect and fair each on its own.
    std::vector<PartArrays> parts =
        parameters.getFloat("voxelSize") > 0 ? std::vector<PartArrays>{} : splitByPart(arrays, m.cm);
    if (parts.empty()) {
        try {
            fairArrays(constrained, parameters, arrays.positions, arrays.polygonOffsets, arrays.polygonIndices,
                       selectedOnly ? arrays.selected.data() : nullptr, importedVoxelSize(m.cm, commonPart(m.cm)),
                       summary);
        } catch (const Error &e) {
            return fail(QString("Voxel Fairing: %1").arg(e.what()));
        }
    } else {
        for (PartArrays &part : parts) {
            try {
                fairArrays(constrained, parameters, part.positions, part.polygonOffsets, part.polygonIndices,
                           selectedOnly ? part.selected.data() : nullptr, importedVoxelSize(m.cm, part.part), summary);
            } catch (const Error &e) {
                return fail(QString("Voxel Fairing: part %1: %2").arg(part.part).arg(e.what()));
            }
            for (size_t v = 0; v < part.positions.size(); ++v)
                arrays.positions[part.globalVertex[v]] = part.positions[v];
        }
    }
    if (summary.parts == 0) {
        report("Voxel Fairing: nothing to do (no polygon edge of non-zero length)");
        return true;
    }
    writePositions(arrays, arrays.positions, m.cm);
    // Area-weighted vertex normals: MeshLab's UpdateBoxAndNormals() weights by angle, which costs
    // an acos per corner and would take longer than the fairing itself.
    vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m.cm);

    const QString voxel = summary.minVoxel == summary.maxVoxel
                              ? QString::number(double(summary.minVoxel))
                              : QString("%1 to %2").arg(double(summary.minVoxel)).arg(double(summary.maxVoxel));
    const QString how = constrained ? QString("constrained mode")
                                    : QString("%1 pass(es), lambda %2")
                                          .arg(parameters.getInt("passes"))
                                          .arg(double(parameters.getFloat("lambda")));
    report(QString("Voxel Fairing: %1, voxel size %2%3%4: %5 vertices moved (at most %6)%7 in %8 ms")
               .arg(how)
               .arg(voxel)
               .arg(parameters.getFloat("voxelSize") > 0 ? "" : " (detected)")
               .arg(parts.empty() ? QString() : QString(" over %1 parts").arg(parts.size()))
               .arg(summary.moved)
               .arg(double(summary.maxMove))
               .arg(summary.extra.empty() ? QString() : "; " + QString::fromStdString(summary.extra))
               .arg(timer.elapsed()));
    if (summary.skipped > 0)
        report(QString("Voxel Fairing: %1 vertices with non-finite coordinates were left alone").arg(summary.skipped));
    return true;
}

bool FilterVoxelfairPlugin::applyAttributeSmoothing(MeshModel &m, const RichParameterList &parameters,
                                                    vcg::CallBackPos *cb) {
    if (m.cm.fn == 0)
        return fail("Attribute Smoothing: the mesh has no faces");
    if (cb)
        cb(10, "Reading polygons");
    const PolygonArrays arrays = polygonArrays(m.cm);
    const size_t polygons = arrays.polygonCount();
    PolygonMesh mesh = polygonMesh(arrays.positions, arrays.polygonOffsets, arrays.polygonIndices);

    std::vector<glm::vec3> polygonNormals(polygons);
    std::vector<glm::vec3> vertexNormals(arrays.positions.size());
    VertexNormalOptions normalOptions;
    if (!parameters.getBool("distinctNormals"))
        normalOptions.sameDirection = 2.0f;  // never merge: plain mean
    // The polygons' normals on a second thread beside the vertex-polygon adjacency and the vertex
    // colours (each writes its own arrays; the library chain's order, testkit smoothAttributes);
    // get() rethrows a MeshError of the polygons.
    std::future<void> normalsDone =
        std::async(std::launch::async, [&] { computePolygonNormals(mesh, polygonNormals.data()); });
    // Face colours: the polygon's first triangle's colour; without face colours, the vertex colours
    // already there (or a flat grey) are kept and said so.
    const bool hasFaceColours = m.hasDataMask(MeshModel::MM_FACECOLOR);
    CsrAdjacency polygonsOf;  // for the normals and the colours
    std::vector<glm::vec4> vertexColours;
    try {
        polygonsOf = buildVertexPolygons(mesh);
        if (hasFaceColours) {
            std::vector<glm::vec4> polygonColours(polygons);
            for (size_t p = 0; p < polygons; ++p) {
                const vcg::Color4b &c = m.cm.face[arrays.polygonFace[p]].C();
                polygonColours[p] = glm::vec4(c[0], c[1], c[2], c[3]);
            }
            vertexColours.resize(arrays.positions.size());
            PolygonMesh coloured = mesh;
            coloured.polygonColours = polygonColours.data();
            computeVertexColours(coloured, polygonsOf, vertexColours.data());
        }
    } catch (...) {
        normalsDone.wait();  // the thread reads `mesh`: done before this frame goes
        throw;
    }
    normalsDone.get();
    computeVertexNormals(mesh, polygonsOf, polygonNormals.data(), vertexNormals.data(), normalOptions);
    if (hasFaceColours) {
        m.updateDataMask(MeshModel::MM_VERTCOLOR);
        for (size_t i = 0; i < arrays.vertexOf.size(); ++i) {
            const glm::vec4 c = glm::clamp(glm::round(vertexColours[i]), 0.0f, 255.0f);
            m.cm.vert[arrays.vertexOf[i]].C() = vcg::Color4b(uint8_t(c.r), uint8_t(c.g), uint8_t(c.b), uint8_t(c.a));
        }
    } else {
        report("Attribute Smoothing: the mesh has no face colours; vertex colours are left as they are");
    }

    if (parameters.getBool("triangulate")) {
        for (CFaceO &f : m.cm.face)
            if (!f.IsD())
                f.ClearF(0), f.ClearF(1), f.ClearF(2);
        m.clearDataMask(MeshModel::MM_POLYGONAL);
    }
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m.cm);
    for (size_t i = 0; i < arrays.vertexOf.size(); ++i) {
        const glm::vec3 &n = vertexNormals[i];
        m.cm.vert[arrays.vertexOf[i]].N() = CMeshO::CoordType(n.x, n.y, n.z);
    }
    report(QString("Attribute Smoothing: %1 polygons%2, vertex normals (%3)%4")
               .arg(polygons)
               .arg(parameters.getBool("triangulate") ? " turned into triangles" : "")
               .arg(parameters.getBool("distinctNormals") ? "distinct face normals" : "all face normals")
               .arg(hasFaceColours ? " and colours" : ""));
    return true;
}
