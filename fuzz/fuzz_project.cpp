// libFuzzer target: the project file reader (app/project_file.h, Qt Core's JSON), linked with Qt
// Core only; the analysis code it calls (import options) is instrumented.
#include "fuzz/fuzz_support.h"

#include "app/project_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    const QByteArray text(reinterpret_cast<const char*>(data), qsizetype(size));
    auto state = app::parseProject(text, QStringLiteral("fuzz-input.bunraku.json"));
    if (!state) {
        fuzz::expect(fuzz::namesSource(state.error().message), "a project error names the file");
        return 0;
    }
    fuzz::expect(!state->corpus.isEmpty(), "an accepted project names its corpus");
    return 0;
}
