#include "core/export/csv_writer.h"

#include <sstream>

namespace demoplan {

namespace {

class CsvWriter final : public ProgramWriter {
public:
  CsvWriter() : ProgramWriter({"csv", "CSV (time, joints, gripper)", ".csv", 100.0}) {}
  ProgramOutput write(const ProgramInput& input, const std::string& file) const override;
};

ProgramOutput CsvWriter::write(const ProgramInput& input, const std::string& file) const {
  const Trajectory& tr = input.trajectory;
  std::vector<int> joints = input.axes.base;
  joints.insert(joints.end(), input.axes.arm.begin(), input.axes.arm.end());
  const double rate = sample_rate(input.options);
  std::ostringstream s;
  for (const auto& line : header_lines(input, "CSV")) s << "# " << line << "\n";
  s << "time";
  for (int j : joints) s << "," << input.limits.names[j];
  for (int j : joints) s << ",v_" << input.limits.names[j];
  s << ",gripper_closed,waypoint\n";
  ProgramOutput result;
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
  result.files.push_back({file, s.str()});
  return result;
}

}  // namespace

const ProgramWriter& csv_writer() {
  static const CsvWriter writer;
  return writer;
}

}  // namespace demoplan
