#include "ui/widgets/cell_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSignalBlocker>
#include <QToolButton>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>
#include <filesystem>

#include "core/cell/cell_edits.h"
#include "core/cell/part_markers.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "ui/widgets/pose_fields.h"

namespace demoplan::ui {

namespace {

constexpr int kKindRole = Qt::UserRole, kIndexRole = Qt::UserRole + 1;

QString q(const std::string& s) { return QString::fromStdString(s); }

QString fileName(const std::string& path) { return q(std::filesystem::path(path).filename().string()); }

// Units a mesh file may be in, metres per unit.
const std::pair<const char*, double> kUnits[] = {
    {QT_TRANSLATE_NOOP("CellPanel", "millimetres"), 0.001},
    {QT_TRANSLATE_NOOP("CellPanel", "centimetres"), 0.01},
    {QT_TRANSLATE_NOOP("CellPanel", "metres"), 1.0},
    {QT_TRANSLATE_NOOP("CellPanel", "inches"), 0.0254}};

const char* kMeshFilter = QT_TRANSLATE_NOOP("CellPanel", "Meshes (*.stl *.obj *.ply *.dae *.gltf *.glb *.STL *.OBJ *.PLY)");

// The SRDF of the same name beside a URDF (NAME.srdf), as the benchmark keeps them; "" when none.
QString srdfBeside(const QString& urdf) {
  const QFileInfo info(urdf);
  const QFileInfo srdf(info.absolutePath() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral(".srdf"));
  return srdf.exists() ? srdf.absoluteFilePath() : QString();
}

QString shapeText(const CellFurniture& f) {
  switch (f.kind) {
    case CellFurniture::Kind::Box:
      return CellPanel::tr("box %1 x %2 x %3 m").arg(f.box.x()).arg(f.box.y()).arg(f.box.z());
    case CellFurniture::Kind::Cylinder:
      return CellPanel::tr("cylinder, radius %1 m, length %2 m").arg(f.radius).arg(f.length);
    case CellFurniture::Kind::Mesh:
      return CellPanel::tr("mesh %1 (scale %2)").arg(fileName(f.file)).arg(f.scale);
    case CellFurniture::Kind::Urdf:
      return CellPanel::tr("URDF %1").arg(fileName(f.file));
  }
  return {};
}

}  // namespace

CellPanel::CellPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  file_label_ = new QLabel(this);
  file_label_->setWordWrap(true);
  layout->addWidget(file_label_);

  tree_ = new QTreeWidget(this);
  tree_->setHeaderHidden(true);
  tree_->setRootIsDecorated(true);
  tree_->setObjectName(QStringLiteral("cellTree"));
  tree_->setMinimumHeight(150);
  layout->addWidget(tree_, 3);

