#include "app/joint_map_dialog.h"

#include "app/offscreen_view.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh_joint_map.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>

namespace bunraku::app {
namespace {

const QString kChoose = QObject::tr("(choose a joint)");
constexpr int kPreviewSize = 260;

} // namespace

QComboBox* makeUnitsBox(QWidget* parent)
{
    auto* units = new QComboBox(parent);
    units->setObjectName(QStringLiteral("units"));
    units->addItem(QObject::tr("Guess"));
    units->addItem(QObject::tr("Centimetres"), 1.0);
    units->addItem(QObject::tr("Metres"), 100.0);
    units->addItem(QObject::tr("Millimetres"), 0.1);
    units->addItem(QObject::tr("Inches"), 2.54);
    units->setToolTip(QObject::tr("The files' length unit. A skeleton 40 to 100 units tall reads as a small figure in "
                                  "centimetres (a puppet, a child) or as a person in inches; Guess tells them apart by a "
                                  "walking take's pace and says which it chose"));
    return units;
}

void applyUnitsChoice(const QComboBox& units, analysis::io::BvhImportOptions& options)
{
    options.guessUnits = units.currentIndex() <= 0;
    if (!options.guessUnits) options.unitScale = units.currentData().toDouble();
}

JointMapDialog::JointMapDialog(const analysis::io::BvhFile& file, const QString& fileName, QWidget* parent)
    : QDialog(parent), m_file(file)
{
    setWindowTitle(tr("Joint map for %1").arg(fileName));
    // The preview needs only the first pose.
    if (m_file.motion.values.rows() > 1) m_file.motion.values.conservativeResize(1, Eigen::NoChange);
    QStringList joints{kChoose};
    for (const auto& joint : m_file.skeleton.joints)
        if (!joint.endSite) joints << QString::fromStdString(joint.name);

    m_side = new QComboBox(this);
    m_side->addItem(tr("Right arm and hand"));
    m_side->addItem(tr("Left arm and hand"));
    m_units = makeUnitsBox(this);
    m_height = new QLabel(this);
    m_height->setObjectName(QStringLiteral("height"));
    m_height->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("Side"), m_side);
    form->addRow(tr("Units"), m_units);
    form->addRow(QString(), m_height);
    for (int part = 0; part < 4; ++part) {
        auto* box = new QComboBox(this);
        box->addItems(joints);
        box->setObjectName(QStringLiteral("part_%1").arg(QString::fromStdString(std::string(analysis::kPuppetParts[std::size_t(part)]))));
        m_parts[std::size_t(part)] = box;
        m_found[std::size_t(part)] = new QLabel(this);
        auto* row = new QHBoxLayout;
        row->addWidget(box, 1);
        row->addWidget(m_found[std::size_t(part)]);
        form->addRow(QString::fromStdString(std::string(analysis::kPuppetParts[std::size_t(part)])), row);
        connect(box, &QComboBox::currentIndexChanged, this, [this, part] {
            if (!m_applying) m_found[std::size_t(part)]->setText(tr("(chosen)"));
            update();
        });
    }
    connect(m_side, &QComboBox::currentIndexChanged, this, &JointMapDialog::applyAutomaticMap);
    connect(m_units, &QComboBox::currentIndexChanged, this, &JointMapDialog::update);

    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setMinimumHeight(4 * fontMetrics().lineSpacing()); // room for the longest message
    m_message->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_image = new QLabel(this);
    m_image->setMinimumSize(kPreviewSize, kPreviewSize);
    m_image->setAlignment(Qt::AlignCenter);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* left = new QVBoxLayout;
    left->addWidget(new QLabel(tr("Which joint of the file drives each part of the puppet?"), this));
    left->addLayout(form);
    left->addWidget(m_message);
    left->addStretch(1);
    auto* columns = new QHBoxLayout;
    columns->addLayout(left, 1);
    columns->addWidget(m_image);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns);
    layout->addWidget(buttons);
    applyAutomaticMap();
}

void JointMapDialog::applyAutomaticMap()
{
    analysis::io::PartMapOptions options;
    options.side = side();
    const auto map = analysis::io::mapPuppetParts(m_file, std::nullopt, options);
    m_applying = true;
    for (std::size_t part = 0; part < 4; ++part) {
        // Nothing is preset for a part the automatic map cannot find: no four identical parts.
        m_parts[part]->setCurrentText(map ? QString::fromStdString(map->names.joints[part]) : kChoose);
        m_found[part]->setText(map ? tr("(by %1)").arg(QString::fromLatin1(analysis::io::mapMethodName(map->methods[part])))
                                   : QString());
    }
    m_applying = false;
    m_note = map ? QString() : QString::fromStdString(map.error().message);
    update();
}

