#include "io_vxl_plugin.h"

#include "import_settings.h"
#include "scene_to_meshlab.h"

#include "formats/file_bytes.h"
#include "formats/format_error.h"
#include "formats/hva.h"
#include "formats/vox.h"
#include "formats/vxl.h"
#include "scene/unit_scene.h"
#include "scene/vox_export_nodes.h"
#include "scene/vox_scene.h"
#include "scene/vxl_scene.h"

#include <QDir>
#include <QFileInfo>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

using namespace voxelfair;

namespace {

std::string local(const QString &s) { return s.toLocal8Bit().toStdString(); }

bool isVox(const QString &format) { return format.compare("vox", Qt::CaseInsensitive) == 0; }

// meshlabserver changes into the file's folder before calling open() but passes the path as the
// user wrote it, so a relative path with folders no longer resolves: fall back to the bare name.
QString resolveInputPath(const QString &fileName) {
    if (QFileInfo::exists(fileName))
        return QFileInfo(fileName).absoluteFilePath();
    const QString bare = QFileInfo(fileName).fileName();
    if (QFileInfo::exists(bare))
        return QFileInfo(bare).absoluteFilePath();
    return fileName;
}

// The .hva beside a .vxl; game files come in any case (3TNK.VXL + 3tnk.hva).
QString companionPath(const QString &vxlPath, const QString &extension) {
    const QFileInfo info(vxlPath);
    for (const QString &candidate : {extension.toLower(), extension.toUpper()}) {
        const QString path = info.absoluteDir().filePath(info.completeBaseName() + "." + candidate);
        if (QFileInfo::exists(path))
            return path;
    }
    return QString();
}

std::vector<uint8_t> readBytes(const QString &path) { return readFileBytes(local(path)); }

}  // namespace

QList<MeshIOInterface::Format> IoVxlPlugin::importFormats() const {
    return {Format("Westwood VXL voxel model (C&C Tiberian Sun, Red Alert 2)", tr("VXL")),
            Format("MagicaVoxel VOX voxel model", tr("VOX"))};
}

QList<MeshIOInterface::Format> IoVxlPlugin::exportFormats() const { return {}; }

void IoVxlPlugin::GetExportMaskCapability(QString &, int &capability, int &defaultBits) const {
    capability = defaultBits = 0;
}

