#include "ui/document/background_job.h"

#include <QMetaObject>
#include <QPointer>

namespace demoplan::ui {

BackgroundJob::BackgroundJob(QObject* parent) : QObject(parent) {}

BackgroundJob::~BackgroundJob() {
  if (cancel_) cancel_->store(true);
  for (auto& t : threads_)
    if (t.joinable()) t.join();
}

bool BackgroundJob::run(std::function<void(const Post& post, const std::atomic<bool>& cancel)> work) {
  if (running_) return false;
  running_ = true;
  const int generation = ++generation_;
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  auto cancel = cancel_;
  QPointer<BackgroundJob> self(this);
  emit started();
  threads_.emplace_back([self, generation, cancel, work = std::move(work)] {
    const Post post = [&](std::function<void()> f) {
      if (cancel->load() || !self) return;
      QMetaObject::invokeMethod(
          self.data(),
          [self, generation, f = std::move(f)] {
            if (self && self->generation_ == generation && self->running_) f();
          },
          Qt::QueuedConnection);
    };
    work(post, *cancel);
  });
  return true;
}

void BackgroundJob::cancel() {
  if (!running_) return;
  cancel_->store(true);
  running_ = false;
  ++generation_;
  emit cancelled();
}

}  // namespace demoplan::ui
