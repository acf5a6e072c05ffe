#include "app/new_corpus_dialog.h"

#include "app/file_dialogs.h"
#include "app/joint_map_dialog.h"

#include "analysis/io/bvh_joint_map.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMimeData>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <map>
#include <set>

namespace bunraku::app {
namespace {

namespace io = analysis::io;

constexpr int kEditedRole = Qt::UserRole + 1; ///< set on cells the user changed: relabelling keeps them

std::filesystem::path toPath(const QString& file) { return std::filesystem::path(file.toStdString()); }

} // namespace

NewCorpusDialog::NewCorpusDialog(QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("New Corpus from Files"));
    setAcceptDrops(true);
    auto* addFiles = new QPushButton(tr("Add Files..."), this);
    auto* addFolder = new QPushButton(tr("Add Folder..."), this);
    m_remove = new QPushButton(tr("Remove"), this);
    m_remove->setToolTip(tr("Remove the selected files from the corpus (Delete)"));
    m_remove->setEnabled(false);
    connect(m_remove, &QPushButton::clicked, this, &NewCorpusDialog::removeSelectedRows);
    auto* clear = new QPushButton(tr("Clear"), this);
    clear->setToolTip(tr("Remove every file"));
    connect(addFiles, &QPushButton::clicked, this, [this] {
        addInputs(QFileDialog::getOpenFileNames(this, tr("Take files"), {}, tr("Takes (*.bvh *.fbx *.glb *.gltf *.dae *.csv *.txt *.fastrak *.fst)")));
    });
    connect(addFolder, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Folder of take files"));
        if (!folder.isEmpty()) addInputs({folder});
    });
    connect(clear, &QPushButton::clicked, this, [this] {
        m_files.clear();
        m_starts.clear();
        m_animationNotes.clear();
        m_table->setRowCount(0);
        validate();
    });

    m_pattern = new QLineEdit(QString::fromLatin1(io::kDefaultLabelPattern), this);
    m_pattern->setToolTip(tr("How the file names read: {function}, {emotion}, {take} (digits) and {any}; other characters as "
                             "written. E.g. {any}_{function}_{emotion}_{take} for dataset-2_wave-right-hand_active_003.bvh"));
    connect(m_pattern, &QLineEdit::textChanged, this, &NewCorpusDialog::relabel);

    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setHorizontalHeaderLabels({tr("File"), tr("Function"), tr("Emotion"), tr("Take"), tr("Part map")});
    m_table->horizontalHeader()->setSectionResizeMode(MapColumn, QHeaderView::Stretch);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setMinimumSize(720, 260);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->installEventFilter(this);
    m_table->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_table, &QWidget::customContextMenuRequested, this, [this](const QPoint& position) {
        if (m_table->selectionModel()->selectedRows().isEmpty()) return;
        QMenu menu(this);
        menu.addAction(tr("Remove Selected Files"), this, &NewCorpusDialog::removeSelectedRows);
        menu.exec(m_table->viewport()->mapToGlobal(position));
    });
    connect(m_table, &QTableWidget::itemSelectionChanged, this,
            [this] { m_remove->setEnabled(!m_table->selectionModel()->selectedRows().isEmpty()); });
    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (m_filling) return;
        item->setData(kEditedRole, true);
        validate();
    });

    m_joints = new QLineEdit(this);
    m_joints->setPlaceholderText(tr("automatic (names, then the skeleton's shape)"));
    m_joints->setToolTip(tr("One part map for every BVH file: head=...,shoulder=...,arm=...,hand=... (parts not named are automatic)"));
    connect(m_joints, &QLineEdit::textChanged, this, &NewCorpusDialog::remap);
    auto* chooseMap = new QPushButton(tr("Joint Map..."), this);
    connect(chooseMap, &QPushButton::clicked, this, &NewCorpusDialog::chooseJointMap);
    m_animation = new QLineEdit(this);
    m_animation->setPlaceholderText(tr("the first"));
    m_animation->setToolTip(tr("FBX, glTF and Collada files: the animation to read, by name or 0-based index (the part map column "
                               "lists each file's animations)"));
    connect(m_animation, &QLineEdit::textChanged, this, [this] {
        for (const auto& file : m_files)
            if (io::takeFileFormat(file) == io::TakeFileFormat::Scene) m_starts.erase(file);
        remap();
    });
    m_units = makeUnitsBox(this);
    connect(m_units, &QComboBox::currentIndexChanged, this, &NewCorpusDialog::remap);
    m_channels = new QComboBox(this);
    m_channels->setObjectName("corpusChannels");
    m_channels->addItems({tr("The puppet's four parts (24 channels)"), tr("Every joint of the skeleton (6 channels each)")});
    m_channels->setToolTip(tr("What each BVH, FBX, glTF or Collada take becomes: the puppet's head, shoulder, arm and hand "
                              "(the thesis's 24 channels, through the part map), or every joint of the performer's skeleton - the "
                              "whole body through every analysis, its motion axis from the performer's body segments"));
    m_side = new QComboBox(this);
    m_side->addItems({tr("Right arm and hand"), tr("Left arm and hand")});
    connect(m_side, &QComboBox::currentIndexChanged, this, &NewCorpusDialog::remap);
    m_neutral = new QComboBox(this);
    m_neutral->setToolTip(tr("The emotion meaning 'no emotion'; automatic: neutral, normal or none when present, else the first"));
    connect(m_neutral, &QComboBox::currentIndexChanged, this, &NewCorpusDialog::validate);
    m_rate = new QDoubleSpinBox(this);
    m_rate->setRange(0.0, 1000000.0);
    m_rate->setDecimals(3);
    m_rate->setSpecialValueText(tr("automatic (the rate most files have)"));
    m_rate->setSuffix(tr(" Hz"));
    m_output = new QLineEdit(this);
    connect(m_output, &QLineEdit::textChanged, this, &NewCorpusDialog::validate);
    auto* browse = new QPushButton(tr("Browse..."), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getSaveFileName(this, tr("Corpus folder to create"), m_output->text());
        if (!folder.isEmpty()) m_output->setText(folder);
    });

    auto* inputs = new QHBoxLayout;
    inputs->addWidget(addFiles);
    inputs->addWidget(addFolder);
    inputs->addWidget(m_remove);
    inputs->addWidget(clear);
    inputs->addStretch(1);
    inputs->addWidget(new QLabel(tr("or drop files and folders here"), this));
    auto* joints = new QHBoxLayout;
    joints->addWidget(m_joints, 1);
    joints->addWidget(chooseMap);
    auto* output = new QHBoxLayout;
    output->addWidget(m_output, 1);
    output->addWidget(browse);
    auto* form = new QFormLayout;
    form->addRow(tr("File names"), m_pattern);
    form->addRow(tr("Channels"), m_channels);
    form->addRow(tr("Part map"), joints);
    form->addRow(tr("Animation"), m_animation);
    form->addRow(tr("Side"), m_side);
    form->addRow(tr("Units"), m_units);
    form->addRow(tr("Neutral emotion"), m_neutral);
    form->addRow(tr("Rate"), m_rate);
    form->addRow(tr("Corpus folder"), output);
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_create = buttons->addButton(tr("Create Corpus"), QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (!m_problem.isEmpty()) return;
        if (!m_creator || m_creator(*this)) accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(inputs);
    layout->addWidget(m_table, 1);
    layout->addLayout(form);
    layout->addWidget(m_message);
    layout->addWidget(buttons);
    validate();
}

