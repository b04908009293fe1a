#include "core/demo/part_correction.h"

#include <set>
#include <utility>

namespace demoplan {

std::vector<PartCorrection> read_part_corrections(const JsonField& list, int start_frame,
                                                  const std::function<bool(const std::string&)>& known,
                                                  const std::string& unknown,
                                                  const std::function<Pose(const JsonField&)>& pose) {
  std::vector<PartCorrection> out;
  std::set<std::pair<std::string, int>> placed;
  for (size_t i = 0; i < list.size(); ++i) {
    const JsonField entry = list[i];
    PartCorrection c;
    c.id = entry["id"].string();
    if (!known(c.id)) entry["id"].fail("part '" + c.id + "' " + unknown);
    c.frame = entry["frame"].integer();
    if (c.frame <= start_frame)
      entry["frame"].fail("must be after the start frame (" + std::to_string(start_frame) + ")");
    if (!placed.insert({c.id, c.frame}).second)
      entry["frame"].fail("part '" + c.id + "' is placed twice in frame " + std::to_string(c.frame));
    c.world_T_object = pose(entry["world_T_object"]);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace demoplan
