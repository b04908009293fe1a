// Events from the benchmark task's pose tracks (issue 14): detection replaces the demonstration
// as one undo step; the Part Tracks panel draws the selected part's track on the timeline's
// frame axis and moves the playhead on a click; doubts are drawn in the timeline, lead there,
// can be dismissed (undoably) and survive saving and opening the project.
#include <QComboBox>
#include <QLabel>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtTest>

#include "core/project/project.h"
#include "perception/events/tracks_demonstration.h"
#include "perception/tracking/track_coverage.h"
#include "ui/document/document.h"
#include "ui/widgets/part_tracks_panel.h"
#include "ui/widgets/part_tracks_view.h"
#include "ui/widgets/style.h"
#include "ui/widgets/timeline_widget.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

namespace {

// Pixels of `image` inside `area` close to `color` (anti-aliased curves are not exact).
int pixelsNear(const QImage& image, const QRect& area, const QColor& color) {
  int n = 0;
  for (int y = area.top(); y <= area.bottom(); ++y)
    for (int x = area.left(); x <= area.right(); ++x) {
      const QColor c = image.pixelColor(x, y);
      n += std::abs(c.red() - color.red()) + std::abs(c.green() - color.green()) + std::abs(c.blue() - color.blue()) < 30;
    }
  return n;
}

}  // namespace

class TestPartTracks : public QObject {
  Q_OBJECT
  std::unique_ptr<Document> doc_;
  std::unique_ptr<QWidget> window_;
  TimelinePanel* timeline_ = nullptr;
  PartTracksPanel* tracks_ = nullptr;

  // A doubt over frames 30-40 of the second part, as the detector would leave one.
  Demonstration withDoubt() const {
    Demonstration d = doc_->demonstration();
    d.doubts.push_back({1, 30, 40, "a rest seen at two places 6 cm apart with no carry between"});
    return d;
  }

private slots:
  void init() {
    doc_ = std::make_unique<Document>(test::dataDir().toStdString());
    doc_->newFromBenchmark("shelf_1", "panda", 1);
    // The timeline and the tracks stacked as in the main window: the same width.
    window_ = std::make_unique<QWidget>();
    auto* layout = new QVBoxLayout(window_.get());
    timeline_ = new TimelinePanel(doc_.get(), window_.get());
    tracks_ = new PartTracksPanel(doc_.get(), window_.get());
    layout->addWidget(timeline_);
    layout->addWidget(tracks_, 1);
    window_->resize(1000, 420);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }
  void cleanup() {
    window_.reset();
    doc_.reset();
  }

  void detectionReplacesTheDemonstrationInOneUndoStep() {
    QVERIFY2(doc_->trackDetection()->blocker().isEmpty(), qPrintable(doc_->trackDetection()->blocker()));
    doc_->removeEvent(0);  // an operator's edit the detection replaces and undo brings back
    const Json edited = demonstration_to_json(doc_->demonstration());
    QCOMPARE(int(doc_->demonstration().events.size()), 3);
    QCOMPARE(doc_->trackDetection()->detect(), 4);
    const Demonstration& d = doc_->demonstration();
    QCOMPARE(int(d.events.size()), 4);
    QCOMPARE(d.object_ids, std::vector<std::string>({"YCBV_02", "YCBV_05"}));  // the scene's order
    QVERIFY(doc_->issues().empty());
    QCOMPARE(doc_->undoStack()->count(), 2);
    QVERIFY(doc_->undoStack()->undoText().startsWith(QStringLiteral("Detect events from tracks (4 events")));
    doc_->undoStack()->undo();
    QCOMPARE(demonstration_to_json(doc_->demonstration()), edited);
    doc_->undoStack()->redo();
    QCOMPARE(int(doc_->demonstration().events.size()), 4);
  }

  void detectionWithoutAProjectChangesNothing() {
    Document empty(test::dataDir().toStdString());
    QVERIFY(!empty.trackDetection()->blocker().isEmpty());
    QVERIFY_THROWS_EXCEPTION(std::exception, empty.trackDetection()->detect());
    QCOMPARE(empty.undoStack()->count(), 0);
    QVERIFY(!empty.trackDetection()->tracks());
  }

