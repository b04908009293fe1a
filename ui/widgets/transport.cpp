#include "ui/widgets/transport.h"

#include <QTimer>
#include <cmath>

namespace demoplan::ui {

Transport::Transport(Document* doc, QObject* parent) : QObject(parent), doc_(doc) {
  timer_ = new QTimer(this);
  timer_->setTimerType(Qt::PreciseTimer);
  connect(timer_, &QTimer::timeout, this, &Transport::tick);
  connect(doc_, &Document::projectLoaded, this, &Transport::pause);
}

bool Transport::isPlaying() const { return timer_->isActive(); }

void Transport::play(double rate) {
  if (!doc_->hasProject()) return;
  rate_ = rate;
  const int last = doc_->frameCount() - 1;
  if (rate > 0 && doc_->currentFrame() >= last) doc_->setCurrentFrame(0);
  if (rate < 0 && doc_->currentFrame() <= 0) doc_->setCurrentFrame(last);
  doc_->setCurrentFrame(doc_->currentFrame());  // back to the demonstration view
  position_ = doc_->currentFrame();
  clock_.start();
  timer_->start(int(std::clamp(1000.0 / (doc_->fps() * std::abs(rate)), 10.0, 100.0)));
  emit stateChanged(true, rate_);
}

void Transport::pause() {
  if (!timer_->isActive()) return;
  timer_->stop();
  emit stateChanged(false, rate_);
}

void Transport::toggle() {
  if (isPlaying()) pause();
  else play(1.0);
}

void Transport::tick() {
  const double elapsed = clock_.restart() / 1000.0;
  position_ += elapsed * doc_->fps() * rate_;
  const int last = doc_->frameCount() - 1;
  const int frame = std::clamp(int(std::floor(position_ + 1e-9)), 0, last);
  doc_->setCurrentFrame(frame);
  if ((rate_ > 0 && frame >= last) || (rate_ < 0 && frame <= 0)) pause();
}

void Transport::stepFrames(int n) {
  pause();
  doc_->setCurrentFrame(doc_->currentFrame() + n);
}

void Transport::stepSeconds(double s) {
  pause();
  doc_->setCurrentFrame(doc_->currentFrame() + int(std::lround(s * doc_->fps())));
}

void Transport::home() {
  pause();
  doc_->setCurrentFrame(0);
}

void Transport::end() {
  pause();
  doc_->setCurrentFrame(doc_->frameCount() - 1);
}

void Transport::j() {
  const double r = isPlaying() && rate_ < 0 ? std::max(-8.0, rate_ * 2) : -1.0;
  play(r);
}

void Transport::k() { pause(); }

void Transport::l() {
  const double r = isPlaying() && rate_ > 0 ? std::min(8.0, rate_ * 2) : 1.0;
  play(r);
}

}  // namespace demoplan::ui
