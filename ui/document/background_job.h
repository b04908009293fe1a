#pragma once
// One long job at a time on a thread of its own, with cancel, as the extraction and the camera
// calibration run: the GUI thread starts it and stays free; what the job reports is queued back
// to the GUI thread, and nothing arrives from a job that was cancelled (Cancel returns the UI to
// idle at once, the thread finishes on its own and is joined when the runner goes).
#include <QObject>
#include <atomic>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace demoplan::ui {

class BackgroundJob : public QObject {
  Q_OBJECT
public:
  explicit BackgroundJob(QObject* parent = nullptr);
  ~BackgroundJob() override;  // cancels the job and waits for its thread
  bool isRunning() const { return running_; }
  void cancel();

signals:
  void started();
  void cancelled();

protected:
  // Runs `work` on a new thread; false when a job is running. `post(f)` runs f on the GUI thread
  // unless the job was cancelled by then; `cancel` is for the work to check.
  using Post = std::function<void(std::function<void()>)>;
  bool run(std::function<void(const Post& post, const std::atomic<bool>& cancel)> work);
  // Called by the job's last posted function: the job is over.
  void finish() { running_ = false; }

private:
  bool running_ = false;
  int generation_ = 0;
  std::shared_ptr<std::atomic<bool>> cancel_;
  std::vector<std::thread> threads_;
};

}  // namespace demoplan::ui
