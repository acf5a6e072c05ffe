#include "app/joint_map_dialog.h"

#include "analysis/core/puppet_layout.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace bunraku::app {

JointMapDialog::JointMapDialog(const analysis::io::BvhSkeleton& skeleton, const QString& fileName, QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Joint map for %1").arg(fileName));
    QStringList joints;
    for (const auto& joint : skeleton.joints)
        if (!joint.endSite) joints << QString::fromStdString(joint.name);
    const auto preset = analysis::io::defaultJointMap(skeleton);

    auto* form = new QFormLayout;
    for (int part = 0; part < 4; ++part) {
        m_parts[std::size_t(part)] = new QComboBox(this);
        m_parts[std::size_t(part)]->addItems(joints);
        if (preset) m_parts[std::size_t(part)]->setCurrentText(QString::fromStdString(preset->joints[std::size_t(part)]));
        form->addRow(QString::fromStdString(std::string(analysis::kPuppetParts[std::size_t(part)])), m_parts[std::size_t(part)]);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Which joint of the file drives each part of the puppet?"), this));
    layout->addLayout(form);
    layout->addWidget(buttons);
}

analysis::io::JointMap JointMapDialog::jointMap() const
{
    analysis::io::JointMap map;
    for (std::size_t part = 0; part < 4; ++part) map.joints[part] = m_parts[part]->currentText().toStdString();
    return map;
}

QString JointMapDialog::jointMapText() const
{
    QStringList items;
    for (std::size_t part = 0; part < 4; ++part)
        items << QStringLiteral("%1=%2").arg(QString::fromStdString(std::string(analysis::kPuppetParts[part])),
                                             m_parts[part]->currentText());
    return items.join(',');
}

} // namespace bunraku::app
