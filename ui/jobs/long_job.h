#pragma once
// Jobs that may run for minutes (a garment bake over a long clip, a fine
// cloth): how long one will take, and the question the editor asks before
// starting it.

#include <QString>

class QWidget;

namespace mq::ui {

// Past this estimate the editor asks before it starts a job.
constexpr double kLongJobSeconds = 60.0;

// Seconds per unit of work (for a bake: one cloth vertex stepped once) on
// this machine: a cautious prior, then what the jobs that ran measured.
class JobRate {
 public:
  explicit JobRate(double priorSecondsPerUnit) : secondsPerUnit_(priorSecondsPerUnit) {}
  double seconds(double units) const { return units * secondsPerUnit_; }
  double secondsPerUnit() const { return secondsPerUnit_; }
  // A finished job: the next estimates follow it (half the old rate, half
  // the new, so one job slowed by another program does not decide alone).
  void measured(double units, double seconds);

 private:
  double secondsPerUnit_;
  bool measured_ = false;
};

// "about 3 minutes", "about 1 hour 20 minutes".
QString durationText(double seconds);

// Asks "Start it now?" when `seconds` exceeds kLongJobSeconds and the user
// has not turned the question off; true to start. `what` names the job
// ("Baking 4,000 frames of 2 garments").
bool confirmLongJob(QWidget* parent, const QString& what, double seconds);

// The "Do not ask again" of that question (QSettings "jobs/ask_before_long").
bool askBeforeLongJobs();
void setAskBeforeLongJobs(bool ask);

}  // namespace mq::ui
