// The per-voxel attribute maps in the base colour's atlas layout (libvoxelfair/maps):
//  * Bake House Colour Mask: a VXL model's remap-range voxels (house colours, maps/house_mask.h).
// Each reads the palette index io_vxl keeps per face, bakes on the layer the atlas was built on
// (before any decimation: a decimated face spans several voxels) and records the file for the
// exporters (MaterialMapFiles, io_vxl/scene_to_meshlab.h).
#include "filter_voxelfair_plugin.h"

#include "maps/house_mask.h"

#include "../io_vxl/scene_to_meshlab.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include <algorithm>
#include <vector>

using namespace voxelfair;

namespace {

struct FaceArrays {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    std::vector<uint8_t> paletteIndex;
    std::vector<glm::u8vec3> colours;
    FaceValueMesh view() const {
        FaceValueMesh m;
        m.positions = positions.data();
        m.vertexCount = positions.size();
        m.triangles = triangles.data();
        m.wedgeUv = wedgeUv.data();
        m.faceCount = triangles.size() / 3;
        return m;
    }
};

// False when the mesh has no palette index per face (not imported by io_vxl).
bool readFaceArrays(CMeshO &cm, FaceArrays &out) {
    if (!vcg::tri::HasPerFaceAttribute(cm, kPaletteIndexAttributeName))
        return false;
    auto index = vcg::tri::Allocator<CMeshO>::FindPerFaceAttribute<uint8_t>(cm, kPaletteIndexAttributeName);
    if (!vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, index))
        return false;
    std::vector<uint32_t> arrayIndex(cm.vert.size(), 0);
    for (size_t v = 0; v < cm.vert.size(); ++v) {
        if (cm.vert[v].IsD())
            continue;
        arrayIndex[v] = uint32_t(out.positions.size());
        const auto &p = cm.vert[v].cP();
        out.positions.emplace_back(p[0], p[1], p[2]);
    }
    const bool colours = cm.face.IsColorEnabled();
    for (CFaceO &face : cm.face) {
        if (face.IsD())
            continue;
        for (int k = 0; k < 3; ++k) {
            out.triangles.push_back(arrayIndex[vcg::tri::Index(cm, face.cV(k))]);
            out.wedgeUv.emplace_back(face.cWT(k).U(), face.cWT(k).V());
        }
        out.paletteIndex.push_back(index[&face]);
        out.colours.push_back(colours ? glm::u8vec3(face.cC()[0], face.cC()[1], face.cC()[2]) : glm::u8vec3(255));
    }
    return true;
}

PaletteKind paletteKind(CMeshO &cm) {
    if (!vcg::tri::HasPerMeshAttribute(cm, kPaletteKindAttributeName))
        return PaletteKind(0);
    auto handle = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<int>(cm, kPaletteKindAttributeName);
    return vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, handle) ? PaletteKind(handle()) : PaletteKind(0);
}

QString besideMesh(const MeshModel &m, const QString &name) {
    if (QFileInfo(name).isAbsolute())
        return QDir::cleanPath(name);
    const QString meshFile = m.fullName();
    const QDir folder = meshFile.isEmpty() ? QDir::current() : QFileInfo(meshFile).absoluteDir();
    return QDir::cleanPath(folder.absoluteFilePath(name));
}

// "NAME_texture.png" -> "NAME<suffix>"; otherwise "<mesh name><suffix>".
QString mapNameFor(const MeshModel &m, const QString &suffix) {
    if (!m.cm.textures.empty()) {
        QString base = QFileInfo(QString::fromStdString(m.cm.textures.front())).completeBaseName();
        if (base.endsWith("_texture"))
            base.chop(8);
        return base + suffix;
    }
    const QString base = QFileInfo(m.fullName()).completeBaseName();
    return (base.isEmpty() ? QString("voxelfair") : base) + suffix;
}

// The base colour's file: beside `mapPath` (where the pipeline writes both), else beside the mesh.
QString baseColourPath(const MeshModel &m, const QString &mapPath) {
    const QString name = QString::fromStdString(m.cm.textures.front());
    QString texture = QFileInfo(name).isAbsolute() ? name : QFileInfo(mapPath).absoluteDir().absoluteFilePath(name);
    if (!QFileInfo::exists(texture))
        texture = besideMesh(m, name);
    return texture;
}

}  // namespace

QString defaultHouseMaskName(const MeshModel &m) { return mapNameFor(m, "_house.png"); }

bool FilterVoxelfairPlugin::applyHouseMask(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    if (m.cm.fn == 0)
        return fail("Bake House Colour Mask: the mesh has no faces");
    if (!m.hasDataMask(MeshModel::MM_WEDGTEXCOORD) || m.cm.textures.empty())
        return fail("Bake House Colour Mask: the mesh has no texture atlas; run Voxel Texture Atlas first");
    FaceArrays arrays;
    if (!readFaceArrays(m.cm, arrays))
        return fail("Bake House Colour Mask: the mesh has no voxel palette index per face; import the model with "
                    "voxelfair's VXL importer (and bake before duplicating or decimating)");
    if (paletteKind(m.cm) != PaletteKind::Westwood)
        return fail("Bake House Colour Mask: house colours (palette indices 16-31) belong to Westwood VXL models; "
                    "this mesh was not imported from a .vxl");

    const QString path = besideMesh(m, parameters.getString("houseFile").trimmed().isEmpty()
                                           ? defaultHouseMaskName(m)
                                           : parameters.getString("houseFile").trimmed());
    const QString texture = baseColourPath(m, path);
    const QSize size = QImageReader(texture).size();
    if (!size.isValid())
        return fail(
            QString("Bake House Colour Mask: could not read the size of the base colour texture %1").arg(texture));
    if (cb)
        cb(10, "Baking the house colour mask");
    const HouseMask mask = bakeHouseMask(arrays.view(), arrays.paletteIndex.data(), size.width(), size.height(),
                                         parameters.getInt("dilation"));
    if (cb)
        cb(80, "Writing the house colour mask");
    const QImage image(mask.grey.data(), mask.width, mask.height, mask.width, QImage::Format_Grayscale8);
    if (!QDir().mkpath(QFileInfo(path).absolutePath()) || !image.save(path, "PNG"))
        return fail(QString("Bake House Colour Mask: could not write the mask to %1").arg(path));
    MaterialMapFiles files;
    if (const MaterialMapFiles *stored = findMaterialMaps(m.cm))
        files = *stored;
    files.houseMask = QFileInfo(path).fileName().toStdString();
    storeMaterialMaps(files, m.cm);
    report(QString("Bake House Colour Mask: %1 of %2 faces use the remap range (palette 16-31), %3 texels, %4 x %5 "
                   "(the size of %6) -> %7 in %8 ms")
               .arg(mask.houseFaces)
               .arg(arrays.paletteIndex.size())
               .arg(mask.houseTexels)
               .arg(mask.width)
               .arg(mask.height)
               .arg(QFileInfo(texture).fileName())
               .arg(path)
               .arg(timer.elapsed()));
    return true;
}
