#include "tests/monkey/monkey.h"

#include "app/analysis_controller.h"
#include "app/design_panel.h"
#include "app/document.h"
#include "app/file_controller.h"
#include "app/file_dialogs.h"
#include "app/playback_controller.h"
#include "app/project_file.h"
#include "app/viewport_panel.h"

#include "widgets/corpus_browser.h"
#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"
#include "widgets/scrub_bar.h"
#include "widgets/timeline_widget.h"
#include "widgets/viewport_widget.h"
#include "widgets/warp_curve_editor.h"

#include <qcustomplot.h>

#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <iterator>
#include <sstream>

namespace bunraku::test {

namespace {

Monkey* g_current = nullptr;

std::string str(const QString& text) { return text.toStdString(); }

/// A control's name in the log: its object name, else its class and its text or tool tip.
std::string describe(const QObject* object)
{
    if (!object) return "(none)";
    QString name = object->objectName();
    if (name.isEmpty()) {
        if (auto* button = qobject_cast<const QAbstractButton*>(object)) name = button->text();
        if (name.isEmpty())
            if (auto* widget = qobject_cast<const QWidget*>(object)) name = widget->toolTip().left(40);
    }
    return std::string(object->metaObject()->className()) + " '" + str(name) + "'";
}

/// Whether `widget` belongs to the main window itself (not to a dialog or a floating window of
/// another kind), is shown and can be used.
bool usable(const QWidget* widget, const QWidget* window)
{
    if (!widget->isVisible() || !widget->isEnabled()) return false;
    // The 3D view's Cloth box starts the kimono's simulation of every take shown: under the
    // sanitizers each costs seconds of both cores and the run's actions slowed fourfold (230
    // actions in 290 s, 2026-11-29). The kimono's jobs have their own tests
    // (tests_app "[kimono]"); the cloth settings dialog stays reachable.
    if (widget->objectName() == QLatin1String("showCloth")) return false;
    for (auto* up = widget->parentWidget(); up; up = up->parentWidget()) {
        if (up == window) return true;
        if (qobject_cast<const QDialog*>(up) || qobject_cast<const QMenu*>(up)) return false;
    }
    return false;
}

/// Every action reachable from the menu bar, in menu order.
void collectActions(QMenu* menu, std::vector<QAction*>& out)
{
    for (auto* action : menu->actions()) {
        if (action->isSeparator() || !action->isEnabled()) continue;
        if (auto* sub = action->menu()) {
            collectActions(sub, out);
            continue;
        }
        out.push_back(action);
    }
}

} // namespace

bool MonkeyExecutor::runNext()
{
    if (m_jobs.empty()) return false;
    auto job = std::move(m_jobs.front());
    m_jobs.pop_front();
    job();
    return true;
}

Monkey* Monkey::current() { return g_current; }

Monkey::Monkey(app::MainWindow& window, MonkeyExecutor& executor, widgets::ManualClock& clock, MonkeyFiles files,
               std::uint64_t seed)
    : m_window(window), m_executor(executor), m_clock(clock), m_files(std::move(files)), m_seed(seed), m_random(seed)
{
    g_current = this;
    // No wall-clock windows: every clock of the views and the document is the manual one.
    m_window.document().setClock([this] { return m_clock.milliseconds(); });
    m_window.setStatusClock(&m_clock);
    m_window.graphPanel()->grid()->setClock(&m_clock);
    m_window.viewportPanel()->viewport()->setClock(&m_clock);
    // The file dialogs: a path of the right kind from the pools, or cancel.
    app::setFileChooser([this](app::FilePurpose purpose, const QString&) -> QString {
        if (chance(0.15)) return {}; // cancelled
        const QString scratch = m_files.scratch;
        switch (purpose) {
        case app::FilePurpose::Corpus:
            if (!m_files.corpora.isEmpty() && chance(0.8)) return m_files.corpora[below(int(m_files.corpora.size()))];
            return m_files.bad.isEmpty() ? QString() : m_files.bad[below(int(m_files.bad.size()))];
        case app::FilePurpose::Project:
            if (!m_projects.isEmpty() && chance(0.5)) return m_projects[below(int(m_projects.size()))];
            return scratch + QStringLiteral("/chosen-%1").arg(below(4)) + QString::fromLatin1(app::kProjectSuffix);
        case app::FilePurpose::ImportTake:
            if (!m_files.takes.isEmpty() && chance(0.7)) return m_files.takes[below(int(m_files.takes.size()))];
            return m_files.bad.isEmpty() ? QString() : m_files.bad[below(int(m_files.bad.size()))];
        case app::FilePurpose::NewCorpus: return scratch + QStringLiteral("/new-corpus-%1").arg(below(3));
        case app::FilePurpose::ExportTake: return scratch + (chance(0.5) ? QStringLiteral("/take.csv") : QStringLiteral("/take.bvh"));
        case app::FilePurpose::Screenshot: return scratch + QStringLiteral("/shot.png");
        case app::FilePurpose::Report: return scratch + QStringLiteral("/report.html");
        case app::FilePurpose::Video: return scratch + QStringLiteral("/video.mp4");
        case app::FilePurpose::VideoFrames: return scratch + QStringLiteral("/frames");
        }
        return {};
    });
    // Modal dialogs and popup menus run their own event loops: this timer answers them there.
    m_modalTimer.setInterval(0);
    QObject::connect(&m_modalTimer, &QTimer::timeout, [this] { answerModal(); });
    m_modalTimer.start();
}

Monkey::~Monkey()
{
    app::setFileChooser({});
    if (g_current == this) g_current = nullptr;
}

int Monkey::below(int n) { return int(std::uniform_int_distribution<int>(0, n - 1)(m_random)); }
double Monkey::uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_random); }
bool Monkey::chance(double p) { return std::bernoulli_distribution(p)(m_random); }

