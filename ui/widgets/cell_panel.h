#pragma once
// The cell editor: the robot, the furniture and the parts of a project on a cell file, each
// placed by typing millimetres and degrees; parts added from mesh files (put down on a free spot
// of a support), furniture as a box, a cylinder, a mesh file or a URDF; a part's handles listed,
// one deleted or all generated again; the robot replaced by a bundled one or a URDF + SRDF from
// disk, and one from disk made mobile; ArUco markers stuck on a part by clicking its face in the 3D view (Stick Markers),
// listed, deleted. Every change is one undo step and is written to the cell file at once
// (Document::editCell); a bundled example is first saved under the user's own name.
#include <QWidget>

#include "ui/document/document.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace demoplan::ui {

class PoseFields;

class CellPanel : public QWidget {
  Q_OBJECT
public:
  explicit CellPanel(Document* doc, QWidget* parent = nullptr);

  enum class Kind { None, Robot, Furniture, Part };
  struct Selection {
    Kind kind = Kind::None;
    int index = -1;  // furniture or part index
  };
  Selection selection() const { return selection_; }
  void select(Kind kind, int index);

  // What the buttons do after their file dialogs; false when the cell refused it (the reason is
  // shown in the panel and returned by lastError()).
  bool addPart(const QString& mesh_file, double scale);
  // `file`: the mesh (Kind::Mesh) or the URDF (Kind::Urdf, its SRDF the NAME.srdf beside it).
  bool addFurniture(CellFurniture::Kind kind, const QString& file = {}, double scale = 1.0);
  bool removeSelected();
  // The cell's robot replaced by a bundled one (`bundled`), or by the robot of `urdf` and `srdf`
  // from disk when `bundled` is empty; the parts' generated handles follow the new gripper.
  bool replaceRobot(const QString& bundled, const QString& urdf = {}, const QString& srdf = {});
  // The robot from disk made mobile (moved on the floor through its own x, y, yaw joints: off its
  // pedestal) or fixed (a pedestal under it when it stands on nothing); refused, with the reason,
  // for a bundled robot and for a URDF without planar base joints.
  bool setRobotMobile(bool mobile);
  bool deleteHandle(int part, int handle);
  bool regenerateHandles(int part);
  // A marker stuck on `part` (cell index) at `point` on the face with outward `normal` (part
  // frame, metres; the 3D view's click), of the size in the panel, with the next free id.
  bool stickMarker(int part, const Eigen::Vector3d& point, const Eigen::Vector3d& normal);
  bool deleteMarker(int part, int marker);
  // "Stick Markers" is on: a click on a part in the 3D view sticks one there.
  bool stickingMarkers() const;
  void setStickingMarkers(bool on);
  void setMarkerSize(double metres);
  bool setSelectedPose(const Pose& pose, int field = -1);
  QString lastError() const { return error_; }

  QTreeWidget* tree() const { return tree_; }
  PoseFields* poseFields() const { return pose_; }
  QListWidget* handleList() const { return handles_; }
  QListWidget* markerList() const { return markers_; }
  QLabel* infoLabel() const { return info_; }
  QCheckBox* mobileCheck() const { return mobile_; }

private:
  void refresh();
  void showSelection();
  bool edit(const Cell& after, const QString& text, int merge_key = -1);
  void saveCellAs();
  void addPartFromDialog();
  void addMeshFurnitureFromDialog();
  void replaceRobotFromDialog();
  // A mesh file from a file dialog and the unit scale guessed for it; "" when none (an unreadable
  // file is reported in the panel).
  QString chooseMesh(const QString& title, double* unit_scale);
  void showError(const QString& text);  // in red; lastError() returns it
  void showNote(const QString& text);

  Document* doc_;
  QTreeWidget* tree_;
  QLabel* file_label_;
  QLabel* info_;
  QCheckBox* mobile_;
  PoseFields* pose_;
  QListWidget* handles_;
  QPushButton* delete_handle_;
  QPushButton* regenerate_;
  QListWidget* markers_;
  QPushButton* stick_marker_;
  QDoubleSpinBox* marker_size_;
  QPushButton* delete_marker_;
  QPushButton* remove_;
  QLabel* message_;
  Selection selection_;
  QString error_;
  bool refreshing_ = false;
};

}  // namespace demoplan::ui
