// The per-voxel attribute maps in the base colour's atlas layout (libvoxelfair/maps):
//  * Bake House Colour Mask: a VXL model's remap-range voxels (house colours, maps/house_mask.h).
//  * Bake Material Maps: a VOX model's MATL materials as glTF PBR maps (maps/material_maps.h).
// Each reads the palette index io_vxl keeps per face, bakes on the layer the atlas was built on
// (before any decimation: a decimated face spans several voxels) and records the file for the
// exporters (MaterialMapFiles, io_vxl/scene_to_meshlab.h).
#include "filter_voxelfair_plugin.h"
#include "map_files.h"
#include "meshlab_arrays.h"

#include "maps/house_mask.h"
#include "maps/material_maps.h"

#include "../io_vxl/scene_to_meshlab.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include <algorithm>
#include <vector>

using namespace voxelfair;

namespace {

// The layer's triangles with the atlas' UVs, each face's palette index (io_vxl's attribute) and
// colour (white where the mesh has none).
struct FaceArrays {
    TriangleArrays triangles;
    std::vector<uint8_t> paletteIndex;
    FaceValueMesh view() const {
        FaceValueMesh m;
        static_cast<TriangleMesh &>(m) = triangleMesh(triangles.positions, triangles.triangles);
        m.wedgeUv = triangles.wedgeUv.data();
        return m;
    }
};

// False when the mesh has no palette index per face (not imported by io_vxl).
bool readFaceArrays(MeshModel &m, FaceArrays &out) {
    CMeshO &cm = m.cm;
    if (!vcg::tri::HasPerFaceAttribute(cm, kPaletteIndexAttributeName))
        return false;
    auto index = vcg::tri::Allocator<CMeshO>::FindPerFaceAttribute<uint8_t>(cm, kPaletteIndexAttributeName);
    if (!vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, index))
        return false;
    TriangleFields fields;
    fields.wedgeUv = true;
    fields.faceColours = m.hasDataMask(MeshModel::MM_FACECOLOR);
    readTriangleArrays(cm, fields, out.triangles);
    if (out.triangles.faceColours.empty())
        out.triangles.faceColours.assign(out.triangles.triangleCount(), glm::u8vec3(255));
    for (const uint32_t f : out.triangles.faceOf)
        out.paletteIndex.push_back(index[f]);
    return true;
}

PaletteKind paletteKind(CMeshO &cm) {
    if (!vcg::tri::HasPerMeshAttribute(cm, kPaletteKindAttributeName))
        return PaletteKind(0);
    auto handle = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<int>(cm, kPaletteKindAttributeName);
    return vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, handle) ? PaletteKind(handle()) : PaletteKind(0);
}

}  // namespace

QString defaultHouseMaskName(const MeshModel &m) { return mapNameFor(m, "_house.png"); }
QString defaultMaterialMapName(const MeshModel &m, const QString &suffix) { return mapNameFor(m, suffix); }

bool FilterVoxelfairPlugin::applyHouseMask(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    if (m.cm.fn == 0)
        return fail("Bake House Colour Mask: the mesh has no faces");
    if (!m.hasDataMask(MeshModel::MM_WEDGTEXCOORD) || m.cm.textures.empty())
        return fail("Bake House Colour Mask: the mesh has no texture atlas; run Voxel Texture Atlas first");
    FaceArrays arrays;
    if (!readFaceArrays(m, arrays))
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
                                         parameters.getInt("dilation"), parameters.getBool("blocks"));
    if (cb)
        cb(80, "Writing the house colour mask");
    const QImage image(mask.grey.data(), mask.width, mask.height, mask.width, QImage::Format_Grayscale8);
    if (!writePng(image, path))
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

