// MeshLab importer for Westwood VXL voxel models (Tiberian Sun, Red Alert 2).
#pragma once

#include <common/interfaces.h>

#include <QObject>

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
    bool open(const QString &format, const QString &fileName, MeshModel &m, int &mask, const RichParameterList &parameters,
              vcg::CallBackPos *cb = nullptr, QWidget *parent = nullptr) override;
    bool save(const QString &format, const QString &fileName, MeshModel &m, const int mask,
              const RichParameterList &parameters, vcg::CallBackPos *cb, QWidget *parent) override;

private:
    // Writes an information line to MeshLab's log and to stderr (meshlabserver's importer has no log).
    void report(const QString &message);
    // Sets errorMessage, logs it and writes it to stderr (meshlabserver shows neither).
    bool fail(const QString &message);
};
