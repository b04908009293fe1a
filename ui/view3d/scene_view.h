#pragma once
// The 3D scene (OpenGL 3.3 core): the robot at its base pose in the displayed configuration,
// the furniture, the parts with their meshes and textures, lit and shaded on a floor grid;
// the planner's trees as they grow (nodes at the gripper positions they reach, edges as lines,
// one colour per tree, roots at the video's transitions marked); the planned gripper trace.
// Mouse: left-drag orbits, right- or middle-drag (or Shift+left) pans, the wheel zooms, F fits,
// a click selects a part; the selected part (or a cell's furniture chosen in the Cell panel) gets
// a gizmo: drag an arrow to move it along a world axis, the ring to turn it about the vertical.
#include <QOpenGLExtraFunctions>
#include <QOpenGLWidget>
#include <memory>
#include <vector>

#include "ui/document/document.h"
#include "ui/view3d/orbit_camera.h"

class QLabel;
class QOpenGLShaderProgram;
class QOpenGLTexture;
class QToolButton;

namespace demoplan::ui {

class SceneView : public QOpenGLWidget, protected QOpenGLExtraFunctions {
  Q_OBJECT
public:
  explicit SceneView(Document* doc, QWidget* parent = nullptr);
  ~SceneView() override;

  OrbitCamera& camera() { return camera_; }
  void fitToScene();
  // The part under a pixel (widget coordinates), -1 for none.
  int pickObject(const QPointF& pixel) const;
  // Where the ray through a pixel first meets a part: the point and the face's normal (towards
  // the camera) in the part's frame, metres. object -1 for none; on a cell's project furniture
  // is hit too (furniture set, object -1).
  struct SurfaceHit {
    int object = -1;
    int furniture = -1;  // on a cell's project: the scene furniture hit first, when no part is nearer
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  };
  SurfaceHit pickSurface(const QPointF& pixel) const;
  // Gizmo handle under a pixel: 0..2 the x/y/z arrows, 3 the ring, -1 none.
  int gizmoHandleAt(const QPointF& pixel) const;
  // Screen position of the selected part's gizmo centre; false when no gizmo is shown.
  bool gizmoCenter(QPointF& pixel) const;
  bool showTrees() const { return show_trees_; }
  void setShowTrees(bool on);
  size_t treeEdgeCount() const { return tree_edges_; }
  size_t treeRootCount() const { return tree_roots_; }
  // Candidates of the placement search drawn on the floor.
  size_t placementSquareCount() const { return placement_squares_.data.size() / 7; }
  // "OpenGL 4.5 (Core Profile) Mesa ..., llvmpipe" once initialised; empty before.
  QString glInfo() const { return gl_info_; }
  bool glFailed() const { return gl_failed_; }
  // Milliseconds the last paintGL took (CPU side).
  double lastPaintMs() const { return last_paint_ms_; }
  // Light geometry: the robot drawn with its (coarse) collision meshes. On by default with a
  // software OpenGL renderer (llvmpipe), where the visual meshes (166k triangles for the Panda)
  // would make every frame cost ~100 ms; DEMOPLAN_RENDER=full or =light overrides.
  bool lightGeometry() const { return light_geometry_; }
  void setLightGeometry(bool on);

signals:
  void objectPicked(int object);
  // A click on a part (also reported by objectPicked): where it met its surface.
  void surfacePicked(const demoplan::ui::SceneView::SurfaceHit& hit);
  // A click on a cell's furniture (its index in the scene's furniture).
  void furniturePicked(int furniture);
  // A gizmo drag the document refused (the reason, naming the file).
  void editRefused(const QString& reason);

protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent*) override;
  void mouseMoveEvent(QMouseEvent*) override;
  void mouseReleaseEvent(QMouseEvent*) override;
  void wheelEvent(QWheelEvent*) override;

private:
  enum class Owner { Robot, Furniture, Object, Floor };
  struct CpuMesh {
    std::vector<float> vertices;  // x y z nx ny nz u v
    std::vector<std::uint32_t> indices;
    std::string texture;
    Eigen::AlignedBox3f bounds;
  };
  struct GpuMesh {
    unsigned vao = 0, vbo = 0, ibo = 0;
    int count = 0;
    QOpenGLTexture* texture = nullptr;
  };
  struct Item {
    Owner owner;
    int index;  // furniture or object index
    int link;   // link of the robot, furniture or object model
    QMatrix4x4 local;  // geometry origin and scale, in the link frame
    int mesh;   // into meshes_
    QVector4D color;
  };
  struct LineBuffer {
    unsigned vao = 0, vbo = 0;
    std::vector<float> data;  // x y z r g b a
    bool dirty = true;
    int uploaded = 0;
  };

  void rebuildScene();
  int addMesh(CpuMesh mesh);
  int meshFor(const Geometry& g, QMatrix4x4& local, QVector4D& color);
  void uploadPending();
  void releaseGl();
  void drawLines(LineBuffer& buffer, unsigned mode, float point_size, bool round, bool depth, float alpha = 1.0f);
  void onPlanStarted();
  void onPlanProgress(const PlanSnapshot& s);
  void rebuildPathTrace();
  void rebuildPlacement();
  void updateHud();
  // World transform of every item for the displayed state.
  std::vector<QMatrix4x4> itemTransforms() const;
  // What the gizmo moves: a part at an event (object, event), or a cell's furniture (furniture
  // >= 0, object and event -1), and where it is.
  struct GizmoTarget {
    Pose pose = Pose::Identity();
    int event = -1, object = -1, furniture = -1;
    int correction = -1;  // the part placed again at the playhead (Document::corrections)
  };
  bool gizmoFrame(QVector3D& origin, float& length, GizmoTarget& target) const;
  void applyGizmoPose(const Pose& pose);
  void buildGizmo(LineBuffer& out) const;

  Document* doc_;
  OrbitCamera camera_;
  std::shared_ptr<const Scene> scene_;  // the scene the items were built for
  std::vector<CpuMesh> cpu_meshes_;
  std::vector<GpuMesh> gpu_meshes_;
  std::vector<Item> items_;
  int box_mesh_ = -1, cylinder_mesh_ = -1, sphere_mesh_ = -1;
  std::vector<std::pair<const TriangleMesh*, int>> file_meshes_;
  bool gl_ready_ = false;
  bool gl_failed_ = false;
  QString gl_info_;
  std::unique_ptr<QOpenGLShaderProgram> mesh_program_, line_program_;
  LineBuffer grid_, tree_lines_, tree_points_, root_points_, root_outline_, path_trace_, gizmo_, selection_, supports_,
      placement_squares_, placement_ticks_;
  size_t tree_edges_ = 0, tree_roots_ = 0;
  bool show_trees_ = true;
  bool fit_pending_ = true;
  bool light_geometry_ = false;
  bool update_pending_ = false;  // a throttled repaint while planning
  double last_paint_ms_ = 0.0;
  QLabel* hud_;
  QToolButton* trees_button_;

  enum class Drag { None, Orbit, Pan, Axis, Ring } drag_ = Drag::None;
  QPointF press_pos_, last_pos_;
  bool moved_ = false;
  int drag_axis_ = -1;
  GizmoTarget drag_target_;  // what the drag moves, and its pose when the drag began
  int drag_serial_ = 0;
};

}  // namespace demoplan::ui
