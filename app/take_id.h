#pragma once
/// Which take the workbench means: a take of the open corpus (its index in Corpus::takes), an
/// imported take (its serial number, 1, 2, ...) or a live analysis result (its name: "designed",
/// "weighted", "normalised", ...). A small value type: the app asks kind(), index() and name()
/// and never reads an id's text.
///
/// The text ("corpus/3", "imported/1", "live/designed") is written by toString() alone, for the
/// project file, the corpus browser's keys and messages; only the project file reads it back
/// (app/project_file.cpp). A ctest check greps app/ for the spelling.

#include <QMetaType>
#include <QString>

#include <cstddef>
#include <utility>

namespace bunraku::app {

class TakeId {
public:
    enum class Kind : unsigned char { None, Corpus, Imported, Live };

    /// No take (take B when none is shown).
    TakeId() = default;
    static TakeId corpus(std::size_t index) { return TakeId(Kind::Corpus, index, {}); }
    static TakeId imported(std::size_t serial) { return TakeId(Kind::Imported, serial, {}); }
    static TakeId live(const QString& name) { return TakeId(Kind::Live, 0, name); }

    Kind kind() const { return m_kind; }
    bool isEmpty() const { return m_kind == Kind::None; }
    bool isCorpus() const { return m_kind == Kind::Corpus; }
    bool isImported() const { return m_kind == Kind::Imported; }
    bool isLive() const { return m_kind == Kind::Live; }
    /// A corpus take's index, an imported take's serial number; 0 for the others.
    std::size_t index() const { return m_index; }
    /// A live result's name; empty for the others.
    const QString& name() const { return m_name; }

    /// "corpus/<index>", "imported/<serial>", "live/<name>", or empty for no take.
    QString toString() const;

    friend bool operator==(const TakeId& a, const TakeId& b)
    {
        return a.m_kind == b.m_kind && a.m_index == b.m_index && a.m_name == b.m_name;
    }
    /// An order for maps: by kind, then index, then name.
    friend bool operator<(const TakeId& a, const TakeId& b)
    {
        if (a.m_kind != b.m_kind) return a.m_kind < b.m_kind;
        if (a.m_index != b.m_index) return a.m_index < b.m_index;
        return a.m_name < b.m_name;
    }

private:
    TakeId(Kind kind, std::size_t index, QString name) : m_kind(kind), m_index(index), m_name(std::move(name)) {}

    Kind m_kind = Kind::None;
    std::size_t m_index = 0;
    QString m_name;
};

size_t qHash(const TakeId& id, size_t seed = 0);

} // namespace bunraku::app

Q_DECLARE_METATYPE(bunraku::app::TakeId)
