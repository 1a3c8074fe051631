#include "io_gltf_plugin.h"

#include "scene_to_meshlab.h"

#include "export/glb_writer.h"
#include "maps/normal_bake.h"

#include <QBuffer>
#include <QElapsedTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <cmath>
#include <cstdio>
#include <exception>

using namespace voxelfair;

namespace {

std::string local(const QString &s) { return s.toLocal8Bit().toStdString(); }

QString env(const char *name) { return QString::fromLocal8Bit(qgetenv(name)).trimmed(); }

float metresPerVoxelFromEnv() {
    bool ok = false;
    const float value = env("VOXELFAIR_METRES_PER_VOXEL").toFloat(&ok);
    return ok && value > 0.0f && std::isfinite(value) ? value : GlbOptions{}.metresPerVoxel;
}

bool linearFromEnv() { return env("VOXELFAIR_TEXTURE_FILTER").compare("linear", Qt::CaseInsensitive) == 0; }

// sRGB face colours to glTF's linear COLOR_0.
float linearFromSrgb(unsigned char c) {
    const float v = float(c) / 255.0f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// The texture's file: as stored when absolute; else beside the .glb, beside the mesh's own file,
// or in the working folder (the atlas filter stores the bare name and the wrapper saves beside it).
QString findTexture(const QString &name, const QString &glbPath, const MeshModel &m) {
    if (QFileInfo(name).isAbsolute())
        return QFileInfo::exists(name) ? name : QString();
    for (const QString &dir :
         {QFileInfo(glbPath).absolutePath(), QFileInfo(m.fullName()).absolutePath(), QDir::currentPath()}) {
        const QString path = QDir(dir).filePath(name);
        if (QFileInfo::exists(path))
            return path;
    }
    return QString();
}

// PNG bytes as they are; any other image Qt reads is encoded as PNG.
std::vector<uint8_t> pngBytes(const QString &path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QByteArray data = file.readAll();
    if (data.startsWith("\x89PNG\r\n\x1a\n"))
        return std::vector<uint8_t>(data.begin(), data.end());
    QImage image;
    if (!image.loadFromData(data))
        return {};
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return std::vector<uint8_t>(png.begin(), png.end());
}

}  // namespace

QList<MeshIOInterface::Format> IoGltfPlugin::exportFormats() const {
    return {Format("glTF 2.0 binary (Blender, Godot, Unity, three.js)", tr("GLB"))};
}

void IoGltfPlugin::GetExportMaskCapability(QString &, int &capability, int &defaultBits) const {
    using vcg::tri::io::Mask;
    capability = Mask::IOM_VERTNORMAL | Mask::IOM_WEDGTEXCOORD | Mask::IOM_VERTTEXCOORD | Mask::IOM_FACECOLOR;
    defaultBits = capability;
}

void IoGltfPlugin::initSaveParameter(const QString &, MeshModel &, RichParameterList &parameters) {
    parameters.addParam(RichFloat("metresPerVoxel", metresPerVoxelFromEnv(), "Metres per voxel",
                                  "The size of one voxel (one unit of the imported model) in metres; glTF's unit is "
                                  "the metre. 0.1: a 30-voxel tank is 3 m long."));
    parameters.addParam(RichEnum("textureFilter", linearFromEnv() ? 1 : 0,
                                 QStringList() << "Nearest"
                                               << "Linear",
                                 "Texture filter",
                                 "Nearest keeps pixel art crisp (magFilter NEAREST, mipmapped minification); "
                                 "Linear blurs it smoothly."));
}

void IoGltfPlugin::report(const QString &message) {
    Log(local(message));
    std::fprintf(stderr, "io_gltf: %s\n", local(message).c_str());
}

bool IoGltfPlugin::fail(const QString &message) {
    errorMessage = message;
    Log(GLLogStream::WARNING, local(message));
    std::fprintf(stderr, "io_gltf: %s\n", local(message).c_str());
    std::fflush(stderr);
    return false;
}

bool IoGltfPlugin::save(const QString &, const QString &fileName, MeshModel &m, const int mask,
                        const RichParameterList &parameters, vcg::CallBackPos *cb, QWidget *) {
    using vcg::tri::io::Mask;
    try {
        QElapsedTimer timer;
        timer.start();
        CMeshO &cm = m.cm;
        if (cm.fn == 0)
            return fail(fileName + ": the mesh has no faces to export");
        GlbOptions options;
        options.metresPerVoxel =
            parameters.hasParameter("metresPerVoxel") ? parameters.getFloat("metresPerVoxel") : metresPerVoxelFromEnv();
        options.textureFilter =
            (parameters.hasParameter("textureFilter") ? parameters.getEnum("textureFilter") == 1 : linearFromEnv())
                ? TextureFilter::Linear
                : TextureFilter::Nearest;
        options.name = local(QFileInfo(fileName).completeBaseName());
        if (!(options.metresPerVoxel > 0.0f))
            return fail(fileName + ": metres per voxel must be positive");
        if (cb)
            cb(0, "Converting the mesh");

        GlbMesh mesh;
        std::vector<uint32_t> index(cm.vert.size(), 0);
        for (size_t i = 0; i < cm.vert.size(); ++i) {
            if (cm.vert[i].IsD())
                continue;
            index[i] = uint32_t(mesh.positions.size());
            const auto &p = cm.vert[i].P();
            mesh.positions.emplace_back(p[0], p[1], p[2]);
        }
        {  // MeshLab's per-vertex normals (the pipeline's smoothed ones) when every one is usable
            bool goodNormals = true;
            mesh.normals.reserve(mesh.positions.size());
            for (const CVertexO &v : cm.vert) {
                if (v.IsD())
                    continue;
                const glm::vec3 n(v.N()[0], v.N()[1], v.N()[2]);
                const float length = glm::length(n);
                if (!(length > 0.5f && std::isfinite(length)))
                    goodNormals = false;
                mesh.normals.push_back(n);
            }
            if (!goodNormals)
                mesh.normals.clear();  // the writer computes them from the faces
        }

        const ExportScene *scene = findExportScene(cm);
        const bool hasParts = scene != nullptr && vcg::tri::HasPerFaceAttribute(cm, kPartAttributeName);
        CMeshO::PerFaceAttributeHandle<int> part;
        if (hasParts)
            part = vcg::tri::Allocator<CMeshO>::FindPerFaceAttribute<int>(cm, kPartAttributeName);

        QString texturePath;
        if (!cm.textures.empty())
            texturePath = findTexture(QString::fromStdString(cm.textures[0]), fileName, m);
        const bool wedgeUv = !texturePath.isEmpty() && cm.face.IsWedgeTexCoordEnabled();
        const bool vertexUv = !texturePath.isEmpty() && !wedgeUv && cm.vert.IsTexCoordEnabled();
        const bool colours = texturePath.isEmpty() && cm.face.IsColorEnabled();
        size_t unplaced = 0;
        for (const CFaceO &f : cm.face) {
            if (f.IsD())
                continue;
            for (int k = 0; k < 3; ++k) {
                mesh.triangles.push_back(index[size_t(vcg::tri::Index(cm, f.cV(k)))]);
                if (wedgeUv)
                    mesh.cornerUvs.emplace_back(f.cWT(k).U(), f.cWT(k).V());
                if (vertexUv)
                    mesh.cornerUvs.emplace_back(f.cV(k)->cT().U(), f.cV(k)->cT().V());
                if (colours) {
                    const vcg::Color4b c = f.cC();
                    mesh.cornerColours.emplace_back(linearFromSrgb(c[0]), linearFromSrgb(c[1]), linearFromSrgb(c[2]),
                                                    1.0f);
                }
            }
            if (hasParts) {
                int node = scene->nodeOfPart(part[&f]);
                if (node < 0)
                    node = 0, ++unplaced;
                mesh.triangleNodes.push_back(node);
            }
        }

        GlbTexture texture;
        if (!texturePath.isEmpty()) {
            texture.png = pngBytes(texturePath);
            texture.name = local(QFileInfo(texturePath).completeBaseName());
            if (texture.png.empty())
                return fail(fileName + ": could not read the texture " + texturePath);
        } else if (!cm.textures.empty()) {
            report(QString("%1: texture %2 not found; exported without it")
                       .arg(fileName, QString::fromStdString(cm.textures[0])));
        }

        // The normal map the Bake Normal Map filter wrote for this mesh, with the MikkTSpace
        // tangents it was baked against (same positions, normals and UVs).
        QString normalMapPath;
        if (vcg::tri::HasPerMeshAttribute(cm, "voxelfair_normal_map") && wedgeUv && !mesh.normals.empty()) {
            auto handle = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<std::string>(cm, "voxelfair_normal_map");
            const QString name =
                vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, handle) ? QString::fromStdString(handle()) : QString();
            if (!name.isEmpty())
                normalMapPath = findTexture(name, fileName, m);
            if (!normalMapPath.isEmpty()) {
                options.normalMap.png = pngBytes(normalMapPath);
                options.normalMap.name = local(QFileInfo(normalMapPath).completeBaseName());
                NormalBakeMesh view;
                view.positions = mesh.positions.data();
                view.normals = mesh.normals.data();
                view.vertexCount = mesh.positions.size();
                view.triangles = mesh.triangles.data();
                view.wedgeUv = mesh.cornerUvs.data();
                view.faceCount = mesh.triangles.size() / 3;
                if (!options.normalMap.png.empty())
                    mesh.cornerTangents = targetTangents(view);
            } else {
                report(QString("%1: normal map %2 not found; exported without it").arg(fileName, name));
            }
        }

        // The maps the material filters baked in the base colour's layout (house colour mask, PBR maps).
        QStringList embedded;
        if (const MaterialMapFiles *maps = findMaterialMaps(cm); maps != nullptr && wedgeUv && !texture.png.empty()) {
            const auto load = [&](const std::string &file, GlbTexture &into, const char *what) {
                if (file.empty())
                    return;
                const QString name = QString::fromStdString(file);
                const QString path = findTexture(name, fileName, m);
                if (!path.isEmpty()) {
                    into.png = pngBytes(path);
                    into.name = local(QFileInfo(path).completeBaseName());
                }
                if (into.png.empty())
                    report(QString("%1: %2 %3 not found; exported without it").arg(fileName, what, name));
                else
                    embedded << QString("%1 %2").arg(what, QFileInfo(path).fileName());
            };
            load(maps->houseMask, options.houseMask, "house colour mask");
            load(maps->metallicRoughness, options.metallicRoughness, "metallic-roughness map");
            load(maps->emissive, options.emissive, "emissive map");
            load(maps->transmission, options.transmission, "transmission map");
            options.emissiveStrength = maps->emissiveStrength;
            options.ior = maps->ior;
        }

        if (cb)
            cb(50, "Writing glTF");
        const std::vector<uint8_t> bytes =
            writeGlb(mesh, hasParts ? *scene : ExportScene{}, texture.png.empty() ? nullptr : &texture, options);
        QFile out(fileName);
        if (!out.open(QIODevice::WriteOnly) ||
            out.write(reinterpret_cast<const char *>(bytes.data()), qint64(bytes.size())) != qint64(bytes.size()))
            return fail(fileName + ": could not write the file");
        out.close();
        report(QString("%1: %2 triangles, %3 nodes%4%5, %6 m per voxel, %7 texture filter, %8 bytes in %9 ms")
                   .arg(QFileInfo(fileName).fileName())
                   .arg(mesh.triangles.size() / 3)
                   .arg(hasParts ? scene->nodes.size() : 1)
                   .arg(hasParts && scene->frameCount() > 1 ? QString(", %1 animation frames").arg(scene->frameCount())
                                                            : QString())
                   .arg(texture.png.empty() ? QString(colours ? ", face colours" : "") : QString(", texture embedded"))
                   .arg(double(options.metresPerVoxel))
                   .arg(options.textureFilter == TextureFilter::Nearest ? "nearest" : "linear")
                   .arg(bytes.size())
                   .arg(timer.elapsed()));
        if (!mesh.cornerTangents.empty())
            report(QString("%1: normal map %2 embedded (normalTexture, MikkTSpace TANGENT)")
                       .arg(QFileInfo(fileName).fileName(), QFileInfo(normalMapPath).fileName()));
        if (!embedded.isEmpty())
            report(QString("%1: embedded %2").arg(QFileInfo(fileName).fileName(), embedded.join(", ")));
        if (unplaced > 0)
            report(QString("%1 faces had no part node and went to the first node").arg(unplaced));
        (void)mask;
        if (cb)
            cb(100, "Done");
        return true;
    } catch (const std::exception &e) {
        return fail(fileName + ": " + QString::fromLocal8Bit(e.what()));
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(IoGltfPlugin)