void IoVxlPlugin::initPreOpenParameter(const QString &format, const QString &fileName, RichParameterList &parameters) {
    // Read the file for the dialog's choices (sections, frames); a broken file is reported by open().
    const QString path = resolveInputPath(fileName);
    if (isVox(format)) {
        int frames = 0;
        try {
            const std::vector<uint8_t> bytes = readBytes(path);
            frames = readVox(bytes.data(), bytes.size()).frameCount;
        } catch (...) {
        }
        declareVoxImportParameters(parameters, frames);
        return;
    }
    QStringList sectionNames;
    try {
        const std::vector<uint8_t> bytes = readBytes(path);
        for (const VxlSection &s : readVxl(bytes.data(), bytes.size()).sections)
            sectionNames << QString::fromLatin1(s.name.c_str());
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

bool IoVxlPlugin::open(const QString &format, const QString &fileName, MeshModel &m, int &mask,
                       const RichParameterList &parameters, vcg::CallBackPos *cb, QWidget *) {
    const QString path = resolveInputPath(fileName);
    QString current = path;  // the file an error is about
    // Nothing may escape into MeshLab: every failure becomes the importer's error.
    try {
        const ImportSettings settings = readImportSettings(parameters);
        if (isVox(format))
            openVox(path, settings, m, mask, cb);
        else
            openVxl(path, settings, m, mask, cb, current);
        if (cb)
            cb(100, "Done");
        return true;
    } catch (const FormatError &e) {
        // Readers say what and where; the file's name comes first.
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

namespace {

// NAMEtur.vxl / NAMEbarl.vxl beside the body, whatever their case (3TNK.VXL + 3tnktur.vxl).
QString findSibling(const QString &bodyPath, const QString &stem, const QString &extension) {
    const QFileInfo body(bodyPath);
    for (const QFileInfo &entry : body.absoluteDir().entryInfoList(QDir::Files))
        if (entry.completeBaseName().compare(stem, Qt::CaseInsensitive) == 0 &&
            entry.suffix().compare(extension, Qt::CaseInsensitive) == 0)
            return entry.absoluteFilePath();
    return QString();
}

// Reads a .vxl and, when placing by transforms, the .hva beside it; `current` names the file read.
UnitFile readUnitFile(const QString &path, UnitRole role, bool withHva, QString &current) {
    UnitFile file;
    file.role = role;
    file.name = local(QFileInfo(path).fileName());
    current = path;
    const std::vector<uint8_t> bytes = readBytes(path);
    file.model = readVxl(bytes.data(), bytes.size());
    const QString hvaPath = companionPath(path, "hva");
    if (withHva && !hvaPath.isEmpty()) {
        current = hvaPath;
        const std::vector<uint8_t> hvaBytes = readBytes(current);
        file.hva = readHva(hvaBytes.data(), hvaBytes.size());
    }
    current = path;
    return file;
}

}  // namespace

void IoVxlPlugin::openVxl(const QString &path, const ImportSettings &settings, MeshModel &m, int &mask,
                          vcg::CallBackPos *cb, QString &current) {
    if (cb)
        cb(0, "Reading VXL");
    VxlSceneOptions options;
    options.section = settings.section;
    options.frame = settings.frame;
    options.applyTransforms = settings.applyTransforms;
    options.houseColour = settings.houseColour;
    Palette external;
    if (!settings.paletteFile.isEmpty()) {
        current = settings.paletteFile;
        const std::vector<uint8_t> palBytes = readBytes(current);
        external = readPal(palBytes.data(), palBytes.size());
        options.externalPalette = &external;
    }
    std::vector<UnitFile> files;
    files.push_back(readUnitFile(path, UnitRole::Body, settings.applyTransforms, current));
    const VxlModel &model = files[0].model;
    const bool hasHva = files[0].hva.has_value();
    const QString hvaPath = companionPath(path, "hva");

    // A wrong frame or section count is a mismatch of the .hva (when there is one) with the .vxl.
    current = hasHva ? hvaPath : path;
    VoxelScene scene = vxlScene(model, hasHva ? &*files[0].hva : nullptr, options);
    current = path;

    // The whole unit: turret and barrel beside the body. A broken one is left out with a message.
    const QString stem = QFileInfo(path).completeBaseName();
    const bool unit = settings.loadUnit && settings.section == -1 && !isUnitCompanionStem(local(stem));
    QStringList loaded{QFileInfo(path).fileName() + (hasHva ? " (+ .hva)" : "")};
    if (unit) {
        for (UnitRole role : {UnitRole::Turret, UnitRole::Barrel}) {
            const QString companion =
                findSibling(path, QString::fromStdString(unitCompanionStem(local(stem), role)), "vxl");
            if (companion.isEmpty())
                continue;
            QString where = companion;
            try {
                UnitFile file = readUnitFile(companion, role, settings.applyTransforms, where);
                VxlSceneOptions o = options;
                if (file.hva)
                    o.frame = std::min(o.frame, file.hva->frameCount - 1);
                if (file.hva)
                    where = companionPath(companion, "hva");
                vxlScene(file.model, file.hva ? &*file.hva : nullptr, o);  // checks the pair
                loaded << QFileInfo(companion).fileName() + (file.hva ? " (+ .hva)" : "");
                files.push_back(std::move(file));
            } catch (const std::exception &e) {
                report(QString("%1: %2; the %3 is left out, the rest of the unit imports")
                           .arg(where, QString::fromLocal8Bit(e.what()), unitRoleName(role)));
            }
        }
    }
    ExportScene nodes;
    size_t sections = model.sections.size();
    if (settings.section == -1) {
        UnitSceneOptions unitOptions;
        unitOptions.vxl = options;
        unitOptions.turretOffsetLeptons = settings.turretOffsetLeptons;
        UnitScene placed = unitScene(files, unitOptions);
        scene = std::move(placed.scene);
        nodes = std::move(placed.nodes);
        sections = 0;
        for (const UnitFile &file : files)
            sections += file.model.sections.size();
    }

    const SceneSurface surface = meshScene(path, scene, PaletteKind::Westwood, m, mask, cb);
    if (!nodes.empty())
        storeExportScene(nodes, m.cm);
    if (files.size() > 1)
        report(QString("%1: unit of %2 files: %3; turret offset %4 leptons")
                   .arg(QFileInfo(path).fileName())
                   .arg(files.size())
                   .arg(loaded.join(", "))
                   .arg(double(settings.turretOffsetLeptons)));
    const QString placement = !settings.applyTransforms ? QString("voxel space")
                              : hasHva                  ? QString("HVA frame %1").arg(settings.frame)
                                                        : QString("section matrices (no .hva found)");
    report(QString("%1: %2 of %3 sections imported; palette: %4%5; placement: %6")
               .arg(QFileInfo(path).fileName())
               .arg(scene.parts.size())
               .arg(sections)
               .arg(settings.paletteFile.isEmpty() ? QString::fromStdString(chooseVxlPalette(model, options).source)
                                                   : settings.paletteFile)
               .arg(settings.houseColour ? ", house colour remapped" : "")
               .arg(placement));
    size_t clamped = 0;
    for (const UnitFile &file : files)
        for (const VxlSection &s : file.model.sections)
            clamped += s.clampedNormals;
    if (clamped > 0)
        report(QString("%1 voxel normal indices were past the normal table and were clamped").arg(clamped));
}

void IoVxlPlugin::openVox(const QString &path, const ImportSettings &settings, MeshModel &m, int &mask,
                          vcg::CallBackPos *cb) {
    if (cb)
        cb(0, "Reading VOX");
    const std::vector<uint8_t> bytes = readBytes(path);
    const VoxFile file = readVox(bytes.data(), bytes.size());
    const VoxelScene scene = voxScene(file, VoxSceneOptions{settings.frame});
    meshScene(path, scene, PaletteKind::MagicaVoxel, m, mask, cb);
    storeExportScene(voxExportNodes(file, settings.frame), m.cm);
    storeVoxMaterials(file.materials, m.cm);
    report(QString("%1: MagicaVoxel version %2, %3 models, %4 instances shown at frame %5 of %6; palette: %7")
               .arg(QFileInfo(path).fileName())
               .arg(file.version)
               .arg(file.models.size())
               .arg(scene.parts.size())
               .arg(settings.frame)
               .arg(file.frameCount)
               .arg(file.defaultPalette ? "MagicaVoxel's default (the file has none)" : "the file's"));
    if (file.materials.chunks > 0) {
        size_t special = 0;
        for (const VoxMaterial &material : file.materials.byIndex)
            special += material.type != VoxMaterialType::Diffuse ? 1 : 0;
        report(QString("%1: %2 MATL materials, %3 of them not diffuse%4")
                   .arg(QFileInfo(path).fileName())
                   .arg(file.materials.chunks)
                   .arg(special)
                   .arg(file.materials.ignoredValues + file.materials.ignoredChunks > 0
                            ? QString("; %1 unreadable values and %2 material ids outside 1..255 ignored")
                                  .arg(file.materials.ignoredValues)
                                  .arg(file.materials.ignoredChunks)
                            : QString()));
    }
}

SceneSurface IoVxlPlugin::meshScene(const QString &path, const VoxelScene &scene, PaletteKind kind, MeshModel &m,
                                    int &mask, vcg::CallBackPos *cb) {
    size_t voxels = 0;
    for (const PlacedVolume &part : scene.parts)
        voxels += part.volume->voxelCount();
    if (voxels == 0)
        throw FormatError("there are no voxels to import (every chosen part is empty)");

    if (cb)
        cb(30, "Extracting the voxel surface");
    SceneSurface surface = extractSceneSurface(scene);
    if (cb)
        cb(80, "Building the mesh");
    mask |= sceneImportMask();
    m.Enable(mask);
    sceneToMeshLab(surface, kind, m);
    report(QString("%1: %2 parts, %3 voxels -> %4 quads, %5 vertices; manifold surface: %6 non-manifold edges and "
                   "%7 non-manifold vertices split, %8 enclosed cavity voxels filled")
               .arg(QFileInfo(path).fileName())
               .arg(scene.parts.size())
               .arg(voxels)
               .arg(surface.quadCount())
               .arg(surface.positions.size())
               .arg(surface.stats.nonManifoldEdgesSplit)
               .arg(surface.stats.nonManifoldVerticesSplit)
               .arg(surface.stats.cavityVoxelsFilled));
    return surface;
}

bool IoVxlPlugin::save(const QString &, const QString &, MeshModel &, const int, const RichParameterList &,
                       vcg::CallBackPos *, QWidget *) {
    errorMessage = "voxel export is not supported";
    return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(IoVxlPlugin)
