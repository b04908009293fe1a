#include "ui/view3d/scene_view.h"

#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLShaderProgram>
#include <QOpenGLTexture>
#include <QTimer>
#include <QToolButton>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/ray_box.h"
#include "core/geometry/ray_triangle.h"
#include "core/scene/support.h"
#include "plot/axis.h"
#include "plot/heat_map.h"
#include "ui/document/demo_poses.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

namespace {

constexpr float kPi = float(M_PI);

QMatrix4x4 toQt(const Pose& T) {
  QMatrix4x4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = float(T.matrix()(r, c));
  return m;
}

QVector3D toQt(const Eigen::Vector3d& v) { return QVector3D(float(v.x()), float(v.y()), float(v.z())); }

void pushVertex(std::vector<float>& v, const QVector3D& p, const QVector3D& n, float u = 0, float w = 0) {
  v.insert(v.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), u, w});
}

void pushLine(std::vector<float>& v, const QVector3D& a, const QVector3D& b, const QColor& c, float alpha = 1.0f) {
  for (const QVector3D& p : {a, b}) v.insert(v.end(), {p.x(), p.y(), p.z(), c.redF(), c.greenF(), c.blueF(), alpha});
}

void pushPoint(std::vector<float>& v, const QVector3D& p, const QColor& c, float alpha = 1.0f) {
  v.insert(v.end(), {p.x(), p.y(), p.z(), c.redF(), c.greenF(), c.blueF(), alpha});
}

// Unit primitives, centred: a cube of side 1, a cylinder of radius 1 and length 1 along z, a
// sphere of radius 1.
struct Primitive {
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
};

Primitive unitBox() {
  Primitive p;
  const QVector3D normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const QVector3D& n : normals) {
    // Two axes spanning the face.
    const QVector3D a = std::abs(n.z()) > 0.5f ? QVector3D(1, 0, 0) : QVector3D(0, 0, 1);
    const QVector3D b = QVector3D::crossProduct(n, a);
    const auto base = std::uint32_t(p.vertices.size() / 8);
    for (int k = 0; k < 4; ++k) {
      const float s = (k == 1 || k == 2) ? 0.5f : -0.5f, t = (k >= 2) ? 0.5f : -0.5f;
      pushVertex(p.vertices, n * 0.5f + a * s + b * t, n, s + 0.5f, t + 0.5f);
    }
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return p;
}

Primitive unitCylinder(int segments = 32) {
  Primitive p;
  for (int i = 0; i <= segments; ++i) {
    const float a = 2 * kPi * i / segments;
    const QVector3D n(std::cos(a), std::sin(a), 0);
    pushVertex(p.vertices, n + QVector3D(0, 0, -0.5f), n);
    pushVertex(p.vertices, n + QVector3D(0, 0, 0.5f), n);
  }
  for (std::uint32_t i = 0; i < std::uint32_t(segments); ++i) {
    const std::uint32_t a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
    p.indices.insert(p.indices.end(), {a, c, b, b, c, d});
  }
  for (float z : {-0.5f, 0.5f}) {
    const QVector3D n(0, 0, z > 0 ? 1.0f : -1.0f);
    const auto centre = std::uint32_t(p.vertices.size() / 8);
    pushVertex(p.vertices, QVector3D(0, 0, z), n);
    for (int i = 0; i <= segments; ++i) {
      const float a = 2 * kPi * i / segments;
      pushVertex(p.vertices, QVector3D(std::cos(a), std::sin(a), z), n);
    }
    for (std::uint32_t i = 0; i < std::uint32_t(segments); ++i) {
      if (z > 0) p.indices.insert(p.indices.end(), {centre, centre + 1 + i, centre + 2 + i});
      else p.indices.insert(p.indices.end(), {centre, centre + 2 + i, centre + 1 + i});
    }
  }
  return p;
}

Primitive unitSphere(int rings = 16, int segments = 24) {
  Primitive p;
  for (int r = 0; r <= rings; ++r) {
    const float th = kPi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const float ph = 2 * kPi * s / segments;
      const QVector3D n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      pushVertex(p.vertices, n, n);
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const auto a = std::uint32_t(r * (segments + 1) + s), b = a + std::uint32_t(segments + 1);
      p.indices.insert(p.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  return p;
}

// Ray against a triangle (core's ray_triangle); t along the (unnormalised) direction, ahead only.
bool rayTriangle(const QVector3D& o, const QVector3D& d, const QVector3D& v0, const QVector3D& v1, const QVector3D& v2,
                 float& t) {
  auto e = [](const QVector3D& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); };
  const std::optional<double> hit = ray_triangle(e(o), e(d), e(v0), e(v1), e(v2));
  if (!hit || !(*hit > 0)) return false;
  t = float(*hit);
  return true;
}

bool rayBox(const QVector3D& o, const QVector3D& d, const Eigen::AlignedBox3f& box) {
  return ray_hits_box(Eigen::Vector3d(o.x(), o.y(), o.z()), Eigen::Vector3d(d.x(), d.y(), d.z()), box.cast<double>(),
                      0.0, std::numeric_limits<double>::infinity());
}

double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
  const QPointF ab = b - a, ap = p - a;
  const double len2 = ab.x() * ab.x() + ab.y() * ab.y();
  const double t = len2 > 0 ? std::clamp((ap.x() * ab.x() + ap.y() * ab.y()) / len2, 0.0, 1.0) : 0.0;
  const QPointF c = a + t * ab;
  return std::hypot(p.x() - c.x(), p.y() - c.y());
}

}  // namespace

