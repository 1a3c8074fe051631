// The texture filter: section 4.5, greedy charts, packing and a baked diffuse texture (PNG).
#include "filter_voxelfair_plugin.h"
#include "map_files.h"
#include "meshlab_arrays.h"

#include "../io_vxl/scene_to_meshlab.h"

#include "atlas/texture_atlas.h"
#include "base/error.h"
#include "fairing/voxel_size.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>

#include <cmath>

using namespace voxelfair;

namespace {

// The triangles of a MeshLab mesh with their colours, and the atlas unit's view on them.
AtlasMesh atlasMesh(const TriangleArrays &in) {
    AtlasMesh mesh;
    mesh.positions = in.positions.data();
    mesh.vertexCount = in.positions.size();
    mesh.triangles = in.triangles.data();
    mesh.faceCount = in.triangleCount();
    mesh.faceColours = in.faceColours.empty() ? nullptr : in.faceColours.data();
    mesh.vertexColours = in.vertexColours.empty() ? nullptr : in.vertexColours.data();
    return mesh;
}

}  // namespace

QString defaultTextureName(const MeshModel &m) {
    const QString base = QFileInfo(m.fullName()).completeBaseName();
    return (base.isEmpty() ? QString("voxelfair") : base) + "_texture.png";
}

bool FilterVoxelfairPlugin::applyTextureAtlas(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb) {
    QElapsedTimer timer;
    timer.start();
    if (m.cm.fn == 0)
        return fail("Texture Atlas: the mesh has no faces");

    TriangleArrays input;
    TriangleFields fields;
    fields.vertexColours = m.hasDataMask(MeshModel::MM_VERTCOLOR);
    fields.faceColours = m.hasDataMask(MeshModel::MM_FACECOLOR);
    readTriangleArrays(m.cm, fields, input);
    AtlasMesh mesh = atlasMesh(input);

    AtlasOptions options;
    const float angle = parameters.getFloat("chartAngle");
    if (!(angle > 0.0f && angle < 90.0f))
        return fail("Texture Atlas: the chart angle must be between 0 and 90 degrees");
    options.charts.minSeedCosine = std::cos(angle * float(M_PI) / 180.0f);
    options.pack.mode = parameters.getEnum("packing") == 1 ? PackMode::Paper : PackMode::Tight;
    float voxelSize = parameters.getFloat("voxelSize");
    std::vector<float> faceScale;
    QString voxelNote = "given";  // where the voxel size came from, for the log
    if (voxelSize <= 0.0f) {
        // Each part's voxels get the same texels: parts may be scaled differently (an HVA frame
        // can shrink a section to 1%). The density is that of the largest part, and the others'
        // faces are scaled by their voxel size relative to it.
        const PolygonArrays arrays = polygonArrays(m.cm);
        const std::vector<PartArrays> parts = splitByPart(arrays, m.cm);
        const PartArrays *largest = nullptr;
        std::vector<float> partVoxel(parts.size());
        size_t fromImport = 0;  // parts whose size is the importer's
        for (size_t k = 0; k < parts.size(); ++k) {
            const PartArrays &part = parts[k];
            if (largest == nullptr || part.polygonCount() > largest->polygonCount())
                largest = &part;
            // The importer's measure where the mesh still has it: a faired thin part's
            // cross-sections would outnumber its voxel edges (fairing/voxel_size.h).
            const float imported = importedVoxelSize(m.cm, part.part);
            partVoxel[k] = detectVoxelSize({part.positions.data(), part.positions.size(), part.polygonOffsets.data(),
                                            part.polygonIndices.data(), part.polygonCount()},
                                           imported);
            fromImport += imported > 0.0f && partVoxel[k] == imported;
        }
        if (largest) {
            voxelSize = partVoxel[size_t(largest - parts.data())];
        } else {  // one part (or none recorded)
            const float imported = importedVoxelSize(m.cm, commonPart(m.cm));
            voxelSize = detectVoxelSize({arrays.positions.data(), arrays.positions.size(), arrays.polygonOffsets.data(),
                                         arrays.polygonIndices.data(), arrays.polygonCount()},
                                        imported);
            fromImport = imported > 0.0f && voxelSize == imported;
        }
        if (!(voxelSize > 0.0f) || !std::isfinite(voxelSize))
            voxelSize = 1.0f;
        voxelNote = fromImport == 0 ? QString("detected")
                    : fromImport == std::max<size_t>(1, parts.size())
                        ? QString("from the import")
                        : QString("from the import for %1 of %2 parts, detected for the others")
                              .arg(fromImport)
                              .arg(parts.size());
        // Part number -> texel scale (part numbers are small, as splitByPart assumes).
        std::vector<float> scaleOfPart;
        for (size_t k = 0; k < parts.size(); ++k) {
            const size_t number = size_t(parts[k].part);
            if (number >= scaleOfPart.size())
                scaleOfPart.resize(number + 1, 1.0f);
            const float scale = voxelSize / partVoxel[k];
            if (partVoxel[k] > 0.0f && std::isfinite(scale) && scale > 0.0f)
                scaleOfPart[number] = scale;
        }
        const std::vector<int> facePart = parts.empty() ? std::vector<int>() : facePartNumbers(m.cm);
        bool scaled = false;
        if (!facePart.empty()) {
            faceScale.assign(input.faceOf.size(), 1.0f);
            for (size_t i = 0; i < input.faceOf.size(); ++i) {
                const int part = facePart[input.faceOf[i]];
                if (part >= 0 && size_t(part) < scaleOfPart.size())
                    faceScale[i] = scaleOfPart[size_t(part)];
                scaled = scaled || faceScale[i] != 1.0f;
            }
        }
        if (scaled)
            mesh.faceTexelScale = faceScale.data();
    }
    const float texelsPerVoxel = parameters.getFloat("texelsPerVoxel");
    if (!(texelsPerVoxel > 0.0f))
        return fail("Texture Atlas: texels per voxel must be positive");
    options.pack.texelsPerUnit = texelsPerVoxel / voxelSize;
    options.pack.maxTextureSize = parameters.getInt("maxTextureSize");
    const int textureSize = parameters.getInt("textureSize");
    if (textureSize < 0 || textureSize > 16384)
        return fail("Texture Atlas: the texture size must be 0 (from the density) to 16384");
    options.pack.textureSize = textureSize;
    options.pack.fillTexture = parameters.getBool("fillTexture");
    options.pack.allowWide = parameters.getBool("wideTextures");
    options.pack.gutter = parameters.getInt("gutter");
    options.bake.source = parameters.getEnum("colours") == 1 ? BakeSource::VertexColours : BakeSource::FaceColours;

    if (cb)
        cb(10, "Building the texture atlas");
    TextureAtlas atlas;
    try {
        atlas = buildTextureAtlas(mesh, options);
    } catch (const Error &e) {
        return fail(QString("Texture Atlas: %1").arg(e.what()));
    }
    if (atlas.charts.faceCount() == 0)
        return fail("Texture Atlas: the mesh has no faces");

    // Write the texture before touching the mesh, so a failure leaves the mesh as it was.
    if (cb)
        cb(80, "Writing the texture");
    const QString path = besideMesh(m, parameters.getString("textureFile").trimmed());
    if (QFileInfo(path).fileName().isEmpty())
        return fail("Texture Atlas: the texture file name is empty");
    const QImage image(atlas.texture.rgba.data(), atlas.texture.width, atlas.texture.height, atlas.texture.width * 4,
                       QImage::Format_RGBA8888);
    if (!writePng(image, path))
        return fail(QString("Texture Atlas: could not write the texture to %1").arg(path));

    m.updateDataMask(MeshModel::MM_WEDGTEXCOORD);
    for (size_t i = 0; i < input.faceOf.size(); ++i) {
        CFaceO &face = m.cm.face[input.faceOf[i]];
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 uv = atlas.layout.wedgeUv[3 * i + size_t(k)];
            face.WT(k).U() = uv.x;
            face.WT(k).V() = uv.y;
            face.WT(k).N() = 0;
        }
    }
    // Exporters write the name as stored: keep it relative so mesh and texture travel together
    // (save the mesh in the texture's folder).
    m.cm.textures.clear();
    m.cm.textures.push_back(QFileInfo(path).fileName().toStdString());

    report(QString("Texture Atlas: %1 charts, %2 texture at %3 texels per voxel%4 (%5 packing), %6 baked%7 -> %8 "
                   "in %9 ms")
               .arg(atlas.charts.chartCount())
               .arg(QString("%1 x %2").arg(atlas.layout.width).arg(atlas.layout.height))
               .arg(atlas.layout.texelsPerUnit * double(voxelSize), 0, 'g', 3)
               .arg(QString(" (voxel size %1, %2)%3")
                        .arg(double(voxelSize), 0, 'g', 4)
                        .arg(voxelNote)
                        .arg(atlas.layout.densityReduced ? " (reduced to fit the maximum size)" : ""))
               .arg(toString(atlas.layout.mode))
               .arg(toString(atlas.texture.source))
               .arg(atlas.texture.note.empty() ? QString()
                                               : QString(" (%1)").arg(QString::fromStdString(atlas.texture.note)))
               .arg(path)
               .arg(timer.elapsed()));
    if (atlas.charts.separatedFaces > 0)
        report(
            QString("Texture Atlas: %1 faces too thin for the texel grid got charts of their own, so every face keeps "
                    "its voxel colour")
                .arg(atlas.charts.separatedFaces));
    if (atlas.crispDensity > double(options.pack.texelsPerUnit) * 1.001)
        report(QString("Texture Atlas: %1 texels per voxel would leave too many faces too thin for their voxel colour: "
                       "raised to at least %2")
                   .arg(double(texelsPerVoxel), 0, 'g', 3)
                   .arg(atlas.crispDensity * double(voxelSize), 0, 'g', 3));
    if (atlas.texture.source == BakeSource::FaceColours && !atlas.crispGuaranteed)
        report(QString("Texture Atlas: warning: at %1 texels per voxel %2 of %3 faces are too thin to be sure of "
                       "their voxel colour in every texel, and the %4 x %5 texture has no room to separate them; "
                       "give a larger Texture size, or 0 to size it from the density")
                   .arg(atlas.layout.texelsPerUnit * double(voxelSize), 0, 'g', 3)
                   .arg(atlas.crowded.crowdedFaces)
                   .arg(atlas.charts.faceCount())
                   .arg(atlas.layout.width)
                   .arg(atlas.layout.height));
    if (atlas.charts.nonManifoldEdges > 0 || atlas.charts.degenerateFaces > 0)
        report(
            QString("Texture Atlas: %1 non-manifold edges used as chart borders, %2 degenerate faces given their own "
                    "texel")
                .arg(atlas.charts.nonManifoldEdges)
                .arg(atlas.charts.degenerateFaces));
    return true;
}
