#pragma once
// Nearest neighbour among configurations added one at a time: a dynamic k-d tree (nanoflann,
// a logarithmic forest of static trees), so insertion and query stay fast at 10^5 points.
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace demoplan {

class NearestNeighbors {
public:
  explicit NearestNeighbors(int dimension);
  ~NearestNeighbors();
  NearestNeighbors(NearestNeighbors&&) noexcept;
  NearestNeighbors& operator=(NearestNeighbors&&) noexcept;

  void add(int id, const Eigen::VectorXd& q);
  // Id of the nearest point (Euclidean), -1 when empty; `distance` gets its distance.
  int nearest(const Eigen::VectorXd& q, double* distance = nullptr) const;
  size_t size() const;
  const std::vector<int>& ids() const;  // in insertion order
  const double* point(size_t k) const;  // k-th inserted point

private:
  struct Index;
  std::unique_ptr<Index> index_;
};

}  // namespace demoplan
