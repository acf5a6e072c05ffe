#include "app/parameters.h"

#include <QVariantList>

namespace bunraku::app::parameters {

QVariant defaultValue(const QString& key)
{
    static const QVariantMap defaults{
        {kNormaliseReference, QString()},
        {kNormaliseTau, 4},
        {kNormaliseSearchBand, 20},
        {kNormaliseMaxScale, 16},
        {kNormaliseCoupling, QStringLiteral("method2")},
        {kNormalisePath, QStringLiteral("greedy")},
        {kEmotionMethod, QStringLiteral("least-squares")},
        {kEmotionOrder, 8},
        {kEmotionWeight, 1.0},
        {kDesignWarp, QVariantList{}},
        {kDesignGains, QVariantMap{}},
        {kDesignBoundaries, QVariantList{}},
    };
    return defaults.value(key);
}

QStringList knownKeys()
{
    return {kNormaliseReference, kNormaliseTau, kNormaliseSearchBand, kNormaliseMaxScale, kNormaliseCoupling,
            kNormalisePath, kEmotionMethod, kEmotionOrder, kEmotionWeight, kDesignWarp, kDesignGains, kDesignBoundaries};
}

} // namespace bunraku::app::parameters
