#pragma once
/// An FBX file's object connections checked before assimp sees the file (scene_take.cpp):
/// assimp 5.2 follows them recursively and overflows its stack on a connection cycle - an object
/// connected to itself or to one of its descendants (found by fuzz_scene_take: a model whose
/// parent is itself) - or on a very deep chain. Reads the `C` records of binary FBX (every
/// version's node record layout) and of FBX ASCII.

#include "analysis/core/result.h"

#include <optional>
#include <string>

namespace bunraku::analysis::io {

/// The deepest chain of connected objects accepted (a rig, with assimp's pivot nodes, is tens).
inline constexpr int kMaxFbxConnectionDepth = 512;

/// An error naming `source` when the connections of the FBX file in `bytes` form a cycle or a
/// chain deeper than kMaxFbxConnectionDepth; nothing otherwise. Bytes that are not FBX, or
/// whose records cannot be read, are left to assimp (which reports them).
std::optional<Error> checkFbxConnections(const std::string& bytes, const std::string& source);

} // namespace bunraku::analysis::io