void Monkey::note(std::string action)
{
    if (m_verbose) std::fprintf(stderr, "monkey %zu: %s\n", m_done, action.c_str());
    m_log.push_back(std::to_string(m_done) + ": " + std::move(action));
    if (m_log.size() > 400) m_log.pop_front();
}

std::string Monkey::log(std::size_t count) const
{
    std::string text = "  (seed " + std::to_string(m_seed) + ")\n";
    const std::size_t first = m_log.size() > count ? m_log.size() - count : 0;
    for (std::size_t k = first; k < m_log.size(); ++k) text += "  " + m_log[k] + "\n";
    return text;
}

template <class T> std::vector<T*> Monkey::controls() const
{
    std::vector<T*> found;
    for (auto* widget : m_window.findChildren<T*>())
        if (usable(widget, &m_window)) found.push_back(widget);
    return found; // findChildren's order: creation order, the same on every run
}

bool Monkey::step()
{
    ++m_done;
    // Weighted actions: what a person does most (controls, takes, time) most often.
    struct Choice {
        int weight;
        void (Monkey::*action)();
    };
    static const Choice choices[] = {
        {6, &Monkey::menuAction},   {10, &Monkey::spinBox},     {6, &Monkey::slider},
        {6, &Monkey::comboBox},     {8, &Monkey::button},       {6, &Monkey::warpDrag},
        {6, &Monkey::phraseDrag},   {8, &Monkey::chooseTake},   {8, &Monkey::playAndScrub},
        {6, &Monkey::undoRedoBurst}, {2, &Monkey::openFile},    {1, &Monkey::saveProject},
        {3, &Monkey::runJobs},      {4, &Monkey::advanceClock}, {4, &Monkey::keyShortcut},
    };
    int total = 0;
    for (const auto& choice : choices) total += choice.weight;
    int pick = below(total);
    const Choice* chosen = &choices[0];
    for (const auto& choice : choices) {
        if (pick < choice.weight) {
            chosen = &choice;
            break;
        }
        pick -= choice.weight;
    }
    const std::size_t before = m_log.size();
    const auto started = std::chrono::steady_clock::now(); // measured only (profile()), never acted on
    (this->*chosen->action)();
    QCoreApplication::sendPostedEvents();
    QCoreApplication::processEvents();
    auto& spent = m_profile[std::size_t(chosen - choices)];
    spent.first += 1;
    spent.second += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    checkInvariants(m_log.size() > before ? m_log.back() : std::string("(nothing to do)"));
    return m_failure.empty();
}

