#pragma once
/// Where the workbench finds the files installed beside it. Everything is located from the
/// executable's folder, PREFIX/bin -> PREFIX/share/bunraku/..., so a package unpacked anywhere
/// (dpkg -x ROOT: ROOT/usr/bin, ROOT/usr/share) finds its own files, and the build tree, which
/// mirrors that layout (build/bin, build/share), works the same way. Nothing is looked up in
/// the source tree.

#include <QIcon>
#include <QString>

namespace bunraku::app {

/// The desktop entry's id (org.bunraku.MotionWorkbench.desktop), also the icon's name in the
/// hicolor theme and the AppStream id.
inline constexpr const char* kDesktopId = "org.bunraku.MotionWorkbench";

/// PREFIX/share/bunraku for the running executable (not checked for existence).
QString dataDir();
/// Where the user guide should be: dataDir()/doc/USER-GUIDE.md.
QString expectedUserGuidePath();
/// The installed user guide, or an empty string when it is missing.
QString userGuidePath();
/// The application icon, from the PNG sizes compiled into the program (:/icons/...).
QIcon applicationIcon();

} // namespace bunraku::app