  auto* buttons = new QHBoxLayout;
  auto* add_part = new QPushButton(tr("Add Part…"), this);
  add_part->setToolTip(tr("A part from its mesh file (STL, OBJ, PLY, DAE, glTF): put down on a free spot of a "
                          "support, its resting placements and grasps computed"));
  connect(add_part, &QPushButton::clicked, this, &CellPanel::addPartFromDialog);
  auto* add_furniture = new QToolButton(this);
  add_furniture->setText(tr("Add Furniture"));
  add_furniture->setPopupMode(QToolButton::InstantPopup);
  auto* menu = new QMenu(add_furniture);
  menu->addAction(tr("Box"), this, [this] { addFurniture(CellFurniture::Kind::Box); });
  menu->addAction(tr("Cylinder"), this, [this] { addFurniture(CellFurniture::Kind::Cylinder); });
  menu->addAction(tr("Mesh File…"), this, &CellPanel::addMeshFurnitureFromDialog);
  menu->addAction(tr("URDF File…"), this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Add furniture from its URDF (an SRDF of the same name "
                                                               "beside it gives its support surfaces)"),
                                                      {}, tr("URDF files (*.urdf *.URDF)"));
    if (!file.isEmpty()) addFurniture(CellFurniture::Kind::Urdf, file);
  });
  add_furniture->setMenu(menu);
  auto* robot = new QToolButton(this);
  robot->setText(tr("Robot"));
  robot->setToolTip(tr("Replace the cell's robot: a bundled one, or your own from its URDF and SRDF files"));
  robot->setPopupMode(QToolButton::InstantPopup);
  auto* robot_menu = new QMenu(robot);
  connect(robot_menu, &QMenu::aboutToShow, this, [this, robot_menu] {
    robot_menu->clear();
    const Cell* cell = doc_->cell();
    for (const auto& name : list_benchmark_robots(doc_->dataDir())) {
      QAction* a = robot_menu->addAction(q(name), this, [this, name] { replaceRobot(q(name)); });
      a->setCheckable(true);
      a->setChecked(cell && cell->robot.bundled == name);
    }
    robot_menu->addSeparator();
    robot_menu->addAction(tr("URDF and SRDF Files…"), this, &CellPanel::replaceRobotFromDialog);
  });
  robot->setMenu(robot_menu);
  remove_ = new QPushButton(tr("Remove"), this);
  remove_->setToolTip(tr("Remove the selected furniture or part from the cell"));
  connect(remove_, &QPushButton::clicked, this, &CellPanel::removeSelected);
  auto* save_as = new QPushButton(tr("Save Cell As…"), this);
  save_as->setToolTip(tr("Write the cell to a file of your own and use that file from now on"));
  connect(save_as, &QPushButton::clicked, this, &CellPanel::saveCellAs);
  buttons->addWidget(add_part);
  buttons->addWidget(add_furniture);
  buttons->addWidget(robot);
  buttons->addWidget(remove_);
  buttons->addStretch(1);
  buttons->addWidget(save_as);
  layout->addLayout(buttons);

  info_ = new QLabel(this);
  info_->setWordWrap(true);
  layout->addWidget(info_);
  mobile_ = new QCheckBox(tr("Mobile base (moves on the floor through its own x, y, yaw joints)"), this);
  mobile_->setObjectName(QStringLiteral("robotMobile"));
  connect(mobile_, &QCheckBox::toggled, this, [this](bool on) {
    if (!refreshing_) setRobotMobile(on);
  });
  layout->addWidget(mobile_);
  pose_ = new PoseFields(tr("Pose in the world"), this);
  layout->addWidget(pose_);
  connect(pose_, &PoseFields::edited, this, [this](const Pose& T, int field) {
    if (!refreshing_) setSelectedPose(T, field);
  });

  handles_ = new QListWidget(this);
  handles_->setToolTip(tr("The part's grasp handles, as the planner uses them"));
  handles_->setMinimumHeight(60);
  layout->addWidget(handles_, 1);
  auto* handle_buttons = new QHBoxLayout;
  delete_handle_ = new QPushButton(tr("Delete Handle"), this);
  delete_handle_->setToolTip(tr("The planner will not grasp the part there (the other handles are kept as they are)"));
  connect(delete_handle_, &QPushButton::clicked, this, [this] {
    if (selection_.kind == Kind::Part && handles_->currentRow() >= 0) deleteHandle(selection_.index, handles_->currentRow());
  });
  regenerate_ = new QPushButton(tr("Generate Handles"), this);
  regenerate_->setToolTip(tr("Generate the part's handles again from its mesh for the robot's gripper"));
  connect(regenerate_, &QPushButton::clicked, this, [this] {
    if (selection_.kind == Kind::Part) regenerateHandles(selection_.index);
  });
  handle_buttons->addWidget(delete_handle_);
  handle_buttons->addWidget(regenerate_);
  handle_buttons->addStretch(1);
  layout->addLayout(handle_buttons);

  markers_ = new QListWidget(this);
  markers_->setToolTip(tr("The ArUco markers stuck on the part (drawn on it in the 3D view; print them with "
                          "demoplan-cli markers --cell)"));
  markers_->setMinimumHeight(40);
  layout->addWidget(markers_, 1);
  auto* marker_buttons = new QHBoxLayout;
  stick_marker_ = new QPushButton(tr("Stick Markers"), this);
  stick_marker_->setCheckable(true);
  stick_marker_->setToolTip(tr("While on, a click on a flat face of a part in the 3D view sticks a marker there, "
                               "its top edge towards the part's +z"));
  marker_size_ = new QDoubleSpinBox(this);
  marker_size_->setRange(5.0, 200.0);
  marker_size_->setDecimals(0);
  marker_size_->setSuffix(tr(" mm"));
  marker_size_->setValue(30.0);
  marker_size_->setToolTip(tr("Side of the marker's black square"));
  delete_marker_ = new QPushButton(tr("Delete Marker"), this);
  connect(delete_marker_, &QPushButton::clicked, this, [this] {
    if (selection_.kind == Kind::Part && markers_->currentRow() >= 0) deleteMarker(selection_.index, markers_->currentRow());
  });
  marker_buttons->addWidget(stick_marker_);
  marker_buttons->addWidget(marker_size_);
  marker_buttons->addWidget(delete_marker_);
  marker_buttons->addStretch(1);
  layout->addLayout(marker_buttons);

  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setObjectName(QStringLiteral("cellMessage"));
  layout->addWidget(message_);

  connect(tree_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (refreshing_ || !item) return;
    selection_ = {static_cast<Kind>(item->data(0, kKindRole).toInt()), item->data(0, kIndexRole).toInt()};
    if (selection_.kind == Kind::Part && doc_->cell())
      doc_->selectObject(doc_->scene().object_index(doc_->cell()->parts[static_cast<size_t>(selection_.index)].name));
    else  // furniture gets the 3D view's gizmo; the robot and the folders none
      doc_->selectFurniture(selection_.kind == Kind::Furniture ? selection_.index : -1);
    showSelection();
  });
  connect(doc_, &Document::projectLoaded, this, [this] {
    selection_ = {};
    message_->clear();
    refresh();
  });
  connect(doc_, &Document::sceneChanged, this, &CellPanel::refresh);
  connect(doc_, &Document::cellFileChanged, this, &CellPanel::refresh);
  connect(doc_, &Document::selectionChanged, this, [this] {
    // A part clicked in the 3D view is selected here too.
    const int o = doc_->selectedObject();
    if (!doc_->cell() || o < 0 || o >= static_cast<int>(doc_->scene().objects.size())) return;
    const int part = doc_->cell()->part_index(doc_->scene().objects[static_cast<size_t>(o)].id);
    if (part >= 0 && !(selection_.kind == Kind::Part && selection_.index == part)) select(Kind::Part, part);
  });
  refresh();
}

