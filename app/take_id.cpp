#include "app/take_id.h"

#include <QHashFunctions>

namespace bunraku::app {

QString TakeId::toString() const
{
    switch (m_kind) {
    case Kind::Corpus: return QStringLiteral("corpus/%1").arg(m_index);
    case Kind::Imported: return QStringLiteral("imported/%1").arg(m_index);
    case Kind::Live: return QStringLiteral("live/") + m_name;
    case Kind::None: break;
    }
    return {};
}

size_t qHash(const TakeId& id, size_t seed)
{
    return qHashMulti(seed, int(id.kind()), id.index(), id.name());
}

} // namespace bunraku::app
