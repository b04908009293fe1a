#pragma once
// Colours and small formatting helpers every panel shares, so a part has the same colour in
// the timeline, the 3D view and the video overlay.
#include <QColor>
#include <QRectF>
#include <QString>

#include "core/demo/demonstration.h"
#include "core/geometry/se3.h"
#include "ui/document/step_status.h"  // kLowConfidence

class QPainter;

namespace demoplan::ui {

QColor objectColor(int object);  // distinct per object index
QColor eventColor(EventType type);  // grasp: green, release: orange
QColor treeColor(int tree);
inline const QColor kOkColor{0x2e, 0x9d, 0x4a};
inline const QColor kWarningColor{0xd9, 0x8e, 0x04};
inline const QColor kErrorColor{0xcf, 0x22, 0x2e};
inline const QColor kBusyColor{0x1f, 0x6f, 0xeb};
inline const QColor kSelectionColor{0xff, 0xc4, 0x00};
// Support polygons (where parts may be put down) and grasp handles in the 3D view.
inline const QColor kSupportColor{0x2e, 0x7d, 0x32};
inline const QColor kHandleColor{0x00, 0x83, 0x8f};
// ArUco markers stuck on a cell's parts (near black, as printed).
inline const QColor kMarkerColor{0x21, 0x21, 0x21};
// x, y, z: the world axes in the 3D view and the position curves of the part tracks.
inline const QColor kAxisColors[3] = {QColor(0xe5, 0x39, 0x35), QColor(0x43, 0xa0, 0x47), QColor(0x1e, 0x88, 0xe5)};
// A frame range the event detection could not decide (timeline and part tracks, hatched).
inline const QColor kDoubtColor = kWarningColor;
// A part at rest in its track (shaded lightly behind the curves).
inline const QColor kTrackRestColor{0x8f, 0xa8, 0xbf};
// A part's rotation angle in its track.
inline const QColor kTrackAngleColor{0x6a, 0x3d, 0x9a};
// A frame in which the tracker did not see the part (the part tracks' confidence strip).
inline const QColor kUnseenColor{0xcc, 0xcc, 0xcc};

// Where the operator placed a part again (Document::corrections): a diamond filling `box`, in the
// part's colour with an `outline` (timeline lanes and part tracks alike).
void paintPlacementMark(QPainter& p, const QRectF& box, int object, const QColor& outline);

// "grasp" / "release"
QString eventTypeName(EventType type);
// "frame 48 (1.60 s)"
QString frameText(int frame, double fps);

// URDF roll-pitch-yaw (R = Rz(yaw) Ry(pitch) Rx(roll)) of a rotation, radians.
Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R);

}  // namespace demoplan::ui
