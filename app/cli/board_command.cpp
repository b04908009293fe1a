// demoplan-cli board: a ChArUco calibration board, as a file for `calibrate` and a page to print
// at true scale (issue 15).
#include <algorithm>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "core/error.h"
#include "perception/camera/charuco_board.h"

namespace demoplan::cli {

namespace {

struct BoardCliOptions {
  std::string squares = "7x5", dictionary = "DICT_5X5_100", out, image;
  double square_mm = 30, marker_mm = 22, dpi = 300;
  int first_id = 0;
  bool json = false;
};

// The option a board field comes from, for the error message.
std::string option_of(const std::string& field) {
  if (field == "squares_x" || field == "squares_y") return "--squares";
  if (field == "square_length") return "--square-mm";
  if (field == "marker_length") return "--marker-mm";
  if (field == "first_id") return "--first-id";
  return "--" + field;
}

int run_board(const BoardCliOptions& o) {
  perception::CharucoBoard b;
  const size_t x = o.squares.find_first_of("xX");
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    size_t used = 0;
    b.squares_x = std::stoi(o.squares.substr(0, x), &used);
    if (used != x) throw std::invalid_argument("junk");
    const std::string rows = o.squares.substr(x + 1);
    b.squares_y = std::stoi(rows, &used);
    if (used != rows.size()) throw std::invalid_argument("junk");
  } catch (const std::exception&) {
    throw InputError(o.out, "--squares", "'" + o.squares + "' is not COLUMNSxROWS, e.g. 7x5");
  }
  b.square_length = o.square_mm / 1000;
  b.marker_length = o.marker_mm / 1000;
  b.dictionary = o.dictionary;
  b.first_id = o.first_id;
  perception::validate(b, [&](const std::string& field, const std::string& reason) {
    throw InputError(o.out, option_of(field), reason);
  });
  // A page beyond A0 at the DPI asked for is surely a unit mistake (metres for mm).
  const double page_mm = std::max(b.width(), b.height()) * 1000 + 2 * perception::kPrintMarginMm + perception::kPrintFooterMm;
  if (!o.image.empty() && page_mm > 1200)
    throw InputError(o.out, "--square-mm", "the page would be " + std::to_string(int(page_mm)) +
                                               " mm long; larger than A0 (1189 mm): are the sizes in mm?");
  perception::save_charuco_board(o.out, b);
  cv::Size image_size;
  if (!o.image.empty()) {
    perception::save_printable_board(o.image, b, o.dpi);
    image_size = perception::printable_board(b, o.dpi).image.size();
  }
  std::cerr << "ChArUco board " << b.squares_x << " x " << b.squares_y << " squares of " << o.square_mm
            << " mm, markers " << o.marker_mm << " mm, " << b.dictionary << " ids " << b.first_id << "-"
            << b.first_id + b.marker_count() - 1 << " (" << b.corner_count() << " corners)\n"
            << "  board file  " << o.out << "\n";
  if (!o.image.empty())
    std::cerr << "  page        " << o.image << " (" << image_size.width << " x " << image_size.height << " px at "
              << o.dpi << " dpi): print at 100 % and check the 50 mm scale bar\n";
  if (o.json) {
    nlohmann::json j{{"board", o.out},
                     {"squares_x", b.squares_x},
                     {"squares_y", b.squares_y},
                     {"square_mm", o.square_mm},
                     {"marker_mm", o.marker_mm},
                     {"dictionary", b.dictionary},
                     {"first_id", b.first_id},
                     {"markers", b.marker_count()},
                     {"corners", b.corner_count()}};
    if (!o.image.empty()) j["image"] = o.image, j["dpi"] = o.dpi, j["image_size"] = {image_size.width, image_size.height};
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_board_command(CLI::App& app) {
  auto o = std::make_shared<BoardCliOptions>();
  CLI::App* sub = add_video_subcommand(app, "board");
  sub->add_option("--squares", o->squares, "squares as COLUMNSxROWS; ROWS must be odd")->capture_default_str();
  sub->add_option("--square-mm", o->square_mm, "side of a square, mm")->capture_default_str();
  sub->add_option("--marker-mm", o->marker_mm, "side of a marker, mm (smaller than a square)")->capture_default_str();
  sub->add_option("--dictionary", o->dictionary, "ArUco dictionary, e.g. DICT_5X5_100")->capture_default_str();
  sub->add_option("--first-id", o->first_id, "id of the first marker")->capture_default_str();
  sub->add_option("--out", o->out, "board file to write (demoplan-charuco-board JSON)")->required();
  sub->add_option("--image", o->image, "page to print, PNG at true scale");
  sub->add_option("--dpi", o->dpi, "resolution of the page")->check(CLI::Range(50.0, 1200.0))->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  return {sub, [o] { return run_board(*o); }};
}

}  // namespace demoplan::cli