void CellPanel::refresh() {
  refreshing_ = true;
  tree_->clear();
  const Cell* cell = doc_->cell();
  setEnabled(cell != nullptr);
  if (!cell) {
    file_label_->setText(doc_->hasProject() ? tr("This project is on a benchmark task: it has no cell to edit. "
                                                 "File > New Cell starts one.")
                                            : tr("No project"));
    selection_ = {};
    refreshing_ = false;
    showSelection();
    return;
  }
  file_label_->setText(tr("<b>%1</b> — %2%3")
                           .arg(q(cell->name), fileName(cell->file),
                                doc_->cellIsBundled() ? tr(" <i>(a bundled example: Save Cell As to change it)</i>")
                                                      : QString()));
  auto add = [&](QTreeWidgetItem* parent, const QString& text, Kind kind, int index) {
    auto* item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(tree_);
    item->setText(0, text);
    item->setData(0, kKindRole, static_cast<int>(kind));
    item->setData(0, kIndexRole, index);
    return item;
  };
  const QString robot = cell->robot.bundled.empty() ? fileName(cell->robot.urdf) : q(cell->robot.bundled);
  QTreeWidgetItem* current = add(nullptr, tr("Robot: %1").arg(robot), Kind::Robot, 0);
  if (selection_.kind != Kind::Robot) current = nullptr;
  auto* furniture = add(nullptr, tr("Furniture (%1)").arg(cell->furniture.size()), Kind::None, -1);
  for (size_t i = 0; i < cell->furniture.size(); ++i) {
    auto* item = add(furniture, q(cell->furniture[i].name), Kind::Furniture, static_cast<int>(i));
    if (selection_.kind == Kind::Furniture && selection_.index == static_cast<int>(i)) current = item;
  }
  auto* parts = add(nullptr, tr("Parts (%1)").arg(cell->parts.size()), Kind::None, -1);
  for (size_t i = 0; i < cell->parts.size(); ++i) {
    auto* item = add(parts, q(cell->parts[i].name), Kind::Part, static_cast<int>(i));
    if (selection_.kind == Kind::Part && selection_.index == static_cast<int>(i)) current = item;
  }
  tree_->expandAll();
  if (!current) selection_ = {};
  tree_->setCurrentItem(current);
  refreshing_ = false;
  showSelection();
}