void NewCorpusDialog::addInputs(const QStringList& paths)
{
    std::vector<std::filesystem::path> inputs;
    for (const QString& path : paths) inputs.push_back(toPath(path));
    if (inputs.empty()) return;
    auto files = io::collectTakeFiles(inputs);
    if (!files) {
        m_message->setText(QString::fromStdString(files.error().message));
        return;
    }
    std::set<std::filesystem::path> known(m_files.begin(), m_files.end());
    m_filling = true;
    for (const auto& file : *files) {
        if (!known.insert(file).second) continue;
        m_files.push_back(file);
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        auto* name = new QTableWidgetItem(QString::fromStdString(file.filename().string()));
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        name->setToolTip(QString::fromStdString(file.string()));
        m_table->setItem(row, FileColumn, name);
        for (int column : {FunctionColumn, EmotionColumn, TakeColumn}) m_table->setItem(row, column, new QTableWidgetItem);
        auto* map = new QTableWidgetItem;
        map->setFlags(map->flags() & ~Qt::ItemIsEditable);
        m_table->setItem(row, MapColumn, map);
    }
    m_filling = false;
    if (m_output->text().isEmpty() && !m_files.empty()) {
        // In the folder corpora were last made in, else the workbench's own: never beside the
        // files (the person's data folder, often shared and read-only).
        const QString remembered = rememberedPurposeFolder(FilePurpose::NewCorpus);
        m_output->setText(unusedFolder(remembered.isEmpty() ? workbenchFolder(FilePurpose::NewCorpus) : remembered,
                                       QStringLiteral("corpus")));
    }
    relabel();
    remap();
    for (int column : {FileColumn, FunctionColumn, EmotionColumn, TakeColumn}) m_table->resizeColumnToContents(column);
}

