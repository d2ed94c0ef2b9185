#include "ui/panels/connections_dialog.h"

#include <QComboBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <chrono>
#include <stdexcept>

namespace reckoner::ui {

namespace {

constexpr const char* kArray = "connections/sources";
constexpr const char* kSpecKey = "spec";

bool hasOption(const QString& spec, const QString& key) {
  const qsizetype q = spec.indexOf('?');
  if (q < 0) return false;
  const QStringList opts = spec.mid(q + 1).split('&');
  for (const QString& o : opts)
    if (o.section('=', 0, 0) == key) return true;
  return false;
}

QString countText(std::uint64_t n) {
  return QString::number(static_cast<qulonglong>(n));
}

}  // namespace

UtcUs systemUtcUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

QString utcClockText(UtcUs t) {
  return QDateTime::fromMSecsSinceEpoch(t / 1000, Qt::UTC).toString(QStringLiteral("HH:mm:ss.zzz"));
}

std::vector<conn::SourceConfig> loadConnections(QSettings& settings, QStringList* errors) {
  std::vector<conn::SourceConfig> out;
  const int n = settings.beginReadArray(kArray);
  for (int i = 0; i < n; ++i) {
    settings.setArrayIndex(i);
    const std::string spec = settings.value(kSpecKey).toString().toStdString();
    try {
      conn::SourceConfig c = conn::parseSource(spec);
      bool taken = false;
      for (const auto& o : out) taken = taken || o.name == c.name;
      if (taken)
        throw std::invalid_argument("connection spec '" + spec + "': name: '" + c.name + "' is taken");
      out.push_back(std::move(c));
    } catch (const std::invalid_argument& e) {
      if (errors != nullptr)
        errors->append(QStringLiteral("%1: %2/%3/%4: %5")
                           .arg(settings.fileName(), QString::fromLatin1(kArray))
                           .arg(i + 1)
                           .arg(QString::fromLatin1(kSpecKey), QString::fromStdString(e.what())));
    }
  }
  settings.endArray();
  return out;
}

void saveConnections(QSettings& settings, const std::vector<conn::SourceConfig>& sources) {
  settings.remove(kArray);
  settings.beginWriteArray(kArray, static_cast<int>(sources.size()));
  for (std::size_t i = 0; i < sources.size(); ++i) {
    settings.setArrayIndex(static_cast<int>(i));
    settings.setValue(kSpecKey, QString::fromStdString(conn::toSpec(sources[i])));
  }
  settings.endArray();
}

std::optional<conn::SourceConfig> sourceFromForm(const QString& spec, const QString& name, conn::Role role,
                                                 int priority, QString* error) {
  try {
    conn::SourceConfig c = conn::parseSource(spec.trimmed().toStdString());
    if (!name.trimmed().isEmpty()) c.name = name.trimmed().toStdString();
    c.role = role;
    c.priority = priority;
    return c;
  } catch (const std::invalid_argument& e) {
    if (error != nullptr) *error = QString::fromStdString(e.what());
    return std::nullopt;
  }
}

QString formSpec(const conn::SourceConfig& c) {
  QString full = QString::fromStdString(conn::toSpec(c));
  const qsizetype q = full.indexOf('?');
  if (q < 0) return full;
  QStringList kept;
  for (const QString& o : full.mid(q + 1).split('&')) {
    const QString key = o.section('=', 0, 0);
    if (key != "name" && key != "role" && key != "priority" && key != "enabled") kept.append(o);
  }
  return kept.isEmpty() ? full.left(q) : full.left(q) + '?' + kept.join('&');
}

// ----------------------------------------------------------------------------------------------------

ConnectionTableModel::ConnectionTableModel(conn::ConnectionHub& hub, QObject* parent)
    : QAbstractTableModel(parent), hub_(hub) {
  refresh();
}

void ConnectionTableModel::refresh() {
  std::vector<conn::SourceConfig> configs = hub_.sources();
  const std::vector<conn::SourceStatus> all = hub_.status();
  std::vector<conn::SourceStatus> status;
  status.reserve(configs.size());
  for (const auto& c : configs) {
    conn::SourceStatus s;
    s.name = c.name;
    for (const auto& a : all)
      if (a.name == c.name) s = a;
    status.push_back(std::move(s));
  }
  nowUtc_ = systemUtcUs();
  if (configs.size() != configs_.size()) {
    beginResetModel();
    configs_ = std::move(configs);
    status_ = std::move(status);
    endResetModel();
    return;
  }
  configs_ = std::move(configs);
  status_ = std::move(status);
  if (!configs_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

QString ConnectionTableModel::addConfig(const conn::SourceConfig& c) {
  try {
    hub_.add(c);
  } catch (const std::invalid_argument& e) {
    return QString::fromStdString(e.what());
  }
  refresh();
  emit sourcesChanged();
  return {};
}

QString ConnectionTableModel::addSource(const QString& spec, const QString& name, conn::Role role,
                                        int priority) {
  QString error;
  const auto c = sourceFromForm(spec, name, role, priority, &error);
  if (!c) return error;
  return addConfig(*c);
}

QString ConnectionTableModel::editSource(int row, const QString& spec, const QString& name, conn::Role role,
                                         int priority) {
  if (row < 0 || row >= rowCount()) return QStringLiteral("connection: row %1: no such source").arg(row);
  QString error;
  auto c = sourceFromForm(spec, name, role, priority, &error);
  if (!c) return error;
  const conn::SourceConfig old = configAt(row);
  c->enabled = old.enabled;
  for (const auto& o : configs_)
    if (o.name == c->name && o.name != old.name)
      return QStringLiteral("connection '%1': name: taken by another source")
          .arg(QString::fromStdString(c->name));
  hub_.remove(old.name);
  try {
    hub_.add(*c);
  } catch (const std::invalid_argument& e) {
    hub_.add(old);  // the name was free a moment ago: the old source comes back
    refresh();
    return QString::fromStdString(e.what());
  }
  refresh();
  emit sourcesChanged();
  return {};
}

bool ConnectionTableModel::removeSource(int row) {
  if (row < 0 || row >= rowCount()) return false;
  const bool removed = hub_.remove(configAt(row).name);
  refresh();
  if (removed) emit sourcesChanged();
  return removed;
}

const conn::SourceStatus* ConnectionTableModel::statusAt(int row) const {
  if (row < 0 || row >= rowCount()) return nullptr;
  return &status_[static_cast<std::size_t>(row)];
}

int ConnectionTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(configs_.size());
}

int ConnectionTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant ConnectionTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const auto& c = configs_[static_cast<std::size_t>(index.row())];
  const auto& s = status_[static_cast<std::size_t>(index.row())];
  if (role == Qt::CheckStateRole && index.column() == Enabled) return c.enabled ? Qt::Checked : Qt::Unchecked;
  if (role == Qt::ToolTipRole) {
    return s.lastError.empty() ? QVariant() : QVariant(QString::fromStdString(s.lastError));
  }
  if (role == Qt::TextAlignmentRole && index.column() >= Rate) {
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  }
  if (role != Qt::DisplayRole) return {};
  switch (index.column()) {
    case Name:
      return QString::fromStdString(c.name);
    case Spec:
      return QString::fromStdString(conn::toSpec(c));
    case RoleColumn:
      return QString::fromLatin1(conn::roleName(c.role));
    case Enabled:
      return c.enabled ? tr("on") : tr("off");
    case StateColumn:
      return QString::fromLatin1(conn::stateName(s.state));
    case Rate:
      return QString::number(s.sentencesPerSecond, 'f', 1);
    case Lines:
      return countText(s.lines);
    case Errors:
      return countText(s.errors());
    case LastSeen:
      if (!s.lastSeenUtc) return QStringLiteral("never");
      return QString::number(std::max<double>(0.0, static_cast<double>(nowUtc_ - *s.lastSeenUtc) / 1e6), 'f',
                             1);
    default:
      return {};
  }
}

bool ConnectionTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (!index.isValid() || index.column() != Enabled || role != Qt::CheckStateRole) return false;
  const bool on = value.toInt() == Qt::Checked;
  if (!hub_.setEnabled(configAt(index.row()).name, on)) return false;
  refresh();
  emit sourcesChanged();
  return true;
}

