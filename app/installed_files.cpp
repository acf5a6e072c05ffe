#include "app/installed_files.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace bunraku::app {

QString dataDir()
{
    return QDir::cleanPath(QCoreApplication::applicationDirPath() + QStringLiteral("/../share/bunraku"));
}

QString expectedUserGuidePath() { return dataDir() + QStringLiteral("/doc/USER-GUIDE.md"); }

QString userGuidePath()
{
    const QString path = expectedUserGuidePath();
    return QFileInfo(path).isFile() ? path : QString();
}

QIcon applicationIcon()
{
    QIcon icon;
    for (int size : {16, 24, 32, 48, 64, 128, 256})
        icon.addFile(QStringLiteral(":/icons/%1x%1/apps/%2.png").arg(size).arg(QLatin1String(kDesktopId)), QSize(size, size));
    return icon;
}

} // namespace bunraku::app