SceneView::SceneView(Document* doc, QWidget* parent) : QOpenGLWidget(parent), doc_(doc) {
  setMinimumSize(320, 240);
  setFocusPolicy(Qt::ClickFocus);
  setMouseTracking(true);
  setAccessibleName(tr("3D scene"));
  hud_ = new QLabel(this);
  hud_->setAttribute(Qt::WA_TransparentForMouseEvents);
  hud_->setStyleSheet(QStringLiteral("QLabel { background: rgba(255,255,255,200); color: #1b1f24; border-radius: 4px; padding: 3px 6px; }"));
  hud_->move(8, 8);
  trees_button_ = new QToolButton(this);
  trees_button_->setText(tr("Trees"));
  trees_button_->setCheckable(true);
  trees_button_->setChecked(true);
  trees_button_->setToolTip(tr("Show the planner's trees (nodes at the gripper positions they reach, one colour per tree)"));
  connect(trees_button_, &QToolButton::toggled, this, &SceneView::setShowTrees);
  auto* fit = new QToolButton(this);
  fit->setText(tr("Fit"));
  fit->setToolTip(tr("Fit the view to the selected part and what is around it, or to the whole scene (F)"));
  connect(fit, &QToolButton::clicked, this, &SceneView::fitToScene);
  fit->setObjectName(QStringLiteral("fitButton"));

  auto redraw = [this] {
    updateHud();
    update();
  };
  connect(doc_, &Document::projectLoaded, this, [this] {
    rebuildScene();
    fit_pending_ = true;
    tree_lines_.data.clear();
    tree_points_.data.clear();
    root_points_.data.clear();
    root_outline_.data.clear();
    tree_lines_.dirty = tree_points_.dirty = root_points_.dirty = root_outline_.dirty = true;
    tree_edges_ = tree_roots_ = 0;
    rebuildPathTrace();
    updateHud();
    update();
  });
  // A cell edit: the same view on the rebuilt scene (no refit, the trees of the old scene kept).
  connect(doc_, &Document::sceneChanged, this, [this] {
    rebuildScene();
    rebuildPathTrace();
    updateHud();
    update();
  });
  connect(doc_, &Document::displayChanged, this, redraw);
  connect(doc_, &Document::selectionChanged, this, redraw);
  connect(doc_, &Document::demonstrationChanged, this, redraw);
  connect(doc_->placement(), &PlacementSearchJob::candidateDone, this, &SceneView::rebuildPlacement);
  connect(doc_->placement(), &PlacementSearchJob::cleared, this, &SceneView::rebuildPlacement);
  connect(doc_->planning(), &PlanningController::resultChanged, this, [this] {
    rebuildPathTrace();
    updateHud();
    update();
  });
  connect(doc_->planning()->runner(), &PlanRunner::started, this, &SceneView::onPlanStarted);
  connect(doc_->planning()->runner(), &PlanRunner::progress, this, &SceneView::onPlanProgress);
  connect(doc_->planning()->runner(), &PlanRunner::graphReady, this, [this](std::shared_ptr<const ConstraintGraph> g) {
    // The start and goal trees' roots.
    if (!scene_) return;
    for (const Eigen::VectorXd* q : {&g->q_start, &g->q_goal}) {
      if (q->size() != scene_->robot.model.nq) continue;
      const QVector3D p = toQt(gripper_pose(*scene_, *q).translation());
      pushPoint(root_points_.data, p, q == &g->q_start ? kOkColor : kErrorColor);
      pushPoint(root_outline_.data, p, QColor(0x20, 0x20, 0x20));
    }
    root_points_.dirty = root_outline_.dirty = true;
    update();
  });
  if (doc_->hasProject()) rebuildScene();
  updateHud();
}

SceneView::~SceneView() {
  // QOpenGLWidget's destructor destroys the context after this one has run: its
  // aboutToBeDestroyed must not call back into a SceneView that is gone (found by UBSan).
  if (QOpenGLContext* c = context()) disconnect(c, nullptr, this, nullptr);
  if (gl_ready_) {
    makeCurrent();
    releaseGl();
    doneCurrent();
  }
}

// -------------------------------------------------------------------------- scene data

int SceneView::addMesh(CpuMesh mesh) {
  cpu_meshes_.push_back(std::move(mesh));
  return int(cpu_meshes_.size()) - 1;
}

int SceneView::meshFor(const Geometry& g, QMatrix4x4& local, QVector4D& color) {
  local = toQt(g.origin);
  color = QVector4D(float(g.color[0]), float(g.color[1]), float(g.color[2]), 1.0f);
  auto primitive = [&](int& slot, const Primitive& p, const Eigen::AlignedBox3f& bounds) {
    if (slot < 0) {
      CpuMesh m;
      m.vertices = p.vertices;
      m.indices = p.indices;
      m.bounds = bounds;
      slot = addMesh(std::move(m));
    }
    return slot;
  };
  if (const auto* b = std::get_if<BoxShape>(&g.shape)) {
    local.scale(float(b->size.x()), float(b->size.y()), float(b->size.z()));
    return primitive(box_mesh_, unitBox(),
                     Eigen::AlignedBox3f(Eigen::Vector3f::Constant(-0.5f), Eigen::Vector3f::Constant(0.5f)));
  }
  if (const auto* c = std::get_if<CylinderShape>(&g.shape)) {
    local.scale(float(c->radius), float(c->radius), float(c->length));
    return primitive(cylinder_mesh_, unitCylinder(), Eigen::AlignedBox3f(Eigen::Vector3f(-1, -1, -0.5f), Eigen::Vector3f(1, 1, 0.5f)));
  }
  if (const auto* s = std::get_if<SphereShape>(&g.shape)) {
    local.scale(float(s->radius));
    return primitive(sphere_mesh_, unitSphere(), Eigen::AlignedBox3f(Eigen::Vector3f::Constant(-1), Eigen::Vector3f::Constant(1)));
  }
  const auto& ms = std::get<MeshShape>(g.shape);
  if (!ms.mesh) return -1;
  local.scale(float(ms.scale.x()), float(ms.scale.y()), float(ms.scale.z()));
  const TriangleMesh& tm = *ms.mesh;
  // The URDF's colour unless it is the loader's default grey and the file has its own.
  const bool default_grey = std::abs(g.color[0] - 0.7) < 1e-6 && std::abs(g.color[1] - 0.7) < 1e-6 &&
                            std::abs(g.color[2] - 0.7) < 1e-6;
  if (default_grey) color = QVector4D(tm.color[0], tm.color[1], tm.color[2], 1.0f);
  if (!tm.texture_path.empty() && tm.uvs.size() == tm.vertices.size()) color = QVector4D(1, 1, 1, 1);
  // One GPU copy per file (the Panda's two fingers share one).
  for (const auto& [mesh, index] : file_meshes_)
    if (mesh == &tm) return index;
  CpuMesh m;
  const size_t n = tm.vertices.size();
  std::vector<Eigen::Vector3f> normals = tm.normals;
  // Many STL exporters write zero normals: such a part would be drawn black.
  const bool file_normals = normals.size() == n && std::all_of(normals.begin(), normals.end(), [](const auto& v) {
                              return v.allFinite() && v.squaredNorm() > 0.25f;
                            });
  if (!file_normals) {  // smooth normals from the faces
    normals.assign(n, Eigen::Vector3f::Zero());
    for (const auto& t : tm.triangles) {
      const Eigen::Vector3f fn = (tm.vertices[t[1]] - tm.vertices[t[0]]).cross(tm.vertices[t[2]] - tm.vertices[t[0]]);
      for (int k = 0; k < 3; ++k) normals[t[k]] += fn;
    }
    for (auto& v : normals) v = v.norm() > 0 ? v.normalized() : Eigen::Vector3f::UnitZ();
  }
  const bool uv = tm.uvs.size() == n;
  m.vertices.reserve(n * 8);
  for (size_t i = 0; i < n; ++i) {
    const auto& p = tm.vertices[i];
    const auto& nn = normals[i];
    m.vertices.insert(m.vertices.end(), {p.x(), p.y(), p.z(), nn.x(), nn.y(), nn.z(), uv ? tm.uvs[i].x() : 0.0f,
                                         uv ? tm.uvs[i].y() : 0.0f});
  }
  m.indices.reserve(tm.triangles.size() * 3);
  for (const auto& t : tm.triangles) m.indices.insert(m.indices.end(), {t[0], t[1], t[2]});
  m.texture = uv ? tm.texture_path : std::string();
  m.bounds = tm.bounds();
  const int index = addMesh(std::move(m));
  file_meshes_.emplace_back(&tm, index);
  return index;
}