  void panelDrawsTheSelectedPartsTrack() {
    QCOMPARE(doc_->trackDetection()->detect(), 4);
    PartTracksView* view = tracks_->view();
    QVERIFY(view->tracks());
    QCOMPARE(tracks_->partList()->count(), int(view->tracks()->tracks.object_ids.size()));
    // The selection picks the part shown, and the list selects the part.
    doc_->selectObject(1);
    QCOMPARE(tracks_->partList()->currentText(), QStringLiteral("YCBV_05"));
    QCOMPARE(view->row(), view->tracks()->tracks.object_index("YCBV_05"));
    tracks_->partList()->setCurrentIndex(view->tracks()->tracks.object_index("YCBV_02"));
    QCOMPARE(doc_->selectedObject(), 0);
    // Where the tracks come from, then shelf_1's one carry each.
    QVERIFY2(tracks_->summaryLabel()->text().startsWith(QStringLiteral("From the task's pose tracks: 2 rests, 1 carry")),
             qPrintable(tracks_->summaryLabel()->text()));
    QVERIFY(!doc_->trackDetection()->fromVideo());
    // The curves are there: x in red in the position strip, the angle in its own strip.
    const QImage shot = view->grab().toImage();
    QVERIFY(pixelsNear(shot, view->positionPlot().toRect(), kAxisColors[0]) > 50);
    QVERIFY(pixelsNear(shot, view->anglePlot().toRect(), kTrackAngleColor) > 50);
    QVERIFY(window_->grab().save(test::artifactDir() + QStringLiteral("/part_tracks_panel.png")));
    // Every grasp of the part sits on the boundary of a carry of its track (the last frame of the
    // rest before), so the shading explains the event.
    const int row = view->row();
    for (const ContactEvent& e : doc_->demonstration().events) {
      if (e.object != 0 || e.type != EventType::Grasp) continue;
      const int after = view->segmentAt(e.frame + 1);
      QVERIFY2(after >= 0, qPrintable(QString::number(e.frame)));
      const auto kind = view->tracks()->segmentation.objects[size_t(row)].segments[size_t(after)].kind;
      QVERIFY2(kind != perception::SegmentKind::Rest, qPrintable(QString::number(e.frame)));
    }
  }

  // Tracks from the video's model tracker that lose a part for good: the summary says from
  // which frame (a link there), and its tooltip how to place the part again; the marker tracker's
  // do not. Placed again later, the part starts where the tracker last had it.
  void aPartTheModelTrackerLostForGoodIsPointedOut() {
    QCOMPARE(doc_->trackDetection()->detect(), 4);
    auto lost = std::make_shared<perception::TracksDemonstration>(*tracks_->view()->tracks());
    const int row = lost->tracks.object_index("YCBV_02");
    QVERIFY(row >= 0);
    auto& samples = lost->tracks.samples[size_t(row)];
    const int from = int(samples.size()) - perception::kLostForGoodFrames - 2;
    for (size_t f = size_t(from); f < samples.size(); ++f) samples[f].valid = false;
    doc_->selectObject(0);
    doc_->trackDetection()->showVideoTracks(lost, QStringLiteral("model"));
    QCOMPARE(tracks_->view()->row(), row);
    const QString text = tracks_->summaryLabel()->text();
    QVERIFY2(text.startsWith(QStringLiteral("From the video (model tracker)")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("lost from frame %1 on").arg(from)), qPrintable(text));
    QVERIFY2(tracks_->summaryLabel()->toolTip().contains(QStringLiteral("corrections")), qPrintable(tracks_->summaryLabel()->toolTip()));
    QVERIFY(window_->grab().save(test::artifactDir() + QStringLiteral("/part_tracks_lost.png")));
    // The link takes the playhead there; placed again later, the part starts where the tracker last had it.
    emit tracks_->summaryLabel()->linkActivated(QStringLiteral("lost:%1").arg(from));
    QCOMPARE(doc_->currentFrame(), from);
    doc_->setCurrentFrame(from + 5);
    const int object = doc_->demonstration().object_index("YCBV_02");
    const int placed = doc_->placeAgain(object);
    QVERIFY(placed >= 0);
    QVERIFY((doc_->corrections()[size_t(placed)].world_T_object.translation() -
             samples[size_t(from - 1)].pose.translation()).norm() < 1e-9);
    // Marked on the part's track too.
    const auto* view = tracks_->view();
    QVERIFY2(view->toolTipAt(view->axis().toX(from + 5)).contains(QStringLiteral("placed again here")),
             qPrintable(view->toolTipAt(view->axis().toX(from + 5))));
    QVERIFY(!view->toolTipAt(view->axis().toX(from + 4)).contains(QStringLiteral("placed again here")));
    QVERIFY(window_->grab().save(test::artifactDir() + QStringLiteral("/part_tracks_placed.png")));
    doc_->trackDetection()->showVideoTracks(lost, QStringLiteral("markers"));
    QVERIFY2(!tracks_->summaryLabel()->text().contains(QStringLiteral("lost from")), qPrintable(tracks_->summaryLabel()->text()));
  }

