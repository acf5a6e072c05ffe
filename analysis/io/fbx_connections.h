#pragma once
/// An FBX file's object connections checked before assimp sees the file (scene_take.cpp):
/// assimp 5.2 follows them recursively and overflows its stack on a connection cycle - an object
/// connected to itself or to one of its descendants (found by fuzz_scene_take: a model whose
/// parent is itself) - or on a very deep chain. Reads the `C` records of binary FBX (every
/// version's node record layout) and of FBX ASCII.

#include "analysis/core/result.h"

#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis::io {

/// The deepest chain of connected objects accepted (a rig, with assimp's pivot nodes, is tens).
inline constexpr int kMaxFbxConnectionDepth = 512;

/// An error naming `source` when the connections of the FBX file in `bytes` form a cycle or a
/// chain deeper than kMaxFbxConnectionDepth; nothing otherwise. Bytes that are not FBX, or
/// whose records cannot be read, are left to assimp (which reports them).
std::optional<Error> checkFbxConnections(const std::string& bytes, const std::string& source);

/// The byte offsets of the type names of every `KTime` property of a model object
/// (Objects > Model > Properties70 > P), binary or ASCII. assimp 5.2 keeps a model's properties it
/// does not read as node metadata and aborts (ai_assert) on a KTime one (found by
/// fuzz_scene_take); a take reads none of them, so scene_take.cpp renames those types before
/// assimp sees the file, which then drops the properties.
std::vector<std::size_t> fbxModelTimeProperties(const std::string& bytes);

} // namespace bunraku::analysis::io