void SceneView::rebuildScene() {
  if (gl_ready_) {
    makeCurrent();
    for (auto& g : gpu_meshes_) {
      glDeleteVertexArrays(1, &g.vao);
      glDeleteBuffers(1, &g.vbo);
      glDeleteBuffers(1, &g.ibo);
      delete g.texture;
    }
    doneCurrent();
  }
  gpu_meshes_.clear();
  cpu_meshes_.clear();
  items_.clear();
  file_meshes_.clear();
  box_mesh_ = cylinder_mesh_ = sphere_mesh_ = -1;
  scene_ = doc_->hasProject() ? doc_->sharedScene() : nullptr;
  if (!scene_) return;
  const Scene& s = *scene_;
  auto add = [&](Owner owner, int index, int link, const Geometry& g) {
    Item it{owner, index, link, {}, -1, {}};
    it.mesh = meshFor(g, it.local, it.color);
    if (it.mesh >= 0) items_.push_back(it);
  };
  auto visuals = [](const Link& l) -> const std::vector<Geometry>& { return l.visuals.empty() ? l.collisions : l.visuals; };
  for (int l = 0; l < int(s.robot.model.links.size()); ++l) {
    const Link& link = s.robot.model.links[l];
    if (light_geometry_ && !link.collisions.empty()) {
      // The collision shapes, in the visual's colour.
      const Eigen::Vector4d color = link.visuals.empty() ? Eigen::Vector4d(0.9, 0.9, 0.9, 1) : link.visuals.front().color;
      for (Geometry g : link.collisions) {
        g.color = color;
        add(Owner::Robot, 0, l, g);
      }
    } else {
      for (const Geometry& g : visuals(link)) add(Owner::Robot, 0, l, g);
    }
  }
  for (int f = 0; f < int(s.furniture.size()); ++f)
    for (int l = 0; l < int(s.furniture[f].model.links.size()); ++l)
      for (const Geometry& g : visuals(s.furniture[f].model.links[l])) add(Owner::Furniture, f, l, g);
  for (int o = 0; o < int(s.objects.size()); ++o)
    for (int l = 0; l < int(s.objects[o].model.links.size()); ++l)
      for (const Geometry& g : visuals(s.objects[o].model.links[l])) add(Owner::Object, o, l, g);
  // The floor: a light square under everything.
  Geometry floor;
  floor.shape = BoxShape{Eigen::Vector3d(6, 6, 0.002)};
  floor.origin.translation() = Eigen::Vector3d(0, 0, -0.0011);
  floor.color = Eigen::Vector4d(0.80, 0.81, 0.82, 1);
  add(Owner::Floor, 0, 0, floor);
  // The grid: 25 cm lines, every metre darker, 3 m around the origin.
  grid_.data.clear();
  for (int i = -12; i <= 12; ++i) {
    const float x = i * 0.25f;
    const QColor c = i % 4 == 0 ? QColor(0x9a, 0xa0, 0xa6) : QColor(0xbe, 0xc2, 0xc6);
    pushLine(grid_.data, QVector3D(x, -3, 0.0005f), QVector3D(x, 3, 0.0005f), c, 0.8f);
    pushLine(grid_.data, QVector3D(-3, x, 0.0005f), QVector3D(3, x, 0.0005f), c, 0.8f);
  }
  // World axes at the origin.
  for (int a = 0; a < 3; ++a) {
    QVector3D e;
    e[a] = 0.3f;
    pushLine(grid_.data, QVector3D(0, 0, 0.001f), e + QVector3D(0, 0, 0.001f), kAxisColors[a]);
  }
  grid_.dirty = true;
  // Where parts may be put down: every fixed support polygon, outlined just above its surface.
  supports_.data.clear();
  for (const SupportPolygon& poly : support_polygons(s)) {
    if (poly.furniture < 0) continue;
    for (size_t k = 0; k < poly.vertices.size(); ++k)
      pushLine(supports_.data, toQt(poly.vertices[k]) + QVector3D(0, 0, 0.001f),
               toQt(poly.vertices[(k + 1) % poly.vertices.size()]) + QVector3D(0, 0, 0.001f), kSupportColor, 0.9f);
  }
  supports_.dirty = true;
}

