#include "app/cli/take_output.h"

#include "app/cli/cli.h"

#include "analysis/body/body_description.h"
#include "render/take_export.h"

#include <iostream>

namespace bunraku::app::cli {

bool isTakeOutput(const std::string& output) { return render::takeExportFormat(output) != render::TakeExportFormat::Unknown; }

void requireTakeOutput(const std::string& output)
{
    if (!isTakeOutput(output)) throw CliError(output + ": unknown output type, " + render::takeExportExpectation());
}

void writeTakeOutput(const analysis::Take& take, const std::string& output)
{
    requireTakeOutput(output);
    unwrap(render::exportTake(take, analysis::defaultBodyDescription(), output));
    // On stderr: a --json answer on stdout stays one document.
    if (const std::string note = render::takeExportNote(take, output); !note.empty()) std::cerr << "note: " << note << "\n";
}

} // namespace bunraku::app::cli
