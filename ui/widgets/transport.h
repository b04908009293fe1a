#pragma once
// Playback of the demonstration's timeline (the video, or the event timeline alone when there
// is no video): play forward or backward at a rate, step by frames or seconds, jump to the ends.
// J/K/L as in video editors: L plays forward (again: faster), J backward, K pauses.
#include <QElapsedTimer>
#include <QObject>

#include "ui/document/document.h"

class QTimer;

namespace demoplan::ui {

class Transport : public QObject {
  Q_OBJECT
public:
  explicit Transport(Document* doc, QObject* parent = nullptr);
  bool isPlaying() const;
  double rate() const { return rate_; }  // signed: < 0 backward

public slots:
  void play(double rate = 1.0);
  void pause();
  void toggle();
  void stepFrames(int n);
  void stepSeconds(double s);
  void home();
  void end();
  void j();
  void k();
  void l();

signals:
  void stateChanged(bool playing, double rate);

private:
  void tick();
  Document* doc_;
  QTimer* timer_;
  QElapsedTimer clock_;
  double rate_ = 1.0;
  double position_ = 0.0;  // fractional frame while playing
};

}  // namespace demoplan::ui