void SceneView::uploadPending() {
  while (gpu_meshes_.size() < cpu_meshes_.size()) {
    const CpuMesh& m = cpu_meshes_[gpu_meshes_.size()];
    GpuMesh g;
    glGenVertexArrays(1, &g.vao);
    glBindVertexArray(g.vao);
    glGenBuffers(1, &g.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.vertices.size() * sizeof(float)), m.vertices.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &g.ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(std::uint32_t)), m.indices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float), reinterpret_cast<void*>(6 * sizeof(float)));
    glBindVertexArray(0);
    g.count = int(m.indices.size());
    if (!m.texture.empty()) {
      QImage image(QString::fromStdString(m.texture));
      if (!image.isNull()) {
        // OBJ texture coordinates start at the bottom row.
        g.texture = new QOpenGLTexture(image.convertToFormat(QImage::Format_RGBA8888).mirrored());
        g.texture->setMinificationFilter(QOpenGLTexture::LinearMipMapLinear);
        g.texture->setMagnificationFilter(QOpenGLTexture::Linear);
        g.texture->setWrapMode(QOpenGLTexture::Repeat);
      }
    }
    gpu_meshes_.push_back(g);
  }
}

void SceneView::releaseGl() {
  for (auto& g : gpu_meshes_) {
    glDeleteVertexArrays(1, &g.vao);
    glDeleteBuffers(1, &g.vbo);
    glDeleteBuffers(1, &g.ibo);
    delete g.texture;
  }
  gpu_meshes_.clear();
  for (LineBuffer* b : {&grid_, &tree_lines_, &tree_points_, &root_points_, &root_outline_, &path_trace_, &gizmo_, &selection_,
                        &supports_, &placement_squares_, &placement_ticks_}) {
    if (b->vao) glDeleteVertexArrays(1, &b->vao);
    if (b->vbo) glDeleteBuffers(1, &b->vbo);
    b->vao = b->vbo = 0;
    b->dirty = true;
  }
  mesh_program_.reset();
  line_program_.reset();
  gl_ready_ = false;
}

std::vector<QMatrix4x4> SceneView::itemTransforms() const {
  std::vector<QMatrix4x4> out(items_.size());
  if (!scene_) return out;
  const Scene& s = *scene_;
  const SceneState state = doc_->displayState();
  PoseVector robot_links;
  Eigen::VectorXd q = state.q;
  if (q.size() != s.robot.model.nq) q = Eigen::VectorXd::Zero(s.robot.model.nq);
  forward_kinematics(s.robot.model, q, s.robot.base, robot_links);
  std::vector<PoseVector> object_links(s.objects.size());
  for (size_t o = 0; o < s.objects.size(); ++o) {
    const Pose base = o < state.objects.size() ? state.objects[o] : Pose::Identity();
    forward_kinematics(s.objects[o].model, Eigen::VectorXd::Zero(s.objects[o].model.nq), base, object_links[o]);
  }
  for (size_t i = 0; i < items_.size(); ++i) {
    const Item& it = items_[i];
    Pose link = Pose::Identity();
    switch (it.owner) {
      case Owner::Robot: link = robot_links[it.link]; break;
      case Owner::Furniture: link = s.furniture[it.index].link_poses[it.link]; break;
      case Owner::Object: link = object_links[it.index][it.link]; break;
      case Owner::Floor: break;
    }
    out[i] = toQt(link) * it.local;
  }
  return out;
}

// --------------------------------------------------------------------------------- GL

void SceneView::initializeGL() {
  initializeOpenGLFunctions();
  const QSurfaceFormat f = context()->format();
  gl_info_ = QStringLiteral("OpenGL %1.%2 %3 · %4")
                 .arg(f.majorVersion())
                 .arg(f.minorVersion())
                 .arg(f.profile() == QSurfaceFormat::CoreProfile ? QStringLiteral("core") : QStringLiteral("compatibility"))
                 .arg(QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER))));
  mesh_program_ = std::make_unique<QOpenGLShaderProgram>();
  line_program_ = std::make_unique<QOpenGLShaderProgram>();
  const bool ok = mesh_program_->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/demoplan/shaders/mesh.vert")) &&
                  mesh_program_->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/demoplan/shaders/mesh.frag")) &&
                  mesh_program_->link() &&
                  line_program_->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/demoplan/shaders/lines.vert")) &&
                  line_program_->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/demoplan/shaders/lines.frag")) &&
                  line_program_->link();
  if (!ok) {
    gl_failed_ = true;
    qWarning("demoplan: the 3D view's shaders failed to build: %s %s", qPrintable(mesh_program_->log()),
             qPrintable(line_program_->log()));
    return;
  }
  const QString renderer = QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER))).toLower();
  const QByteArray mode = qgetenv("DEMOPLAN_RENDER");
  const bool software = renderer.contains(QLatin1String("llvmpipe")) || renderer.contains(QLatin1String("softpipe")) ||
                        renderer.contains(QLatin1String("software"));
  const bool light = mode == "light" || (mode != "full" && software);
  if (light != light_geometry_) {
    light_geometry_ = light;
    rebuildScene();  // nothing is on the GPU yet: gl_ready_ is still false
  }
  if (light_geometry_) gl_info_ += tr(" · light geometry");
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
    makeCurrent();
    releaseGl();
    doneCurrent();
  });
  gl_ready_ = true;
}

void SceneView::resizeGL(int, int) {
  if (auto* fit = findChild<QToolButton*>(QStringLiteral("fitButton"))) {
    fit->move(width() - fit->sizeHint().width() - 8, 8);
    trees_button_->move(fit->x() - trees_button_->sizeHint().width() - 4, 8);
  }
}

void SceneView::drawLines(LineBuffer& b, unsigned mode, float point_size, bool round, bool depth, float alpha) {
  if (b.data.empty()) return;
  if (!b.vao) {
    glGenVertexArrays(1, &b.vao);
    glGenBuffers(1, &b.vbo);
    glBindVertexArray(b.vao);
    glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    b.dirty = true;
  }
  glBindVertexArray(b.vao);
  if (b.dirty) {
    glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(b.data.size() * sizeof(float)), b.data.data(), GL_DYNAMIC_DRAW);
    b.dirty = false;
  }
  line_program_->setUniformValue("u_point_size", point_size);
  line_program_->setUniformValue("u_round_points", round);
  line_program_->setUniformValue("u_alpha", alpha);
  if (depth) glEnable(GL_DEPTH_TEST);
  else glDisable(GL_DEPTH_TEST);
  glDrawArrays(mode, 0, GLsizei(b.data.size() / 7));
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
}

