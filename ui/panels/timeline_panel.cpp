#include "ui/panels/timeline_panel.h"

#include <cmath>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>

#include "ui/document/editor_document.h"
#include "ui/icons.h"

namespace mq::ui {

TimelinePanel::TimelinePanel(EditorDocument* document, QWidget* parent)
    : QWidget(parent), document_(document), timer_(new QTimer(this)) {
  auto makeButton = [this](Icon icon, const QString& tip) {
    auto* b = new QToolButton(this);
    b->setIcon(makeIcon(icon));
    b->setIconSize(QSize(18, 18));
    b->setToolTip(tip);
    b->setAutoRaise(true);
    return b;
  };
  toStart_ = makeButton(Icon::ToStart, tr("Go to start"));
  stepBack_ = makeButton(Icon::StepBack, tr("Previous frame"));
  play_ = makeButton(Icon::Play, tr("Play / pause (Space)"));
  play_->setObjectName("playButton");
  stepForward_ = makeButton(Icon::StepForward, tr("Next frame"));
  toEnd_ = makeButton(Icon::ToEnd, tr("Go to end"));

  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setTickPosition(QSlider::TicksBelow);
  slider_->setMinimumWidth(200);
  timeLabel_ = new QLabel(this);
  timeLabel_->setMinimumWidth(150);
  timeLabel_->setAlignment(Qt::AlignVCenter | Qt::AlignRight);
  timeLabel_->setFont(QFont("monospace"));
  clipBox_ = new QComboBox(this);
  clipBox_->setMinimumContentsLength(12);
  clipBox_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  fps_ = new QSpinBox(this);
  fps_->setRange(1, 240);
  fps_->setValue(30);
  fps_->setSuffix(tr(" fps"));

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 4, 6, 4);
  for (QToolButton* b : {toStart_, stepBack_, play_, stepForward_, toEnd_}) layout->addWidget(b);
  layout->addWidget(slider_, 1);
  layout->addWidget(timeLabel_);
  layout->addSpacing(12);
  layout->addWidget(new QLabel(tr("Clip"), this));
  layout->addWidget(clipBox_);
  layout->addWidget(fps_);

  connect(play_, &QToolButton::clicked, this, &TimelinePanel::togglePlaying);
  connect(toStart_, &QToolButton::clicked, this, [this] { document_->setTime(document_->clipStart()); });
  connect(toEnd_, &QToolButton::clicked, this, [this] { document_->setTime(document_->clipEnd()); });
  connect(stepBack_, &QToolButton::clicked, this, [this] { stepFrames(-1); });
  connect(stepForward_, &QToolButton::clicked, this, [this] { stepFrames(1); });
  connect(slider_, &QSlider::valueChanged, this, &TimelinePanel::onSliderMoved);
  connect(clipBox_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (!syncing_) document_->setClip(index - 1);  // entry 0 is the rest pose
  });
  connect(fps_, &QSpinBox::valueChanged, this, [this] {
    showClip();
    if (isPlaying()) timer_->start(int(1000.0f * framePeriod()));
  });
  connect(timer_, &QTimer::timeout, this, &TimelinePanel::advance);

  connect(document_, &EditorDocument::clipsChanged, this, &TimelinePanel::rebuildClips);
  connect(document_, &EditorDocument::clipChanged, this, &TimelinePanel::showClip);
  connect(document_, &EditorDocument::timeAxisChanged, this, &TimelinePanel::showClip);
  connect(document_, &EditorDocument::timeChanged, this, &TimelinePanel::showTime);
  rebuildClips();
}

float TimelinePanel::framePeriod() const { return 1.0f / float(fps_->value()); }

bool TimelinePanel::isPlaying() const { return timer_->isActive(); }

void TimelinePanel::setPlaying(bool playing) {
  if (playing == isPlaying()) return;
  if (playing && !(document_->clipEnd() > document_->clipStart())) return;
  if (playing) {
    if (document_->time() >= document_->clipEnd()) document_->setTime(document_->clipStart());
    clock_.start();
    timer_->start(int(1000.0f * framePeriod()));
  } else {
    timer_->stop();
  }
  play_->setIcon(makeIcon(playing ? Icon::Pause : Icon::Play));
  emit playingChanged(playing);
}

void TimelinePanel::stepFrames(int frames) {
  setPlaying(false);
  document_->setTime(document_->time() + frames * framePeriod());
}

void TimelinePanel::advance() {
  // Wall-clock time, so playback keeps real speed when frames take longer.
  const float elapsed = clock_.restart() / 1000.0f;
  const float start = document_->clipStart(), end = document_->clipEnd();
  float t = document_->time() + elapsed;
  if (end > start && t > end) t = start + std::fmod(t - start, end - start);
  document_->setTime(t);
}

void TimelinePanel::rebuildClips() {
  syncing_ = true;
  clipBox_->clear();
  clipBox_->addItem(tr("(rest pose)"));
  for (const Clip& clip : document_->character().clips)
    clipBox_->addItem(QString::fromStdString(clip.name.empty() ? "clip" : clip.name));
  syncing_ = false;
  showClip();
}

void TimelinePanel::showClip() {
  syncing_ = true;
  const int clip = document_->clipIndex();
  clipBox_->setCurrentIndex(clip + 1);
  const float duration = document_->clipEnd() - document_->clipStart();
  const bool hasAxis = duration > 0.0f;  // a clip, or a scene's own duration without one
  const int frames = std::max(0, int(std::ceil(duration / framePeriod() - 1e-3f)));
  slider_->setRange(0, frames);
  slider_->setTickInterval(std::max(1, fps_->value() / 2));
  for (QWidget* w :
       {static_cast<QWidget*>(slider_), static_cast<QWidget*>(play_), static_cast<QWidget*>(toStart_),
        static_cast<QWidget*>(toEnd_), static_cast<QWidget*>(stepBack_), static_cast<QWidget*>(stepForward_)})
    w->setEnabled(hasAxis);
  if (!hasAxis) setPlaying(false);
  syncing_ = false;
  showTime();
}

void TimelinePanel::showTime() {
  const float t = document_->time() - document_->clipStart();
  const float duration = document_->clipEnd() - document_->clipStart();
  const int frame = int(std::lround(t / framePeriod()));
  syncing_ = true;
  slider_->setValue(frame);
  syncing_ = false;
  timeLabel_->setText(tr("%1 / %2 s   frame %3").arg(t, 0, 'f', 2).arg(duration, 0, 'f', 2).arg(frame, 3));
}

void TimelinePanel::onSliderMoved(int frame) {
  if (syncing_) return;
  document_->setTime(document_->clipStart() + frame * framePeriod());
}

}  // namespace mq::ui
