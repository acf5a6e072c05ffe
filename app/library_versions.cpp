#include "app/library_versions.h"

#include <Eigen/Core>
#include <assimp/version.h>
#include <fftw3.h>
#include <glm/detail/setup.hpp>
#include <nlohmann/json.hpp>
#include <qcustomplot.h>

#include <QtGlobal>

namespace bunraku::app {
namespace {

/// "fftw-3.3.10-sse2-avx" -> "3.3.10".
QString fftwVersion()
{
    QString text = QString::fromLatin1(fftw_version);
    if (text.startsWith(QStringLiteral("fftw-"))) text.remove(0, 5);
    const qsizetype dash = text.indexOf(QLatin1Char('-'));
    return dash < 0 ? text : text.left(dash);
}

QString dotted(unsigned major, unsigned minor, unsigned patch)
{
    return QStringLiteral("%1.%2.%3").arg(major).arg(minor).arg(patch);
}

QString qtVersion()
{
    const QString running = QString::fromLatin1(qVersion());
    const QString built = QStringLiteral(QT_VERSION_STR);
    return running == built ? running : QStringLiteral("%1 (built with %2)").arg(running, built);
}

} // namespace

QList<LibraryVersion> libraryVersions()
{
    return {
        {QStringLiteral("Qt"), qtVersion(), QStringLiteral("LGPL-3.0-only OR GPL-2.0-or-later")},
        {QStringLiteral("QCustomPlot"), QStringLiteral(QCUSTOMPLOT_VERSION_STR), QStringLiteral("GPL-3.0-or-later")},
        {QStringLiteral("Eigen"), dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION), QStringLiteral("MPL-2.0")},
        {QStringLiteral("FFTW"), fftwVersion(), QStringLiteral("GPL-2.0-or-later")},
        {QStringLiteral("assimp"), dotted(aiGetVersionMajor(), aiGetVersionMinor(), aiGetVersionPatch()), QStringLiteral("BSD-3-Clause")},
        {QStringLiteral("GLM"), dotted(GLM_VERSION_MAJOR, GLM_VERSION_MINOR, GLM_VERSION_PATCH) + QStringLiteral(".%1").arg(GLM_VERSION_REVISION),
         QStringLiteral("MIT")},
        {QStringLiteral("nlohmann-json"),
         dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH), QStringLiteral("MIT")},
    };
}

} // namespace bunraku::app
