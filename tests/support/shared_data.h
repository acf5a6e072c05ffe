#pragma once
/// The shared Bandai motion capture as a peer of the tests (tests/support/peer.h).
#include "tests/support/peer.h"
#include "tests/support/test_paths.h"

namespace bunraku::test {

/// requirePeer for the shared Bandai data (bandaiDir()).
inline bool requireBandaiData(bool available)
{
    return requirePeer(available, "the shared Bandai data (" + bandaiDir().string() + ")",
                       "install the shared data under ../shared/data/bandai");
}

} // namespace bunraku::test
