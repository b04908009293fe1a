#include "ui/widgets/start_pose_outlines.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QStringList>
#include <algorithm>

#include "perception/camera/camera_model.h"
#include "perception/render/part_meshes.h"
#include "perception/render/silhouette_outline.h"
#include "ui/document/document.h"

namespace demoplan::ui {

namespace {
QString tr(const char* text) { return QCoreApplication::translate("StartPoseOutlines", text); }
}  // namespace

void StartPoseOutlines::forgetMeshes() {
  meshes_.clear();
  meshes_built_ = false;
  forgetOutlines();
}

void StartPoseOutlines::forgetOutlines() {
  poses_.clear();
  outlines_.clear();
  camera_ = nullptr;
}

void StartPoseOutlines::buildMeshes(const Document& doc) {
  meshes_.clear();
  for (const SceneObject& o : doc.scene().objects) {
    try {
      // No texture: only where the mesh covers the image counts, and decoding a YCB-V texture
      // would cost more than every outline.
      meshes_.push_back(perception::part_render_mesh(o.model, o.id, perception::TextureUse::Skip));
    } catch (const std::exception&) {
      meshes_.emplace_back();  // a part with nothing to draw has no outline
    }
  }
  meshes_built_ = true;
}

QRectF StartPoseOutlines::bounds(int object) const {
  QRectF r;
  if (object >= 0 && object < int(outlines_.size()))
    for (const QPolygonF& piece : outlines_[object]) r = r.united(piece.boundingRect());
  return r;
}

void StartPoseOutlines::update(Document& doc, bool frame_shown) {
  shown_ = false;
  caption_.clear();
  const perception::Camera* camera = doc.hasProject() ? doc.media()->camera() : nullptr;
  if (!frame_shown || !camera || !camera->world_T_camera || !doc.detection()->modelTracker() ||
      doc.displayMode() != Document::DisplayMode::Demonstration)
    return;
  perception::TrackerInit start;
  std::string source;
  try {
    start = doc.detection()->modelTrackerStart(&source);
  } catch (const std::exception& e) {
    const auto& placed = doc.corrections();
    if (doc.currentFrame() == 0 ||
        std::any_of(placed.begin(), placed.end(), [&](const auto& c) { return c.frame == doc.currentFrame(); }))
      caption_ = QString::fromUtf8(e.what());
    return;
  }
  // Over the start frame every part's start; over a later frame the parts placed again there.
  const int frame = doc.currentFrame();
  std::vector<perception::PartStart> shown;
  if (frame == start.frame) {
    shown = start.parts;
  } else {
    for (const auto& c : start.corrections)
      if (c.frame == frame) shown.push_back({c.id, c.world_T_object});
    if (shown.empty()) return;
  }
  shown_ = true;
  const bool from_poses = source.rfind(EventDetection::kPosesAtFrameZero, 0) == 0;
  if (frame != start.frame) {
    QStringList ids;
    for (const auto& p : shown) ids << QString::fromStdString(p.id);
    caption_ = tr("%1 placed again here: move it onto the part").arg(ids.join(", "));
  } else {
    caption_ = from_poses
                   ? tr("Start poses of the part models: move a part (3D view or Inspector) until its outline lies on it")
                   : tr("Start poses from %1 (Detect Events uses these; moving a part does not change them)")
                         .arg(QString::fromStdString(source));
  }
  if (!meshes_built_) buildMeshes(doc);
  if (camera != camera_) forgetOutlines();
  camera_ = camera;
  const auto& objects = doc.scene().objects;
  poses_.resize(objects.size());
  outlines_.resize(objects.size());
  QElapsedTimer clock;
  clock.start();
  const int computed_before = computed_;
  for (size_t o = 0; o < objects.size() && o < meshes_.size(); ++o) {
    const auto it = std::find_if(shown.begin(), shown.end(), [&](const auto& p) { return p.id == objects[o].id; });
    const perception::PartStart* part = it == shown.end() ? nullptr : &*it;
    if (!part) {
      poses_[o].reset();
      outlines_[o].clear();
      continue;
    }
    if (poses_[o] && poses_[o]->matrix() == part->world_T_object.matrix()) continue;
    poses_[o] = part->world_T_object;
    outlines_[o].clear();
    for (const auto& piece : perception::silhouette_outline(meshes_[o], part->world_T_object, *camera)) {
      QPolygonF line;
      line.reserve(int(piece.size()));
      for (const auto& p : piece) line << QPointF(p.x, p.y);
      outlines_[o].push_back(std::move(line));
    }
    ++computed_;
  }
  if (computed_ > computed_before) last_ms_ = clock.nsecsElapsed() / 1e6;
}

}  // namespace demoplan::ui
