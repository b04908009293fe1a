#pragma once
// The parts' outlines where the part-model tracker would start them (EventDetection::
// modelTrackerStart), over the start frame of the video, and of the parts placed again over the
// frame they were placed in: the operator moves a part with the 3D view's gizmo or types its pose
// until its outline lies on the part in the video, then detects the events. Each outline is the silhouette edge of the part's mesh through the project's
// camera (perception's silhouette_outline), recomputed only for a part whose start pose or the
// camera changed.
#include <QPolygonF>
#include <QString>
#include <optional>
#include <vector>

#include "core/geometry/se3.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {
struct Camera;
}

namespace demoplan::ui {

class Document;

class StartPoseOutlines {
public:
  // Recomputes for the document as it stands. Shown only with a video frame on screen
  // (`frame_shown`), a camera with its pose, the part-model tracker chosen and the playhead on
  // the start frame or a frame where parts were placed again (then only those): over any other
  // frame the parts have moved, and the outlines would mislead.
  void update(Document& doc, bool frame_shown);
  void forgetMeshes();    // another project or scene
  void forgetOutlines();  // another camera

  bool shown() const { return shown_; }
  // Per scene object: its silhouette edge as polylines in image pixels (empty: not drawn).
  const std::vector<std::vector<QPolygonF>>& outlines() const { return outlines_; }
  QRectF bounds(int object) const;
  // What the outlines are and what to do with them (or why there are none: init.json unreadable).
  const QString& caption() const { return caption_; }
  // How many silhouettes were computed so far, and how long the last one that computed any took.
  int outlinesComputed() const { return computed_; }
  double lastComputeMs() const { return last_ms_; }

private:
  void buildMeshes(const Document& doc);

  std::vector<perception::RenderMesh> meshes_;  // per scene object, geometry only; built when first shown
  bool meshes_built_ = false;
  const perception::Camera* camera_ = nullptr;  // the one the outlines were computed through
  std::vector<std::optional<Pose>> poses_;      // the start pose each outline was computed at
  std::vector<std::vector<QPolygonF>> outlines_;
  bool shown_ = false;
  QString caption_;
  int computed_ = 0;
  double last_ms_ = 0.0;
};

}  // namespace demoplan::ui
