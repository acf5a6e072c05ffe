#pragma once
/// The names and defaults of the document's undoable analysis parameters. Keys are
/// "<panel>.<name>"; values are QVariants of the documented type. The project file stores them
/// by these names.

#include <QString>
#include <QVariant>

namespace bunraku::app::parameters {

// Normalisation (thesis 3.5-3.6): the cell of take A is normalised to a reference take.
inline const QString kNormaliseReference = QStringLiteral("normalise.reference"); ///< QString take id; empty: suggested
inline const QString kNormaliseTau = QStringLiteral("normalise.tau");             ///< int, frames (thesis: 4)
inline const QString kNormaliseSearchBand = QStringLiteral("normalise.searchBand"); ///< int, T_cmp frames (thesis: 20)
inline const QString kNormaliseMaxScale = QStringLiteral("normalise.maxScale");   ///< int, scales 1..max (thesis: 16)
inline const QString kNormaliseCoupling = QStringLiteral("normalise.coupling");   ///< QString preset or explicit spec
inline const QString kNormalisePath = QStringLiteral("normalise.path");           ///< QString "greedy" | "optimal"

// Emotion (thesis ch. 4): decomposition and the emotion weight a.
inline const QString kEmotionMethod = QStringLiteral("emotion.method"); ///< QString
inline const QString kEmotionOrder = QStringLiteral("emotion.order");   ///< int, M
inline const QString kEmotionWeight = QStringLiteral("emotion.weight"); ///< double, a (1 = measured emotion)

// Design (thesis ch. 5): the warp curve and per-phrase gains.
inline const QString kDesignWarp = QStringLiteral("design.warp");   ///< QVariantList of QVariantList{reference s, sample s}
inline const QString kDesignGains = QStringLiteral("design.gains"); ///< QVariantMap "phrase/dof" -> QVariantList{g0, g1}
/// QVariantList of int: the inner phrase boundaries, functional frames, increasing; empty: suggested
inline const QString kDesignBoundaries = QStringLiteral("design.boundaries");

/// The default value of `key`; an invalid QVariant for unknown keys.
QVariant defaultValue(const QString& key);
/// Every key with a default, for the project file and "reset".
QStringList knownKeys();

} // namespace bunraku::app::parameters