void CellPanel::select(Kind kind, int index) {
  for (QTreeWidgetItemIterator it(tree_); *it; ++it)
    if ((*it)->data(0, kKindRole).toInt() == static_cast<int>(kind) && (*it)->data(0, kIndexRole).toInt() == index) {
      tree_->setCurrentItem(*it);
      return;
    }
}

void CellPanel::showSelection() {
  refreshing_ = true;
  const Cell* cell = doc_->cell();
  const Selection s = cell ? selection_ : Selection{};
  pose_->setEditable(s.kind != Kind::None);
  remove_->setEnabled(s.kind == Kind::Furniture || s.kind == Kind::Part);
  handles_->clear();
  markers_->clear();
  const bool part = s.kind == Kind::Part;
  handles_->setEnabled(part);
  delete_handle_->setEnabled(part);
  regenerate_->setEnabled(part);
  markers_->setEnabled(part);
  delete_marker_->setEnabled(part);
  stick_marker_->setEnabled(cell && !cell->parts.empty());
  mobile_->setVisible(s.kind == Kind::Robot);
  if (s.kind == Kind::None) {
    info_->setText(cell ? tr("Select the robot, a piece of furniture or a part to place it.") : QString());
    refreshing_ = false;
    return;
  }
  if (s.kind == Kind::Robot) {
    pose_->setTitle(tr("Robot base in the world"));
    pose_->setPose(cell->robot.base, true);
    const bool bundled = !cell->robot.bundled.empty();
    mobile_->setChecked(cell->robot.mobile);
    mobile_->setEnabled(!bundled);
    mobile_->setToolTip(bundled ? tr("A bundled robot is mobile or not as its data says (the KMR iiwa is); "
                                     "a robot from URDF and SRDF files can be made mobile here")
                                : tr("For a URDF whose root is followed by x and y prismatic joints and a yaw joint: "
                                     "the planner drives the base on the floor. A fixed robot stands on a pedestal"));
    const SceneRobot& r = doc_->scene().robot;
    const QString source = cell->robot.bundled.empty()
                               ? tr("%1 with %2").arg(fileName(cell->robot.urdf), fileName(cell->robot.srdf))
                               : tr("bundled %1").arg(q(cell->robot.bundled));
    info_->setText(tr("%1: %2 joints, gripper %3. %4 Robot > replaces it.")
                       .arg(source)
                       .arg(r.model.nq)
                       .arg(r.srdf.grippers.empty() ? tr("none") : q(r.gripper().name))
                       .arg(cell->robot.mobile ? tr("A mobile robot: its base moves through joints of its own; this is "
                                                    "where they start from.")
                                               : tr("Where the robot's base stands.")));
  } else if (s.kind == Kind::Furniture) {
    const CellFurniture& f = cell->furniture[static_cast<size_t>(s.index)];
    pose_->setTitle(tr("Pose of %1 in the world").arg(q(f.name)));
    pose_->setPose(f.pose, true);
    int supports = 0;
    for (const auto& sf : doc_->scene().furniture)
      if (sf.name == f.name)
        for (const auto& c : sf.srdf.contacts) supports += static_cast<int>(c.polygons.size());
    info_->setText(tr("%1; %2 support polygon(s)%3 (outlined green in the 3D view)")
                       .arg(shapeText(f))
                       .arg(supports)
                       .arg(f.auto_supports ? tr(", found on its upward faces") : tr(", given")));
  } else {
    const CellPart& p = cell->parts[static_cast<size_t>(s.index)];
    pose_->setTitle(tr("Pose of %1 at the start").arg(q(p.name)));
    pose_->setPose(p.pose, true);
    const int o = doc_->scene().object_index(p.name);
    if (o >= 0) {
      const SceneObject& so = doc_->scene().objects[static_cast<size_t>(o)];
      for (const auto& h : so.srdf.handles) handles_->addItem(q(h.name));
      for (const CellMarker& m : p.markers) {
        // Rounded to whole millimetres, without a "-0".
        const Eigen::Vector3d c = (m.pose.translation() * 1000.0).array().round() + 0.0;
        markers_->addItem(tr("id %1, %2 mm, at (%3, %4, %5) mm")
                              .arg(m.id)
                              .arg(m.size * 1000.0, 0, 'f', 0)
                              .arg(c.x(), 0, 'f', 0)
                              .arg(c.y(), 0, 'f', 0)
                              .arg(c.z(), 0, 'f', 0));
      }
      int placements = 0;
      for (const auto& c : so.srdf.contacts) placements += static_cast<int>(c.polygons.size());
      info_->setText(tr("Mesh %1 (scale %2); %3 handle(s) %4; %5 resting placement(s)")
                         .arg(fileName(p.mesh))
                         .arg(p.scale)
                         .arg(so.srdf.handles.size())
                         .arg(p.auto_handles ? tr("generated for the gripper") : tr("kept as edited"))
                         .arg(placements));
    }
  }
  refreshing_ = false;
}

