#pragma once
/// Debian's Blender 3.4 as a peer of the tests (tests/support/peer.h): the real client our
/// exports are checked against. A missing blender fails under CI=true and is reported as skipped
/// otherwise.
#include "tests/support/peer.h"

#include <cstdlib>

namespace bunraku::test {

inline bool requireBlender()
{
    return requirePeer(std::system("command -v blender >/dev/null 2>&1") == 0, "blender (Debian's Blender 3.4)",
                       "apt-get install blender (scripts/install-deps.sh)");
}

} // namespace bunraku::test
