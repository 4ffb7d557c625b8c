#include "widgets/parameter_panel.h"

#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "widgets/core_message.h"
#include "widgets/option_editor.h"

namespace sightline {
namespace {

// "mapping.ransac.max_iterations" -> {"mapping.ransac", "max_iterations"}.
std::pair<std::string, std::string> SplitKey(const std::string& key) {
  const size_t dot = key.rfind('.');
  if (dot == std::string::npos) return {"general", key};
  return {key.substr(0, dot), key.substr(dot + 1)};
}

bool SameSpecs(const std::vector<OptionSpec>& a, const std::vector<OptionSpec>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].key != b[i].key || a[i].type != b[i].type || a[i].min != b[i].min ||
        a[i].max != b[i].max || a[i].choices != b[i].choices) {
      return false;
    }
  }
  return true;
}

}  // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent), last_dir_(QDir::homePath()) {
  auto* layout = new QVBoxLayout(this);

  auto* buttons = new QHBoxLayout();
  filter_ = new QLineEdit(this);
  filter_->setPlaceholderText(tr("Filter options"));
  filter_->setClearButtonEnabled(true);
  connect(filter_, &QLineEdit::textChanged, this, &ParameterPanel::SetFilter);
  buttons->addWidget(filter_, 1);
  auto* load = new QPushButton(tr("Load profile…"), this);
  connect(load, &QPushButton::clicked, this, &ParameterPanel::OnLoadClicked);
  buttons->addWidget(load);
  auto* save = new QPushButton(tr("Save profile…"), this);
  connect(save, &QPushButton::clicked, this, &ParameterPanel::OnSaveClicked);
  buttons->addWidget(save);
  auto* reset = new QPushButton(tr("Reset all"), this);
  connect(reset, &QPushButton::clicked, this, &ParameterPanel::ResetAll);
  buttons->addWidget(reset);
  layout->addLayout(buttons);

  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  message_->hide();
  layout->addWidget(message_);

  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  content_ = new QWidget(scroll);
  auto* content_layout = new QVBoxLayout(content_);
  content_layout->setContentsMargins(0, 0, 0, 0);
  content_layout->setSpacing(4);
  content_layout->addStretch(1);
  scroll->setWidget(content_);
  scroll->setMinimumHeight(fontMetrics().height() * 2);  // The rows scroll; the window stays small.
  layout->addWidget(scroll, 1);
}

ParameterPanel::~ParameterPanel() = default;

void ParameterPanel::SetOptions(const OptionSet& options) {
  const bool same = SameSpecs(options.specs(), options_.specs());
  options_ = options;
  if (same && !rows_.empty()) {
    RefreshValues();
  } else {
    Rebuild();
  }
}

void ParameterPanel::Rebuild() {
  for (QGroupBox* group : groups_) delete group;
  groups_.clear();
  rows_.clear();

  auto* content_layout = static_cast<QVBoxLayout*>(content_->layout());
  std::map<std::string, QGroupBox*> by_name;
  for (const OptionSpec& spec : options_.specs()) {
    const auto [group_name, short_key] = SplitKey(spec.key);
    QGroupBox*& group = by_name[group_name];
    if (group == nullptr) {
      group = new QGroupBox(QString::fromStdString(group_name), content_);
      // Compact rows: a dozen options in sight in a dock of a 1280x800 screen.
      auto* form = new QFormLayout(group);
      form->setVerticalSpacing(2);
      form->setContentsMargins(6, 2, 6, 4);
      // Before the trailing stretch, in declaration order of each group's first option.
      content_layout->insertWidget(content_layout->count() - 1, group);
      groups_.push_back(group);
    }
    auto* label = new QLabel(QString::fromStdString(short_key), group);
    label->setToolTip(OptionTooltip(spec));
    auto* editor = new OptionEditor(spec, group);
    connect(editor, &OptionEditor::ValueEdited, this, &ParameterPanel::OnValueEdited);
    connect(editor, &OptionEditor::ResetRequested, this, &ParameterPanel::OnResetRequested);
    static_cast<QFormLayout*>(group->layout())->addRow(label, editor);
    rows_[spec.key] = Row{editor, label, group};
  }
  RefreshValues();
  SetFilter(filter_->text());
}

void ParameterPanel::changeEvent(QEvent* event) {
  // The option descriptions come from the core in English: each row's tool tip is built anew
  // in the new language (the editors do the same for their inputs).
  if (event->type() == QEvent::LanguageChange) {
    for (const auto& [key, row] : rows_) row.label->setToolTip(OptionTooltip(row.editor->spec()));
    if (!message_status_.empty()) message_->setText(CoreMessage(message_status_));
  }
  QWidget::changeEvent(event);
}

