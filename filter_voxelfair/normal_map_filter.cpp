// The normal map filter: the shading of a source layer (the undecimated faired mesh) baked as a
// tangent-space normal map into the atlas of the current layer (its decimation, which kept the
// atlas' UVs) by libvoxelfair/maps (normal_bake.h, MikkTSpace tangents), written as a PNG.
#include "filter_voxelfair_plugin.h"
#include "map_files.h"
#include "meshlab_arrays.h"

#include "maps/normal_bake.h"

#include "../io_vxl/scene_to_meshlab.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include <algorithm>
#include <cmath>

using namespace voxelfair;

namespace {

// The layer's triangles with vertex normals and the atlas' UVs, and the bake's view on them.
NormalBakeMesh readBakeMesh(const CMeshO &cm, TriangleArrays &arrays) {
    TriangleFields fields;
    fields.normals = fields.wedgeUv = true;
    readTriangleArrays(cm, fields, arrays);
    return normalBakeMesh(arrays.positions, arrays.normals, arrays.triangles, arrays.wedgeUv);
}

// MeshLab's "Duplicate Current layer" copies faces and their quality but not user attributes: the
// decimated copy loses io_vxl's parts (the node tree per mesh, the part per face) that io_gltf
// writes one node per part from. Restored from the source layer it was duplicated from, and
// from the face quality, where io_vxl writes each face's part too.
bool restoreParts(MeshModel &target, MeshModel &source) {
    const ExportScene *scene = findExportScene(source.cm);
    if (scene == nullptr || findExportScene(target.cm) != nullptr)
        return false;
    if (!target.hasDataMask(MeshModel::MM_FACEQUALITY))
        return false;
    storeExportScene(*scene, target.cm);
    if (const MaterialMapFiles *maps = findMaterialMaps(source.cm))  // the maps baked in the same layout
        storeMaterialMaps(*maps, target.cm);
    if (!vcg::tri::HasPerFaceAttribute(target.cm, kPartAttributeName)) {
        auto part = vcg::tri::Allocator<CMeshO>::GetPerFaceAttribute<int>(target.cm, kPartAttributeName);
        for (CFaceO &f : target.cm.face)
            if (!f.IsD())
                part[f] = int(std::lround(f.Q()));
    }
    return true;
}

}  // namespace

QString defaultNormalMapName(const MeshModel &m) { return mapNameFor(m, "_normal.png"); }

bool FilterVoxelfairPlugin::applyNormalMap(MeshDocument &md, const RichParameterList &parameters,
                                           vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    MeshModel &target = *md.mm();
    MeshModel *source = parameters.getMesh("sourceMesh");
    if (source == nullptr)
        return fail("Bake Normal Map: choose the source layer (the undecimated faired mesh)");
    if (source == &target)
        return fail("Bake Normal Map: the source layer is the current layer; duplicate the faired layer before "
                    "decimating and bake from the copy that was not decimated");
    if (target.cm.fn == 0 || source->cm.fn == 0)
        return fail("Bake Normal Map: the source and the current layer need faces");
    if (!target.hasDataMask(MeshModel::MM_WEDGTEXCOORD) || !source->hasDataMask(MeshModel::MM_WEDGTEXCOORD))
        return fail("Bake Normal Map: both layers need the texture atlas' coordinates (run Voxel Texture Atlas before "
                    "duplicating and decimating)");

    const QString path = besideMesh(target, parameters.getString("normalFile").trimmed().isEmpty()
                                                ? defaultNormalMapName(target)
                                                : parameters.getString("normalFile").trimmed());
    int width = parameters.getInt("textureSize"), height = width;
    QString sizeFrom = "given";
    if (width <= 0) {
        // The base colour's size: its PNG beside the normal map (where the pipeline writes both),
        // else beside the mesh. UVs are normalised per axis, so a wide (2:1) atlas gets a 2:1 map
        // with the base colour's texel density.
        if (target.cm.textures.empty())
            return fail("Bake Normal Map: the current layer has no texture; give the texture size");
        const QString texture = baseColourPath(target, path);
        const QSize imageSize = QImageReader(texture).size();
        if (!imageSize.isValid())
            return fail(
                QString("Bake Normal Map: could not read the size of the base colour texture %1; give the texture size")
                    .arg(texture));
        width = imageSize.width();
        height = imageSize.height();
        sizeFrom = QFileInfo(texture).fileName();
    }

    TriangleArrays lowArrays, highArrays;
    const NormalBakeMesh low = readBakeMesh(target.cm, lowArrays), high = readBakeMesh(source->cm, highArrays);
    NormalBakeOptions options;
    options.width = width;
    options.height = height;
    options.level = parameters.getEnum("level");
    // A given texture size is the map's own; else small atlases get a finer map (normal_bake.h).
    options.minSide = sizeFrom == "given" ? 0 : std::max(0, parameters.getInt("minSide"));
    options.dilation = parameters.getInt("dilation");
    options.blocks = parameters.getBool("blocks");
    if (cb)
        cb(10, "Baking the normal map");
    NormalMap map;
    try {
        map = bakeNormalMap(high, low, options);
    } catch (const Error &e) {
        return fail(QString("Bake Normal Map: %1").arg(e.what()));
    }

    if (cb)
        cb(80, "Writing the normal map");
    const QImage image(map.rgba.data(), map.width, map.height, map.width * 4, QImage::Format_RGBA8888);
    if (!writePng(image.convertToFormat(QImage::Format_RGB888), path))
        return fail(QString("Bake Normal Map: could not write the normal map to %1").arg(path));
    // Exporters that know it (the glTF writer) find the map's file name here.
    auto attribute = vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<std::string>(target.cm, "voxelfair_normal_map");
    attribute() = QFileInfo(path).fileName().toStdString();

    if (restoreParts(target, *source))
        report(
            "Bake Normal Map: the parts of the source layer (nodes, each face's part) restored on the current layer");
    report(QString("Bake Normal Map: %1 texels from layer '%2' (%3 faces) onto %4 faces, %5 (size from %6), "
                   "level %7 (x%11), MikkTSpace tangents, %8 gutter rings -> %9 in %10 ms")
               .arg(map.texelsBaked)
               .arg(source->label())
               .arg(source->cm.fn)
               .arg(target.cm.fn)
               .arg(QString("%1 x %2").arg(map.width).arg(map.height))
               .arg(sizeFrom)
               .arg(options.level)
               .arg(options.dilation)
               .arg(path)
               .arg(timer.elapsed())
               .arg(normalMapScale(options)));
    if (map.texelsWithoutSource > 0)
        report(QString("Bake Normal Map: %1 texels had no source face near their UV and stay flat")
                   .arg(map.texelsWithoutSource));
    return true;
}
