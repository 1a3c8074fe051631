#include "filter_voxelfair_plugin.h"

#include <cstdio>
#include <exception>
#include <new>

FilterVoxelfairPlugin::FilterVoxelfairPlugin() {
    typeList << FP_LANCZOS_FAIRING << FP_ATTRIBUTE_SMOOTHING;
    for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterVoxelfairPlugin::filterName(FilterIDType filter) const {
    switch (filter) {
    case FP_LANCZOS_FAIRING: return "Voxel Fairing: Modified Lanczos";
    case FP_ATTRIBUTE_SMOOTHING: return "Voxel Fairing: Attribute Smoothing";
    }
    return QString();
}

QString FilterVoxelfairPlugin::filterInfo(FilterIDType filter) const {
    switch (filter) {
    case FP_LANCZOS_FAIRING:
        return "Smooths a voxel surface in one pass, strongly where the voxel staircase is and gently where "
               "the shape is flat: the modified discrete Laplacian with a Lanczos kernel of "
               "<i>Fast polygonization and texture map extraction from volumetric objects based on surface "
               "fairing using a modified discrete Laplacian operator</i> (SBGames 2010, section 4.3), as its "
               "authors implemented it.<br>Each vertex moves, per axis, by 1 - Lanczos3 of lambda times the mean "
               "unit vector to its neighbours (every vertex sharing a polygon with it, quad diagonals included), "
               "all vertices reading the old positions. Works on any mesh; meant for the quad meshes the VXL "
               "importer produces. The displacement is in voxels, so a scaled model smooths the same.";
    case FP_ATTRIBUTE_SMOOTHING:
        return "Section 4.4 of the SBGames 2010 paper: turns the polygons (quads) into triangles and computes "
               "per-vertex normals as the normalised mean of the <b>distinct</b> normals of the adjacent faces "
               "(repeated directions counted once, so a voxel corner gets the diagonal whatever its faces' sizes) "
               "and per-vertex colours as the mean of the adjacent faces' colours.";
    }
    return QString();
}

MeshFilterInterface::FilterClass FilterVoxelfairPlugin::getClass(QAction *action) {
    // Never Generic: a Generic filter makes MeshLab 2020.09 abort plugin loading for everyone.
    switch (ID(action)) {
    case FP_LANCZOS_FAIRING: return MeshFilterInterface::Smoothing;
    case FP_ATTRIBUTE_SMOOTHING: return FilterClass(MeshFilterInterface::Normal | MeshFilterInterface::VertexColoring);
    }
    return MeshFilterInterface::Smoothing;
}

int FilterVoxelfairPlugin::getPreConditions(QAction *) const { return MeshModel::MM_FACENUMBER; }

int FilterVoxelfairPlugin::getRequirements(QAction *action) {
    switch (ID(action)) {
    case FP_ATTRIBUTE_SMOOTHING: return MeshModel::MM_VERTCOLOR;
    default: return MeshModel::MM_NONE;
    }
}

int FilterVoxelfairPlugin::postCondition(QAction *action) const {
    switch (ID(action)) {
    case FP_LANCZOS_FAIRING: return MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL;
    case FP_ATTRIBUTE_SMOOTHING:
        return MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL | MeshModel::MM_VERTCOLOR | MeshModel::MM_FACEFLAG |
               MeshModel::MM_POLYGONAL;
    }
    return MeshModel::MM_ALL;
}

void FilterVoxelfairPlugin::initParameterSet(QAction *action, MeshModel &m, RichParameterList &parameters) {
    switch (ID(action)) {
    case FP_LANCZOS_FAIRING:
        parameters.addParam(RichFloat("lambda", 4.0f / 3.0f, "Lambda",
                                      "Scales the estimated frequency (eq. 8). 4/3 is the authors' value; the paper's "
                                      "text says 1.3. Higher smooths more; above 1.5 the staircase starts to overshoot."));
        parameters.addParam(RichInt("passes", 1, "Passes", "The paper needs one pass; each further pass smooths more."));
        parameters.addParam(RichFloat("voxelSize", 0.0f, "Voxel size",
                                      "Length of a voxel in mesh units: the unit of the displacement. 0 detects it as "
                                      "the mesh's dominant edge length, so a scaled model smooths the same."));
        parameters.addParam(RichBool("Selected", m.cm.svn > 0, "Affect only selected vertices",
                                     "Only selected vertices move; the others still act as neighbours."));
        break;
    case FP_ATTRIBUTE_SMOOTHING:
        parameters.addParam(RichBool("distinctNormals", true, "Count each normal direction once",
                                     "The paper's rule: a vertex normal is the mean of the distinct adjacent face "
                                     "normals. Off: the plain mean of all adjacent faces."));
        parameters.addParam(RichBool("triangulate", true, "Quads to triangles",
                                     "Make the polygons plain triangles (as the paper does before the atlas). Off "
                                     "keeps MeshLab's polygon (faux edge) flags."));
        break;
    }
}

void FilterVoxelfairPlugin::report(const QString &message) {
    Log(message.toStdString());
    std::fprintf(stderr, "filter_voxelfair: %s\n", message.toLocal8Bit().constData());
}

bool FilterVoxelfairPlugin::fail(const QString &message) {
    errorMessage = message;
    Log(GLLogStream::WARNING, message.toStdString());
    std::fprintf(stderr, "filter_voxelfair: %s\n", message.toLocal8Bit().constData());
    return false;
}

bool FilterVoxelfairPlugin::applyFilter(QAction *action, MeshDocument &md, const RichParameterList &parameters,
                                        vcg::CallBackPos *cb) {
    // Nothing may escape into MeshLab: every failure becomes this filter's error.
    try {
        MeshModel *m = md.mm();
        if (m == nullptr) return fail("there is no current mesh");
        switch (ID(action)) {
        case FP_LANCZOS_FAIRING: return applyLanczosFairing(*m, parameters, cb);
        case FP_ATTRIBUTE_SMOOTHING: return applyAttributeSmoothing(*m, parameters, cb);
        }
        return fail("unknown filter");
    } catch (const std::bad_alloc &) {
        return fail(action->text() + ": not enough memory");
    } catch (const std::exception &e) {
        return fail(action->text() + ": " + e.what());
    } catch (...) {
        return fail(action->text() + ": unexpected error");
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVoxelfairPlugin)
