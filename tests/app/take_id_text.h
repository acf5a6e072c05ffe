#pragma once
/// Tests compare take ids with their text ("corpus/3", "live/designed"), as the project file
/// writes it: a readable expected value, and the one Catch2 prints when a comparison fails. Only
/// tests may compare an id with text; the app asks TakeId::kind(), index() and name().

#include "app/take_id.h"

#include <QString>

#include <ostream>

namespace bunraku::app {

inline bool operator==(const TakeId& id, const QString& text) { return id.toString() == text; }
inline bool operator==(const TakeId& id, const char* text) { return id.toString() == QLatin1String(text); }
inline std::ostream& operator<<(std::ostream& out, const TakeId& id)
{
    return out << (id.isEmpty() ? std::string("(no take)") : id.toString().toStdString());
}

} // namespace bunraku::app