Qt::ItemFlags ConnectionTableModel::flags(const QModelIndex& index) const {
  Qt::ItemFlags f = QAbstractTableModel::flags(index);
  if (index.isValid() && index.column() == Enabled) f |= Qt::ItemIsUserCheckable;
  return f;
}

QVariant ConnectionTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Name:
      return tr("Name");
    case Spec:
      return tr("Spec");
    case RoleColumn:
      return tr("Role");
    case Enabled:
      return tr("Enabled");
    case StateColumn:
      return tr("State");
    case Rate:
      return tr("Sentences/s");
    case Lines:
      return tr("Lines");
    case Errors:
      return tr("Errors");
    case LastSeen:
      return tr("Last seen (s ago)");
    default:
      return {};
  }
}

// ----------------------------------------------------------------------------------------------------

ConnectionForm::ConnectionForm(QWidget* parent)
    : QDialog(parent),
      spec_(new QLineEdit(this)),
      name_(new QLineEdit(this)),
      role_(new QComboBox(this)),
      priority_(new QSpinBox(this)),
      error_(new QLabel(this)) {
  setWindowTitle(tr("Connection"));
  spec_->setPlaceholderText(QStringLiteral("udp://:10110   tcp://host:10110   serial:///dev/ttyUSB0:4800"));
  spec_->setMinimumWidth(360);
  name_->setPlaceholderText(tr("from the spec"));
  role_->addItem(tr("NMEA 0183 / AIS"), static_cast<int>(conn::Role::Nmea));
  role_->addItem(tr("Radar plots"), static_cast<int>(conn::Role::Radar));
  priority_->setRange(-1000, 1000);
  error_->setWordWrap(true);
  error_->setStyleSheet(QStringLiteral("color: #b00000;"));
  auto* form = new QFormLayout;
  form->addRow(tr("Spec"), spec_);
  form->addRow(tr("Name"), name_);
  form->addRow(tr("Role"), role_);
  form->addRow(tr("Priority"), priority_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  ok_ = buttons->button(QDialogButtonBox::Ok);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(error_);
  layout->addWidget(buttons);
  connect(spec_, &QLineEdit::textChanged, this, &ConnectionForm::validate);
  validate();
}

void ConnectionForm::setSource(const conn::SourceConfig& c) {
  spec_->setText(formSpec(c));
  name_->setText(QString::fromStdString(c.name));
  role_->setCurrentIndex(c.role == conn::Role::Radar ? 1 : 0);
  priority_->setValue(c.priority);
}

void ConnectionForm::validate() {
  // The spec's own name=, role= and priority= fill the fields; the fields are what is added.
  const QString text = spec_->text().trimmed();
  if (text.isEmpty()) {
    error_->setText(tr("A spec, e.g. udp://:10110"));
    ok_->setEnabled(false);
    return;
  }
  try {
    const conn::SourceConfig parsed = conn::parseSource(text.toStdString());
    if (hasOption(text, "name")) name_->setText(QString::fromStdString(parsed.name));
    if (hasOption(text, "role")) role_->setCurrentIndex(parsed.role == conn::Role::Radar ? 1 : 0);
    if (hasOption(text, "priority")) priority_->setValue(parsed.priority);
    error_->clear();
    ok_->setEnabled(true);
  } catch (const std::invalid_argument& e) {
    error_->setText(QString::fromStdString(e.what()));
    ok_->setEnabled(false);
  }
}

QString ConnectionForm::spec() const {
  return spec_->text();
}
QString ConnectionForm::name() const {
  return name_->text();
}
conn::Role ConnectionForm::role() const {
  return role_->currentIndex() == 1 ? conn::Role::Radar : conn::Role::Nmea;
}
int ConnectionForm::priority() const {
  return priority_->value();
}
QString ConnectionForm::errorText() const {
  return error_->text();
}
void ConnectionForm::showError(const QString& text) {
  error_->setText(text);
}

// ----------------------------------------------------------------------------------------------------

ConnectionsDialog::ConnectionsDialog(conn::ConnectionHub& hub, QSettings* settings, QWidget* parent)
    : QDialog(parent),
      hub_(hub),
      settings_(settings),
      model_(new ConnectionTableModel(hub, this)),
      table_(new QTableView(this)),
      timer_(new QTimer(this)) {
  setWindowTitle(tr("Connections"));
  table_->setModel(model_);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(ConnectionTableModel::Spec, QHeaderView::Stretch);
  auto* add = new QPushButton(tr("Add..."), this);
  edit_ = new QPushButton(tr("Edit..."), this);
  remove_ = new QPushButton(tr("Remove"), this);
  auto* close = new QPushButton(tr("Close"), this);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(add);
  buttons->addWidget(edit_);
  buttons->addWidget(remove_);
  buttons->addStretch(1);
  buttons->addWidget(close);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(table_);
  layout->addLayout(buttons);
  resize(900, 300);
  connect(add, &QPushButton::clicked, this, &ConnectionsDialog::addClicked);
  connect(edit_, &QPushButton::clicked, this, &ConnectionsDialog::editClicked);
  connect(remove_, &QPushButton::clicked, this, &ConnectionsDialog::removeClicked);
  connect(close, &QPushButton::clicked, this, &QDialog::accept);
  auto updateButtons = [this] {
    edit_->setEnabled(selectedRow() >= 0);
    remove_->setEnabled(selectedRow() >= 0);
  };
  connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, updateButtons);
  connect(model_, &QAbstractItemModel::modelReset, this, updateButtons);
  updateButtons();
  connect(model_, &ConnectionTableModel::sourcesChanged, this, [this] {
    if (settings_ != nullptr) saveConnections(*settings_, hub_.sources());
  });
  connect(timer_, &QTimer::timeout, model_, &ConnectionTableModel::refresh);
  timer_->start(1000);
}

int ConnectionsDialog::selectedRow() const {
  const QModelIndexList rows = table_->selectionModel()->selectedRows();
  return rows.isEmpty() ? -1 : rows.front().row();
}

void ConnectionsDialog::addClicked() {
  ConnectionForm form(this);
  form.setWindowTitle(tr("Add connection"));
  while (form.exec() == QDialog::Accepted) {
    const QString error = model_->addSource(form.spec(), form.name(), form.role(), form.priority());
    if (error.isEmpty()) return;
    form.showError(error);
  }
}

void ConnectionsDialog::editClicked() {
  const int row = selectedRow();
  if (row < 0) return;
  ConnectionForm form(this);
  form.setWindowTitle(tr("Edit connection"));
  form.setSource(model_->configAt(row));
  while (form.exec() == QDialog::Accepted) {
    const QString error = model_->editSource(row, form.spec(), form.name(), form.role(), form.priority());
    if (error.isEmpty()) return;
    form.showError(error);
  }
}

void ConnectionsDialog::removeClicked() {
  model_->removeSource(selectedRow());
}

}  // namespace reckoner::ui