analysis::io::JointMap JointMapDialog::jointMap() const
{
    analysis::io::JointMap map;
    for (std::size_t part = 0; part < 4; ++part)
        if (m_parts[part]->currentIndex() > 0) map.joints[part] = m_parts[part]->currentText().toStdString();
    return map;
}

std::optional<double> JointMapDialog::cmPerUnit() const
{
    if (m_units->currentIndex() <= 0) return std::nullopt;
    return m_units->currentData().toDouble();
}

void JointMapDialog::applyUnits(analysis::io::BvhImportOptions& options) const { applyUnitsChoice(*m_units, options); }

QString JointMapDialog::heightText() const
{
    const auto guess = analysis::io::guessBvhUnits(m_file);
    const auto chosen = cmPerUnit();
    const double metres = guess.height * chosen.value_or(guess.cmPerUnit) / 100.0;
    QString text = chosen ? tr("%1 m tall").arg(metres, 0, 'f', 2)
                          : tr("%1 m tall (guessed: %2)").arg(metres, 0, 'f', 2).arg(QString::fromStdString(guess.unit));
    if (guess.height >= 40.0 && guess.height < 100.0 && (!chosen || *chosen == 1.0))
        text += tr("; in inches %1 m: choose Inches for a person").arg(guess.height * 2.54 / 100.0, 0, 'f', 2);
    return text;
}

analysis::BodySide JointMapDialog::side() const
{
    return m_side->currentIndex() == 1 ? analysis::BodySide::Left : analysis::BodySide::Right;
}

QString JointMapDialog::jointMapText() const
{
    QStringList items;
    for (std::size_t part = 0; part < 4; ++part)
        items << QStringLiteral("%1=%2").arg(QString::fromStdString(std::string(analysis::kPuppetParts[part])),
                                             m_parts[part]->currentText());
    return items.join(',');
}

void JointMapDialog::update()
{
    if (m_applying) return;
    m_height->setText(heightText());
    m_problem.clear();
    for (std::size_t part = 0; part < 4 && m_problem.isEmpty(); ++part) {
        if (m_parts[part]->currentIndex() <= 0)
            m_problem = tr("Choose a joint for the %1.").arg(QString::fromStdString(std::string(analysis::kPuppetParts[part])));
        for (std::size_t other = 0; other < part && m_problem.isEmpty(); ++other)
            if (m_parts[part]->currentIndex() == m_parts[other]->currentIndex())
                m_problem = tr("%1 drives both the %2 and the %3: each part needs its own joint.")
                                .arg(m_parts[part]->currentText(), QString::fromStdString(std::string(analysis::kPuppetParts[other])),
                                     QString::fromStdString(std::string(analysis::kPuppetParts[part])));
    }
    m_preview = QImage();
    if (m_problem.isEmpty()) {
        // The first pose as the import will make it: calibrated parts on the fitted puppet.
        analysis::io::BvhImportOptions options;
        options.jointMap = jointMap();
        options.side = side();
        applyUnits(options);
        auto take = analysis::io::bvhToPuppetTake(m_file, options);
        if (!take) {
            m_problem = QString::fromStdString(take.error().message);
        } else {
            double top = 0.0;
            for (int p = 0; p < analysis::kPuppetPartCount; ++p) top = std::max(top, take->values(0, analysis::puppetChannel(p, analysis::Dof::Z)));
            render::Camera camera;
            camera.angleDeg = 300.0f;
            camera.elevationDeg = 10.0f;
            camera.distance = float(std::max(top, 30.0) * 2.1);
            camera.target = {0.0f, 0.0f, float(top * 0.55)};
            render::SceneVisibility visibility;
            visibility.axis = false;
            visibility.partner = false;
            auto view = OffscreenView::create({std::move(take).value()}, camera, visibility, QSize(kPreviewSize, kPreviewSize));
            if (view) m_preview = (*view)->render(0.0);
        }
    }
    m_image->setPixmap(m_preview.isNull() ? QPixmap() : QPixmap::fromImage(m_preview));
    m_image->setText(m_preview.isNull() ? tr("No preview") : QString());
    m_message->setText(m_problem.isEmpty() || m_note.isEmpty() ? m_problem : m_problem + QStringLiteral("\n") + m_note);
    m_message->setStyleSheet(m_problem.isEmpty() ? QString() : QStringLiteral("color: #b00020"));
    m_ok->setEnabled(m_problem.isEmpty());
}

} // namespace bunraku::app