bool FilterVoxelfairPlugin::applyMaterialMaps(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    if (m.cm.fn == 0)
        return fail("Bake Material Maps: the mesh has no faces");
    if (!m.hasDataMask(MeshModel::MM_WEDGTEXCOORD) || m.cm.textures.empty())
        return fail("Bake Material Maps: the mesh has no texture atlas; run Voxel Texture Atlas first");
    FaceArrays arrays;
    const VoxMaterialTable *materials = findVoxMaterials(m.cm);
    if (!readFaceArrays(m, arrays) || materials == nullptr || paletteKind(m.cm) != PaletteKind::MagicaVoxel)
        return fail("Bake Material Maps: the mesh has no MagicaVoxel materials per face; import a .vox with "
                    "voxelfair's importer (and bake before duplicating or decimating)");

    const auto pathOf = [&](const char *parameter, const char *suffix) {
        const QString given = parameters.getString(parameter).trimmed();
        return besideMesh(m, given.isEmpty() ? defaultMaterialMapName(m, suffix) : given);
    };
    const QString metalRoughPath = pathOf("metallicRoughnessFile", "_metallic_roughness.png");
    const QString emissivePath = pathOf("emissiveFile", "_emissive.png");
    const QString transmissionPath = pathOf("transmissionFile", "_transmission.png");
    const QString texture = baseColourPath(m, metalRoughPath);
    const QSize size = QImageReader(texture).size();
    if (!size.isValid())
        return fail(QString("Bake Material Maps: could not read the size of the base colour texture %1").arg(texture));
    if (cb)
        cb(10, "Baking the material maps");
    const MaterialMaps maps =
        bakeMaterialMaps(arrays.view(), arrays.paletteIndex.data(), arrays.triangles.faceColours.data(), *materials,
                         size.width(), size.height(), parameters.getInt("dilation"), parameters.getBool("blocks"));
    if (cb)
        cb(80, "Writing the material maps");
    // Stale maps of an earlier bake would be taken for this one's.
    for (const QString &path : {metalRoughPath, emissivePath, transmissionPath})
        QFile::remove(path);
    MaterialMapFiles files;
    if (const MaterialMapFiles *stored = findMaterialMaps(m.cm))
        files = *stored;
    QStringList written;
    const auto save = [&](const std::vector<uint8_t> &pixels, int channels, const QString &path, std::string &name) {
        name.clear();
        if (pixels.empty())
            return true;
        const QImage image(pixels.data(), maps.width, maps.height, maps.width * channels,
                           channels == 1 ? QImage::Format_Grayscale8 : QImage::Format_RGB888);
        if (!writePng(image, path))
            return false;
        name = QFileInfo(path).fileName().toStdString();
        written << QFileInfo(path).fileName();
        return true;
    };
    if (!save(maps.metallicRoughness, 3, metalRoughPath, files.metallicRoughness) ||
        !save(maps.emissive, 3, emissivePath, files.emissive) ||
        !save(maps.transmission, 1, transmissionPath, files.transmission))
        return fail(QString("Bake Material Maps: could not write the maps beside %1").arg(metalRoughPath));
    files.emissiveStrength = maps.emissive.empty() ? 1.0f : maps.emissiveStrength;
    files.ior = maps.transmission.empty() ? 0.0f : maps.ior;
    storeMaterialMaps(files, m.cm);
    report(QString("Bake Material Maps: %1 MATL materials; of %2 faces %3 metal or rough, %4 emissive (strength %5), "
                   "%6 transmissive (ior %7) -> %8 in %9 ms")
               .arg(materials->chunks)
               .arg(arrays.paletteIndex.size())
               .arg(maps.metalRoughFaces)
               .arg(maps.emissiveFaces)
               .arg(double(maps.emissiveStrength), 0, 'g', 3)
               .arg(maps.transmissiveFaces)
               .arg(double(maps.ior), 0, 'g', 3)
               .arg(written.isEmpty() ? QString("no map needed (every voxel is diffuse)") : written.join(", "))
               .arg(timer.elapsed()));
    if (materials->ignoredValues + materials->ignoredChunks > 0)
        report(QString("Bake Material Maps: %1 unreadable MATL values (not numbers, unknown types) and %2 material ids "
                       "outside 1..255 were ignored")
                   .arg(materials->ignoredValues)
                   .arg(materials->ignoredChunks));
    return true;
}