void SceneView::paintGL() {
  QElapsedTimer clock;
  clock.start();
  glClearColor(0.72f, 0.77f, 0.82f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!gl_ready_) return;
  if (fit_pending_ && scene_) {
    fit_pending_ = false;
    fitToScene();
  }
  uploadPending();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  const float aspect = float(width()) / std::max(1, height());
  const QMatrix4x4 vp = camera_.projection(aspect) * camera_.view();

  mesh_program_->bind();
  mesh_program_->setUniformValue("u_view_projection", vp);
  mesh_program_->setUniformValue("u_eye", camera_.eye());
  mesh_program_->setUniformValue("u_texture", 0);
  mesh_program_->setUniformValue("u_highlight", QVector3D(1.0f, 0.77f, 0.0f));
  const std::vector<QMatrix4x4> transforms = itemTransforms();
  const int selected = doc_->selectedObject();
  for (size_t i = 0; i < items_.size(); ++i) {
    const Item& it = items_[i];
    if (it.mesh < 0 || it.mesh >= int(gpu_meshes_.size())) continue;
    const GpuMesh& g = gpu_meshes_[it.mesh];
    mesh_program_->setUniformValue("u_model", transforms[i]);
    mesh_program_->setUniformValue("u_normal_matrix", transforms[i].normalMatrix());
    mesh_program_->setUniformValue("u_color", it.color);
    mesh_program_->setUniformValue("u_textured", g.texture != nullptr);
    const bool sel = it.owner == Owner::Object && it.index == selected;
    mesh_program_->setUniformValue("u_highlight_amount", sel ? 0.28f : 0.0f);
    mesh_program_->setUniformValue("u_ambient_boost", it.owner == Owner::Floor ? 0.25f : 0.0f);
    if (g.texture) {
      glActiveTexture(GL_TEXTURE0);
      g.texture->bind();
    }
    glBindVertexArray(g.vao);
    glDrawElements(GL_TRIANGLES, g.count, GL_UNSIGNED_INT, nullptr);
    if (g.texture) g.texture->release();
  }
  glBindVertexArray(0);
  mesh_program_->release();

  line_program_->bind();
  line_program_->setUniformValue("u_view_projection", vp);
  glLineWidth(1.0f);
  drawLines(grid_, GL_LINES, 1, false, true);
  drawLines(supports_, GL_LINES, 1, false, true);
  drawLines(placement_squares_, GL_POINTS, 13.0f, false, true);
  drawLines(placement_ticks_, GL_LINES, 1, false, true);
  // While the path plays, the trees step back so the robot and the path stand out.
  const bool playing_path = doc_->displayMode() == Document::DisplayMode::Result && doc_->planning()->interpolator();
  const float tree_alpha = playing_path ? 0.12f : 1.0f;
  if (show_trees_) {
    drawLines(tree_lines_, GL_LINES, 1, false, true, tree_alpha);
    drawLines(tree_points_, GL_POINTS, 3.5f, true, true, tree_alpha);
    if (!playing_path) {
      // Roots: a dark ring around a white dot (start green, goal red, transitions white).
      drawLines(root_outline_, GL_POINTS, 13.0f, true, false);
      drawLines(root_points_, GL_POINTS, 9.0f, true, false);
    }
  }
  if (playing_path) {
    glLineWidth(2.0f);
    drawLines(path_trace_, GL_LINE_STRIP, 1, false, false);
    glLineWidth(1.0f);
  }
  // The selected part: its bounding box and, when editable, the gizmo.
  selection_.data.clear();
  if (selected >= 0) {
    for (size_t i = 0; i < items_.size(); ++i) {
      const Item& it = items_[i];
      if (it.owner != Owner::Object || it.index != selected) continue;
      const auto& b = cpu_meshes_[it.mesh].bounds;
      QVector3D c[8];
      for (int k = 0; k < 8; ++k)
        c[k] = transforms[i].map(QVector3D(k & 1 ? b.max().x() : b.min().x(), k & 2 ? b.max().y() : b.min().y(),
                                           k & 4 ? b.max().z() : b.min().z()));
      const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
      for (const auto& e : edges) pushLine(selection_.data, c[e[0]], c[e[1]], kSelectionColor);
    }
    // Its grasp handles as open grippers: fingertips either side of the handle along the
    // closing axis (z), fingers and wrist back along the approach (x).
    const SceneState state = doc_->displayState();
    if (selected < int(state.objects.size()))
      for (const GraspFrame& h : scene_->objects[selected].srdf.handles) {
        const Pose w = state.objects[selected] * h.pose;
        const Eigen::Vector3d x = w.linear().col(0), z = w.linear().col(2), o = w.translation();
        const double half = 0.5 * std::max(h.clearance, 0.01), finger = 0.04, wrist = 0.03;
        const Eigen::Vector3d a = o - half * z, b = o + half * z, pa = a - finger * x, pb = b - finger * x;
        const Eigen::Vector3d palm = o - finger * x;
        for (const auto& [p, q] : {std::pair{a, pa}, std::pair{b, pb}, std::pair{pa, pb}, std::pair{palm, Eigen::Vector3d(palm - wrist * x)}})
          pushLine(selection_.data, toQt(p), toQt(q), kHandleColor, 0.9f);
      }
    // A cell part's markers: the black square and, inside it, a tick from the centre to the
    // image's top edge (how the printed marker goes on).
    if (const Cell* cell = doc_->cell(); cell && selected < int(state.objects.size()))
      for (const CellPart& p : cell->parts) {
        if (p.name != scene_->objects[selected].id) continue;
        for (const CellMarker& m : p.markers) {
          const Pose w = state.objects[selected] * m.pose;
          const double h = 0.5 * m.size;
          auto at = [&](double x, double y) { return toQt(w * Eigen::Vector3d(x, y, 0.0)); };
          const QVector3D c[4] = {at(-h, h), at(h, h), at(h, -h), at(-h, -h)};
          // The printed white margin around it (one bit wide, ~1/6 of the side), so it shows on
          // dark parts too.
          const double m2 = 1.33 * h;
          const QVector3D w4[4] = {at(-m2, m2), at(m2, m2), at(m2, -m2), at(-m2, -m2)};
          for (int k = 0; k < 4; ++k) {
            pushLine(selection_.data, c[k], c[(k + 1) % 4], kMarkerColor, 1.0f);
            pushLine(selection_.data, w4[k], w4[(k + 1) % 4], Qt::white, 1.0f);
          }
          pushLine(selection_.data, at(0, 0), at(0, h), kMarkerColor, 1.0f);
        }
      }
  }
  selection_.dirty = true;
  drawLines(selection_, GL_LINES, 1, false, true);
  gizmo_.data.clear();
  buildGizmo(gizmo_);
  gizmo_.dirty = true;
  glLineWidth(1.0f);
  drawLines(gizmo_, GL_LINES, 1, false, false);
  line_program_->release();
  last_paint_ms_ = clock.nsecsElapsed() / 1e6;
}

