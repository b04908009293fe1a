#include "perception/tracking/track_coverage.h"

#include <algorithm>
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
    auto run = [&](const std::pair<int, int>& r) {
      out << r.first;
      if (r.second > r.first) out << "-" << r.second;
    };
    // Cut short: the last run too when the part was lost for good.
    const bool cut = c.unseen.size() > runs, last_too = cut && c.lost_from() >= 0 && runs > 1;
    const size_t listed = std::min(c.unseen.size(), last_too ? runs - 1 : runs);
    for (size_t i = 0; i < listed; ++i) {
      out << (i ? ", " : "");
      run(c.unseen[i]);
    }
    if (const size_t more = c.unseen.size() - listed - (last_too ? 1 : 0); more > 0)
      out << (last_too ? ", " : " and ") << more << (more == 1 ? " more run" : " more runs");
    if (last_too) {
      out << " and ";
      run(c.unseen.back());
    }
  }
  return out.str();
}

}  // namespace demoplan::perception
