#include "filter_voxelfair_plugin.h"

#include <cstdio>
#include <exception>

FilterVoxelfairPlugin::FilterVoxelfairPlugin() {
    typeList << FP_VOXEL_INFO;
    for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterVoxelfairPlugin::filterName(FilterIDType filter) const {
    switch (filter) {
    case FP_VOXEL_INFO: return "Voxel Surface: Report Lattice";
    }
    return QString();
}

QString FilterVoxelfairPlugin::filterInfo(FilterIDType filter) const {
    switch (filter) {
    case FP_VOXEL_INFO:
        return "Reports whether the current mesh is a voxel boundary surface as voxelfair's importers "
               "produce it (every vertex on an integer lattice, quads of unit area) and its voxel size.";
    }
    return QString();
}

MeshFilterInterface::FilterClass FilterVoxelfairPlugin::getClass(QAction *) {
    // Never Generic: a Generic filter makes MeshLab 2020.09 abort plugin loading for everyone.
    return MeshFilterInterface::Measure;
}

int FilterVoxelfairPlugin::getPreConditions(QAction *) const { return MeshModel::MM_NONE; }
int FilterVoxelfairPlugin::getRequirements(QAction *) { return MeshModel::MM_NONE; }
int FilterVoxelfairPlugin::postCondition(QAction *) const { return MeshModel::MM_NONE; }

void FilterVoxelfairPlugin::initParameterSet(QAction *, MeshModel &, RichParameterList &) {}

bool FilterVoxelfairPlugin::fail(const QString &message) {
    errorMessage = message;
    Log(GLLogStream::WARNING, message.toStdString());
    std::fprintf(stderr, "filter_voxelfair: %s\n", message.toLocal8Bit().constData());
    return false;
}

bool FilterVoxelfairPlugin::applyFilter(QAction *action, MeshDocument &md, const RichParameterList &,
                                        vcg::CallBackPos *) {
    try {
        MeshModel *m = md.mm();
        if (m == nullptr) return fail("no current mesh");
        switch (ID(action)) {
        case FP_VOXEL_INFO: {
            const CMeshO &cm = m->cm;
            size_t offLattice = 0;
            for (const CVertexO &v : cm.vert) {
                if (v.IsD()) continue;
                for (int k = 0; k < 3; ++k)
                    if (v.cP()[k] != std::round(v.cP()[k])) { ++offLattice; break; }
            }
            Log("%s: %d vertices, %d faces, %zu vertices off the integer lattice", m->shortName().toStdString().c_str(),
                cm.vn, cm.fn, offLattice);
            return true;
        }
        }
        return fail("unknown filter");
    } catch (const std::exception &e) {
        return fail(QString("unexpected error: ") + e.what());
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVoxelfairPlugin)
