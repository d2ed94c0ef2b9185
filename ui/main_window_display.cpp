// MainWindow's display modes (docs/gui.md, "The chart display"): orientation, motion, following own
// ship, vectors, targets' past positions and labels, the CCRP and the units, in the display toolbar and
// the View menu, each control following the chart's settings (a pan unchecks "Follow own ship"), and
// all of them remembered (QSettings "display/...") as soon as they change.
#include <QActionGroup>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QMenu>
#include <QSettings>
#include <QSignalBlocker>
#include <QToolBar>
#include <QToolTip>
#include <algorithm>
#include <cmath>

#include "ui/main_window.h"
#include "ui/map/range_scale.h"
#include "ui/panels/alert_panel.h"
#include "ui/panels/alert_sound.h"
#include "ui/panels/own_ship_panel.h"
#include "ui/panels/route_panel.h"
#include "ui/panels/target_table_model.h"
#include "ui/panels/voyage_panel.h"
#include "ui/panels/widget_palette.h"
#include "ui/plots/error_plots.h"

namespace reckoner::ui {
namespace {
constexpr double kVectorMinutes[] = {1.0, 3.0, 6.0, 12.0, 30.0};
struct PastPositions {
  const char* name;
  int count;
  double intervalS;
};
constexpr PastPositions kPastPositions[] = {
    {"Off", 0, 30.0}, {"6 at 30 s", 6, 30.0}, {"6 at 1 min", 6, 60.0}, {"6 at 2 min", 6, 120.0}};

template <class F>
void editOverlay(EcdisView* view, F&& edit) {
  OverlaySettings s = view->overlay();
  edit(s);
  view->setOverlay(s);
}

/// Radio items in `menu` ("STEM_0", ...) that set the chart's settings through apply(s, i) and follow
/// them through current(s) (-1: none checked).
template <class Apply, class Current>
void addRadioGroup(QObject* owner, EcdisView* view, QMenu* menu, const char* stem, const QStringList& names,
                   Apply apply, Current current) {
  auto* group = new QActionGroup(owner);
  std::vector<QAction*> actions;
  for (int i = 0; i < names.size(); ++i) {
    QAction* a = menu->addAction(names[i]);
    a->setObjectName(QStringLiteral("%1_%2").arg(QString::fromLatin1(stem)).arg(i));
    a->setCheckable(true);
    group->addAction(a);
    actions.push_back(a);
    QObject::connect(a, &QAction::triggered, owner,
                     [view, i, apply] { editOverlay(view, [&](OverlaySettings& s) { apply(s, i); }); });
  }
  const auto sync = [actions, current](const OverlaySettings& s) {
    const int i = current(s);
    for (std::size_t k = 0; k < actions.size(); ++k) actions[k]->setChecked(static_cast<int>(k) == i);
  };
  sync(view->overlay());
  QObject::connect(view, &EcdisView::overlayChanged, owner, sync);
}

QString key(const char* name) {
  return QStringLiteral("display/") + QString::fromLatin1(name);
}
}  // namespace

void MainWindow::buildDisplayModes(QToolBar* bar) {
  // Orientation and motion: combo boxes that follow the chart's settings.
  const auto combo = [this, bar](const char* name, const QStringList& items, const QString& tip) {
    auto* box = new QComboBox(this);
    box->setObjectName(QString::fromLatin1(name));
    box->addItems(items);
    box->setToolTip(tip);
    bar->addWidget(box);
    return box;
  };
  QComboBox* orientation = combo("orientation", {tr("N UP"), tr("C UP"), tr("H UP")},
                                 tr("North up, course up (stabilised) or head up (O)"));
  connect(orientation, &QComboBox::activated, this, [this](int i) {
    editOverlay(view_, [i](OverlaySettings& s) { s.orientation = static_cast<Orientation>(i); });
  });
  QComboBox* motion =
      combo("motion", {tr("TM"), tr("RM")}, tr("True motion with reset, or relative motion (M)"));
  connect(motion, &QComboBox::activated, this, [this](int i) {
    editOverlay(view_, [i](OverlaySettings& s) { s.motion = static_cast<Motion>(i); });
  });
  QComboBox* vectors = combo("vectorMode", {tr("True vectors"), tr("Relative vectors")},
                             tr("Targets' vectors over ground, or relative to own ship"));
  connect(vectors, &QComboBox::activated, this,
          [this](int i) { editOverlay(view_, [i](OverlaySettings& s) { s.relativeVectors = i == 1; }); });
  QStringList minuteItems;
  for (const double m : kVectorMinutes) minuteItems << tr("%1 min").arg(m);
  QComboBox* minutes = combo("vectorMinutes", minuteItems, tr("Vector time: the length of every vector"));
  connect(minutes, &QComboBox::activated, this, [this](int i) {
    editOverlay(view_, [i](OverlaySettings& s) { s.vectorMinutes = kVectorMinutes[i]; });
  });
  connect(view_, &EcdisView::overlayChanged, this, [=](const OverlaySettings& s) {
    const QSignalBlocker b1(orientation), b2(motion), b3(vectors), b4(minutes);
    orientation->setCurrentIndex(static_cast<int>(s.orientation));
    motion->setCurrentIndex(static_cast<int>(s.motion));
    vectors->setCurrentIndex(s.relativeVectors ? 1 : 0);
    const auto* it = std::find(std::begin(kVectorMinutes), std::end(kVectorMinutes), s.vectorMinutes);
    minutes->setCurrentIndex(it == std::end(kVectorMinutes) ? -1 : static_cast<int>(it - kVectorMinutes));
    minutes->setPlaceholderText(tr("%1 min").arg(s.vectorMinutes));
  });
  bar->addAction(displayAction("offCentred"));
  bar->addAction(displayAction("followOwnShip"));
  bar->addAction(displayAction("centreOwnShip"));
}

QAction* MainWindow::displayAction(const char* name) {
  // The display's actions exist once, shared by the toolbar and the View menu.
  const QString id = QString::fromLatin1(name);
  if (auto* a = findChild<QAction*>(id)) return a;
  auto* a = new QAction(this);
  a->setObjectName(id);
  const auto toggle = [this, a](bool OverlaySettings::*member) {
    a->setCheckable(true);
    a->setChecked(view_->overlay().*member);
    connect(a, &QAction::triggered, this, [this, member](bool on) {
      editOverlay(view_, [member, on](OverlaySettings& s) { s.*member = on; });
    });
    connect(view_, &EcdisView::overlayChanged, a, [a, member](const OverlaySettings& s) {
      const QSignalBlocker block(a);
      a->setChecked(s.*member);
    });
  };
  if (id == QLatin1String("offCentred")) {
    a->setText(tr("Off-centred"));
    a->setToolTip(tr("Own ship half the range astern of the centre (relative motion and true-motion reset)"));
    toggle(&OverlaySettings::offCentred);
  } else if (id == QLatin1String("followOwnShip")) {
    a->setText(tr("Follow own ship"));
    a->setToolTip(tr("The view follows own ship; a pan switches it off, C switches it on again"));
    toggle(&OverlaySettings::followOwnShip);
  } else if (id == QLatin1String("centreOwnShip")) {
    a->setText(tr("Centre own ship"));
    a->setToolTip(tr("Own ship back to its place on screen and followed: the true-motion reset (C or R)"));
    a->setShortcuts({QKeySequence(Qt::Key_C), QKeySequence(Qt::Key_R)});
    connect(a, &QAction::triggered, view_, &EcdisView::centreOnOwnShip);
  } else if (id == QLatin1String("targetLabels")) {
    a->setText(tr("Target labels"));
    toggle(&OverlaySettings::showTargetLabels);
  }
  return a;
}

void MainWindow::buildDisplayMenu(QMenu* viewMenu) {
  // View > Orientation, Motion, Vector time, Target past positions, Units: radio groups that follow
  // the chart's settings; keys O (next orientation) and M (true / relative motion).
  const auto radio = [this](QMenu* menu, const char* stem, const QStringList& names, auto apply,
                            auto current) { addRadioGroup(this, view_, menu, stem, names, apply, current); };
  QMenu* orientation = viewMenu->addMenu(tr("Orientation"));
  radio(
      orientation, "orientation", {tr("North up"), tr("Course up (stabilised)"), tr("Head up")},
      [](OverlaySettings& s, int i) { s.orientation = static_cast<Orientation>(i); },
      [](const OverlaySettings& s) { return static_cast<int>(s.orientation); });
  orientation->addSeparator();
  QAction* next = orientation->addAction(tr("Next orientation"), QKeySequence(Qt::Key_O), this, [this] {
    editOverlay(view_, [](OverlaySettings& s) {
      s.orientation = static_cast<Orientation>((static_cast<int>(s.orientation) + 1) % 3);
    });
  });
  next->setObjectName(QStringLiteral("nextOrientation"));
  QMenu* motion = viewMenu->addMenu(tr("Motion"));
  radio(
      motion, "motion", {tr("True motion (with reset)"), tr("Relative motion")},
      [](OverlaySettings& s, int i) { s.motion = static_cast<Motion>(i); },
      [](const OverlaySettings& s) { return static_cast<int>(s.motion); });
  motion->addSeparator();
  motion
      ->addAction(tr("Toggle true / relative motion"), QKeySequence(Qt::Key_M), this,
                  [this] {
                    editOverlay(view_, [](OverlaySettings& s) {
                      s.motion = s.motion == Motion::True ? Motion::Relative : Motion::True;
                    });
                  })
      ->setObjectName(QStringLiteral("toggleMotion"));
  motion->addAction(displayAction("offCentred"));
  motion->addAction(displayAction("followOwnShip"));
  motion->addAction(displayAction("centreOwnShip"));
  QStringList minuteNames;
  for (const double m : kVectorMinutes) minuteNames << tr("%1 min").arg(m);
  QMenu* vectors = viewMenu->addMenu(tr("Vectors"));
  radio(
      vectors, "vectorMode", {tr("True vectors"), tr("Relative vectors")},
      [](OverlaySettings& s, int i) { s.relativeVectors = i == 1; },
      [](const OverlaySettings& s) { return s.relativeVectors ? 1 : 0; });
  vectors->addSeparator();
  radio(
      vectors, "vectorTime", minuteNames,
      [](OverlaySettings& s, int i) { s.vectorMinutes = kVectorMinutes[i]; },
      [](const OverlaySettings& s) {
        const auto* it = std::find(std::begin(kVectorMinutes), std::end(kVectorMinutes), s.vectorMinutes);
        return it == std::end(kVectorMinutes) ? -1 : static_cast<int>(it - kVectorMinutes);
      });
  QStringList pastNames;
  for (const PastPositions& p : kPastPositions) pastNames << tr(p.name);
  radio(
      viewMenu->addMenu(tr("Target past positions")), "pastPositions", pastNames,
      [](OverlaySettings& s, int i) {
        s.targetPastCount = kPastPositions[i].count;
        s.targetPastIntervalS = kPastPositions[i].intervalS;
      },
      [](const OverlaySettings& s) {
        for (int i = 0; i < static_cast<int>(std::size(kPastPositions)); ++i)
          if (kPastPositions[i].count == s.targetPastCount &&
              (s.targetPastCount == 0 || kPastPositions[i].intervalS == s.targetPastIntervalS))
            return i;
        return -1;
      });
  viewMenu->addAction(displayAction("targetLabels"));
  buildUnitsMenu(viewMenu->addMenu(tr("Units")));
  viewMenu->addAction(tr("CCRP…"), this, &MainWindow::askCcrp)->setObjectName(QStringLiteral("ccrpSettings"));
  readDisplaySettings();  // before remembering: reading sets the overlay, which would write defaults
  connectDisplay();
}

void MainWindow::buildUnitsMenu(QMenu* units) {
  units->setObjectName(QStringLiteral("unitsMenu"));
  auto* distance = new QActionGroup(this);
  auto* speed = new QActionGroup(this);
  const auto add = [this, units](QActionGroup* group, const char* name, const QString& text, auto apply) {
    QAction* a = units->addAction(text);
    a->setObjectName(QString::fromLatin1(name));
    a->setCheckable(true);
    group->addAction(a);
    connect(a, &QAction::triggered, this, [this, apply] {
      DisplayUnits u = view_->units();
      apply(u);
      setDisplayUnits(u);
    });
  };
  add(distance, "units_nm", tr("Distances in nautical miles"),
      [](DisplayUnits& u) { u.distance = DistanceUnit::NauticalMiles; });
  add(distance, "units_km", tr("Distances in kilometres"),
      [](DisplayUnits& u) { u.distance = DistanceUnit::Kilometres; });
  units->addSeparator();
  add(speed, "units_kn", tr("Speeds in knots"), [](DisplayUnits& u) { u.speed = SpeedUnit::Knots; });
  add(speed, "units_mps", tr("Speeds in metres per second"),
      [](DisplayUnits& u) { u.speed = SpeedUnit::MetresPerSecond; });
}

void MainWindow::connectDisplay() {
  // The helm order shown by the chart is the panel's too; an order typed there goes through the chart
  // (shown at once, then sent). The table's figures are from the CCRP.
  connect(view_, &EcdisView::orderShown, ownPanel_, &OwnShipPanel::showOrder);
  connect(ownPanel_, &OwnShipPanel::orderTyped, view_, &EcdisView::requestOrder);
  connect(view_, &EcdisView::ccrpOffsetChanged, model_, &TargetTableModel::setCcrpOffset);
  connect(view_, &EcdisView::overlayChanged, this, &MainWindow::rememberDisplaySettings);
}

void MainWindow::setDisplayUnits(const DisplayUnits& units) {
  view_->setUnits(units);
  model_->setUnits(units);
  ownPanel_->setUnits(units);
  routePanel_->setUnits(units);
  voyagePanel_->setUnits(units);
  if (localFrame_ && !history_.empty()) ownPanel_->setFrame(history_.latest(), *localFrame_);
  const std::pair<const char*, bool> checks[] = {{"units_nm", units.distance == DistanceUnit::NauticalMiles},
                                                 {"units_km", units.distance == DistanceUnit::Kilometres},
                                                 {"units_kn", units.speed == SpeedUnit::Knots},
                                                 {"units_mps", units.speed == SpeedUnit::MetresPerSecond}};
  for (const auto& [name, on] : checks)
    if (auto* a = findChild<QAction*>(QString::fromLatin1(name))) a->setChecked(on);
  // The ranges are IEC 62388's, in nautical miles; in kilometres the box gives both.
  if (auto* range = findChild<QComboBox*>(QStringLiteral("range")))
    for (int i = 0; i < range->count(); ++i) {
      const double nm = range->itemData(i).toDouble();
      range->setItemText(
          i, units.distance == DistanceUnit::NauticalMiles
                 ? tr("%1 NM").arg(nm)
                 : tr("%1 NM (%2)").arg(nm).arg(formatDistance(nmToMetres(nm), units, nm < 1.0 ? 2 : 1)));
    }
  QSettings settings;
  settings.setValue(key("distanceUnit"), static_cast<int>(units.distance));
  settings.setValue(key("speedUnit"), static_cast<int>(units.speed));
}

void MainWindow::readDisplaySettings() {
  QSettings settings;
  OverlaySettings o = view_->overlay();
  const auto index = [&](const char* name, int fallback, int count) {
    const int i = settings.value(key(name), fallback).toInt();
    return i >= 0 && i < count ? i : fallback;
  };
  o.orientation = static_cast<Orientation>(index("orientation", static_cast<int>(o.orientation), 3));
  o.motion = static_cast<Motion>(index("motion", static_cast<int>(o.motion), 2));
  o.offCentred = settings.value(key("offCentred"), o.offCentred).toBool();
  o.showTargetLabels = settings.value(key("targetLabels"), o.showTargetLabels).toBool();
  o.targetPastCount = std::clamp(settings.value(key("targetPastCount"), o.targetPastCount).toInt(), 0, 20);
  o.targetPastIntervalS =
      std::clamp(settings.value(key("targetPastIntervalS"), o.targetPastIntervalS).toDouble(), 5.0, 600.0);
  o.ccrpFromBowM =
      std::clamp(settings.value(key("ccrpFromBowM"), o.ccrpFromBowM).toDouble(), 0.0, o.ownLengthM);
  o.ccrpToStarboardM = std::clamp(settings.value(key("ccrpToStarboardM"), o.ccrpToStarboardM).toDouble(),
                                  -0.5 * o.ownBeamM, 0.5 * o.ownBeamM);
  view_->setOverlay(o);
  DisplayUnits u;
  u.distance = static_cast<DistanceUnit>(index("distanceUnit", 0, 2));
  u.speed = static_cast<SpeedUnit>(index("speedUnit", 0, 2));
  setDisplayUnits(u);
}

void MainWindow::rememberDisplaySettings(const OverlaySettings& o) {
  QSettings settings;
  settings.setValue(key("orientation"), static_cast<int>(o.orientation));
  settings.setValue(key("motion"), static_cast<int>(o.motion));
  settings.setValue(key("offCentred"), o.offCentred);
  settings.setValue(key("targetLabels"), o.showTargetLabels);
  settings.setValue(key("targetPastCount"), o.targetPastCount);
  settings.setValue(key("targetPastIntervalS"), o.targetPastIntervalS);
  settings.setValue(key("ccrpFromBowM"), o.ccrpFromBowM);
  settings.setValue(key("ccrpToStarboardM"), o.ccrpToStarboardM);
  settings.setValue(key("vectorMinutes"), o.vectorMinutes);
  settings.setValue(key("relativeVectors"), o.relativeVectors);
}

void MainWindow::setCcrp(double fromBowM, double toStarboardM) {
  const OverlaySettings& o = view_->overlay();
  if (!(fromBowM >= 0.0 && fromBowM <= o.ownLengthM) || !(std::abs(toStarboardM) <= 0.5 * o.ownBeamM)) {
    reportError(
        tr("The CCRP must lie in the hull: 0 to %1 m from the bow, %2 m either side of the centreline "
           "(got %3 m, %4 m)")
            .arg(o.ownLengthM)
            .arg(0.5 * o.ownBeamM)
            .arg(fromBowM)
            .arg(toStarboardM));
    return;
  }
  editOverlay(view_, [=](OverlaySettings& s) {
    s.ccrpFromBowM = fromBowM;
    s.ccrpToStarboardM = toStarboardM;
  });
}

void MainWindow::askCcrp() {
  QDialog dialog(this);
  dialog.setWindowTitle(tr("CCRP"));
  auto* form = new QFormLayout(&dialog);
  const OverlaySettings& o = view_->overlay();
  auto* bow = new QDoubleSpinBox(&dialog);
  bow->setRange(0.0, o.ownLengthM);
  bow->setDecimals(1);
  bow->setSuffix(tr(" m"));
  bow->setValue(o.ccrpFromBowM);
  auto* side = new QDoubleSpinBox(&dialog);
  side->setRange(-0.5 * o.ownBeamM, 0.5 * o.ownBeamM);
  side->setDecimals(1);
  side->setSuffix(tr(" m"));
  side->setValue(o.ccrpToStarboardM);
  form->addRow(tr("Aft of the bow (the ship's centre: %1 m)").arg(0.5 * o.ownLengthM), bow);
  form->addRow(tr("To starboard of the centreline (port < 0)"), side);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  form->addRow(buttons);
  if (dialog.exec() == QDialog::Accepted) setCcrp(bow->value(), side->value());
}

void MainWindow::setPalette(charts::Palette palette) {
  charts::MarinerSettings s = view_->settings();
  s.palette = palette;
  view_->setSettings(s);
  const QPalette pal = widgetPalette(palette);
  QMainWindow::setPalette(pal);
  QToolTip::setPalette(pal);
  for (QWidget* w : findChildren<QWidget*>()) w->setPalette(pal);
  ownPlots_->setDark(palette != charts::Palette::Day);
  targetPlots_->setDark(palette != charts::Palette::Day);
  alertPanel_->setDisplayPalette(palette);
  alertPanel_->refresh(history_);
  ownPanel_->setDisplayPalette(palette);
  voyagePanel_->setDisplayPalette(palette);
  if (!history_.alerts().empty()) updateAlarms();
  for (auto* combo : findChildren<QComboBox*>(QStringLiteral("palette")))
    combo->setCurrentIndex(static_cast<int>(palette));
}

}  // namespace reckoner::ui