void ParameterPanel::RefreshValues() {
  for (const auto& [key, row] : rows_) RefreshRow(key);
}

void ParameterPanel::RefreshRow(const std::string& key) {
  auto it = rows_.find(key);
  if (it == rows_.end()) return;
  StatusOr<OptionValue> value = options_.Get(key);
  if (!value.ok()) return;
  it->second.editor->SetValue(*value);
  // Bold names show at a glance what differs from the defaults.
  QFont font = it->second.label->font();
  font.setBold(it->second.editor->modified());
  it->second.label->setFont(font);
}

void ParameterPanel::OnValueEdited(const std::string& key, const OptionValue& value) {
  const Status status = options_.Set(key, value, "parameter panel");
  if (!status.ok()) {
    ShowStatus(status);
    RefreshRow(key);  // Back to the value the set holds.
    return;
  }
  RefreshRow(key);
  message_->hide();
  message_status_.clear();
  emit OptionsChanged(options_);
}

void ParameterPanel::OnResetRequested(const std::string& key) {
  options_.Reset(key);
  RefreshRow(key);
  emit OptionsChanged(options_);
}

void ParameterPanel::ResetAll() {
  options_.ResetToDefaults();
  RefreshValues();
  ShowMessage(tr("All options reset to their defaults."), false);
  emit OptionsChanged(options_);
}

Status ParameterPanel::LoadProfile(const QString& path) {
  Status status = options_.LoadYaml(path.toStdString());  // All or nothing.
  if (!status.ok()) {
    ShowStatus(status);
    return status;
  }
  RefreshValues();
  ShowMessage(tr("Loaded profile %1").arg(QDir::toNativeSeparators(path)), false);
  emit OptionsChanged(options_);
  return status;
}

Status ParameterPanel::SaveProfile(const QString& path) {
  Status status = (profile_exclusion_.empty() ? options_ : options_.Without(profile_exclusion_))
                      .SaveYaml(path.toStdString());
  if (!status.ok()) {
    ShowStatus(status);
  } else {
    ShowMessage(tr("Saved profile %1").arg(QDir::toNativeSeparators(path)), false);
  }
  return status;
}

void ParameterPanel::OnLoadClicked() {
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Load profile"), last_dir_, tr("YAML profiles (*.yaml *.yml);;All files (*)"));
  if (path.isEmpty()) return;
  last_dir_ = QFileInfo(path).absolutePath();
  (void)LoadProfile(path);  // Errors are shown in the message area.
}

void ParameterPanel::OnSaveClicked() {
  QString path = QFileDialog::getSaveFileName(this, tr("Save profile"), last_dir_,
                                              tr("YAML profiles (*.yaml *.yml)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".yaml");
  last_dir_ = QFileInfo(path).absolutePath();
  (void)SaveProfile(path);  // Errors are shown in the message area.
}

void ParameterPanel::SetFilter(const QString& text) {
  if (filter_->text() != text) filter_->setText(text);  // Re-enters once via textChanged.
  std::map<QGroupBox*, bool> group_visible;
  for (const auto& [key, row] : rows_) {
    const bool visible =
        text.isEmpty() || QString::fromStdString(key).contains(text, Qt::CaseInsensitive);
    static_cast<QFormLayout*>(row.group->layout())->setRowVisible(row.editor, visible);
    group_visible[row.group] |= visible;
  }
  for (const auto& [group, visible] : group_visible) group->setVisible(visible);
}

QWidget* ParameterPanel::InputFor(const std::string& key) const {
  auto it = rows_.find(key);
  return it == rows_.end() ? nullptr : it->second.editor->input();
}

OptionEditor* ParameterPanel::EditorFor(const std::string& key) const {
  auto it = rows_.find(key);
  return it == rows_.end() ? nullptr : it->second.editor;
}

QString ParameterPanel::message() const {
  return message_->isHidden() ? QString() : message_->text();
}

void ParameterPanel::ShowStatus(const Status& status) {
  ShowMessage(CoreMessage(status.ToString()), true);
  message_status_ = status.ToString();
}

void ParameterPanel::ShowMessage(const QString& text, bool error) {
  message_status_.clear();
  message_->setText(text);
  message_->setStyleSheet(error ? QStringLiteral("color: #d03030;") : QString());
  message_->show();
}

}  // namespace sightline