// ----------------------------------------------------------------------- trees, trace

void SceneView::onPlanStarted() {
  tree_lines_.data.clear();
  tree_points_.data.clear();
  root_points_.data.clear();
  root_outline_.data.clear();
  tree_lines_.dirty = tree_points_.dirty = root_points_.dirty = root_outline_.dirty = true;
  tree_edges_ = tree_roots_ = 0;
  path_trace_.data.clear();
  path_trace_.dirty = true;
  updateHud();
  update();
}

void SceneView::onPlanProgress(const PlanSnapshot& s) {
  for (const TreeEdge& e : s.new_edges) {
    const QColor c = treeColor(e.tree);
    pushLine(tree_lines_.data, e.from, e.to, c, 0.75f);
    pushPoint(tree_points_.data, e.to, c, 0.95f);
  }
  for (const TreeRoot& r : s.new_roots) {
    pushPoint(root_points_.data, r.position, QColor(0xff, 0xff, 0xff));
    pushPoint(root_outline_.data, r.position, QColor(0x20, 0x20, 0x20));
  }
  root_outline_.dirty = true;
  tree_edges_ += s.new_edges.size();
  tree_roots_ += s.new_roots.size();
  tree_lines_.dirty = tree_points_.dirty = root_points_.dirty = true;
  updateHud();
  // At most ~6 frames a second while the trees grow: the planner's snapshots come at 20 Hz.
  if (show_trees_ && !update_pending_) {
    update_pending_ = true;
    QTimer::singleShot(150, this, [this] {
      update_pending_ = false;
      update();
    });
  }
}

void SceneView::rebuildPathTrace() {
  path_trace_.data.clear();
  path_trace_.dirty = true;
  const PathInterpolator* interp = doc_->planning()->interpolator();
  if (!interp || !scene_) return;
  for (int i = 0; i <= 400; ++i) {
    const SceneState st = interp->at(i / 400.0);
    pushPoint(path_trace_.data, toQt(gripper_pose(*scene_, st.q).translation()), QColor(0xff, 0x6d, 0x00));
  }
}

void SceneView::rebuildPlacement() {
  // The placement search on the floor, as its heat map colours it: a square per candidate base
  // pose (grey without a valid plan) and a tick along the way the robot would face.
  placement_squares_.data.clear();
  placement_ticks_.data.clear();
  placement_squares_.dirty = placement_ticks_.dirty = true;
  const auto& candidates = doc_->placement()->candidates();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& c : candidates)
    if (c.usable()) lo = std::min(lo, *c.cycle_time_s()), hi = std::max(hi, *c.cycle_time_s());
  const plot::Ticks scale = std::isfinite(lo) ? plot::nice_ticks(lo, hi, 5) : plot::Ticks{};
  for (const auto& c : candidates) {
    const auto t = c.usable() ? c.cycle_time_s() : std::nullopt;
    const QColor color = t ? plot::sequential_color((*t - scale.min) / std::max(scale.max - scale.min, 1e-12))
                           : QColor(0xc8, 0xc8, 0xc8);
    const QVector3D at(float(c.base.x), float(c.base.y), 0.003f);
    pushPoint(placement_squares_.data, at, color);
    pushPoint(placement_ticks_.data, at, QColor(0x20, 0x20, 0x20));
    pushPoint(placement_ticks_.data, at + 0.08f * QVector3D(float(std::cos(c.base.yaw)), float(std::sin(c.base.yaw)), 0),
              QColor(0x20, 0x20, 0x20));
  }
  update();
}

void SceneView::setLightGeometry(bool on) {
  if (on == light_geometry_) return;
  light_geometry_ = on;
  rebuildScene();
  update();
}

void SceneView::setShowTrees(bool on) {
  show_trees_ = on;
  if (trees_button_->isChecked() != on) trees_button_->setChecked(on);
  update();
}

void SceneView::updateHud() {
  QString text;
  if (!doc_->hasProject()) {
    text = tr("No project");
  } else if (doc_->displayMode() == Document::DisplayMode::Result && doc_->planning()->interpolator()) {
    text = tr("<b>Planned path</b> · %1%").arg(doc_->playbackT() * 100, 0, 'f', 0);
  } else {
    text = tr("<b>Demonstration</b> · frame %1").arg(doc_->currentFrame());
    if (doc_->selectedObject() >= 0)
      text += tr(" · <span style='color:#b07d00'>%1</span>")
                  .arg(QString::fromStdString(doc_->demonstration().object_ids[doc_->selectedObject()]));
  }
  if (doc_->planning()->runner()->isRunning() || tree_edges_ > 0)
    text += tr("<br>trees: %L1 edges, %2 transition roots").arg(qulonglong(tree_edges_)).arg(qulonglong(tree_roots_));
  hud_->setText(text);
  hud_->adjustSize();
}

// --------------------------------------------------------------------------- interaction

void SceneView::fitToScene() {
  if (!scene_) return;
  Eigen::AlignedBox3f box;
  const std::vector<QMatrix4x4> transforms = itemTransforms();
  // A selected part is framed with room around it for its handles and its neighbours.
  const int selected = doc_->selectedObject();
  const float room = selected >= 0 ? 3.0f : 0.8f;
  for (size_t i = 0; i < items_.size(); ++i) {
    if (items_[i].owner == Owner::Floor) continue;
    if (selected >= 0 && (items_[i].owner != Owner::Object || items_[i].index != selected)) continue;
    const auto& b = cpu_meshes_[items_[i].mesh].bounds;
    for (int k = 0; k < 8; ++k) {
      const QVector3D p = transforms[i].map(QVector3D(k & 1 ? b.max().x() : b.min().x(), k & 2 ? b.max().y() : b.min().y(),
                                                      k & 4 ? b.max().z() : b.min().z()));
      box.extend(Eigen::Vector3f(p.x(), p.y(), p.z()));
    }
  }
  if (box.isEmpty()) return;
  const Eigen::Vector3f c = box.center();
  // The sphere around the box is loose for a flat scene; 0.8 of it frames the furniture well.
  camera_.fit(QVector3D(c.x(), c.y(), c.z()), 0.5f * box.diagonal().norm() * room, float(width()) / std::max(1, height()));
  update();
}