std::string Monkey::profile() const
{
    static const char* names[] = {"menu", "spin box", "slider", "combo", "button", "warp drag", "phrase drag", "take",
                                  "play/scrub", "undo/redo", "open", "save", "jobs", "clock", "key"};
    std::string text;
    for (std::size_t k = 0; k < m_profile.size(); ++k)
        if (m_profile[k].first > 0)
            text += std::string("  ") + names[k] + ": " + std::to_string(m_profile[k].first) + " actions, " +
                    std::to_string(m_profile[k].second) + " s\n";
    return text;
}

void Monkey::fail(const std::string& what)
{
    if (m_failure.empty()) m_failure = what;
}

// --- actions ----------------------------------------------------------------------------------

void Monkey::menuAction()
{
    std::vector<QAction*> actions;
    for (auto* action : m_window.menuBar()->actions())
        if (action->menu() && action->isEnabled()) collectActions(action->menu(), actions);
    // Quit closes the window the run needs; it is the one menu action left out.
    actions.erase(std::remove_if(actions.begin(), actions.end(),
                                 [](QAction* a) { return a->text().remove('&') == QStringLiteral("Quit"); }),
                  actions.end());
    if (actions.empty()) return;
    auto* action = actions[std::size_t(below(int(actions.size())))];
    note("menu " + str(action->text().remove('&')));
    action->trigger();
}

void Monkey::spinBox()
{
    const auto boxes = controls<QAbstractSpinBox>();
    if (boxes.empty()) return;
    auto* box = boxes[std::size_t(below(int(boxes.size())))];
    double lo = 0, hi = 0;
    if (auto* spin = qobject_cast<QSpinBox*>(box)) lo = spin->minimum(), hi = spin->maximum();
    else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(box)) lo = dspin->minimum(), hi = dspin->maximum();
    else return; // (time edits: none in the window)
    const int mode = below(5);
    if (mode == 0 || mode == 1) { // at a limit, or typed beyond it
        const double span = std::max(1.0, hi - lo);
        const double value = mode == 0 ? (chance(0.5) ? lo : hi) : (chance(0.5) ? lo - uniform(0.0, span) : hi + uniform(0.0, 10 * span));
        const QString text = QString::number(value, 'g', 12);
        note("spin box " + describe(box) + " typed " + str(text));
        box->setFocus();
        if (auto* edit = box->findChild<QLineEdit*>()) edit->selectAll();
        QTest::keyClicks(box, text);
        QTest::keyClick(box, Qt::Key_Return);
        if (chance(0.5)) box->clearFocus(); // ends the step series
    } else if (mode == 2) { // a burst of arrow steps (merging into one undo step)
        const int steps = 1 + below(8);
        const int sign = chance(0.5) ? 1 : -1;
        note("spin box " + describe(box) + " steps " + std::to_string(sign * steps));
        for (int k = 0; k < steps; ++k) {
            box->stepBy(sign);
            if (chance(0.3)) m_clock.advance(below(1500));
        }
    } else { // a value inside the range
        const double value = uniform(lo, hi);
        note("spin box " + describe(box) + " set " + std::to_string(value));
        if (auto* spin = qobject_cast<QSpinBox*>(box)) spin->setValue(int(std::lround(value)));
        else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(box)) dspin->setValue(value);
    }
}

void Monkey::slider()
{
    const auto sliders = controls<QAbstractSlider>();
    if (sliders.empty()) return;
    auto* slider = sliders[std::size_t(below(int(sliders.size())))];
    const int lo = slider->minimum(), hi = slider->maximum();
    const int mode = below(4);
    if (mode == 0) { // a drag: pressed, moved through values (beyond the ends), released
        note("slider " + describe(slider) + " drag");
        slider->setSliderDown(true);
        const int moves = 1 + below(6);
        for (int k = 0; k < moves; ++k) {
            const long long span = std::max(1LL, (long long)hi - lo);
            slider->setSliderPosition(int(std::clamp<long long>(lo - span / 4 + below(int(std::min<long long>(span * 3 / 2 + 1, 1 << 30))), INT_MIN / 2, INT_MAX / 2)));
            QCoreApplication::processEvents();
        }
        slider->setSliderDown(false);
    } else if (mode == 1) {
        const int value = chance(0.5) ? lo : hi;
        note("slider " + describe(slider) + " to limit " + std::to_string(value));
        slider->setValue(value);
    } else {
        note("slider " + describe(slider) + " page step");
        slider->triggerAction(chance(0.5) ? QAbstractSlider::SliderPageStepAdd : QAbstractSlider::SliderPageStepSub);
    }
}

