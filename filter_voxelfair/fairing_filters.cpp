// The smoothing filters: sections 4.3 (fairing) and 4.4 (attribute smoothing).
#include "filter_voxelfair_plugin.h"
#include "meshlab_arrays.h"

#include "attributes/face_normals.h"
#include "attributes/vertex_colours.h"
#include "attributes/vertex_normals.h"
#include "fairing/lanczos_fairing.h"

#include <QElapsedTimer>

#include <glm/common.hpp>

using namespace voxelfair;

bool FilterVoxelfairPlugin::applyLanczosFairing(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    if (m.cm.fn == 0) return fail("Voxel Fairing: the mesh has no faces to smooth");
    LanczosFairingOptions options;
    options.lambda = parameters.getFloat("lambda");
    options.passes = parameters.getInt("passes");
    options.voxelSize = parameters.getFloat("voxelSize");
    const bool selectedOnly = parameters.getBool("Selected");

    if (cb) cb(10, "Reading polygons");
    PolygonArrays arrays = polygonArrays(m.cm);
    if (cb) cb(40, "Fairing");
    const FairingReport result = fairModifiedLanczos(
        arrays.positions.data(), arrays.positions.size(), arrays.polygonOffsets.data(), arrays.polygonIndices.data(),
        arrays.polygonCount(), selectedOnly ? arrays.selected.data() : nullptr, options);
    if (result.failed()) return fail(QString("Voxel Fairing: %1").arg(result.message));
    if (result.status == FairingStatus::NothingToDo) {
        report(QString("Voxel Fairing: nothing to do (%1)").arg(result.message));
        return true;
    }
    writePositions(arrays, arrays.positions, m.cm);
    // Area-weighted vertex normals: MeshLab's UpdateBoxAndNormals() weights by angle, which costs
    // an acos per corner and would take longer than the fairing itself.
    vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m.cm);
    report(QString("Voxel Fairing: %1 pass(es), lambda %2, voxel size %3%4: %5 vertices moved (at most %6) in %7 ms")
               .arg(result.passes)
               .arg(double(options.lambda))
               .arg(double(result.voxelSize))
               .arg(options.voxelSize > 0 ? "" : " (detected)")
               .arg(result.movedVertices)
               .arg(double(result.maxDisplacement))
               .arg(timer.elapsed()));
    if (result.skippedVertices > 0)
        report(QString("Voxel Fairing: %1 vertices with non-finite coordinates were left alone")
                   .arg(result.skippedVertices));
    return true;
}

bool FilterVoxelfairPlugin::applyAttributeSmoothing(MeshModel &m, const RichParameterList &parameters,
                                                   vcg::CallBackPos *cb) {
    if (m.cm.fn == 0) return fail("Attribute Smoothing: the mesh has no faces");
    if (cb) cb(10, "Reading polygons");
    const PolygonArrays arrays = polygonArrays(m.cm);
    const size_t polygons = arrays.polygonCount();

    std::vector<glm::vec3> polygonNormals(polygons);
    std::vector<glm::vec3> vertexNormals(arrays.positions.size());
    computePolygonNormals(arrays.positions.data(), arrays.positions.size(), arrays.polygonOffsets.data(),
                          arrays.polygonIndices.data(), polygons, polygonNormals.data());
    VertexNormalOptions normalOptions;
    if (!parameters.getBool("distinctNormals")) normalOptions.sameDirection = 2.0f;  // never merge: plain mean
    computeVertexNormals(arrays.positions.size(), arrays.polygonOffsets.data(), arrays.polygonIndices.data(), polygons,
                         polygonNormals.data(), vertexNormals.data(), normalOptions);

    // Face colours: the polygon's first triangle's colour; without face colours, the vertex colours
    // already there (or a flat grey) are kept and said so.
    const bool hasFaceColours = m.hasDataMask(MeshModel::MM_FACECOLOR);
    if (hasFaceColours) {
        std::vector<glm::vec4> polygonColours(polygons);
        for (size_t p = 0; p < polygons; ++p) {
            const vcg::Color4b &c = m.cm.face[arrays.polygonFace[p]].C();
            polygonColours[p] = glm::vec4(c[0], c[1], c[2], c[3]);
        }
        std::vector<glm::vec4> vertexColours(arrays.positions.size());
        computeVertexColours(arrays.positions.size(), arrays.polygonOffsets.data(), arrays.polygonIndices.data(),
                             polygons, polygonColours.data(), vertexColours.data());
        m.updateDataMask(MeshModel::MM_VERTCOLOR);
        for (size_t i = 0; i < arrays.vertexOf.size(); ++i) {
            const glm::vec4 c = glm::clamp(glm::round(vertexColours[i]), 0.0f, 255.0f);
            m.cm.vert[arrays.vertexOf[i]].C() =
                vcg::Color4b(uint8_t(c.r), uint8_t(c.g), uint8_t(c.b), uint8_t(c.a));
        }
    } else {
        report("Attribute Smoothing: the mesh has no face colours; vertex colours are left as they are");
    }

    if (parameters.getBool("triangulate")) {
        for (CFaceO &f : m.cm.face)
            if (!f.IsD()) f.ClearF(0), f.ClearF(1), f.ClearF(2);
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
