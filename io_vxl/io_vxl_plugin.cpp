#include "io_vxl_plugin.h"

#include "import_settings.h"
#include "scene_to_meshlab.h"

#include "formats/file_bytes.h"
#include "formats/format_error.h"
#include "formats/hva.h"
#include "formats/vxl.h"
#include "scene/vxl_scene.h"

#include <QDir>
#include <QFileInfo>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

using namespace voxelfair;

namespace {

std::string local(const QString &s) { return s.toLocal8Bit().toStdString(); }

// meshlabserver changes into the file's folder before calling open() but passes the path as the
// user wrote it, so a relative path with folders no longer resolves: fall back to the bare name.
QString resolveInputPath(const QString &fileName) {
    if (QFileInfo::exists(fileName)) return QFileInfo(fileName).absoluteFilePath();
    const QString bare = QFileInfo(fileName).fileName();
    if (QFileInfo::exists(bare)) return QFileInfo(bare).absoluteFilePath();
    return fileName;
}

QString companionPath(const QString &vxlPath, const QString &extension) {
    const QFileInfo info(vxlPath);
    const QDir dir = info.absoluteDir();
    // Game files are named in any case (3TNK.VXL + 3tnk.hva): match the extension case-insensitively.
    for (const QString &candidate : {extension.toLower(), extension.toUpper()}) {
        const QString path = dir.filePath(info.completeBaseName() + "." + candidate);
        if (QFileInfo::exists(path)) return path;
    }
    return QString();
}

}  // namespace

QList<MeshIOInterface::Format> IoVxlPlugin::importFormats() const {
    return {Format("Westwood VXL voxel model (C&C Tiberian Sun, Red Alert 2)", tr("VXL"))};
}

QList<MeshIOInterface::Format> IoVxlPlugin::exportFormats() const { return {}; }

void IoVxlPlugin::GetExportMaskCapability(QString &, int &capability, int &defaultBits) const {
    capability = defaultBits = 0;
}

void IoVxlPlugin::initPreOpenParameter(const QString &, const QString &fileName, RichParameterList &parameters) {
    // List the sections by name when the file can be read; a broken file is reported by open().
    QStringList sectionNames;
    try {
        const std::vector<uint8_t> bytes = readFileBytes(local(resolveInputPath(fileName)));
        const VxlModel model = readVxl(bytes.data(), bytes.size());
        for (const VxlSection &s : model.sections) sectionNames << QString::fromLatin1(s.name.c_str());
    } catch (...) {
    }
    declareImportParameters(parameters, sectionNames);
}

void IoVxlPlugin::report(const QString &message) {
    Log(local(message));
    std::fprintf(stderr, "io_vxl: %s\n", local(message).c_str());
}

bool IoVxlPlugin::fail(const QString &message) {
    errorMessage = message;
    Log(GLLogStream::WARNING, local(message));
    std::fprintf(stderr, "io_vxl: %s\n", local(message).c_str());
    std::fflush(stderr);
    return false;
}

bool IoVxlPlugin::open(const QString &, const QString &fileName, MeshModel &m, int &mask,
                       const RichParameterList &parameters, vcg::CallBackPos *cb, QWidget *) {
    const QString path = resolveInputPath(fileName);
    QString current = path;  // the file a FormatError is about
    try {
        const ImportSettings settings = readImportSettings(parameters);
        if (cb) cb(0, "Reading VXL");
        const std::vector<uint8_t> bytes = readFileBytes(local(path));
        const VxlModel model = readVxl(bytes.data(), bytes.size());

        VxlSceneOptions options;
        options.section = settings.section;
        options.frame = settings.frame;
        options.applyTransforms = settings.applyTransforms;
        options.houseColour = settings.houseColour;

        Palette external;
        if (!settings.paletteFile.isEmpty()) {
            current = settings.paletteFile;
            const std::vector<uint8_t> palBytes = readFileBytes(local(current));
            external = readPal(palBytes.data(), palBytes.size());
            options.externalPalette = &external;
        }

        std::unique_ptr<HvaAnimation> hva;
        const QString hvaPath = companionPath(path, "hva");
        if (settings.applyTransforms && !hvaPath.isEmpty()) {
            current = hvaPath;
            const std::vector<uint8_t> hvaBytes = readFileBytes(local(current));
            hva = std::make_unique<HvaAnimation>(readHva(hvaBytes.data(), hvaBytes.size()));
        }
        current = hva ? hvaPath : path;
        const VoxelScene scene = vxlScene(model, hva.get(), options);
        current = path;

        size_t voxels = 0;
        for (const PlacedVolume &part : scene.parts) voxels += part.volume->voxelCount();
        if (voxels == 0)
            return fail(QString("%1: no voxels to import (%2)")
                            .arg(path, settings.section < 0 ? QString("every section is empty")
                                                            : QString("section %1 is empty").arg(settings.section)));

        if (cb) cb(30, "Extracting the voxel surface");
        const SceneSurface surface = extractSceneSurface(scene);
        if (cb) cb(80, "Building the mesh");
        mask |= sceneImportMask();
        m.Enable(mask);
        sceneToMeshLab(surface, m);

        const PaletteChoice palette = chooseVxlPalette(model, options);
        const QString placement = !settings.applyTransforms ? QString("voxel space")
                                  : hva ? QString("HVA frame %1").arg(settings.frame)
                                        : QString("section matrices (no .hva found)");
        report(QString("%1: %2 of %3 sections, %4 voxels -> %5 quads, %6 vertices; palette: %7%8; placement: %9")
                   .arg(QFileInfo(path).fileName())
                   .arg(scene.parts.size())
                   .arg(model.sections.size())
                   .arg(voxels)
                   .arg(surface.quadCount())
                   .arg(surface.positions.size())
                   .arg(settings.paletteFile.isEmpty() ? QString::fromStdString(palette.source) : settings.paletteFile)
                   .arg(settings.houseColour ? ", house colour remapped" : "")
                   .arg(placement));
        report(QString("manifold surface: %1 non-manifold edges and %2 non-manifold vertices split; "
                       "%3 enclosed cavity voxels filled")
                   .arg(surface.stats.nonManifoldEdgesSplit)
                   .arg(surface.stats.nonManifoldVerticesSplit)
                   .arg(surface.stats.cavityVoxelsFilled));
        size_t clamped = 0;
        for (const VxlSection &s : model.sections) clamped += s.clampedNormals;
        if (clamped > 0) report(QString("%1 voxel normal indices were past the normal table and were clamped").arg(clamped));
        if (cb) cb(100, "Done");
        return true;
    } catch (const FormatError &e) {
        // Readers' messages say what and where; the file's name comes first.
        const QString what = QString::fromLocal8Bit(e.what());
        return fail(what.startsWith(current) ? what : current + ": " + what);
    } catch (const std::bad_alloc &) {
        return fail(current + ": not enough memory to import this model");
    } catch (const std::exception &e) {
        return fail(current + ": " + QString::fromLocal8Bit(e.what()));
    } catch (...) {
        return fail(current + ": unexpected error while importing");
    }
}

bool IoVxlPlugin::save(const QString &, const QString &, MeshModel &, const int, const RichParameterList &,
                       vcg::CallBackPos *, QWidget *) {
    errorMessage = "VXL export is not supported";
    return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(IoVxlPlugin)
