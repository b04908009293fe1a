#include "core/export/csv_writer.h"

#include <sstream>

namespace demoplan {

ExportResult write_csv(const ExportJob& job, const std::string& file) {
  const Trajectory& tr = job.trajectory;
  std::vector<int> joints = job.axes.base;
  joints.insert(joints.end(), job.axes.arm.begin(), job.axes.arm.end());
  const double rate = job.options.rate > 0 ? job.options.rate : 100.0;
  std::ostringstream s;
  for (const auto& line : header_lines(job, "CSV")) s << "# " << line << "\n";
  s << "time";
  for (int j : joints) s << "," << job.limits.names[j];
  for (int j : joints) s << ",v_" << job.limits.names[j];
  s << ",gripper_closed,waypoint\n";
  ExportResult result;
  size_t next = 0;
  for (const auto& p : tr.sample(rate, true)) {
    long waypoint = -1;
    if (next < tr.waypoint_times.size() && p.t == tr.waypoint_times[next]) waypoint = static_cast<long>(next);
    // Several waypoints at one time (a zero-length segment): the row names the last.
    while (next < tr.waypoint_times.size() && tr.waypoint_times[next] <= p.t) waypoint = static_cast<long>(next++);
    s << fixed(p.t, 9);
    for (int j : joints) s << "," << fixed(p.q[j], 10);
    for (int j : joints) s << "," << fixed(p.v[j], 10);
    s << "," << (p.gripper_closed ? 1 : 0) << "," << (waypoint >= 0 && tr.waypoint_times[waypoint] == p.t ? waypoint : -1) << "\n";
    ++result.samples;
  }
  write_text_file_atomic(file, s.str());
  result.files.push_back(file);
  return result;
}

}  // namespace demoplan
