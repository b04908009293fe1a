// demoplan-cli figure: the paper's Fig. 4 from `bench --out` files, as SVG or PNG. Rows are
// robots; columns success rate, planning time, path length and grasps; groups are tasks; one bar
// per planner found in the files, each planner in the same colour in every figure.
#include <QStringList>
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/bench_results.h"
#include "app/cli/command.h"
#include "app/cli/offscreen_gui.h"
#include "core/error.h"
#include "plot/bar_chart.h"
#include "plot/figure_file.h"
#include "plot/legend.h"
#include "plot/palette.h"

namespace demoplan::cli {

namespace {

struct FigureOptions {
  std::vector<std::string> files;
  std::string out, title;
  bool json = false;
};

struct Metric {
  const char* id;
  QString title, unit;
  int decimals;
};

const std::vector<Metric>& metrics() {
  static const std::vector<Metric> m{
      {"success_rate", QStringLiteral("Success rate"), QStringLiteral("% of runs solved and valid"), 0},
      {"planning_time", QStringLiteral("Planning time"), QStringLiteral("s, median (whiskers 25–75 %)"), 2},
      {"path_length", QStringLiteral("Path length"), QStringLiteral("rad, median"), 1},
      {"grasps", QStringLiteral("Number of grasps"), QStringLiteral("mean per solved run"), 1}};
  return m;
}

QString robot_label(const std::string& robot) {
  if (robot == "panda") return QStringLiteral("Panda");
  if (robot == "ur5") return QStringLiteral("UR5");
  if (robot == "kmr_iiwa") return QStringLiteral("KMR iiwa");
  return QString::fromStdString(robot);
}

plot::Bar bar(const BenchCell* c, size_t metric) {
  plot::Bar b;
  if (!c) return b;
  switch (metric) {
    case 0: b.value = 100.0 * c->success_rate; break;
    case 1: b.value = c->median_time_s, b.low = c->time_q1_s, b.high = c->time_q3_s; break;
    case 2: b.value = c->median_path_length_rad; break;
    default: b.value = c->mean_grasps; break;
  }
  return b;
}

// Panel and page geometry, in SVG units (PNG pixels at scale 1).
constexpr double kPanelW = 330, kPanelH = 250, kRowLabelW = 46, kMargin = 24;

int run_figure(const FigureOptions& o) {
  const QString out = QString::fromStdString(o.out);
  if (!plot::is_figure_file(out)) throw InputError("command line", "--out", "the figure's file must end in .svg or .png");
  const BenchResults results = read_bench_results(o.files);
  for (const auto& n : results.notes) std::cerr << "note: " << n << "\n";

  const OffscreenGui gui;  // fonts

  std::vector<QString> groups, series;
  for (const auto& t : results.tasks) groups.push_back(QString::fromStdString(t));
  for (const auto& p : results.planners) series.push_back(QString::fromStdString(p));
  const std::vector<QColor> colors = plot::series_colors(series);
  std::vector<plot::LegendEntry> legend;
  for (size_t i = 0; i < series.size(); ++i) legend.push_back({series[i], colors[i]});

  const size_t cols = metrics().size(), rows = results.robots.size();
  const double width = kMargin * 2 + kRowLabelW + kPanelW * static_cast<double>(cols);
  const QString title = o.title.empty() ? QStringLiteral("Planners on the guided-TAMP benchmark")
                                        : QString::fromStdString(o.title);
  QStringList files;
  for (const auto& f : results.files) files << QString::fromStdString(f).section(QLatin1Char('/'), -1);
  const QString subtitle = QStringLiteral("%1 runs · %2 task(s) × %3 robot(s) · %4")
                               .arg(results.runs).arg(results.tasks.size()).arg(rows).arg(files.join(QStringLiteral(", ")));
  const double legend_h = plot::legend_height(legend, width - 2 * kMargin, 12.5);
  const double header_h = 30 + 22 + legend_h + 12;
  const double footer_h = 30;
  const double height = kMargin + header_h + kPanelH * static_cast<double>(rows) + footer_h;

  int panels = 0;
  auto draw = [&](plot::Canvas& c) {
    panels = 0;
    c.text({kMargin, kMargin}, title, plot::TextStyle{.size = 18, .bold = true});
    c.text({kMargin, kMargin + 28}, subtitle, plot::TextStyle{.size = 11.5, .color = QColor(0x66, 0x66, 0x66)});
    c.beginGroup(QStringLiteral("legend"));
    plot::draw_legend(c, QRectF(kMargin, kMargin + 52, width - 2 * kMargin, legend_h), legend, 12.5);
    c.endGroup();
    for (size_t r = 0; r < rows; ++r) {
      const std::string& robot = results.robots[r];
      const double top = kMargin + header_h + kPanelH * static_cast<double>(r);
      // The robot's name left of its row, and a thin rule between rows.
      if (r > 0) c.line({kMargin, top - 6}, {width - kMargin, top - 6}, plot::Stroke{plot::kGridColor, 1});
      c.text({kMargin + 4, top + kPanelH / 2}, robot_label(robot),
             plot::TextStyle{.size = 15, .bold = true, .align = Qt::AlignHCenter | Qt::AlignTop, .vertical = true});
      for (size_t m = 0; m < cols; ++m) {
        const Metric& metric = metrics()[m];
        plot::BarChart chart;
        chart.title = metric.title;
        chart.y_label = metric.unit;
        chart.groups = groups;
        chart.series = series;
        chart.colors = colors;
        chart.decimals = metric.decimals;
        if (m == 0) chart.y_max = 100;
        for (const auto& task : results.tasks) {
          auto& g = chart.bars.emplace_back();
          for (const auto& planner : results.planners) g.push_back(bar(results.find(robot, task, planner), m));
        }
        c.beginGroup(QStringLiteral("panel-%1-%2").arg(QString::fromStdString(robot), QLatin1String(metric.id)));
        plot::draw_bar_chart(c, QRectF(kMargin + kRowLabelW + kPanelW * static_cast<double>(m), top, kPanelW - 14,
                                       kPanelH - 16), chart);
        c.endGroup();
        ++panels;
      }
    }
    c.text({kMargin, height - kMargin / 2}, QStringLiteral(
               "Success: solved within the time limit and valid by the benchmark's rules. Time, length and grasps over "
               "the successful runs; whiskers: 25–75 % of the planner's own times. \"+shortcut\": the shortened path "
               "(time includes shortcutting). –: no data."),
           plot::TextStyle{.size = 10, .color = QColor(0x77, 0x77, 0x77), .align = Qt::AlignLeft | Qt::AlignBottom});
  };
  const double scale = 2.0;
  const QString error = plot::save_figure(out, QSizeF(width, height), title, draw, scale);
  if (!error.isEmpty()) throw InputError(o.out, "", error.toStdString());
  const bool png = out.endsWith(QLatin1String(".png"), Qt::CaseInsensitive);
  const int w = static_cast<int>(std::lround(width * (png ? scale : 1))), h = static_cast<int>(std::lround(height * (png ? scale : 1)));
  std::cerr << "wrote " << o.out << ": " << panels << " panels (" << rows << " robot(s) x " << cols << " metrics), "
            << results.tasks.size() << " task(s), " << results.planners.size() << " planner(s), " << w << "x" << h
            << (png ? " px" : "") << "\n";
  if (o.json)
    std::cout << nlohmann::json{{"out", o.out}, {"panels", panels}, {"robots", results.robots},
                                {"tasks", results.tasks}, {"planners", results.planners},
                                {"width", w}, {"height", h}}.dump()
              << std::endl;
  return kOk;
}

}  // namespace

Command register_figure_command(CLI::App& app) {
  auto opts = std::make_shared<FigureOptions>();
  CLI::App* sub = app.add_subcommand("figure", "draw the paper's Fig. 4 from bench --out files (SVG or PNG)");
  sub->add_option("files", opts->files, "demoplan-bench JSON files (bench --out)")->required();
  sub->add_option("--out", opts->out, "the figure: FILE.svg or FILE.png")->required();
  sub->add_option("--title", opts->title, "the figure's title");
  sub->add_flag("--json", opts->json, "print {\"out\", \"panels\", \"robots\", \"planners\", ...} on stdout");
  return {sub, [opts] { return run_figure(*opts); }};
}

}  // namespace demoplan::cli
