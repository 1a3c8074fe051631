// MeshLab exporter for glTF 2.0 binary (.glb): the mesh with its parts as nodes (when io_vxl
// imported it: a unit's body / turret / barrel and their sections, a VOX scene's instances, with
// their animation), the baked texture embedded, per-vertex normals and UVs. The file layout is
// libvoxelfair/export/glb_writer.h's; this adapter converts CMeshO and reads the parameters.
//
// meshlabserver cannot set an exporter's parameters, so each default can be overridden by an
// environment variable:
//   VOXELFAIR_METRES_PER_VOXEL   size of one voxel in metres (default 0.1)
//   VOXELFAIR_TEXTURE_FILTER     nearest (default: crisp pixel art) or linear
#pragma once

#include <common/interfaces.h>

#include <QObject>

class IoGltfPlugin : public QObject, public MeshIOInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_IO_INTERFACE_IID)
    Q_INTERFACES(MeshIOInterface)

public:
    QString pluginName() const override { return "IOGLTF"; }
    QList<Format> importFormats() const override { return {}; }
    QList<Format> exportFormats() const override;
    void GetExportMaskCapability(QString &format, int &capability, int &defaultBits) const override;
    void initSaveParameter(const QString &format, MeshModel &m, RichParameterList &parameters) override;
    bool open(const QString &, const QString &, MeshModel &, int &, const RichParameterList &, vcg::CallBackPos *,
              QWidget *) override {
        return false;
    }
    bool save(const QString &format, const QString &fileName, MeshModel &m, const int mask,
              const RichParameterList &parameters, vcg::CallBackPos *cb, QWidget *parent) override;

private:
    void report(const QString &message);
    bool fail(const QString &message);
};
