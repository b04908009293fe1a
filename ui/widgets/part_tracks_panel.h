#pragma once
// The Part Tracks dock under the timeline: which part (a list synced with the selection: a part
// picked in the timeline or the 3D view is shown here, one chosen here is selected there), the
// track's measured noise and carries in one line, and the plot (PartTracksView) on the
// timeline's frame axis.
#include <QWidget>

#include "ui/document/document.h"

class QComboBox;
class QLabel;

namespace demoplan::ui {

class PartTracksView;

class PartTracksPanel : public QWidget {
  Q_OBJECT
public:
  explicit PartTracksPanel(Document* doc, QWidget* parent = nullptr);
  PartTracksView* view() const { return view_; }
  QComboBox* partList() const { return parts_; }
  QLabel* summaryLabel() const { return summary_; }

private:
  void refill();          // the parts of the tracks
  void followSelection();  // the selected part, when it has a track
  void refreshSummary();
  Document* doc_;
  QComboBox* parts_;
  QLabel* summary_;
  PartTracksView* view_;
};

}  // namespace demoplan::ui
