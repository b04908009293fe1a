#pragma once
// The five steps of the operator's job across the top of the window (UX.md): each shows a tick,
// a warning or an error and says why in its tooltip; clicking one brings its panels forward.
#include <QWidget>
#include <array>

#include "ui/document/document.h"

class QPainter;

namespace demoplan::ui {

class StepBar : public QWidget {
  Q_OBJECT
public:
  explicit StepBar(QWidget* parent = nullptr);
  void setState(Step step, const StepState& state);
  const StepState& state(Step step) const { return states_[int(step)]; }
  void setCurrent(Step step);
  Step current() const { return current_; }
  QRect stepRect(Step step) const;
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

signals:
  void stepClicked(Step step);

protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent*) override;
  bool event(QEvent*) override;

private:
  std::array<StepState, 5> states_{};
  Step current_ = Step::Video;
};

// Draws a status badge (tick, warning, cross, busy, or a hollow dot) in `r`.
void paintStatusIcon(QPainter& p, const QRectF& r, StepStatus status);

}  // namespace demoplan::ui