void NewCorpusDialog::removeSelectedRows()
{
    std::vector<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows()) rows.push_back(index.row());
    if (rows.empty()) return;
    std::sort(rows.rbegin(), rows.rend()); // from the last, so the earlier rows keep their index
    m_filling = true;
    for (int row : rows) {
        m_table->removeRow(row);
        m_files.erase(m_files.begin() + row);
    }
    m_filling = false;
    relabel(); // takes numbered by file order within a cell are renumbered
}

bool NewCorpusDialog::eventFilter(QObject* watched, QEvent* event)
{
    // (While a cell is edited its editor gets the keys, not the table.)
    if (watched == m_table && event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Delete || key->key() == Qt::Key_Backspace) {
            removeSelectedRows();
            return true;
        }
    }
    return QDialog::eventFilter(watched, event);
}

void NewCorpusDialog::showCreateError(const QString& message)
{
    m_message->setText(tr("The corpus was not made: %1").arg(message));
    m_message->setStyleSheet(QStringLiteral("color: #b00020"));
    // The row of the file the error names (errors start with the file's path).
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (message.contains(QString::fromStdString(m_files[std::size_t(row)].string()))) {
            m_table->selectRow(row);
            m_table->scrollToItem(m_table->item(row, FileColumn));
            m_table->setFocus();
            break;
        }
}

QString NewCorpusDialog::messageText() const { return m_message->text(); }

void NewCorpusDialog::setPattern(const QString& pattern) { m_pattern->setText(pattern); }
void NewCorpusDialog::setOutputFolder(const QString& folder) { m_output->setText(folder); }
QString NewCorpusDialog::outputFolder() const { return m_output->text(); }

void NewCorpusDialog::relabel()
{
    const std::string pattern = m_pattern->text().toStdString();
    const bool valid = io::checkLabelPattern(pattern).ok();
    m_filling = true;
    std::map<std::pair<QString, QString>, int> next;
    std::vector<int> unnumbered;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto labels = valid ? io::parseTakeLabels(m_files[std::size_t(row)].stem().string(), pattern) : std::nullopt;
        const QString values[3] = {labels ? QString::fromStdString(labels->function) : QString(),
                                   labels ? QString::fromStdString(labels->emotion.empty() ? std::string("none") : labels->emotion) : QString(),
                                   labels && labels->takeIndex > 0 ? QString::number(labels->takeIndex) : QString()};
        for (int k = 0; k < 3; ++k) {
            QTableWidgetItem* item = m_table->item(row, FunctionColumn + k);
            if (!item->data(kEditedRole).toBool()) item->setText(values[k]);
        }
        const QString function = m_table->item(row, FunctionColumn)->text();
        const QString emotion = m_table->item(row, EmotionColumn)->text();
        bool numbered = false;
        const int take = m_table->item(row, TakeColumn)->text().toInt(&numbered);
        if (numbered) next[{function, emotion}] = std::max(next[{function, emotion}], take);
        else if (labels && !m_table->item(row, TakeColumn)->data(kEditedRole).toBool()) unnumbered.push_back(row);
    }
    // Takes without an index in the name: 1, 2, ... in file order within their cell.
    for (int row : unnumbered) {
        const auto key = std::make_pair(m_table->item(row, FunctionColumn)->text(), m_table->item(row, EmotionColumn)->text());
        m_table->item(row, TakeColumn)->setText(QString::number(++next[key]));
    }
    m_filling = false;
    validate();
}

