#include "ui/document/calibration_runner.h"

#include "perception/camera/charuco_board.h"

namespace demoplan::ui {

bool CalibrationRunner::start(const std::string& source, const std::string& board_file) {
  return run([this, source, board_file](const Post& post, const std::atomic<bool>& cancel) {
    auto outcome = std::make_shared<CalibrationOutcome>();
    try {
      const perception::CharucoBoard board = perception::load_charuco_board(board_file);
      perception::CharucoCalibrationOptions options;
      options.cancel = &cancel;
      options.progress = [&](int done, int total) { post([this, done, total] { emit progress(done, total); }); };
      outcome->calibration = perception::calibrate_charuco(source, board, options);
      outcome->ok = !outcome->calibration.cancelled;
    } catch (const std::exception& e) {
      outcome->error = e.what();
    }
    post([this, outcome] {
      finish();
      emit finished(*outcome);
    });
  });
}

}  // namespace demoplan::ui
