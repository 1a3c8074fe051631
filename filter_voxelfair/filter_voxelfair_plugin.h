// MeshLab filters of voxelfair. A thin dispatcher: each filter converts CMeshO to the arrays of
// a host-free unit in libvoxelfair/ (meshlab_arrays.h), runs it, and writes the result back.
#pragma once

#include <common/interfaces.h>

#include <QObject>

// The texture file a mesh's atlas is written to by default: "<mesh name>_texture.png" beside it.
QString defaultTextureName(const MeshModel &m);
// The normal map a mesh's bake is written to by default: "NAME_normal.png" for "NAME_texture.png".
QString defaultNormalMapName(const MeshModel &m);
// The house colour mask's default file: "NAME_house.png" for "NAME_texture.png".
QString defaultHouseMaskName(const MeshModel &m);
// A material map's default file: "NAME<suffix>" for "NAME_texture.png".
QString defaultMaterialMapName(const MeshModel &m, const QString &suffix);

class FilterVoxelfairPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum FilterId {
        FP_LANCZOS_FAIRING,      // section 4.3
        FP_ATTRIBUTE_SMOOTHING,  // section 4.4
        FP_TEXTURE_ATLAS,        // section 4.5
        FP_NORMAL_MAP,           // beyond the paper (its future work): tangent-space normal map
        FP_HOUSE_MASK,           // beyond the paper: VXL house colours (remap range) as a mask texture
        FP_MATERIAL_MAPS         // beyond the paper (its future work: material maps): VOX materials as PBR maps
    };

    FilterVoxelfairPlugin();

    QString pluginName() const override { return "FilterVoxelfair"; }
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction *action) override;
    FILTER_ARITY filterArity(QAction *) const override { return SINGLE_MESH; }
    int getPreConditions(QAction *action) const override;
    int getRequirements(QAction *action) override;
    int postCondition(QAction *action) const override;
    void initParameterSet(QAction *action, MeshModel &m, RichParameterList &parameters) override;
    void initParameterSet(QAction *action, MeshDocument &md, RichParameterList &parameters) override;
    bool applyFilter(QAction *action, MeshDocument &md, const RichParameterList &parameters,
                     vcg::CallBackPos *cb) override;

private:
    bool applyLanczosFairing(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb);
    bool applyAttributeSmoothing(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb);
    bool applyTextureAtlas(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb);
    bool applyNormalMap(MeshDocument &md, const RichParameterList &parameters, vcg::CallBackPos *cb);
    bool applyHouseMask(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb);
    bool applyMaterialMaps(MeshModel &m, const RichParameterList &parameters, vcg::CallBackPos *cb);

    // Sets errorMessage, logs it and writes it to stderr (meshlabserver never prints errorMessage).
    bool fail(const QString &message);
    // An information line for MeshLab's log, echoed to stderr for headless runs.
    void report(const QString &message);
};
