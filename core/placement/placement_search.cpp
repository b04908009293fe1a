#include "core/placement/placement_search.h"

#include "core/parallel_for.h"

namespace demoplan {

std::vector<PlacementCandidate> run_placement_search(const ProblemAtBase& problem_at,
                                                     const std::vector<BasePose>& candidates,
                                                     const std::vector<int>& indices,
                                                     const PlacementSettings& settings, int jobs,
                                                     const CandidateDone& on_done, const std::atomic<bool>* cancel) {
  std::vector<PlacementCandidate> out(indices.size());
  for (size_t k = 0; k < indices.size(); ++k) {
    out[k].index = indices[k];
    out[k].base = candidates.at(static_cast<size_t>(indices[k]));
  }
  size_t done = 0;
  parallel_for(
      indices.size(), jobs,
      [&](size_t k) { out[k] = evaluate_candidate(problem_at, out[k].index, out[k].base, settings, cancel); },
      [&](size_t k) {
        if (on_done) on_done(out[k], ++done, indices.size());
      },
      cancel);
  return out;
}

}  // namespace demoplan
