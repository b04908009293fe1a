#pragma once
// Colours that stay the same for the same name in every figure: known planners get fixed,
// colour-blind-safe colours (Okabe-Ito); other names one of the rest by a hash of the name.
#include <QColor>
#include <QString>
#include <vector>

namespace demoplan::plot {

// The colour of a series name, e.g. a planner: "guided+shortcut" is a lighter "guided".
QColor series_color(const QString& name);
// The colours of the series shown together: as series_color, except that a name whose hashed
// colour another base name already has (e.g. "guided (raw)" beside "guided") takes the next free
// one, so no two planners look alike.
std::vector<QColor> series_colors(const std::vector<QString>& names);
// The joint plots' colours: position, velocity, acceleration.
QColor quantity_color(int quantity);

inline const QColor kAxisColor{0x55, 0x55, 0x55};
inline const QColor kGridColor{0xe4, 0xe4, 0xe4};
inline const QColor kLimitColor{0xc0, 0x39, 0x2b};
inline const QColor kRestColor{0xf0, 0xa2, 0x02, 0x50};

}  // namespace demoplan::plot
