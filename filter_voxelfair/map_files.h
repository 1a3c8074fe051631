// Where the Texture filters' maps go: the file names and folders the bake filters (normal map,
// house colour mask, material maps) share, so every map lands beside the base colour texture.
#pragma once

#include <common/meshmodel.h>

#include <QString>

namespace voxelfair {

// `name` as given when absolute, else in the folder of the mesh's file (the current folder for
// a mesh without one).
QString besideMesh(const MeshModel &m, const QString &name);

// "NAME_texture.png" -> "NAME<suffix>"; otherwise "<mesh name><suffix>" ("voxelfair<suffix>"
// for a mesh without a name).
QString mapNameFor(const MeshModel &m, const QString &suffix);

// The base colour texture's file (the mesh's first texture): beside `mapPath`, where the pipeline
// writes both, else beside the mesh.
QString baseColourPath(const MeshModel &m, const QString &mapPath);

}  // namespace voxelfair
