#include "ui/jobs/long_job.h"

#include <cmath>

#include <QCheckBox>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

namespace mq::ui {

namespace {
constexpr const char* kAskKey = "jobs/ask_before_long";
}

void JobRate::measured(double units, double seconds) {
  if (!(units > 0.0) || !(seconds > 0.0) || !std::isfinite(seconds)) return;
  const double rate = seconds / units;
  secondsPerUnit_ = measured_ ? 0.5 * (secondsPerUnit_ + rate) : rate;
  measured_ = true;
}

QString durationText(double seconds) {
  const long minutes = std::lround(seconds / 60.0);
  if (minutes < 1) return QObject::tr("under a minute");
  if (minutes < 60) return minutes == 1 ? QObject::tr("about 1 minute") : QObject::tr("about %1 minutes").arg(minutes);
  const long hours = minutes / 60, rest = minutes % 60;
  const QString hourText = hours == 1 ? QObject::tr("1 hour") : QObject::tr("%1 hours").arg(hours);
  return rest == 0 ? QObject::tr("about %1").arg(hourText) : QObject::tr("about %1 %2 minutes").arg(hourText).arg(rest);
}

bool askBeforeLongJobs() { return QSettings().value(kAskKey, true).toBool(); }
void setAskBeforeLongJobs(bool ask) { QSettings().setValue(kAskKey, ask); }

bool confirmLongJob(QWidget* parent, const QString& what, double seconds) {
  if (seconds <= kLongJobSeconds || !askBeforeLongJobs()) return true;
  QMessageBox box(QMessageBox::Question, QObject::tr("A long job"),
                  QObject::tr("%1 will take %2 on this machine.").arg(what, durationText(seconds)),
                  QMessageBox::NoButton, parent);
  box.setInformativeText(QObject::tr("It runs with a progress bar and can be cancelled. Start it now?"));
  QPushButton* start = box.addButton(QObject::tr("Start"), QMessageBox::AcceptRole);
  box.addButton(QMessageBox::Cancel);
  box.setDefaultButton(start);
  box.setObjectName("longJobQuestion");
  auto* dontAsk = new QCheckBox(QObject::tr("Do not ask again"), &box);
  box.setCheckBox(dontAsk);
  box.exec();
  const bool started = box.clickedButton() == start;
  if (started && dontAsk->isChecked()) setAskBeforeLongJobs(false);
  return started;
}

}  // namespace mq::ui