void NewCorpusDialog::remap()
{
    std::optional<io::JointMap> given;
    if (!m_joints->text().trimmed().isEmpty()) {
        auto parsed = io::parseJointMap(m_joints->text().toStdString());
        if (parsed) given = parsed.value();
    }
    io::PartMapOptions options;
    options.side = m_side->currentIndex() == 1 ? analysis::BodySide::Left : analysis::BodySide::Right;
    m_filling = true;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto& file = m_files[std::size_t(row)];
        QTableWidgetItem* item = m_table->item(row, MapColumn);
        const auto format = io::takeFileFormat(file);
        if (format != io::TakeFileFormat::Bvh && format != io::TakeFileFormat::Scene) {
            item->setText(tr("(not a BVH, FBX, glTF or Collada file: its parts as they are)"));
            item->setData(Qt::UserRole, QString());
            continue;
        }
        auto& start = m_starts[file];
        if (!start.first && start.second.isEmpty()) {
            if (format == io::TakeFileFormat::Bvh) {
                auto read = io::readBvhStart(file, 1);
                if (read) start.first = std::move(read).value();
                else start.second = QString::fromStdString(read.error().message);
            } else {
                // The whole scene is converted (the importer reads it again when the corpus is made).
                io::ImportOptions importOptions;
                importOptions.scene.animation = m_animation->text().trimmed().toStdString();
                io::SceneTakeInfo info;
                auto read = io::readSkeletalFile(file, importOptions, {}, &info);
                if (read) start.first = std::move(read).value();
                else start.second = QString::fromStdString(read.error().message);
                QStringList names;
                for (std::size_t a = 0; a < info.animations.size(); ++a)
                    names << QStringLiteral("%1 '%2'").arg(a).arg(QString::fromStdString(info.animations[a]));
                m_animationNotes[file] = read ? tr("animation %1 of %2 (%3); ").arg(info.animation).arg(info.animations.size()).arg(names.join(QStringLiteral(", ")))
                                              : QString();
            }
        }
        auto map = start.first ? io::mapPuppetParts(*start.first, given, options) : analysis::Result<io::PartMap>(analysis::Error{});
        const QString error = start.first ? (map ? QString() : QString::fromStdString(map.error().message)) : start.second;
        const QString note = format == io::TakeFileFormat::Scene ? m_animationNotes[file] : QString();
        QString height;
        if (start.first) {
            // The performer's height in metres as the Units box reads the file.
            const auto guess = io::guessBvhUnits(*start.first);
            const double cmPerUnit = format == io::TakeFileFormat::Scene ? 1.0
                                     : m_units->currentIndex() > 0   ? m_units->currentData().toDouble()
                                                                     : guess.cmPerUnit;
            height = tr("; %1 m tall").arg(guess.height * cmPerUnit / 100.0, 0, 'f', 2);
        }
        item->setText(error.isEmpty() ? note + QString::fromStdString(map->describe()) + height : error);
        item->setForeground(error.isEmpty() ? palette().text() : QBrush(QColor(0xb0, 0x00, 0x20)));
        item->setData(Qt::UserRole, error); // non-empty: this file cannot be mapped
    }
    m_filling = false;
    validate();
}

void NewCorpusDialog::chooseJointMap()
{
    for (const auto& file : m_files) {
        const auto format = io::takeFileFormat(file);
        if (format != io::TakeFileFormat::Bvh && format != io::TakeFileFormat::Scene) continue;
        io::ImportOptions importOptions;
        importOptions.scene.animation = m_animation->text().trimmed().toStdString();
        auto start = format == io::TakeFileFormat::Bvh ? io::readBvhStart(file, 1) : io::readSkeletalFile(file, importOptions);
        if (!start) {
            m_message->setText(QString::fromStdString(start.error().message));
            return;
        }
        JointMapDialog dialog(*start, QString::fromStdString(file.filename().string()), this);
        if (dialog.exec() != QDialog::Accepted) return;
        m_side->setCurrentIndex(dialog.side() == analysis::BodySide::Left ? 1 : 0);
        m_joints->setText(dialog.jointMapText());
        return;
    }
    m_message->setText(tr("No BVH, FBX, glTF or Collada file to map."));
}