int SceneView::pickObject(const QPointF& pixel) const { return pickSurface(pixel).object; }

SceneView::SurfaceHit SceneView::pickSurface(const QPointF& pixel) const {
  SurfaceHit hit;
  if (!scene_) return hit;
  const Ray ray = camera_.rayAt(pixel, size());
  const std::vector<QMatrix4x4> transforms = itemTransforms();
  float best_t = 1e30f;
  int best_item = -1;
  QVector3D best_a, best_b, best_c, best_o, best_d;  // in the item's mesh frame
  const bool furniture_too = doc_->cell() != nullptr;  // a cell's furniture is edited, not the benchmark's
  for (size_t i = 0; i < items_.size(); ++i) {
    const Item& it = items_[i];
    if (it.owner != Owner::Object && !(furniture_too && it.owner == Owner::Furniture)) continue;
    const QMatrix4x4 inv = transforms[i].inverted();
    const QVector3D o = inv.map(ray.origin);
    const QVector3D d = inv.mapVector(ray.direction);
    const CpuMesh& m = cpu_meshes_[it.mesh];
    if (!rayBox(o, d, m.bounds)) continue;
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3) {
      auto v = [&](std::uint32_t idx) {
        return QVector3D(m.vertices[idx * 8], m.vertices[idx * 8 + 1], m.vertices[idx * 8 + 2]);
      };
      float t;
      const QVector3D a = v(m.indices[k]), b = v(m.indices[k + 1]), c = v(m.indices[k + 2]);
      if (rayTriangle(o, d, a, b, c, t) && t < best_t) {
        best_t = t;
        best_item = int(i);
        best_a = a, best_b = b, best_c = c, best_o = o, best_d = d;
      }
    }
  }
  if (best_item < 0) return hit;
  if (items_[size_t(best_item)].owner == Owner::Furniture) {
    hit.furniture = items_[size_t(best_item)].index;
    return hit;
  }
  // The hit and the triangle's normal, facing the ray's origin, into the world, then the part's frame.
  const QMatrix4x4& M = transforms[size_t(best_item)];
  const QVector3D wa = M.map(best_a);
  QVector3D world_n = QVector3D::crossProduct(M.map(best_b) - wa, M.map(best_c) - wa).normalized();
  if (QVector3D::dotProduct(world_n, ray.direction) > 0) world_n = -world_n;
  const QVector3D world = M.map(best_o + best_t * best_d);
  hit.object = items_[size_t(best_item)].index;
  const SceneState state = doc_->displayState();
  const Pose part = hit.object < int(state.objects.size()) ? state.objects[size_t(hit.object)] : Pose::Identity();
  hit.point = part.inverse() * Eigen::Vector3d(world.x(), world.y(), world.z());
  hit.normal = (part.linear().transpose() * Eigen::Vector3d(world_n.x(), world_n.y(), world_n.z())).normalized();
  return hit;
}

bool SceneView::gizmoFrame(QVector3D& origin, float& length, GizmoTarget& target) const {
  if (!scene_ || doc_->displayMode() != Document::DisplayMode::Demonstration) return false;
  target = {};
  const int furniture = doc_->selectedFurniture();
  const Cell* cell = doc_->cell();
  if (furniture >= 0 && cell && furniture < int(cell->furniture.size()) && !doc_->cellIsBundled()) {
    target.furniture = furniture;
    target.pose = cell->furniture[size_t(furniture)].pose;
  } else {
    target.object = doc_->selectedObject();
    target.correction = doc_->correctionAt(target.object, doc_->currentFrame());
    if (target.correction >= 0) {
      target.pose = doc_->corrections()[size_t(target.correction)].world_T_object;
    } else {
      target.event = doc_->editEvent();
      if (target.object < 0 || target.event < 0) return false;
      target.pose = world_pose_at_event(*scene_, doc_->demonstration(), size_t(target.event), target.object,
                                        doc_->initialConfiguration());
    }
  }
  origin = toQt(target.pose.translation());
  length = std::clamp((camera_.eye() - origin).length() * 0.1f, 0.06f, 0.25f);
  return true;
}

void SceneView::buildGizmo(LineBuffer& out) const {
  QVector3D o;
  float len;
  GizmoTarget target;
  if (!gizmoFrame(o, len, target)) return;
  for (int a = 0; a < 3; ++a) {
    QVector3D e;
    e[a] = 1.0f;
    const bool active = drag_ == Drag::Axis && drag_axis_ == a;
    const QColor c = active ? kSelectionColor : kAxisColors[a];
    const QVector3D tip = o + e * len;
    pushLine(out.data, o, tip, c);
    // Arrow head: a small cone of lines.
    const QVector3D u = a == 2 ? QVector3D(1, 0, 0) : QVector3D(0, 0, 1);
    const QVector3D v = QVector3D::crossProduct(e, u);
    for (int k = 0; k < 8; ++k) {
      const float ang = 2 * kPi * k / 8;
      const QVector3D rim = tip - e * len * 0.18f + (u * std::cos(ang) + v * std::sin(ang)) * len * 0.06f;
      pushLine(out.data, tip, rim, c);
    }
  }
  const QColor ring = drag_ == Drag::Ring ? kSelectionColor : QColor(0x1e, 0x88, 0xe5);
  const int n = 48;
  for (int k = 0; k < n; ++k) {
    const float a0 = 2 * kPi * k / n, a1 = 2 * kPi * (k + 1) / n;
    pushLine(out.data, o + QVector3D(std::cos(a0), std::sin(a0), 0) * len * 0.75f,
             o + QVector3D(std::cos(a1), std::sin(a1), 0) * len * 0.75f, ring);
  }
}

bool SceneView::gizmoCenter(QPointF& pixel) const {
  QVector3D o;
  float len;
  GizmoTarget target;
  return gizmoFrame(o, len, target) && camera_.project(o, size(), pixel);
}

