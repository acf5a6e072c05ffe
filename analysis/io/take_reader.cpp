#include "analysis/io/take_reader.h"

#include "analysis/io/bvh_export.h"
#include "analysis/io/bvh_skeleton_export.h"

#include <algorithm>
#include <cctype>

namespace bunraku::analysis::io {

TakeFileFormat takeFileFormat(const std::filesystem::path& file)
{
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".csv") return TakeFileFormat::Csv;
    if (extension == ".bvh") return TakeFileFormat::Bvh;
    if (extension == ".txt" || extension == ".fastrak" || extension == ".fst") return TakeFileFormat::Fastrak;
    if (isSceneTakeFile(file)) return TakeFileFormat::Scene;
    return TakeFileFormat::Unknown;
}

BvhImportOptions sceneBvhOptions(const BvhImportOptions& options)
{
    BvhImportOptions converted = options;
    converted.upAxis = BvhUpAxis::Y;
    converted.unitScale = 1.0;
    converted.guessUnits = false;
    converted.kinematics.positionMode = BvhPositionMode::ReplaceOffset;
    return converted;
}

Result<BvhFile> readSkeletalFile(const std::filesystem::path& file, const ImportOptions& options, const RunControl& control, SceneTakeInfo* info)
{
    switch (takeFileFormat(file)) {
    case TakeFileFormat::Bvh: return readBvh(file, control);
    case TakeFileFormat::Scene: {
        auto scene = readSceneTake(file, options.scene, control);
        if (!scene) return scene.error();
        if (info) *info = scene->info;
        return std::move(scene->bvh);
    }
    default: break;
    }
    return makeError(ErrorCode::Unsupported, file.string() + ": not a file with a skeleton (expected .bvh, .fbx, .glb, .gltf or .dae)");
}

Result<Take> readTakeFile(const std::filesystem::path& file, const ImportOptions& options, const RunControl& control)
{
    switch (takeFileFormat(file)) {
    case TakeFileFormat::Csv: return readTakeCsv(file, options.csv);
    case TakeFileFormat::Bvh:
    case TakeFileFormat::Scene: {
        auto bvh = readSkeletalFile(file, options, control.step(0.0, 0.5));
        if (!bvh) return bvh.error();
        const BvhImportOptions bvhOptions = takeFileFormat(file) == TakeFileFormat::Scene ? sceneBvhOptions(options.bvh) : options.bvh;
        if (options.bvhLayout == BvhTakeLayout::AllJoints) return bvhToJointTake(*bvh, bvhOptions);
        auto imported = importBvhPuppet(*bvh, bvhOptions, control.step(0.5, 1.0));
        if (!imported) return imported.error();
        return std::move(imported->take);
    }
    case TakeFileFormat::Fastrak: return readFastrak(file, options.fastrak);
    case TakeFileFormat::Unknown: break;
    }
    return makeError(ErrorCode::Unsupported, file.string() + ": unknown take file type '" + file.extension().string() +
                                                 "' (expected .csv, .bvh, .fbx, .glb, .gltf, .dae, .txt, .fastrak or .fst)");
}

Status writeTakeFile(const Take& take, const std::filesystem::path& file)
{
    switch (takeFileFormat(file)) {
    case TakeFileFormat::Csv: return writeTakeCsv(take, file);
    case TakeFileFormat::Bvh: return take.skeleton ? writeSkeletonBvh(take, file) : writeTakeBvh(take, file);
    default: break;
    }
    return makeError(ErrorCode::Unsupported, file.string() + ": cannot write '" + file.extension().string() + "' (expected .csv or .bvh)");
}

} // namespace bunraku::analysis::io
