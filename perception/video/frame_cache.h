#pragma once
// A small least-recently-used cache of decoded frames, for scrubbing back and forth in a video.
#include <list>
#include <optional>
#include <unordered_map>
#include <utility>

#include <opencv2/core.hpp>

namespace demoplan::perception {

class FrameCache {
public:
  explicit FrameCache(size_t capacity = 32) : capacity_(capacity) {}

  // The frame when cached (a shallow cv::Mat header; do not modify it), and marks it recent.
  std::optional<cv::Mat> get(int frame) {
    auto it = index_.find(frame);
    if (it == index_.end()) return std::nullopt;
    order_.splice(order_.begin(), order_, it->second);
    return it->second->second;
  }

  void put(int frame, const cv::Mat& image) {
    if (capacity_ == 0) return;
    if (auto it = index_.find(frame); it != index_.end()) {
      it->second->second = image;
      order_.splice(order_.begin(), order_, it->second);
      return;
    }
    order_.emplace_front(frame, image);
    index_[frame] = order_.begin();
    if (order_.size() > capacity_) {
      index_.erase(order_.back().first);
      order_.pop_back();
    }
  }

  void clear() {
    order_.clear();
    index_.clear();
  }
  size_t size() const { return order_.size(); }
  size_t capacity() const { return capacity_; }

private:
  size_t capacity_;
  std::list<std::pair<int, cv::Mat>> order_;  // most recent first
  std::unordered_map<int, std::list<std::pair<int, cv::Mat>>::iterator> index_;
};

}  // namespace demoplan::perception