void Monkey::comboBox()
{
    const auto combos = controls<QComboBox>();
    if (combos.empty()) return;
    auto* combo = combos[std::size_t(below(int(combos.size())))];
    if (combo->count() == 0) return;
    const int index = below(combo->count());
    note("combo " + describe(combo) + " index " + std::to_string(index));
    combo->setCurrentIndex(index);
}

void Monkey::button()
{
    const auto buttons = controls<QAbstractButton>();
    if (buttons.empty()) return;
    auto* button = buttons[std::size_t(below(int(buttons.size())))];
    note("click " + describe(button));
    button->click();
}

void Monkey::warpDrag()
{
    auto* editor = m_window.designPanel()->editor();
    if (!usable(editor, &m_window)) return;
    auto* plot = editor->plot();
    const QRect area = plot->rect();
    if (area.width() < 4 || area.height() < 4) return;
    const auto point = [&](double margin) {
        // Inside the plot, and sometimes beyond its edges (a drag leaving the widget).
        const int w = area.width(), h = area.height();
        return QPoint(int(uniform(-margin * w, (1 + margin) * w)), int(uniform(-margin * h, (1 + margin) * h)));
    };
    QPoint from = point(0.0);
    const auto& points = editor->curve().points;
    if (!points.empty() && chance(0.7)) from = editor->pointPosition(std::size_t(below(int(points.size())))); // grab a point
    if (chance(0.15)) {
        note("warp double click");
        QTest::mouseDClick(plot, Qt::LeftButton, Qt::NoModifier, from);
        return;
    }
    const int moves = 1 + below(5);
    note("warp drag from " + std::to_string(from.x()) + "," + std::to_string(from.y()) + " moves " + std::to_string(moves));
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, from);
    QPoint at = from;
    for (int k = 0; k < moves; ++k) {
        at = point(0.3);
        QMouseEvent move(QEvent::MouseMove, at, plot->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(plot, &move);
    }
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, at);
}