bool CellPanel::edit(const Cell& after, const QString& text, int merge_key) {
  try {
    doc_->editCell(after, text, merge_key);
  } catch (const InputError& e) {
    showError(q(e.what()));
    showSelection();  // the fields go back to what the cell holds
    return false;
  }
  showNote(tr("%1 — written to %2").arg(text, fileName(after.file)));
  return true;
}

bool CellPanel::setSelectedPose(const Pose& pose, int field) {
  if (!doc_->cell() || selection_.kind == Kind::None) return false;
  Cell after = *doc_->cell();
  QString text;
  const auto i = static_cast<size_t>(selection_.index);
  if (selection_.kind == Kind::Robot) {
    after.robot.base = pose;
    text = tr("Move the robot base");
  } else if (selection_.kind == Kind::Furniture) {
    after.furniture[i].pose = pose;
    text = tr("Move %1").arg(q(after.furniture[i].name));
  } else {
    after.parts[i].pose = pose;
    text = tr("Move %1").arg(q(after.parts[i].name));
  }
  // One field's spin steps on one item are one undo step.
  const int key = field < 0 ? -1 : (static_cast<int>(selection_.kind) * 10000 + selection_.index) * 10 + field;
  return edit(after, text, key);
}

bool CellPanel::addPart(const QString& mesh_file, double scale) {
  if (!doc_->cell()) return false;
  Cell after = *doc_->cell();
  int index = -1;
  try {
    index = add_part_from_mesh(after, mesh_file.toStdString(), scale, doc_->cellSceneOptions());
  } catch (const InputError& e) {
    showError(q(e.what()));
    return false;
  }
  if (!edit(after, tr("Add part %1").arg(q(after.parts[static_cast<size_t>(index)].name)))) return false;
  select(Kind::Part, index);
  return true;
}

bool CellPanel::addFurniture(CellFurniture::Kind kind, const QString& mesh_file, double scale) {
  if (!doc_->cell()) return false;
  Cell after = *doc_->cell();
  CellFurniture f;
  f.kind = kind;
  // Beside everything there is, on the floor, for the operator to move where it belongs.
  double y = 0;
  for (const auto& g : after.furniture) y = std::min(y, g.pose.translation().y() - 1.0);
  if (kind == CellFurniture::Kind::Box) {
    f.name = unique_cell_name(after, "box");
    f.box = {0.6, 0.4, 0.75};
    f.pose.translation() = Eigen::Vector3d(0.6, y, 0.375);
  } else if (kind == CellFurniture::Kind::Cylinder) {
    f.name = unique_cell_name(after, "cylinder");
    f.radius = 0.2;
    f.length = 0.75;
    f.pose.translation() = Eigen::Vector3d(0.6, y, 0.375);
  } else {
    const QFileInfo info(mesh_file);
    f.name = unique_cell_name(after, info.completeBaseName().toStdString());
    f.file = info.absoluteFilePath().toStdString();
    f.scale = scale;
    f.pose.translation() = Eigen::Vector3d(0.6, y, 0.0);
    // A URDF's support surfaces come from the SRDF beside it, when there is one.
    if (kind == CellFurniture::Kind::Urdf) f.srdf = srdfBeside(mesh_file).toStdString();
  }
  after.furniture.push_back(f);
  if (!edit(after, tr("Add %1").arg(q(f.name)))) return false;
  select(Kind::Furniture, static_cast<int>(after.furniture.size()) - 1);
  return true;
}

