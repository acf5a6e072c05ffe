#pragma once
/// The libraries the workbench is built on, for Help > About: each with the version in use and
/// its licence. Versions are read at run time where the library tells them (Qt, FFTW, assimp)
/// and otherwise from the headers the program was compiled with (QCustomPlot, Eigen, GLM,
/// nlohmann-json, which are compiled in or carry no run-time version).

#include <QList>
#include <QString>

namespace bunraku::app {

struct LibraryVersion {
    QString name;    ///< "Qt", "QCustomPlot", "Eigen", "FFTW", "assimp", ...
    QString version; ///< "6.4.2", "3.3.10", ...
    QString license; ///< SPDX expression of the library's licence
};

/// Qt, QCustomPlot, Eigen, FFTW, assimp, GLM and nlohmann-json, in that order.
QList<LibraryVersion> libraryVersions();

} // namespace bunraku::app
