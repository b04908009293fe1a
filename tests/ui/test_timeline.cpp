// Editing events through the timeline changes the demonstration; undo restores it; a broken rule
// is shown with its reason and jumps to the event.
#include <QComboBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QLabel>
#include <QPushButton>
#include <QUndoStack>
#include <QtTest>

#include "ui/document/document.h"
#include "ui/document/event_detection.h"
#include "ui/document/extraction_runner.h"
#include "ui/widgets/timeline_widget.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestTimeline : public QObject {
  Q_OBJECT
  std::unique_ptr<Document> doc_;
  std::unique_ptr<TimelinePanel> panel_;
  Json original_;

  TimelineWidget* timeline() { return panel_->timeline(); }

private slots:
  void init() {
    doc_ = std::make_unique<Document>(test::dataDir().toStdString());
    doc_->open(test::sampleProject());
    original_ = demonstration_to_json(doc_->demonstration());
    panel_ = std::make_unique<TimelinePanel>(doc_.get());
    panel_->resize(900, 160);
    panel_->show();
    QVERIFY(QTest::qWaitForWindowExposed(panel_.get()));
  }
  void cleanup() {
    panel_.reset();
    doc_.reset();
  }

  void dragMovesAnEventAndUndoRestoresIt() {
    const int ev = 1;  // release of YCBV_05 at frame 48
    QCOMPARE(doc_->demonstration().events[ev].frame, 48);
    const QPoint from = timeline()->markerRect(ev).center().toPoint();
    const QPoint to(int(timeline()->frameToX(55)), from.y());
    QTest::mousePress(timeline(), Qt::LeftButton, {}, from);
    QTest::mouseMove(timeline(), from + QPoint(5, 0));
    QTest::mouseMove(timeline(), to);
    QTest::mouseRelease(timeline(), Qt::LeftButton, {}, to);
    QCOMPARE(doc_->demonstration().events[ev].frame, 55);
    QCOMPARE(doc_->selectedEvent(), ev);
    QCOMPARE(doc_->currentFrame(), 55);
    QCOMPARE(doc_->undoStack()->count(), 1);
    QVERIFY(doc_->isModified());
    doc_->undoStack()->undo();
    QCOMPARE(doc_->demonstration().events[ev].frame, 48);
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original_);
    QVERIFY(!doc_->isModified());
    doc_->undoStack()->redo();
    QCOMPARE(doc_->demonstration().events[ev].frame, 55);
  }

  void clickSelectsAndScrubs() {
    QTest::mouseClick(timeline(), Qt::LeftButton, {}, timeline()->markerRect(2).center().toPoint());
    QCOMPARE(doc_->selectedEvent(), 2);
    QCOMPARE(doc_->selectedObject(), doc_->demonstration().events[2].object);
    const QPoint empty(int(timeline()->frameToX(120)), TimelineWidget::kRuler / 2);
    QTest::mouseClick(timeline(), Qt::LeftButton, {}, empty);
    QCOMPARE(doc_->currentFrame(), 120);
    QCOMPARE(doc_->undoStack()->count(), 0);  // selecting and scrubbing are not edits
  }

  void doubleClickAddsTheEventThatAlternates() {
    const int lane = 0;  // YCBV_02: held from 60 to 97
    const int y = timeline()->laneTop(lane) + TimelineWidget::kLane / 2;
    QTest::mouseDClick(timeline(), Qt::LeftButton, {}, QPoint(int(timeline()->frameToX(120)), y));
    const auto& d = doc_->demonstration();
    QCOMPARE(int(d.events.size()), 5);
    QCOMPARE(d.events.back().frame, 120);
    QCOMPARE(d.events.back().type, EventType::Grasp);  // not held there
    QCOMPARE(d.events.back().object, lane);
    // A grasp never released breaks a rule: the panel says so.
    QVERIFY(!doc_->issues().empty());
    QVERIFY2(panel_->validityLabel()->text().contains(QStringLiteral("never released")),
             qPrintable(panel_->validityLabel()->text()));
    QCOMPARE(doc_->steps()->state(Step::Events).status, StepStatus::Error);
    doc_->undoStack()->undo();
    QVERIFY(doc_->issues().empty());
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original_);
    QVERIFY(panel_->validityLabel()->text().contains(QStringLiteral("valid")));
  }

  void brokenRuleLinksToItsEvent() {
    doc_->removeEvent(0);  // the grasp of YCBV_05: its release now has no grasp
    QVERIFY(!doc_->issues().empty());
    const auto& issue = doc_->issues().front();
    QVERIFY2(QString::fromStdString(issue.message).contains(QStringLiteral("release without a grasp")), issue.message.c_str());
    QVERIFY(panel_->validityLabel()->text().contains(QStringLiteral("href='issue:0'")));
    doc_->setCurrentFrame(0);
    panel_->jumpToIssue(0);
    QCOMPARE(doc_->selectedEvent(), issue.event);
    QCOMPARE(doc_->currentFrame(), doc_->demonstration().events[issue.event].frame);
    doc_->undoStack()->undo();
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original_);
  }

  void detectingEventsInTheVideoReplacesThemUndoably() {
    QVERIFY2(doc_->detection()->blocker().isEmpty(), qPrintable(doc_->detection()->blocker()));
    QVERIFY(panel_->detectButton()->isEnabled());
    QTest::mouseClick(panel_->detectButton(), Qt::LeftButton);
    QVERIFY(doc_->detection()->runner()->isRunning());
    QVERIFY(test::waitFor([&] { return !doc_->detection()->runner()->isRunning(); }, 30000));
    QVERIFY2(panel_->detectionLabel()->text().startsWith(QStringLiteral("Found")), qPrintable(panel_->detectionLabel()->text()));
    const Demonstration& d = doc_->demonstration();
    QCOMPARE(d.object_ids, std::vector<std::string>({"YCBV_02", "YCBV_05"}));  // the scene's order
    QCOMPARE(int(d.events.size()), 4);
    // The detected frames are within a few frames of the labelled ones.
    const int labelled[] = {9, 48, 60, 97};
    for (int i = 0; i < 4; ++i) QVERIFY2(std::abs(d.events[i].frame - labelled[i]) <= 5, qPrintable(QString::number(d.events[i].frame)));
    QVERIFY(demonstration_to_json(d) != original_);
    QCOMPARE(doc_->undoStack()->count(), 1);
    doc_->undoStack()->undo();
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original_);
  }

  void detectingWithThePartModelsStartsFromThePosesAtFrameZero() {
    // The sample's marker scene has no init.json beside it: the parts start where the project
    // shows them at frame 0; the markers on them are only texture to this tracker.
    panel_->trackerChoice()->setCurrentIndex(1);
    QVERIFY(doc_->detection()->modelTracker());
    QTest::mouseClick(panel_->detectButton(), Qt::LeftButton);
    QVERIFY(test::waitFor([&] { return !doc_->detection()->runner()->isRunning(); }, 60000));
    QVERIFY2(panel_->detectionLabel()->text().startsWith(QStringLiteral("Found")), qPrintable(panel_->detectionLabel()->text()));
    const Demonstration& d = doc_->demonstration();
    QCOMPARE(int(d.events.size()), 4);
    const int labelled[] = {9, 48, 60, 97};
    for (int i = 0; i < 4; ++i) QVERIFY2(std::abs(d.events[i].frame - labelled[i]) <= 2, qPrintable(QString::number(d.events[i].frame)));
    QCOMPARE(doc_->undoStack()->count(), 1);
  }

  void detectionWarningsShowTheFirstAndListAllOnHover() {
    ExtractionOutcome o;
    o.ok = true;
    o.frames = 130;
    o.demonstration = doc_->demonstration();
    o.warnings = {"init.json: part 'YCBV_02', frame 0: 24 % of what shows of it does not look like its mesh there",
                  "init.json: part 'YCBV_05', frame 0: 30 % of what shows of it does not look like its mesh there"};
    emit doc_->detection()->done(o);
    QVERIFY2(panel_->detectionLabel()->text().startsWith(QStringLiteral("Found")), qPrintable(panel_->detectionLabel()->text()));
    const QLabel* warnings = panel_->detectionWarningsLabel();
    QVERIFY(!warnings->isHidden());
    const QString text = warnings->text(), tip = warnings->toolTip();
    QVERIFY2(text.contains(QStringLiteral("part 'YCBV_02'")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("1 more")) && !text.contains(QStringLiteral("YCBV_05")), qPrintable(text));
    QVERIFY2(tip.contains(QStringLiteral("part 'YCBV_02'")) && tip.contains(QStringLiteral("part 'YCBV_05'")), qPrintable(tip));
    // A detection without warnings takes the line away.
    o.warnings.clear();
    emit doc_->detection()->done(o);
    QVERIFY(warnings->isHidden());
  }

  void aMarkerSceneWithoutMarkersChoosesThePartModels() {
    // The sample's parts carry markers: followed by them.
    QVERIFY(!doc_->detection()->modelTracker());
    QCOMPARE(panel_->trackerChoice()->currentIndex(), 0);
    // The same scene with the markers taken off: by the parts' models, and the choice shows.
    QFile in(QString::fromStdString(doc_->media()->markersFile()));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QJsonObject scene = QJsonDocument::fromJson(in.readAll()).object();
    QJsonArray objects = scene["objects"].toArray();
    QVERIFY(!objects.isEmpty());
    for (auto o : objects) {
      QJsonObject object = o.toObject();
      object["markers"] = QJsonArray();
      o = object;
    }
    scene["objects"] = objects;
    QTemporaryDir dir;
    const QString bare = dir.filePath("bare_scene.json");
    QFile out(bare);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(scene).toJson());
    out.close();
    const QString original = doc_->media()->markersPath();
    doc_->media()->setMarkers(bare);
    QVERIFY(doc_->detection()->modelTracker());
    QCOMPARE(panel_->trackerChoice()->currentIndex(), 1);
    doc_->media()->setMarkers(original);
    QVERIFY(!doc_->detection()->modelTracker());
    QCOMPARE(panel_->trackerChoice()->currentIndex(), 0);
  }

  void detectionCanBeCancelled() {
    QVERIFY(doc_->detection()->start());
    doc_->detection()->runner()->cancel();
    QVERIFY(!doc_->detection()->runner()->isRunning());
    QVERIFY(panel_->detectButton()->isEnabled());
    QTest::qWait(200);
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original_);
    QCOMPARE(doc_->undoStack()->count(), 0);
  }

  void draggingPastAnotherEventReordersAndUndoes() {
    // Move the grasp of YCBV_02 (frame 60) before the release of YCBV_05 (48): two parts held.
    const QPoint from = timeline()->markerRect(2).center().toPoint();
    const QPoint to(int(timeline()->frameToX(30)), from.y());
    QTest::mousePress(timeline(), Qt::LeftButton, {}, from);
    QTest::mouseMove(timeline(), from - QPoint(5, 0));
    QTest::mouseMove(timeline(), to);
    QTest::mouseRelease(timeline(), Qt::LeftButton, {}, to);
    const auto& d = doc_->demonstration();
    QCOMPARE(d.events[1].frame, 30);
    QCOMPARE(d.events[1].type, EventType::Grasp);
    QVERIFY(!doc_->issues().empty());
    QVERIFY2(QString::fromStdString(doc_->issues().front().message).contains(QStringLiteral("one object at a time")),
             doc_->issues().front().message.c_str());
    doc_->undoStack()->undo();
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original_);
  }
};

DEMOPLAN_UI_TEST_MAIN(TestTimeline)
#include "test_timeline.moc"