void Monkey::phraseDrag()
{
    auto* bar = m_window.timeline()->scrubBar();
    if (!usable(bar, &m_window) || bar->width() < 4) return;
    const int y = bar->height() / 4; // the ticks are above the bar
    int x = below(bar->width());
    const auto& marks = bar->boundaries();
    if (!marks.empty() && chance(0.7)) x = bar->xOfTime(marks[std::size_t(below(int(marks.size())))]);
    const int mode = below(6);
    if (mode == 0) { // the context menu: add or remove a boundary
        std::unique_ptr<QMenu> menu(bar->createContextMenu(QPoint(x, y)));
        if (!menu || menu->actions().isEmpty()) return;
        auto* action = menu->actions()[below(int(menu->actions().size()))];
        note("phrase menu at " + std::to_string(x) + ": " + str(action->text()));
        action->trigger();
        return;
    }
    if (mode == 1) {
        note("phrase double click at " + std::to_string(x));
        QTest::mouseDClick(bar, Qt::LeftButton, Qt::NoModifier, QPoint(x, y));
        return;
    }
    const int moves = 1 + below(5);
    note("phrase drag from x " + std::to_string(x) + " moves " + std::to_string(moves));
    QTest::mousePress(bar, Qt::LeftButton, Qt::NoModifier, QPoint(x, y));
    QPoint at(x, y);
    for (int k = 0; k < moves; ++k) {
        at = QPoint(int(uniform(-0.2, 1.2) * bar->width()), y);
        QMouseEvent move(QEvent::MouseMove, at, bar->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(bar, &move);
    }
    QTest::mouseRelease(bar, Qt::LeftButton, Qt::NoModifier, at);
    if (chance(0.2)) {
        note("phrase key Delete");
        QTest::keyClick(bar, Qt::Key_Delete);
    }
}

void Monkey::chooseTake()
{
    auto& document = m_window.document();
    QList<app::TakeId> ids;
    for (std::size_t k = 0; k < document.corpus().takes.size(); ++k) ids << app::TakeId::corpus(k);
    for (const auto& derived : document.derivedTakes()) ids << derived.id;
    if (ids.isEmpty()) return;
    const app::TakeId id = ids[below(int(ids.size()))];
    const auto slot = chance(0.6) ? app::TakeSlot::A : app::TakeSlot::B;
    const char* name = slot == app::TakeSlot::A ? "A" : "B";
    if (chance(0.5)) { // as a person does: the browser's row, then its button
        auto* browser = m_window.browser();
        if (!browser->selectId(id.toString())) return;
        for (auto* button : browser->findChildren<QPushButton*>()) {
            if (button->text() == (slot == app::TakeSlot::A ? QStringLiteral("Show as A") : QStringLiteral("Show as B"))) {
                note(std::string("browser: ") + str(id.toString()) + " shown as " + name);
                if (button->isEnabled()) button->click();
                return;
            }
        }
        return;
    }
    if (slot == app::TakeSlot::B && chance(0.2)) {
        note("take B none");
        document.selectTake(slot, {});
        return;
    }
    note("take " + std::string(name) + " " + str(id.toString()));
    document.selectTake(slot, id);
}

void Monkey::playAndScrub()
{
    auto& document = m_window.document();
    auto* timeline = m_window.timeline();
    const int mode = below(6);
    if (mode == 0) { // play for a while: the timer's ticks, made by hand (no wall clock)
        const int ticks = 1 + below(20);
        note("play " + std::to_string(ticks) + " ticks");
        timeline->playAction()->trigger();
        for (int k = 0; k < ticks; ++k) m_window.playback().advance(uniform(0.0, 0.5));
        if (m_window.playback().playing()) timeline->playAction()->trigger();
    } else if (mode == 1) {
        const double t = uniform(-0.2, 1.2) * std::max(document.duration(), 1.0);
        note("set time " + std::to_string(t));
        document.setCurrentTime(t);
    } else if (mode == 2) {
        auto* bar = timeline->scrubBar();
        if (!usable(bar, &m_window) || bar->width() < 2) return;
        const int x = int(uniform(-0.1, 1.1) * bar->width());
        note("scrub press at x " + std::to_string(x));
        QTest::mousePress(bar, Qt::LeftButton, Qt::NoModifier, QPoint(x, bar->height() * 3 / 4));
        QTest::mouseRelease(bar, Qt::LeftButton, Qt::NoModifier, QPoint(x, bar->height() * 3 / 4));
    } else {
        QAction* actions[] = {timeline->stepForwardAction(), timeline->stepBackAction(), timeline->homeAction(),
                              timeline->endAction(), timeline->loopAction()};
        auto* action = actions[below(5)];
        note("timeline " + str(action->text().remove('&')));
        action->trigger();
    }
}

void Monkey::undoRedoBurst()
{
    auto& document = m_window.document();
    auto* stack = document.undoStack();
    const int mode = below(3);
    if (mode == 0 && stack->index() > 0) { // undo then redo as many: the same parameters again
        const int n = 1 + below(stack->index());
        note("undo " + std::to_string(n) + " then redo " + std::to_string(n));
        const auto before = document.parameters();
        const auto imported = document.derivedTakes().size();
        const int index = stack->index();
        for (int k = 0; k < n; ++k) stack->undo();
        for (int k = 0; k < n; ++k) stack->redo();
        if (stack->index() != index) fail("undo/redo round trip: index " + std::to_string(stack->index()) + ", was " + std::to_string(index));
        if (app::changedSections(before, document.parameters()) != 0)
            fail("undo/redo round trip: the parameters differ in sections " + std::to_string(app::changedSections(before, document.parameters())));
        (void)imported; // live takes come and go with the parameters: only the parameters are compared
        return;
    }
    const int n = 1 + below(10);
    const bool undo = mode != 2;
    note(std::string(undo ? "undo" : "redo") + " burst " + std::to_string(n));
    for (int k = 0; k < n; ++k) undo ? stack->undo() : stack->redo();
}

void Monkey::openFile()
{
    auto& files = m_window.files();
    const int mode = below(7);
    if (mode == 0) {
        note("open demo corpus");
        files.corpora().openDemoCorpus();
    } else if (mode == 1 && !m_files.corpora.isEmpty()) {
        const QString path = m_files.corpora[below(int(m_files.corpora.size()))];
        note("open corpus " + str(path));
        files.openPath(path);
    } else if (mode == 2 && !m_projects.isEmpty()) {
        const QString path = m_projects[below(int(m_projects.size()))];
        note("open project " + str(path));
        files.openPath(path);
    } else if (mode == 3 && !m_files.takes.isEmpty()) {
        const QString path = m_files.takes[below(int(m_files.takes.size()))];
        note("import take " + str(path));
        files.openPath(path);
    } else if (!m_files.bad.isEmpty()) {
        const QString path = m_files.bad[below(int(m_files.bad.size()))];
        note("open bad " + str(path));
        if (files.openPath(path)) fail("a bad file opened: " + str(path));
    }
}

void Monkey::saveProject()
{
    const QString path = m_files.scratch + QStringLiteral("/project-%1").arg(below(3)) + QString::fromLatin1(app::kProjectSuffix);
    note("save project " + str(path));
    if (m_window.files().projects().saveProject(path)) {
        if (!m_projects.contains(path)) m_projects << path;
    }
}

void Monkey::runJobs()
{
    // Mostly one job (results arrive one by one, between other actions), sometimes all: the
    // analysis itself is the time of a run (its own tests and fuzzers cover it).
    const int n = chance(0.15) ? 1000 : 1 + below(2);
    note("run " + (n == 1000 ? std::string("all") : std::to_string(n)) + " analysis jobs (" + std::to_string(m_executor.pending()) + " waiting)");
    for (int k = 0; k < n && m_executor.runNext(); ++k) {
        QCoreApplication::sendPostedEvents(); // the scheduler's delivery
        QCoreApplication::processEvents();
    }
}

void Monkey::advanceClock()
{
    const int ms = chance(0.5) ? below(300) : below(5000);
    note("clock +" + std::to_string(ms) + " ms");
    m_clock.advance(ms);
}

void Monkey::keyShortcut()
{
    struct Key {
        Qt::Key key;
        Qt::KeyboardModifiers modifiers;
        const char* name;
    };
    static const Key keys[] = {
        {Qt::Key_Left, Qt::NoModifier, "Left"},  {Qt::Key_Right, Qt::NoModifier, "Right"},
        {Qt::Key_Home, Qt::NoModifier, "Home"},  {Qt::Key_End, Qt::NoModifier, "End"},
        {Qt::Key_Z, Qt::ControlModifier, "Ctrl+Z"}, {Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier, "Ctrl+Shift+Z"},
        {Qt::Key_Escape, Qt::NoModifier, "Escape"}, {Qt::Key_Tab, Qt::NoModifier, "Tab"},
    };
    const auto& key = keys[below(int(std::size(keys)))];
    QWidget* target = QApplication::focusWidget();
    if (!target || target->window() != &m_window) target = &m_window;
    note(std::string("key ") + key.name + " to " + describe(target));
    QTest::keyClick(target, key.key, key.modifiers);
}

// --- dialogs ----------------------------------------------------------------------------------

void Monkey::answerModal()
{
    if (auto* popup = QApplication::activePopupWidget()) { // a menu or a combo box's list
        note("close popup " + describe(popup));
        popup->close();
        return;
    }
    auto* modal = QApplication::activeModalWidget();
    if (!modal) {
        m_modalPokes = 0;
        return;
    }
    if (auto* box = qobject_cast<QMessageBox*>(modal)) { // a question or a message: any answer
        const auto buttons = box->buttons();
        if (!buttons.isEmpty()) {
            auto* answer = buttons[below(int(buttons.size()))];
            note("message box '" + str(box->text().left(80)) + "': " + str(answer->text()));
            answer->click();
            return;
        }
    }
    auto* dialog = qobject_cast<QDialog*>(modal);
    // Some use of the dialog's controls first (closing it midway), then Cancel: accepting could
    // start an export of minutes under the sanitizers; the exports have their own tests.
    if (dialog && m_modalPokes < 4 && chance(0.6)) {
        ++m_modalPokes;
        std::vector<QWidget*> inside;
        for (auto* widget : dialog->findChildren<QWidget*>())
            if (widget->isVisible() && widget->isEnabled() &&
                (qobject_cast<QAbstractSpinBox*>(widget) || qobject_cast<QComboBox*>(widget) || qobject_cast<QCheckBox*>(widget)))
                inside.push_back(widget);
        if (!inside.empty()) {
            auto* widget = inside[std::size_t(below(int(inside.size())))];
            note("in dialog " + describe(dialog) + ": " + describe(widget));
            if (auto* combo = qobject_cast<QComboBox*>(widget); combo && combo->count() > 0) combo->setCurrentIndex(below(combo->count()));
            else if (auto* check = qobject_cast<QCheckBox*>(widget)) check->click();
            else if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget)) spin->stepBy(chance(0.5) ? 5 : -5);
            return;
        }
    }
    note("close dialog " + describe(modal));
    if (dialog) dialog->reject();
    else modal->close();
}