void NewCorpusDialog::validate()
{
    m_problem.clear();
    const auto fail = [this](const QString& problem) {
        if (m_problem.isEmpty()) m_problem = problem;
    };
    if (m_files.empty()) fail(tr("Add take files or a folder of them."));
    if (auto pattern = io::checkLabelPattern(m_pattern->text().toStdString()); !pattern) fail(QString::fromStdString(pattern.error().message));
    if (!m_joints->text().trimmed().isEmpty())
        if (auto map = io::parseJointMap(m_joints->text().toStdString()); !map) fail(QString::fromStdString(map.error().message));
    std::map<std::tuple<QString, QString, int>, QString> seen;
    QStringList emotions;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QString file = m_table->item(row, FileColumn)->text();
        const QString function = m_table->item(row, FunctionColumn)->text().trimmed();
        const QString emotion = m_table->item(row, EmotionColumn)->text().trimmed();
        bool number = false;
        const int take = m_table->item(row, TakeColumn)->text().toInt(&number);
        if (function.isEmpty() || emotion.isEmpty())
            fail(tr("%1: the name does not match the pattern; type its function and emotion in the table.").arg(file));
        else if (!number || take < 1)
            fail(tr("%1: the take must be a whole number from 1.").arg(file));
        else if (const auto [it, added] = seen.emplace(std::make_tuple(function, emotion, take), file); !added)
            fail(tr("%1 and %2 both have the labels %3/%4/%5.").arg(it->second, file, function, emotion).arg(take));
        if (!emotion.isEmpty() && !emotions.contains(emotion)) emotions << emotion;
        if (const QString mapError = m_table->item(row, MapColumn)->data(Qt::UserRole).toString(); !mapError.isEmpty()) fail(mapError);
    }
    if (m_output->text().trimmed().isEmpty()) {
        fail(tr("Choose the corpus folder to create."));
    } else {
        // The nearest existing folder above the output must be writable (shared data often is not).
        QFileInfo parent(QFileInfo(m_output->text().trimmed()).absolutePath());
        while (!parent.exists() && !parent.isRoot()) parent = QFileInfo(parent.absolutePath());
        if (!parent.isWritable()) fail(tr("%1 cannot be written: choose another corpus folder.").arg(parent.absoluteFilePath()));
    }
    // The neutral emotion: automatic or one of the table's emotions.
    const QString chosen = m_neutral->currentIndex() > 0 ? m_neutral->currentText() : QString();
    const bool blocked = m_neutral->blockSignals(true);
    m_neutral->clear();
    m_neutral->addItem(tr("(automatic)"));
    m_neutral->addItems(emotions);
    m_neutral->setCurrentIndex(std::max(0, m_neutral->findText(chosen)));
    m_neutral->blockSignals(blocked);
    m_message->setText(m_problem.isEmpty() ? tr("%n take(s) ready.", nullptr, m_table->rowCount()) : m_problem);
    m_message->setStyleSheet(m_problem.isEmpty() ? QString() : QStringLiteral("color: #b00020"));
    m_create->setEnabled(m_problem.isEmpty());
}

std::vector<io::CorpusSource> NewCorpusDialog::sources() const
{
    std::vector<io::CorpusSource> sources;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        analysis::TakeLabels labels;
        labels.function = m_table->item(row, FunctionColumn)->text().trimmed().toStdString();
        labels.emotion = m_table->item(row, EmotionColumn)->text().trimmed().toStdString();
        labels.takeIndex = m_table->item(row, TakeColumn)->text().toInt();
        sources.push_back({m_files[std::size_t(row)], labels});
    }
    return sources;
}

io::CorpusBuildOptions NewCorpusDialog::buildOptions() const
{
    io::CorpusBuildOptions options;
    applyUnitsChoice(*m_units, options.import.bvh);
    options.import.scene.animation = m_animation->text().trimmed().toStdString();
    options.import.bvh.side = m_side->currentIndex() == 1 ? analysis::BodySide::Left : analysis::BodySide::Right;
    if (m_channels->currentIndex() == 1) options.import.bvhLayout = io::BvhTakeLayout::AllJoints;
    if (!m_joints->text().trimmed().isEmpty())
        if (auto map = io::parseJointMap(m_joints->text().toStdString())) options.import.bvh.jointMap = map.value();
    options.neutralEmotion = m_neutral->currentIndex() > 0 ? m_neutral->currentText().toStdString() : std::string();
    options.rateHz = m_rate->value();
    options.name = QFileInfo(m_output->text()).fileName().toStdString();
    return options;
}

void NewCorpusDialog::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void NewCorpusDialog::dropEvent(QDropEvent* event)
{
    QStringList paths;
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile()) paths << url.toLocalFile();
    addInputs(paths);
    event->acceptProposedAction();
}

} // namespace bunraku::app