  void clickOnThePanelMovesThePlayheadToThatFrame() {
    PartTracksView* view = tracks_->view();
    QVERIFY(view->tracks());  // segmented on first sight, without a detection
    doc_->setCurrentFrame(0);
    const QPoint at(int(std::lround(view->axis().toX(77))), int(view->positionPlot().center().y()));
    QTest::mouseClick(view, Qt::LeftButton, {}, at);
    QCOMPARE(doc_->currentFrame(), 77);
    // The same frame sits at the same x in the timeline above.
    QCOMPARE(timeline_->timeline()->xToFrame(at.x()), 77);
    const QPoint to(int(std::lround(view->axis().toX(120))), at.y());
    QTest::mousePress(view, Qt::LeftButton, {}, at);
    QTest::mouseMove(view, to);
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    QCOMPARE(doc_->currentFrame(), 120);
    QCOMPARE(doc_->undoStack()->count(), 0);  // scrubbing is no edit
  }

  void doubtsAreShownInTheTimelineAndLeadThere() {
    doc_->replaceDemonstration(withDoubt(), QStringLiteral("a doubt"));
    TimelineWidget* t = timeline_->timeline();
    const QRectF r = t->doubtRect(0);
    QVERIFY(r.left() <= t->frameToX(30) + 0.5 && r.right() >= t->frameToX(40) - 0.5);
    QVERIFY(r.top() >= t->laneTop(1) && r.bottom() <= t->laneTop(2));
    QCOMPARE(t->doubtAt(r.center()), 0);
    QCOMPARE(t->doubtAt(QPointF(t->frameToX(100), r.center().y())), -1);
    QVERIFY2(timeline_->validityLabel()->text().contains(QStringLiteral("href='doubt:0'")),
             qPrintable(timeline_->validityLabel()->text()));
    QCOMPARE(doc_->steps()->state(Step::Events).status, StepStatus::Warning);
    doc_->setCurrentFrame(90);
    QCOMPARE(timeline_->jumpToNextDoubt(), 0);  // none after 90: round to the first
    QCOMPARE(doc_->currentFrame(), 30);
    QCOMPARE(doc_->selectedObject(), 1);
    // The part tracks follow: the doubt's reason under the cursor, not elsewhere.
    PartTracksView* view = tracks_->view();
    QCOMPARE(tracks_->partList()->currentText(), QStringLiteral("YCBV_05"));
    QVERIFY2(view->toolTipAt(view->axis().toX(35)).contains(QStringLiteral("no carry between")),
             qPrintable(view->toolTipAt(view->axis().toX(35))));
    QVERIFY(!view->toolTipAt(view->axis().toX(90)).contains(QStringLiteral("no carry between")));
    // Dismissed after a look, and back with undo.
    doc_->removeDoubt(0);
    QVERIFY(doc_->demonstration().doubts.empty());
    QCOMPARE(t->doubtAt(r.center()), -1);
    doc_->undoStack()->undo();
    QCOMPARE(int(doc_->demonstration().doubts.size()), 1);
  }

  void doubtsSurviveSavingAndOpening() {
    doc_->replaceDemonstration(withDoubt(), QStringLiteral("a doubt"));
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("doubt.demoplan"));
    doc_->saveAs(file);
    Document again(test::dataDir().toStdString());
    again.open(file);
    const auto& doubts = again.demonstration().doubts;
    QCOMPARE(int(doubts.size()), 1);
    QCOMPARE(doubts[0].object, 1);
    QCOMPARE(doubts[0].first_frame, 30);
    QCOMPARE(doubts[0].last_frame, 40);
    QCOMPARE(doubts[0].message, withDoubt().doubts.back().message);
  }
};

DEMOPLAN_UI_TEST_MAIN(TestPartTracks)
#include "test_part_tracks.moc"
