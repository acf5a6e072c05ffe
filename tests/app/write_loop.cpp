// The child of the kill test (kill_write_test.cpp): writes one kind of output over and over, each
// version recognisable from its content, until it is killed. Usage:
//   bunraku_test_write_loop project|take|corpus|frames TARGET FIRST_VERSION [LAST_VERSION]
// Prints "ready" once set up, then "wrote N" after each complete write of version N; returns
// after LAST_VERSION when given.
#include "tests/app/write_loop_content.h"

#include "app/project_file.h"
#include "app/video_export.h"

#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"

#include <QGuiApplication>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace bunraku;
using namespace bunraku::test::writeloop;

analysis::Status writeVersion(Kind kind, const std::string& target, int version)
{
    switch (kind) {
    case Kind::Project: return app::writeProject(projectOf(version), QString::fromStdString(target));
    case Kind::Take: return analysis::io::writeTakeFile(takeOf(version, 0), target);
    case Kind::Corpus: return analysis::io::writeCorpus(corpusOf(version), target);
    case Kind::Frames: {
        auto sink = app::makePngSequenceSink(QString::fromStdString(target), true);
        const QImage first = frameOf(version, 0);
        if (auto opened = sink->open(first.size(), 5.0); !opened) return opened;
        for (int i = 0; i < frameCountOf(version); ++i)
            if (auto written = sink->write(frameOf(version, i)); !written) return written;
        return sink->finish();
    }
    }
    return analysis::makeError(analysis::ErrorCode::InvalidArgument, "unknown kind");
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 4 && argc != 5) {
        std::fprintf(stderr, "usage: %s project|take|corpus|frames TARGET FIRST_VERSION [LAST_VERSION]\n", argv[0]);
        return 2;
    }
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication application(argc, argv); // image encoders
    const auto kind = kindOf(argv[1]);
    if (!kind) return 2;
    const std::string target = argv[2];
    int version = std::atoi(argv[3]);
    const int last = argc == 5 ? std::atoi(argv[4]) : -1;
    std::printf("ready\n");
    std::fflush(stdout);
    for (; last < 0 || version <= last; ++version) {
        if (auto written = writeVersion(*kind, target, version); !written) {
            std::fprintf(stderr, "%s\n", written.error().message.c_str());
            return 1;
        }
        std::printf("wrote %d\n", version);
        std::fflush(stdout);
    }
    return 0;
}
