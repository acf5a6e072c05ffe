#pragma once
/// The workbench's monkey (tests/monkey/README.md): random, valid user actions on a real
/// MainWindow - menu actions, dock controls, spin boxes and sliders at and beyond their limits,
/// warp-curve and phrase drags, take selection, A/B, play and scrub, undo/redo bursts, opening
/// good and bad files and projects, dialogs closed midway - chosen by a seeded generator, with
/// the workbench's invariants checked after every step.
///
/// Replayable: nothing the monkey does depends on the wall clock or on thread timing. The
/// analysis jobs run on a manual executor (they finish when the seed says), the views' timers run
/// on a widgets::ManualClock, the file dialogs are answered by a chooser (app/file_dialogs.h) and
/// modal dialogs and popup menus are answered by a timer that the generator drives. A failure
/// names the seed and the last actions; BUNRAKU_MONKEY_SEED replays it (monkey_test.cpp).

#include "app/main_window.h"
#include "app/stage_scheduler.h"

#include "widgets/clock.h"

#include <QString>
#include <QStringList>
#include <QTimer>

#include <deque>
#include <functional>
#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace bunraku::test {

/// Analysis jobs queue here and run when the monkey says (one of its actions).
class MonkeyExecutor : public app::Executor {
public:
    void run(std::function<void()> work) override { m_jobs.push_back(std::move(work)); }
    std::size_t pending() const { return m_jobs.size(); }
    /// Runs the oldest job; false when none waits.
    bool runNext();

private:
    std::deque<std::function<void()>> m_jobs;
};

struct MonkeyFiles {
    QStringList corpora;  ///< corpus folders that open (the Bandai corpus)
    QStringList takes;    ///< take files that import (CSV, BVH)
    QStringList bad;      ///< files and folders that must be refused with a message
    QString scratch;      ///< where projects, exports and screenshots go
};

class Monkey {
public:
    /// `window` was made with `executor`; its clocks are set to `clock` here.
    Monkey(app::MainWindow& window, MonkeyExecutor& executor, widgets::ManualClock& clock, MonkeyFiles files,
           std::uint64_t seed);
    ~Monkey();

    /// One random action, then the invariants. False on a broken invariant (failure() says which).
    bool step();
    /// The empty string while every invariant holds.
    const std::string& failure() const { return m_failure; }
    /// The actions done, one a line (the last `count` of them).
    std::string log(std::size_t count = 60) const;
    std::size_t actions() const { return m_done; }
    /// Prints every action as it is done (BUNRAKU_MONKEY_VERBOSE).
    void setVerbose(bool verbose) { m_verbose = verbose; }

    /// Seconds spent per kind of action (BUNRAKU_MONKEY_PROFILE): where a run's time goes.
    std::string profile() const;

    /// The monkey running now, for the crash handlers that print its log.
    static Monkey* current();

private:
    int below(int n); ///< uniform in [0, n), n > 0
    double uniform(double lo, double hi);
    bool chance(double p);
    void note(std::string action);

    // The actions.
    void menuAction();
    void spinBox();
    void slider();
    void comboBox();
    void button();
    void warpDrag();
    void phraseDrag();
    void chooseTake();
    void playAndScrub();
    void undoRedoBurst();
    void openFile();
    void saveProject();
    void runJobs();
    void advanceClock();
    void keyShortcut();

    /// Answers a modal dialog or closes a popup menu when one is open (the dialog timer).
    void answerModal();
    /// The visible, enabled widgets of type T in the main window (not in dialogs), in a stable order.
    template <class T> std::vector<T*> controls() const;
    void checkInvariants(const std::string& action);
    void fail(const std::string& what);

    app::MainWindow& m_window;
    MonkeyExecutor& m_executor;
    widgets::ManualClock& m_clock;
    MonkeyFiles m_files;
    std::uint64_t m_seed;
    std::mt19937_64 m_random;
    QStringList m_projects; ///< projects saved during the run (they open again)
    QTimer m_modalTimer;
    int m_modalPokes = 0;
    std::deque<std::string> m_log;
    std::size_t m_done = 0;
    std::string m_failure;
    bool m_verbose = false;
    std::array<std::pair<std::size_t, double>, 15> m_profile{};
};

} // namespace bunraku::test
