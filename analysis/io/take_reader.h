#pragma once
/// One entry point to import a take from any supported file, chosen by extension:
/// .csv (take_csv.h), .bvh (bvh_import.h, puppet parts), .txt/.fastrak/.fst (fastrak.h).

#include "analysis/io/bvh_import.h"
#include "analysis/io/fastrak.h"
#include "analysis/io/take_csv.h"

#include <filesystem>

namespace bunraku::analysis::io {

enum class TakeFileFormat { Csv, Bvh, Fastrak, Unknown };

/// By extension, case-insensitive.
TakeFileFormat takeFileFormat(const std::filesystem::path& file);

enum class BvhTakeLayout { PuppetParts, AllJoints };

struct ImportOptions {
    TakeCsvOptions csv;
    BvhImportOptions bvh;
    BvhTakeLayout bvhLayout = BvhTakeLayout::PuppetParts;
    FastrakOptions fastrak;
};

/// Reads a take of any supported format; Unsupported error for unknown extensions. A BVH file's
/// reading and import report their progress to `control` and stop when it asks (Cancelled).
Result<Take> readTakeFile(const std::filesystem::path& file, const ImportOptions& options = {}, const RunControl& control = {});
/// Writes a take as .csv or .bvh by extension (atomic). A take with a skeleton goes to BVH on
/// that skeleton (bvh_skeleton_export.h), one without in the part layout (bvh_export.h).
Status writeTakeFile(const Take& take, const std::filesystem::path& file);

} // namespace bunraku::analysis::io