// --- invariants -------------------------------------------------------------------------------

void Monkey::checkInvariants(const std::string& action)
{
    (void)action;
    auto& document = m_window.document();
    // The undo stack is consistent with itself.
    auto* stack = document.undoStack();
    if (stack->index() < 0 || stack->index() > stack->count())
        fail("undo stack index " + std::to_string(stack->index()) + " outside [0, " + std::to_string(stack->count()) + "]");
    if (stack->canUndo() != (stack->index() > 0) || stack->canRedo() != (stack->index() < stack->count()))
        fail("undo stack: canUndo/canRedo disagree with its index");
    // The shown takes exist; the time is inside them.
    const app::TakeId idA = document.selectedId(app::TakeSlot::A);
    const app::TakeId idB = document.selectedId(app::TakeSlot::B);
    if (!idA.isEmpty() && !document.take(idA)) fail("take A " + str(idA.toString()) + " is shown but is no take of the document");
    if (!idB.isEmpty() && !document.take(idB)) fail("take B " + str(idB.toString()) + " is shown but is no take of the document");
    if (idA.isEmpty() && !document.corpus().takes.empty()) fail("no take A with a corpus open");
    const double t = document.currentTime();
    if (!(t >= 0.0) || t > document.duration() + 1e-9)
        fail("time " + std::to_string(t) + " outside [0, " + std::to_string(document.duration()) + "]");
    // The status bar names takes A and B as they are now (a live take's label follows its
    // recomputation): in full in its tool tip.
    if (!idA.isEmpty()) {
        QString shown = document.takeLabel(idA);
        if (!idB.isEmpty()) shown += QStringLiteral(" vs ") + document.takeLabel(idB);
        if (!m_window.shownTakesLabel()->toolTip().endsWith(shown))
            fail("the status bar's takes are '" + str(m_window.shownTakesLabel()->toolTip()) + "', the document shows '" + str(shown) + "'");
    }
    // No live result of a stale key: once every job has run, every stage shown is the current
    // inputs' (AnalysisController::isCurrent) and nothing is left running.
    auto& analysis = m_window.analysis();
    if (m_executor.pending() == 0) {
        for (int slot : {app::AnalysisController::kPreprocessSlot, app::AnalysisController::kNormaliseSlot,
                         app::AnalysisController::kDecomposeSlot, app::AnalysisController::kAxesSlot}) {
            const auto state = analysis.scheduler().state(slot);
            if (state == app::SlotState::Running)
                fail("stage " + str(app::AnalysisController::slotTitle(slot)) + " running with no job left");
            if (state == app::SlotState::Finished && !analysis.isCurrent(slot))
                fail("stage " + str(app::AnalysisController::slotTitle(slot)) + " shows a result of a stale key");
        }
        // The live takes shown are published ones.
        for (const auto& id : {idA, idB})
            if (id.isLive() && document.indexOfDerived(id) < 0)
                fail("live take " + str(id.toString()) + " shown but not published");
    }
    // The 3D view's motion axis of take A is take A's (never another take's or older parameters').
    if (auto take = document.selectedTake(app::TakeSlot::A)) (void)analysis.takeAxis(app::TakeSlot::A, take);
    if (!m_failure.empty()) m_failure = "after step " + std::to_string(m_done) + " (" + action + "): " + m_failure;
}

} // namespace bunraku::test
