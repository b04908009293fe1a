#include "plot/palette.h"

#include <array>
#include <map>

namespace demoplan::plot {

namespace {

// Okabe & Ito's palette without black and yellow (too light on white).
const std::array<QColor, 6> kOkabeIto{QColor(0x00, 0x72, 0xb2), QColor(0xe6, 0x9f, 0x00), QColor(0x00, 0x9e, 0x73),
                                      QColor(0xd5, 0x5e, 0x00), QColor(0xcc, 0x79, 0xa7), QColor(0x56, 0xb4, 0xe9)};

QColor base_color(const QString& base) {
  static const std::map<QString, int> known{{QStringLiteral("guided"), 0}, {QStringLiteral("unguided"), 3},
                                            {QStringLiteral("ompl-rrtconnect"), 2}, {QStringLiteral("ompl-prm"), 4},
                                            {QStringLiteral("ompl-rrt"), 1}};
  if (auto it = known.find(base); it != known.end()) return kOkabeIto[it->second];
  // FNV-1a: stable across runs and machines, unlike qHash's seed.
  quint32 h = 2166136261u;
  for (QChar c : base) h = (h ^ c.unicode()) * 16777619u;
  return kOkabeIto[h % kOkabeIto.size()];
}

}  // namespace

QColor series_color(const QString& name) {
  QString base = name;
  const int paren = base.indexOf(QLatin1String(" ("));
  if (paren > 0) base.truncate(paren);
  const bool shortcut = base.endsWith(QLatin1String("+shortcut"));
  if (shortcut) base.chop(int(sizeof("+shortcut") - 1));
  const QColor c = base_color(base);
  if (!shortcut) return c;
  // The shortened path of the same planner: the same hue, lighter.
  return QColor::fromHslF(c.hslHueF(), c.hslSaturationF() * 0.85, std::min(0.8, c.lightnessF() + 0.25));
}

QColor quantity_color(int quantity) {
  static const std::array<QColor, 3> c{QColor(0x00, 0x72, 0xb2), QColor(0x00, 0x9e, 0x73), QColor(0xd5, 0x5e, 0x00)};
  return c[static_cast<size_t>(quantity) % c.size()];
}

}  // namespace demoplan::plot
