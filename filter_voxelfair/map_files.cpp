#include "map_files.h"

#include <QDir>
#include <QFileInfo>
#include <QImageWriter>

namespace voxelfair {

QString besideMesh(const MeshModel &m, const QString &name) {
    if (QFileInfo(name).isAbsolute())
        return QDir::cleanPath(name);
    const QString meshFile = m.fullName();
    const QDir folder = meshFile.isEmpty() ? QDir::current() : QFileInfo(meshFile).absoluteDir();
    return QDir::cleanPath(folder.absoluteFilePath(name));
}

QString mapNameFor(const MeshModel &m, const QString &suffix) {
    if (!m.cm.textures.empty()) {
        QString base = QFileInfo(QString::fromStdString(m.cm.textures.front())).completeBaseName();
        if (base.endsWith("_texture"))
            base.chop(8);
        return base + suffix;
    }
    const QString base = QFileInfo(m.fullName()).completeBaseName();
    return (base.isEmpty() ? QString("voxelfair") : base) + suffix;
}

QString baseColourPath(const MeshModel &m, const QString &mapPath) {
    const QString name = QString::fromStdString(m.cm.textures.front());
    QString texture = QFileInfo(name).isAbsolute() ? name : QFileInfo(mapPath).absoluteDir().absoluteFilePath(name);
    if (!QFileInfo::exists(texture))
        texture = besideMesh(m, name);
    return texture;
}

bool writePng(const QImage &image, const QString &path) {
    if (!QDir().mkpath(QFileInfo(path).absolutePath()))
        return false;
    QImageWriter writer(path, "png");
    writer.setQuality(50);  // zlib level (100 - quality) * 9 / 91 = 4
    return writer.write(image);
}

}  // namespace voxelfair
