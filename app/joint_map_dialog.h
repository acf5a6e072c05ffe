#pragma once
/// Chooses which BVH joints become the puppet's head, shoulder, arm and hand, preset from the
/// built-in maps (analysis/io/bvh_import.h defaultJointMap) when one fits the skeleton.

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

#include <QDialog>

#include <array>

class QComboBox;

namespace bunraku::app {

class JointMapDialog : public QDialog {
    Q_OBJECT
public:
    JointMapDialog(const analysis::io::BvhSkeleton& skeleton, const QString& fileName, QWidget* parent = nullptr);

    analysis::io::JointMap jointMap() const;
    /// "head=...,shoulder=...,arm=...,hand=..." as the CLI's --joints takes it.
    QString jointMapText() const;

private:
    std::array<QComboBox*, 4> m_parts{};
};

} // namespace bunraku::app
