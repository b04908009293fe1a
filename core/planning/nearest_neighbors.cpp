#include "core/planning/nearest_neighbors.h"

#include <nanoflann.hpp>

#include <limits>

namespace demoplan {

namespace {
// nanoflann's view of our flat coordinate array.
struct Cloud {
  int dim = 0;
  std::vector<double> coords;  // dim per point
  size_t kdtree_get_point_count() const { return dim ? coords.size() / dim : 0; }
  double kdtree_get_pt(size_t i, size_t d) const { return coords[i * dim + d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
using Tree = nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, -1, size_t>;
// Below this many points a linear scan beats the tree.
constexpr size_t kLinearScan = 24;
}  // namespace

struct NearestNeighbors::Index {
  Cloud cloud;
  std::vector<int> ids;
  std::unique_ptr<Tree> tree;
};

NearestNeighbors::NearestNeighbors(int dimension) : index_(std::make_unique<Index>()) {
  index_->cloud.dim = dimension;
}
NearestNeighbors::~NearestNeighbors() = default;
NearestNeighbors::NearestNeighbors(NearestNeighbors&&) noexcept = default;
NearestNeighbors& NearestNeighbors::operator=(NearestNeighbors&&) noexcept = default;

void NearestNeighbors::add(int id, const Eigen::VectorXd& q) {
  Index& ix = *index_;
  ix.cloud.coords.insert(ix.cloud.coords.end(), q.data(), q.data() + q.size());
  ix.ids.push_back(id);
  const size_t n = ix.ids.size();
  if (n == kLinearScan) {
    ix.tree = std::make_unique<Tree>(ix.cloud.dim, ix.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  } else if (n > kLinearScan) {
    ix.tree->addPoints(n - 1, n - 1);
  }
}

int NearestNeighbors::nearest(const Eigen::VectorXd& q, double* distance) const {
  const Index& ix = *index_;
  const size_t n = ix.ids.size();
  if (n == 0) return -1;
  size_t best = 0;
  double best_sq = std::numeric_limits<double>::infinity();
  if (!ix.tree) {
    for (size_t k = 0; k < n; ++k) {
      const double d = (Eigen::Map<const Eigen::VectorXd>(&ix.cloud.coords[k * ix.cloud.dim], ix.cloud.dim) - q).squaredNorm();
      if (d < best_sq) best_sq = d, best = k;
    }
  } else {
    nanoflann::KNNResultSet<double, size_t> result(1);
    result.init(&best, &best_sq);
    ix.tree->findNeighbors(result, q.data(), nanoflann::SearchParams());
  }
  if (distance) *distance = std::sqrt(best_sq);
  return ix.ids[best];
}

size_t NearestNeighbors::size() const { return index_->ids.size(); }
const std::vector<int>& NearestNeighbors::ids() const { return index_->ids; }
const double* NearestNeighbors::point(size_t k) const { return &index_->cloud.coords[k * index_->cloud.dim]; }

}  // namespace demoplan
