#include "plot/palette.h"

#include <array>
#include <map>

namespace demoplan::plot {

namespace {

// Okabe & Ito's palette without black and yellow (too light on white).
const std::array<QColor, 6> kOkabeIto{QColor(0x00, 0x72, 0xb2), QColor(0xe6, 0x9f, 0x00), QColor(0x00, 0x9e, 0x73),
                                      QColor(0xd5, 0x5e, 0x00), QColor(0xcc, 0x79, 0xa7), QColor(0x56, 0xb4, 0xe9)};

const std::map<QString, int>& known_bases() {
  static const std::map<QString, int> known{{QStringLiteral("guided"), 0}, {QStringLiteral("unguided"), 3},
                                            {QStringLiteral("ompl-rrtconnect"), 2}, {QStringLiteral("ompl-prm"), 4},
                                            {QStringLiteral("ompl-rrt"), 1}};
  return known;
}

// The palette index of a base name: fixed for known planners, else a hash of the name.
size_t base_index(const QString& base) {
  if (auto it = known_bases().find(base); it != known_bases().end()) return static_cast<size_t>(it->second);
  // FNV-1a: stable across runs and machines, unlike qHash's seed.
  quint32 h = 2166136261u;
  for (QChar c : base) h = (h ^ c.unicode()) * 16777619u;
  return h % kOkabeIto.size();
}

// "guided+shortcut" -> ("guided", true); "guided+shortcut (raw)" -> ("guided (raw)", true).
std::pair<QString, bool> split_shortcut(const QString& name) {
  QString base = name;
  const int at = base.indexOf(QLatin1String("+shortcut"));
  if (at < 0) return {base, false};
  base.remove(at, int(sizeof("+shortcut") - 1));
  return {base, true};
}

QColor shade(const QColor& c, bool shortcut) {
  if (!shortcut) return c;
  // The shortened path of the same planner: the same hue, lighter.
  return QColor::fromHslF(c.hslHueF(), c.hslSaturationF() * 0.85, std::min(0.8, c.lightnessF() + 0.25));
}

}  // namespace

QColor series_color(const QString& name) {
  const auto [base, shortcut] = split_shortcut(name);
  return shade(kOkabeIto[base_index(base)], shortcut);
}

std::vector<QColor> series_colors(const std::vector<QString>& names) {
  std::map<QString, size_t> chosen;  // base name -> palette index
  std::vector<bool> used(kOkabeIto.size(), false);
  // Known planners first: they keep their colours whatever else is shown.
  for (const QString& n : names)
    if (const QString base = split_shortcut(n).first; known_bases().count(base)) {
      chosen[base] = base_index(base);
      used[chosen[base]] = true;
    }
  for (const QString& n : names) {
    const QString base = split_shortcut(n).first;
    if (chosen.count(base)) continue;
    size_t i = base_index(base);
    for (size_t k = 0; k < used.size() && used[i]; ++k) i = (i + 1) % used.size();
    chosen[base] = i;
    used[i] = true;
  }
  std::vector<QColor> out;
  for (const QString& n : names) {
    const auto [base, shortcut] = split_shortcut(n);
    out.push_back(shade(kOkabeIto[chosen[base]], shortcut));
  }
  return out;
}

QColor quantity_color(int quantity) {
  static const std::array<QColor, 3> c{QColor(0x00, 0x72, 0xb2), QColor(0x00, 0x9e, 0x73), QColor(0xd5, 0x5e, 0x00)};
  return c[static_cast<size_t>(quantity) % c.size()];
}

}  // namespace demoplan::plot