int SceneView::gizmoHandleAt(const QPointF& p) const {
  QVector3D o;
  float len;
  GizmoTarget target;
  if (!gizmoFrame(o, len, target)) return -1;
  QPointF c;
  if (!camera_.project(o, size(), c)) return -1;
  for (int a = 0; a < 3; ++a) {
    QVector3D e;
    e[a] = 1.0f;
    QPointF tip;
    if (camera_.project(o + e * len, size(), tip) && distanceToSegment(p, c + (tip - c) * 0.15, tip) < 7) return a;
  }
  for (int k = 0; k < 48; ++k) {
    const float a0 = 2 * kPi * k / 48, a1 = 2 * kPi * (k + 1) / 48;
    QPointF p0, p1;
    if (camera_.project(o + QVector3D(std::cos(a0), std::sin(a0), 0) * len * 0.75f, size(), p0) &&
        camera_.project(o + QVector3D(std::cos(a1), std::sin(a1), 0) * len * 0.75f, size(), p1) &&
        distanceToSegment(p, p0, p1) < 6)
      return 3;
  }
  return -1;
}

void SceneView::applyGizmoPose(const Pose& T) {
  if (drag_target_.furniture >= 0) {
    // One drag, one undo step (keys apart from the Cell panel's per-field ones).
    QString error;
    if (!doc_->moveFurniture(drag_target_.furniture, T, 1'000'000 + drag_serial_ % 800, &error)) emit editRefused(error);
    return;
  }
  if (drag_target_.correction >= 0) {
    doc_->setCorrectionPose(drag_target_.correction, T, 100 + drag_serial_ % 800);
    return;
  }
  doc_->setObjectPose(drag_target_.event, drag_target_.object, T, 100 + drag_serial_ % 800);
}

void SceneView::mousePressEvent(QMouseEvent* e) {
  press_pos_ = last_pos_ = e->position();
  moved_ = false;
  if (e->button() == Qt::LeftButton && !(e->modifiers() & Qt::ShiftModifier)) {
    const int handle = gizmoHandleAt(e->position());
    if (handle >= 0) {
      QVector3D o;
      float len;
      gizmoFrame(o, len, drag_target_);
      drag_ = handle < 3 ? Drag::Axis : Drag::Ring;
      drag_axis_ = handle;
      ++drag_serial_;
      update();
      return;
    }
    drag_ = Drag::Orbit;
  } else if (e->button() == Qt::RightButton || e->button() == Qt::MiddleButton ||
             (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier))) {
    drag_ = Drag::Pan;
  }
}

void SceneView::mouseMoveEvent(QMouseEvent* e) {
  const QPointF d = e->position() - last_pos_;
  last_pos_ = e->position();
  if ((e->position() - press_pos_).manhattanLength() > 3) moved_ = true;
  switch (drag_) {
    case Drag::Orbit:
      camera_.orbit(float(d.x()), float(d.y()));
      update();
      break;
    case Drag::Pan:
      camera_.pan(float(d.x()), float(d.y()), float(height()));
      update();
      break;
    case Drag::Axis: {
      // The part follows the cursor along the axis: the point of the axis line closest to the
      // ray under the cursor, now and at the press.
      const QVector3D o = toQt(drag_target_.pose.translation());
      QVector3D axis;
      axis[drag_axis_] = 1.0f;
      auto along = [&](const QPointF& pixel, bool& ok) {
        const Ray r = camera_.rayAt(pixel, size());
        const float b = QVector3D::dotProduct(axis, r.direction);
        const float denom = 1.0f - b * b;
        ok = denom > 0.02f;  // not when the axis points at the camera
        const QVector3D w0 = o - r.origin;
        return ok ? (b * QVector3D::dotProduct(r.direction, w0) - QVector3D::dotProduct(axis, w0)) / denom : 0.0f;
      };
      bool ok0, ok1;
      const float s0 = along(press_pos_, ok0), s1 = along(e->position(), ok1);
      if (!ok0 || !ok1) break;
      double shift = double(s1 - s0);
      const double step = (e->modifiers() & Qt::ControlModifier) ? 0.01 : 0.001;  // 1 cm or 1 mm steps
      shift = std::clamp(std::round(shift / step) * step, -2.0, 2.0);
      Pose T = drag_target_.pose;
      T.translation()[drag_axis_] += shift;
      applyGizmoPose(T);
      break;
    }
    case Drag::Ring: {
      QPointF c;
      if (!camera_.project(toQt(drag_target_.pose.translation()), size(), c)) break;
      const double a0 = std::atan2(-(press_pos_.y() - c.y()), press_pos_.x() - c.x());
      const double a1 = std::atan2(-(e->position().y() - c.y()), e->position().x() - c.x());
      double delta = a1 - a0;
      if (camera_.eye().z() < float(drag_target_.pose.translation().z())) delta = -delta;
      const double step = (e->modifiers() & Qt::ControlModifier) ? 5.0 : 0.5;  // degrees
      delta = std::round(delta * 180 / M_PI / step) * step * M_PI / 180;
      Pose T = drag_target_.pose;
      T.linear() = Eigen::AngleAxisd(delta, Eigen::Vector3d::UnitZ()).toRotationMatrix() * drag_target_.pose.linear();
      applyGizmoPose(T);
      break;
    }
    case Drag::None: {
      const int handle = gizmoHandleAt(e->position());
      setCursor(handle >= 0 ? Qt::PointingHandCursor : Qt::ArrowCursor);
      break;
    }
  }
}

void SceneView::mouseReleaseEvent(QMouseEvent* e) {
  const Drag was = drag_;
  drag_ = Drag::None;
  drag_axis_ = -1;
  if (was == Drag::Orbit && !moved_ && e->button() == Qt::LeftButton) {
    const SurfaceHit hit = pickSurface(e->position());
    doc_->selectObject(hit.object);
    emit objectPicked(hit.object);
    if (hit.object >= 0) emit surfacePicked(hit);
    if (hit.furniture >= 0) emit furniturePicked(hit.furniture);
  }
  update();
}

void SceneView::wheelEvent(QWheelEvent* e) {
  camera_.zoom(float(e->angleDelta().y()) / 120.0f);
  update();
}

}  // namespace demoplan::ui
