#include "perception/tracking/track_coverage.h"

#include <sstream>

namespace demoplan::perception {

TrackCoverage track_coverage(const std::vector<PoseSample>& samples, double sure) {
  TrackCoverage c;
  c.frames = static_cast<int>(samples.size());
  for (int f = 0; f < c.frames; ++f) {
    const PoseSample& s = samples[static_cast<size_t>(f)];
    if (s.valid) {
      ++c.seen;
      c.unsure += s.confidence < sure;
    } else if (!c.unseen.empty() && c.unseen.back().second == f - 1) {
      c.unseen.back().second = f;
    } else {
      c.unseen.push_back({f, f});
    }
  }
  return c;
}

std::string describe_coverage(const TrackCoverage& c, double sure, size_t runs) {
  std::ostringstream out;
  out << "seen in " << c.seen << " of " << c.frames << " frames";
  if (c.unsure > 0) out << ", " << c.unsure << " of them below " << sure << " confidence";
  if (!c.unseen.empty()) {
    out << "; not seen in frame" << (c.unseen.size() == 1 && c.unseen[0].first == c.unseen[0].second ? " " : "s ");
    for (size_t i = 0; i < c.unseen.size() && i < runs; ++i) {
      const auto& [first, last] = c.unseen[i];
      out << (i ? ", " : "") << first;
      if (last > first) out << "-" << last;
    }
    if (const size_t more = c.unseen.size() > runs ? c.unseen.size() - runs : 0; more > 0)
      out << " and " << more << (more == 1 ? " more run" : " more runs");
  }
  return out.str();
}

}  // namespace demoplan::perception
