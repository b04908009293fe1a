// The cell editor as an operator uses it: a new cell (robot and table), a box added, a part
// added from an STL file (put down on the table, its grasps generated), moved by typing, a
// handle deleted and the handles generated again, a part removed; every change one undo step,
// written to the cell file at once and written back on undo. A bundled example is not changed
// in place; a part too wide for the gripper and a part with events are refused with the reason.
#include <QCheckBox>
#include <QDir>
#include <QLabel>
#include <QListWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>
#include <fstream>
#include <sstream>

#include "core/cell/cell_edits.h"
#include "ui/document/document.h"
#include "ui/widgets/cell_panel.h"
#include "ui_test_support.h"
#include "tests/support/box_stl.h"

using namespace demoplan;
using namespace demoplan::ui;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

class TestCellPanel : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  std::unique_ptr<Document> doc_;
  std::unique_ptr<CellPanel> panel_;

  std::string path(const char* name) const { return dir_.filePath(QString::fromLatin1(name)).toStdString(); }

private slots:
  void init() {
    QVERIFY(dir_.isValid());
    const std::string cell = path("my_cell.json");
    save_cell(cell, starter_cell(cell, "ur5", ui::test::dataDir().toStdString()));
    doc_ = std::make_unique<Document>(ui::test::dataDir().toStdString());
    doc_->newFromCell(cell);
    panel_ = std::make_unique<CellPanel>(doc_.get());
    panel_->show();
  }
  void cleanup() {
    panel_.reset();
    doc_.reset();
  }

  void furnitureIsAddedUndoneAndRedoneInTheFile() {
    QVERIFY(doc_->cell());
    QCOMPARE(doc_->cell()->furniture.size(), size_t(2));  // pedestal and table
    QCOMPARE(panel_->tree()->topLevelItemCount(), 3);
    const int steps = doc_->undoStack()->count();
    QVERIFY2(panel_->addFurniture(CellFurniture::Kind::Box), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->undoStack()->count(), steps + 1);
    QCOMPARE(doc_->cell()->furniture.size(), size_t(3));
    QCOMPARE(doc_->scene().furniture.size(), size_t(3));
    QCOMPARE(load_cell(doc_->cell()->file).furniture.size(), size_t(3));
    QCOMPARE(panel_->selection().kind, CellPanel::Kind::Furniture);
    doc_->undoStack()->undo();
    QCOMPARE(doc_->cell()->furniture.size(), size_t(2));
    QCOMPARE(load_cell(doc_->cell()->file).furniture.size(), size_t(2));
    doc_->undoStack()->redo();
    QCOMPARE(load_cell(doc_->cell()->file).furniture.size(), size_t(3));
  }

  void furnitureFromAUrdfTakesTheSupportsOfItsSrdf() {
    // The benchmark's shelf: shelf_2_1_shelf.urdf with its SRDF beside it.
    const QString urdf = ui::test::dataDir() + QStringLiteral("/furniture/shelf_2_1_shelf.urdf");
    QVERIFY2(panel_->addFurniture(CellFurniture::Kind::Urdf, urdf), qPrintable(panel_->lastError()));
    const CellFurniture& f = doc_->cell()->furniture.back();
    QCOMPARE(f.kind, CellFurniture::Kind::Urdf);
    QVERIFY(QString::fromStdString(f.srdf).endsWith(QStringLiteral("shelf_2_1_shelf.srdf")));
    int supports = 0;
    for (const auto& sf : doc_->scene().furniture)
      if (sf.name == f.name)
        for (const auto& c : sf.srdf.contacts) supports += static_cast<int>(c.polygons.size());
    QVERIFY(supports > 0);
    QCOMPARE(load_cell(doc_->cell()->file).furniture.back().kind, CellFurniture::Kind::Urdf);
    // Not a URDF: refused naming the file, the cell unchanged.
    const std::string bad = path("not_a_robot.urdf");
    std::ofstream(bad) << "<robot name='x'><link name='a'/><joint/></robot>";
    const size_t count = doc_->cell()->furniture.size();
    QVERIFY(!panel_->addFurniture(CellFurniture::Kind::Urdf, QString::fromStdString(bad)));
    QVERIFY2(panel_->lastError().contains(QStringLiteral("not_a_robot.urdf")), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->cell()->furniture.size(), count);
  }

  void theRobotIsReplacedUndoneAndReadFromFiles() {
    const std::string stl = path("block.stl");
    demoplan::test::write_box_stl(stl, 40, 30, 20);
    QVERIFY2(panel_->addPart(QString::fromStdString(stl), 0.001), qPrintable(panel_->lastError()));
    auto handle_poses = [this] {
      std::vector<Pose> poses;
      for (const auto& h : doc_->scene().objects.at(0).srdf.handles) poses.push_back(h.pose);
      return poses;
    };
    const int steps = doc_->undoStack()->count();
    QVERIFY2(panel_->replaceRobot(QStringLiteral("panda")), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->scene().robot.name, std::string("panda"));
    QCOMPARE(load_cell(doc_->cell()->file).robot.bundled, std::string("panda"));
    QCOMPARE(panel_->selection().kind, CellPanel::Kind::Robot);
    QCOMPARE(panel_->tree()->topLevelItem(0)->text(0), QStringLiteral("Robot: panda"));
    QVERIFY(!handle_poses().empty());  // generated again for the new robot's gripper
    QCOMPARE(doc_->undoStack()->count(), steps + 1);
    doc_->undoStack()->undo();
    QCOMPARE(doc_->scene().robot.name, std::string("ur5"));
    QCOMPARE(load_cell(doc_->cell()->file).robot.bundled, std::string("ur5"));

    // The user's own files: the bundled iiwa's URDF and SRDF, read as any URDF from disk.
    const QString iiwa = ui::test::dataDir() + QStringLiteral("/robots/kuka_iiwa/kuka_iiwa");
    QVERIFY2(panel_->replaceRobot({}, iiwa + QStringLiteral(".urdf"), iiwa + QStringLiteral(".srdf")),
             qPrintable(panel_->lastError()));
    QVERIFY(doc_->cell()->robot.bundled.empty());
    QVERIFY(doc_->scene().robot.model.nq >= 7);
    QCOMPARE(panel_->tree()->topLevelItem(0)->text(0), QStringLiteral("Robot: kuka_iiwa.urdf"));
    // A URDF that is not a robot is refused naming the file; the cell keeps the iiwa.
    const std::string bad = path("broken_arm.urdf");
    std::ofstream(bad) << "<robot name='x'><link name='a'/><joint/></robot>";
    QVERIFY(!panel_->replaceRobot({}, QString::fromStdString(bad), iiwa + QStringLiteral(".srdf")));
    QVERIFY2(panel_->lastError().contains(QStringLiteral("broken_arm.urdf")), qPrintable(panel_->lastError()));
    QVERIFY(doc_->cell()->robot.urdf.ends_with("kuka_iiwa.urdf"));
  }

  void aRobotFromDiskIsMadeMobileAndBackWithUndo() {
    panel_->select(CellPanel::Kind::Robot, 0);
    QCheckBox* mobile = panel_->mobileCheck();
    QVERIFY(mobile->isVisible());
    QVERIFY(!mobile->isEnabled());  // the bundled UR5: its data says it is fixed
    QVERIFY(!mobile->isChecked());

    // The UR5 read from its files: no planar base joints, refused with the reason, nothing changed.
    const QString robots = ui::test::dataDir() + QStringLiteral("/robots/");
    QVERIFY2(panel_->replaceRobot({}, robots + QStringLiteral("ur5/ur5.urdf"), robots + QStringLiteral("ur5/ur5.srdf")),
             qPrintable(panel_->lastError()));
    QVERIFY(mobile->isEnabled());
    const int steps = doc_->undoStack()->count();
    mobile->click();
    QVERIFY2(panel_->lastError().contains(QStringLiteral("robot.mobile: ur5.urdf has no planar base joints")),
             qPrintable(panel_->lastError()));
    QVERIFY(!mobile->isChecked());
    QVERIFY(!doc_->cell()->robot.mobile);
    QCOMPARE(doc_->undoStack()->count(), steps);
    panel_->resize(440, 720);  // about the Cell dock's size in a 1280 x 800 window
    QDir().mkpath(ui::test::artifactDir() + QStringLiteral("/ui"));
    QVERIFY(panel_->grab().save(ui::test::artifactDir() + QStringLiteral("/ui/cell-panel-mobile-refused.png")));

    // The KMR read from its files: made mobile by a click, off its pedestal onto the floor.
    const QString kmr = robots + QStringLiteral("kuka_kmr_iiwa/kuka_kmr_iiwa");
    QVERIFY2(panel_->replaceRobot({}, kmr + QStringLiteral(".urdf"), kmr + QStringLiteral(".srdf")),
             qPrintable(panel_->lastError()));
    QCOMPARE(doc_->cell()->furniture.size(), size_t(2));
    const int before = doc_->undoStack()->count();
    mobile->click();
    QVERIFY2(panel_->lastError().isEmpty(), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->undoStack()->count(), before + 1);
    QVERIFY(mobile->isChecked());
    QVERIFY(doc_->cell()->robot.mobile);
    QVERIFY(!doc_->scene().robot.fixed_base);
    QCOMPARE(doc_->cell()->robot.base.translation().z(), 0.0);
    QCOMPARE(doc_->cell()->furniture.size(), size_t(1));  // the table; the pedestal is gone
    QVERIFY(load_cell(doc_->cell()->file).robot.mobile);
    QVERIFY(panel_->infoLabel()->text().contains(QStringLiteral("mobile robot")));
    QVERIFY(panel_->grab().save(ui::test::artifactDir() + QStringLiteral("/ui/cell-panel-mobile-robot.png")));

    // Undone: fixed on its pedestal again, in the file too; redone: mobile.
    doc_->undoStack()->undo();
    QVERIFY(!doc_->cell()->robot.mobile);
    QVERIFY(!mobile->isChecked());
    QCOMPARE(doc_->cell()->furniture.size(), size_t(2));
    QVERIFY(!load_cell(doc_->cell()->file).robot.mobile);
    doc_->undoStack()->redo();
    QVERIFY(load_cell(doc_->cell()->file).robot.mobile);

    // Made fixed by a click: a pedestal is put under it again.
    mobile->click();
    QVERIFY(!doc_->cell()->robot.mobile);
    QCOMPARE(doc_->cell()->furniture.size(), size_t(2));
    QCOMPARE(doc_->cell()->robot.base.translation().z(), 0.75);
  }

  void aPartFromAnStlRestsOnTheTableWithGrasps() {
    const std::string stl = path("block.stl");
    demoplan::test::write_box_stl(stl, 40, 30, 20);  // millimetres
    QCOMPARE(guess_unit_scale(stl), 0.001);
    QVERIFY2(panel_->addPart(QString::fromStdString(stl), 0.001), qPrintable(panel_->lastError()));
    const Cell& cell = *doc_->cell();
    QCOMPARE(cell.parts.size(), size_t(1));
    QCOMPARE(cell.parts[0].name, std::string("block"));
    // On the table top (0.75 m) on one of its faces: its centre 10, 15 or 20 mm above it.
    const Eigen::Vector3d at = cell.parts[0].pose.translation();
    const double lift = at.z() - 0.75;
    QVERIFY2(std::abs(lift - 0.010) < 1e-3 || std::abs(lift - 0.015) < 1e-3 || std::abs(lift - 0.020) < 1e-3,
             qPrintable(QString::number(lift)));
    QVERIFY(std::abs(at.x() - 0.65) < 0.4 && std::abs(at.y()) < 0.6);
    // Before any event the 3D view shows it where the cell puts it.
    QVERIFY(doc_->displayState().objects.at(0).isApprox(cell.parts[0].pose));
    // The demonstration follows the parts; the handles are listed.
    QCOMPARE(doc_->demonstration().object_ids, std::vector<std::string>{"block"});
    QCOMPARE(panel_->selection().kind, CellPanel::Kind::Part);
    const int handles = panel_->handleList()->count();
    QVERIFY(handles > 0);
    QVERIFY(panel_->infoLabel()->text().contains(QStringLiteral("generated")));

    // Typing moves it: steps of one field are one undo step; the file follows.
    const int steps = doc_->undoStack()->count();
    Pose moved = cell.parts[0].pose;
    moved.translation().x() += 0.05;
    QVERIFY(panel_->setSelectedPose(moved, 0));
    moved.translation().x() += 0.05;
    QVERIFY(panel_->setSelectedPose(moved, 0));
    QCOMPARE(doc_->undoStack()->count(), steps + 1);
    QVERIFY((load_cell(doc_->cell()->file).parts[0].pose.translation() - moved.translation()).norm() < 1e-9);

    // One handle deleted: the rest kept as they are; generated again: all back.
    QVERIFY(panel_->deleteHandle(0, 0));
    QCOMPARE(panel_->handleList()->count(), handles - 1);
    QVERIFY(!doc_->cell()->parts[0].auto_handles);
    QCOMPARE(load_cell(doc_->cell()->file).parts[0].handles.size(), size_t(handles - 1));
    QVERIFY(panel_->regenerateHandles(0));
    QCOMPARE(panel_->handleList()->count(), handles);

    // Removed, and back with undo.
    panel_->select(CellPanel::Kind::Part, 0);
    QVERIFY(panel_->removeSelected());
    QVERIFY(doc_->cell()->parts.empty());
    QVERIFY(doc_->demonstration().object_ids.empty());
    doc_->undoStack()->undo();
    QCOMPARE(doc_->cell()->parts.size(), size_t(1));
    QCOMPARE(doc_->demonstration().object_ids.size(), size_t(1));
  }

  void markersAreStuckOnFacesListedDeletedAndUndone() {
    const std::string stl = path("block.stl");
    demoplan::test::write_box_stl(stl, 40, 30, 20);  // millimetres
    QVERIFY2(panel_->addPart(QString::fromStdString(stl), 0.001), qPrintable(panel_->lastError()));
    QVERIFY(panel_->markerList()->isEnabled());
    QCOMPARE(panel_->markerList()->count(), 0);
    const int steps = doc_->undoStack()->count();
    // Where a click on the +x face (x = 20 mm) and on the top (z = 10 mm) would land.
    panel_->setMarkerSize(0.015);
    QVERIFY2(panel_->stickMarker(0, {0.02, 0.0, 0.0}, {1, 0, 0}), qPrintable(panel_->lastError()));
    QVERIFY2(panel_->stickMarker(0, {0.0, 0.0, 0.01}, {0, 0, 1}), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->undoStack()->count(), steps + 2);
    QCOMPARE(panel_->markerList()->count(), 2);
    QVERIFY(panel_->markerList()->item(1)->text().contains(QStringLiteral("id 1, 15 mm")));
    const Cell saved = load_cell(doc_->cell()->file);
    QCOMPARE(saved.parts[0].markers.size(), size_t(2));
    QCOMPARE(saved.parts[0].markers[0].id, 0);
    QVERIFY(saved.parts[0].markers[0].pose.translation().isApprox(Eigen::Vector3d(0.021, 0, 0)));
    QVERIFY(saved.parts[0].markers[1].pose.linear().col(2).isApprox(Eigen::Vector3d::UnitZ()));
    // Over the edge of the 30 x 20 mm face: refused with the reason, nothing changed.
    QVERIFY(!panel_->stickMarker(0, {0.02, 0.0, 0.006}, {1, 0, 0}));
    QVERIFY2(panel_->lastError().contains(QStringLiteral("does not lie flat")), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->undoStack()->count(), steps + 2);
    // Deleted, then back with undo; the file follows.
    QVERIFY(panel_->deleteMarker(0, 0));
    QCOMPARE(panel_->markerList()->count(), 1);
    QCOMPARE(load_cell(doc_->cell()->file).parts[0].markers.size(), size_t(1));
    doc_->undoStack()->undo();
    QCOMPARE(load_cell(doc_->cell()->file).parts[0].markers.size(), size_t(2));
  }

  void aPartWithEventsOrTooWideIsRefusedWithTheReason() {
    const std::string wide = path("wide.stl");
    demoplan::test::write_box_stl(wide, 300, 300, 300);
    const std::string before = readFile(doc_->cell()->file);
    QVERIFY(!panel_->addPart(QString::fromStdString(wide), 0.001));
    QVERIFY2(panel_->lastError().contains(QStringLiteral("wide.stl")), qPrintable(panel_->lastError()));
    QVERIFY2(panel_->lastError().contains(QStringLiteral("too wide")), qPrintable(panel_->lastError()));
    QVERIFY(doc_->cell()->parts.empty());
    QCOMPARE(readFile(doc_->cell()->file), before);

    const std::string stl = path("block.stl");
    demoplan::test::write_box_stl(stl, 40, 30, 20);
    QVERIFY(panel_->addPart(QString::fromStdString(stl), 0.001));
    doc_->addEvent(10, 0, EventType::Grasp);
    panel_->select(CellPanel::Kind::Part, 0);
    QVERIFY(!panel_->removeSelected());
    QVERIFY2(panel_->lastError().contains(QStringLiteral("delete its events first")), qPrintable(panel_->lastError()));
    QCOMPARE(doc_->cell()->parts.size(), size_t(1));
  }

  void aBundledExampleIsSavedUnderTheUsersNameBeforeItChanges() {
    const std::string bundled = ui::test::dataDir().toStdString() + "/../cells/ur5_workbench.json";
    doc_->newFromCell(bundled);
    QVERIFY(doc_->cellIsBundled());
    const std::string before = readFile(bundled);
    panel_->select(CellPanel::Kind::Furniture, 0);
    Pose p = doc_->cell()->furniture[0].pose;
    p.translation().y() += 0.1;
    QVERIFY(!panel_->setSelectedPose(p));
    QVERIFY2(panel_->lastError().contains(QStringLiteral("Save Cell As")), qPrintable(panel_->lastError()));
    const std::string mine = path("workbench_copy.json");
    doc_->saveCellAs(QString::fromStdString(mine));
    QVERIFY(!doc_->cellIsBundled());
    QCOMPARE(doc_->sceneReference().cell, mine);
    QVERIFY(doc_->isModified());
    QVERIFY2(panel_->setSelectedPose(p), qPrintable(panel_->lastError()));
    QCOMPARE(readFile(bundled), before);
    // The copy finds the bundled meshes from where it is.
    const Cell copy = load_cell(mine);
    QVERIFY(std::abs(copy.furniture[0].pose.translation().y() - p.translation().y()) < 1e-9);
    QVERIFY(std::filesystem::exists(copy.parts[0].mesh));
  }
};

DEMOPLAN_UI_TEST_MAIN(TestCellPanel)

#include "test_cell_panel.moc"
