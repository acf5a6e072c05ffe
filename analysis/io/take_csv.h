#pragma once
/// CSV takes: `time_s` then one column per channel named `part.dof` (e.g. `head.x ... hand.roll`).
/// Reading is tolerant: `,` `;` or tab separators (detected from the header), CRLF line ends,
/// `#` comment lines and blank lines; a header name holding a separator or quote is written in
/// double quotes (RFC 4180). Values are range-checked (analysis/core/take.h valueLimit). Writing
/// is atomic (see atomic_file.h). Format: docs/FORMATS.md.

#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <filesystem>
#include <optional>
#include <string>

namespace bunraku::analysis::io {

struct TakeCsvOptions {
    /// Sample rate in Hz. Without a `time_s` column it is required; with one it overrides the
    /// rate measured from the time column (which must still be uniform).
    std::optional<double> rateHz;
    /// With rateHz and a time column: the column's rate must be rateHz (within timeTolerance),
    /// else a Parse error naming the line (a take of another rate inside a corpus).
    bool timeMustMatchRate = false;
    /// Relative tolerance on the spacing of the time column (fraction of the mean step).
    double timeTolerance = 1e-3;
    /// Labels given to the take (source defaults to the file path).
    TakeLabels labels;
};

/// Reads one take. Units come from the DOF name: x, y, z are "cm", yaw, pitch, roll "deg",
/// anything else "". Errors name the file, line and (where meaningful) the column/channel.
Result<Take> readTakeCsv(const std::filesystem::path& file, const TakeCsvOptions& options = {});
/// Parses CSV text; `sourceName` is used in error messages.
Result<Take> parseTakeCsv(const std::string& text, const std::string& sourceName, const TakeCsvOptions& options = {});
/// CSV text of a take: header `time_s,part.dof,...`, one row per frame, full double precision.
/// `comment` (e.g. how a derived take was made), when not empty, opens the file as `#` lines,
/// one per line of it: the reader skips them.
std::string formatTakeCsv(const Take& take, const std::string& comment = {});
/// Writes the take atomically; rejects non-finite values (validateTake) before writing anything.
Status writeTakeCsv(const Take& take, const std::filesystem::path& file, const std::string& comment = {});

} // namespace bunraku::analysis::io
