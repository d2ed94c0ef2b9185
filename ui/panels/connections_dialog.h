#pragma once
// The live connections of the window (docs/connections.md, "The window"): a table of the hub's sources
// (name, spec, role, enabled, state, sentences/s, lines, errors, last seen) refreshed once a second
// from ConnectionHub::status(); Add / Edit / Remove through a small form that checks the spec with
// conn::parseSource and shows its error inline; the enabled checkbox calls hub.setEnabled. The
// sources are saved in QSettings under "connections/" as an array of spec strings (conn::toSpec).
#include <QAbstractTableModel>
#include <QDialog>
#include <QSettings>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "connections/connection_hub.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableView;
class QTimer;

namespace reckoner::ui {

/// The saved sources: settings array "connections/sources", one spec each (conn::toSpec). A spec
/// that does not parse is skipped and its error (naming the settings file, the entry and the field)
/// appended to *errors when given.
std::vector<conn::SourceConfig> loadConnections(QSettings& settings, QStringList* errors = nullptr);
/// Replaces the saved sources with `sources`.
void saveConnections(QSettings& settings, const std::vector<conn::SourceConfig>& sources);

/// The source a form describes: `spec` parsed (conn::parseSource), then the form's name (when not
/// empty), role and priority put over it. nullopt with the parser's message (naming the spec and the
/// field) in *error when the spec is bad.
std::optional<conn::SourceConfig> sourceFromForm(const QString& spec, const QString& name, conn::Role role,
                                                 int priority, QString* error);
/// The spec line the form shows for `c`: its toSpec() without the options the form has fields for
/// (name, role, priority, enabled).
QString formSpec(const conn::SourceConfig& c);

/// One row per source of the hub, in the order they were added.
class ConnectionTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Name, Spec, RoleColumn, Enabled, StateColumn, Rate, Lines, Errors, LastSeen, ColumnCount };

  explicit ConnectionTableModel(conn::ConnectionHub& hub, QObject* parent = nullptr);

  /// Reads the hub's sources and status again (the dialog's 1 s timer calls it).
  void refresh();
  /// Adds the source the form describes to the hub; the error text (the spec's field, or a name
  /// taken) or an empty string when it was added.
  QString addSource(const QString& spec, const QString& name, conn::Role role, int priority);
  /// Replaces the source of `row` by the one the form describes (keeping its enabled state); the
  /// error text or empty. On an error the old source stays.
  QString editSource(int row, const QString& spec, const QString& name, conn::Role role, int priority);
  bool removeSource(int row);
  [[nodiscard]] const conn::SourceConfig& configAt(int row) const {
    return configs_.at(static_cast<std::size_t>(row));
  }
  [[nodiscard]] const conn::SourceStatus* statusAt(int row) const;
  [[nodiscard]] const std::vector<conn::SourceConfig>& configs() const { return configs_; }

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 signals:
  /// A source was added, edited, removed, enabled or disabled (the settings should be saved).
  void sourcesChanged();

 private:
  QString addConfig(const conn::SourceConfig& c);
  conn::ConnectionHub& hub_;
  std::vector<conn::SourceConfig> configs_;
  std::vector<conn::SourceStatus> status_;  ///< same order as configs_ (by name)
  UtcUs nowUtc_ = 0;                        ///< the system clock at the last refresh
};

/// The Add / Edit form: spec (checked as it is typed), name, role, priority.
class ConnectionForm : public QDialog {
  Q_OBJECT
 public:
  explicit ConnectionForm(QWidget* parent = nullptr);
  /// Fills the form with `c` (Edit).
  void setSource(const conn::SourceConfig& c);
  [[nodiscard]] QString spec() const;
  [[nodiscard]] QString name() const;
  [[nodiscard]] conn::Role role() const;
  [[nodiscard]] int priority() const;
  /// The inline error ("" while the spec parses).
  [[nodiscard]] QString errorText() const;
  /// Shows an error the hub gave (a name taken) under the fields.
  void showError(const QString& text);
  [[nodiscard]] QLineEdit* specEdit() const { return spec_; }
  [[nodiscard]] QLineEdit* nameEdit() const { return name_; }

 private:
  void validate();
  QLineEdit* spec_;
  QLineEdit* name_;
  QComboBox* role_;
  QSpinBox* priority_;
  QLabel* error_;
  QPushButton* ok_;
};

class ConnectionsDialog : public QDialog {
  Q_OBJECT
 public:
  /// With `settings`, every change of the sources is saved there at once (saveConnections).
  explicit ConnectionsDialog(conn::ConnectionHub& hub, QSettings* settings = nullptr,
                             QWidget* parent = nullptr);
  [[nodiscard]] ConnectionTableModel* model() const { return model_; }
  [[nodiscard]] QTableView* table() const { return table_; }

 private:
  void addClicked();
  void editClicked();
  void removeClicked();
  [[nodiscard]] int selectedRow() const;

  conn::ConnectionHub& hub_;
  QSettings* settings_;
  ConnectionTableModel* model_;
  QTableView* table_;
  QPushButton* edit_;
  QPushButton* remove_;
  QTimer* timer_;
};

/// "HH:MM:SS.mmm" of a UTC time in microseconds (the monitor and the table).
QString utcClockText(UtcUs t);
/// The system clock, UTC microseconds (as the hub stamps lines).
UtcUs systemUtcUs();

}  // namespace reckoner::ui