bool CellPanel::replaceRobot(const QString& bundled, const QString& urdf, const QString& srdf) {
  if (!doc_->cell()) return false;
  Cell after = *doc_->cell();
  try {
    replace_robot(after, bundled.toStdString(), urdf.toStdString(), srdf.toStdString(), doc_->dataDir());
  } catch (const InputError& e) {
    showError(q(e.what()));
    return false;
  }
  const QString name = bundled.isEmpty() ? QFileInfo(urdf).fileName() : bundled;
  if (!edit(after, tr("Replace the robot by %1").arg(name))) return false;
  select(Kind::Robot, 0);
  return true;
}

void CellPanel::replaceRobotFromDialog() {
  const QString urdf = QFileDialog::getOpenFileName(this, tr("The robot's URDF (its meshes found through relative paths "
                                                             "or package:// folders around it)"),
                                                    {}, tr("URDF files (*.urdf *.URDF)"));
  if (urdf.isEmpty()) return;
  // The SRDF (groups, gripper, collision pairs to skip) of the same name beside it, else asked for.
  QString srdf = srdfBeside(urdf);
  if (srdf.isEmpty()) {
    const QFileInfo info(urdf);
    srdf = QFileDialog::getOpenFileName(this, tr("The SRDF of %1 (its gripper and the link pairs that never collide)")
                                                  .arg(info.fileName()),
                                        info.absolutePath(), tr("SRDF files (*.srdf *.SRDF)"));
  }
  if (!srdf.isEmpty()) replaceRobot({}, urdf, srdf);
}

bool CellPanel::removeSelected() {
  if (!doc_->cell()) return false;
  Cell after = *doc_->cell();
  const auto i = static_cast<size_t>(selection_.index);
  QString text;
  if (selection_.kind == Kind::Furniture) {
    text = tr("Remove %1").arg(q(after.furniture[i].name));
    after.furniture.erase(after.furniture.begin() + static_cast<long>(i));
  } else if (selection_.kind == Kind::Part) {
    text = tr("Remove %1").arg(q(after.parts[i].name));
    after.parts.erase(after.parts.begin() + static_cast<long>(i));
  } else {
    return false;
  }
  const Selection was = selection_;
  selection_ = {};
  if (!edit(after, text)) {
    selection_ = was;
    return false;
  }
  return true;
}

bool CellPanel::setRobotMobile(bool mobile) {
  if (!doc_->cell()) return false;
  Cell after = *doc_->cell();
  try {
    set_robot_mobile(after, doc_->scene(), mobile);
  } catch (const InputError& e) {
    showError(q(e.what()));
    showSelection();  // the box goes back to what the cell holds
    return false;
  }
  if (after.robot.mobile == doc_->cell()->robot.mobile) return true;
  if (!edit(after, mobile ? tr("Make the robot mobile") : tr("Make the robot fixed"))) return false;
  select(Kind::Robot, 0);
  return true;
}

bool CellPanel::deleteHandle(int part, int handle) {
  if (!doc_->cell() || part < 0 || part >= static_cast<int>(doc_->cell()->parts.size())) return false;
  Cell after = *doc_->cell();
  CellPart& p = after.parts[static_cast<size_t>(part)];
  const int o = doc_->scene().object_index(p.name);
  if (o < 0) return false;
  std::vector<GraspFrame> handles = doc_->scene().objects[static_cast<size_t>(o)].srdf.handles;
  if (handle < 0 || handle >= static_cast<int>(handles.size())) return false;
  const std::string name = handles[static_cast<size_t>(handle)].name;
  handles.erase(handles.begin() + handle);
  // The generated handles become the part's own, less the deleted one.
  p.auto_handles = false;
  p.handles = handles;
  return edit(after, tr("Delete handle %1 of %2").arg(q(name), q(p.name)));
}

