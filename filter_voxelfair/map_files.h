// Where the Texture filters' maps go: the file names and folders the bake filters (normal map,
// house colour mask, material maps) share, so every map lands beside the base colour texture.
#pragma once

#include <common/meshmodel.h>

#include <QImage>
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

// Writes `image` as a PNG at `path`, creating its folder; false when either fails. zlib level 4
// (Qt's PNG quality 50), not Qt's default level 6: on a normal map's noisy texels the default
// takes about 4 times as long for a file about 12% smaller (the example tank's 1024 x 1024 normal
// map: 212 -> 50 ms, 233 -> 263 KB); pixel-art base colours and masks differ by a few percent.
bool writePng(const QImage &image, const QString &path);

}  // namespace voxelfair
