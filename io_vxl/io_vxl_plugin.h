// MeshLab importer for voxel models: Westwood VXL (Tiberian Sun, Red Alert 2; with .hva and
// .pal) and MagicaVoxel VOX. Both become the same manifold quad surface (scene_to_meshlab.h).
#pragma once

#include <common/interfaces.h>

#include <QObject>

namespace voxelfair {
struct ImportSettings;
struct SceneSurface;
struct VoxelScene;
enum class PaletteKind : int;
}  // namespace voxelfair

class IoVxlPlugin : public QObject, public MeshIOInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_IO_INTERFACE_IID)
    Q_INTERFACES(MeshIOInterface)

public:
    QString pluginName() const override { return "IOVXL"; }
    QList<Format> importFormats() const override;
    QList<Format> exportFormats() const override;
    void GetExportMaskCapability(QString &format, int &capability, int &defaultBits) const override;
    void initPreOpenParameter(const QString &format, const QString &fileName, RichParameterList &parameters) override;
    bool open(const QString &format, const QString &fileName, MeshModel &m, int &mask,
              const RichParameterList &parameters, vcg::CallBackPos *cb = nullptr, QWidget *parent = nullptr) override;
    bool save(const QString &format, const QString &fileName, MeshModel &m, const int mask,
              const RichParameterList &parameters, vcg::CallBackPos *cb, QWidget *parent) override;

private:
    // Each reads its format into a scene and meshes it into `m`; errors are thrown as
    // voxelfair::FormatError with `current` naming the file they are about.
    void openVxl(const QString &path, const voxelfair::ImportSettings &settings, MeshModel &m, int &mask,
                 vcg::CallBackPos *cb, QString &current);
    void openVox(const QString &path, const voxelfair::ImportSettings &settings, MeshModel &m, int &mask,
                 vcg::CallBackPos *cb);
    // Extracts the scene's surface into `m` and reports it; throws when there is nothing to mesh.
    voxelfair::SceneSurface meshScene(const QString &path, const voxelfair::VoxelScene &scene,
                                      voxelfair::PaletteKind kind, MeshModel &m, int &mask, vcg::CallBackPos *cb);

    // Writes an information line to MeshLab's log and to stderr (meshlabserver's importer has no log).
    void report(const QString &message);
    // Sets errorMessage, logs it and writes it to stderr (meshlabserver shows neither).
    bool fail(const QString &message);
};