bool CellPanel::regenerateHandles(int part) {
  if (!doc_->cell() || part < 0 || part >= static_cast<int>(doc_->cell()->parts.size())) return false;
  Cell after = *doc_->cell();
  CellPart& p = after.parts[static_cast<size_t>(part)];
  p.auto_handles = true;
  p.handles.clear();
  return edit(after, tr("Generate the handles of %1").arg(q(p.name)));
}

bool CellPanel::stickingMarkers() const { return stick_marker_->isChecked() && stick_marker_->isEnabled(); }

void CellPanel::setStickingMarkers(bool on) { stick_marker_->setChecked(on); }

void CellPanel::setMarkerSize(double metres) { marker_size_->setValue(metres * 1000.0); }

bool CellPanel::stickMarker(int part, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  if (!doc_->cell() || part < 0 || part >= static_cast<int>(doc_->cell()->parts.size())) return false;
  Cell after = *doc_->cell();
  CellPart& p = after.parts[static_cast<size_t>(part)];
  try {
    const CellMarker m = marker_on_face(after, part, *load_mesh(p.mesh), point, normal, marker_size_->value() / 1000.0);
    p.markers.push_back(m);
    if (!edit(after, tr("Stick marker %1 on %2").arg(m.id).arg(q(p.name)))) return false;
  } catch (const InputError& e) {
    showError(q(e.what()));
    return false;
  }
  select(Kind::Part, part);
  markers_->setCurrentRow(markers_->count() - 1);
  return true;
}

bool CellPanel::deleteMarker(int part, int marker) {
  if (!doc_->cell() || part < 0 || part >= static_cast<int>(doc_->cell()->parts.size())) return false;
  Cell after = *doc_->cell();
  CellPart& p = after.parts[static_cast<size_t>(part)];
  if (marker < 0 || marker >= static_cast<int>(p.markers.size())) return false;
  const int id = p.markers[static_cast<size_t>(marker)].id;
  p.markers.erase(p.markers.begin() + marker);
  return edit(after, tr("Delete marker %1 of %2").arg(id).arg(q(p.name)));
}

void CellPanel::saveCellAs() {
  if (!doc_->cell()) return;
  const QString dir = QFileInfo(doc_->filePath().isEmpty() ? QString() : doc_->filePath()).absolutePath();
  const QString file = QFileDialog::getSaveFileName(this, tr("Save the cell as"), dir, tr("Cell files (*.json)"));
  if (file.isEmpty()) return;
  try {
    doc_->saveCellAs(file);
    showNote(tr("The cell is now %1").arg(file));
  } catch (const InputError& e) {
    showError(q(e.what()));
  }
}

void CellPanel::showError(const QString& text) {
  error_ = text;
  message_->setStyleSheet(QStringLiteral("color: #c62828"));
  message_->setText(text);
}

void CellPanel::showNote(const QString& text) {
  error_.clear();
  message_->setStyleSheet({});
  message_->setText(text);
}

QString CellPanel::chooseMesh(const QString& title, double* unit_scale) {
  const QString file = QFileDialog::getOpenFileName(this, title, {}, tr(kMeshFilter));
  if (file.isEmpty()) return {};
  try {
    *unit_scale = guess_unit_scale(file.toStdString());
  } catch (const InputError& e) {
    showError(q(e.what()));
    return {};
  }
  return file;
}

void CellPanel::addPartFromDialog() {
  double guess = 0.001;
  const QString file = chooseMesh(tr("Add a part from its mesh"), &guess);
  if (file.isEmpty()) return;
  QStringList units;
  int preset = 0;
  for (size_t k = 0; k < std::size(kUnits); ++k) {
    units << tr(kUnits[k].first);
    if (kUnits[k].second == guess) preset = static_cast<int>(k);
  }
  bool ok = false;
  const QString unit = QInputDialog::getItem(this, tr("Units of %1").arg(QFileInfo(file).fileName()),
                                             tr("The mesh file's coordinates are in"), units, preset, false, &ok);
  if (!ok) return;
  addPart(file, kUnits[units.indexOf(unit)].second);
}

void CellPanel::addMeshFurnitureFromDialog() {
  double scale = 1.0;
  const QString file = chooseMesh(tr("Add furniture from its mesh"), &scale);
  if (!file.isEmpty()) addFurniture(CellFurniture::Kind::Mesh, file, scale);
}

}  // namespace demoplan::ui
