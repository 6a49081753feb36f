#pragma once
// The timeline: play/pause, a slider to scrub the current clip (or, with no
// clip, the scene's own duration: EditorDocument::setNoClipDuration), the time,
// the clip chooser and the playback frame rate. Playback runs on a QTimer
// and loops over the clip.

#include <QElapsedTimer>
#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTimer;
class QToolButton;

namespace mq::ui {

class EditorDocument;

class TimelinePanel : public QWidget {
  Q_OBJECT

 public:
  explicit TimelinePanel(EditorDocument* document, QWidget* parent = nullptr);

  bool isPlaying() const;
  void setPlaying(bool playing);
  void togglePlaying() { setPlaying(!isPlaying()); }
  void stepFrames(int frames);

  QSlider* slider() const { return slider_; }
  QComboBox* clipBox() const { return clipBox_; }

 signals:
  void playingChanged(bool playing);

 private:
  void rebuildClips();
  void showClip();
  void showTime();
  void advance();
  void onSliderMoved(int frame);
  float framePeriod() const;

  EditorDocument* document_;
  QToolButton* toStart_;
  QToolButton* stepBack_;
  QToolButton* play_;
  QToolButton* stepForward_;
  QToolButton* toEnd_;
  QSlider* slider_;
  QLabel* timeLabel_;
  QComboBox* clipBox_;
  QSpinBox* fps_;
  QTimer* timer_;
  QElapsedTimer clock_;
  bool syncing_ = false;
};

}  // namespace mq::ui
