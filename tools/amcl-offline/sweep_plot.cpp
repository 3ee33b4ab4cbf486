// The plot of `sweep collect --plot`: enough to see which parameter value
// helps, not a plotting library. Drawn with OpenCV (core, imgproc) and
// encoded by lib/image, as lib/map's trajectory plots are.
#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "files/output_file.hpp"
#include "image/png.hpp"
#include "sweep_collect.hpp"

namespace playerkit::amcl_offline {
namespace sweep_plot_detail {

constexpr int kPanelWidth = 340, kPanelHeight = 260, kLeft = 56, kBottom = 46, kTop = 28, kLegend = 24;

const cv::Scalar kBlack(0, 0, 0), kGrey(200, 200, 200);
// BGR; logs beyond the eighth reuse them.
const cv::Scalar kLogColours[] = {{180, 119, 31}, {14, 127, 255}, {44, 160, 44}, {40, 39, 214},
                                  {189, 103, 148}, {75, 86, 140}, {194, 119, 227}, {34, 189, 188}};

void text(cv::Mat& image, const std::string& words, cv::Point at, const cv::Scalar& colour = kBlack) {
  cv::putText(image, words, at, cv::FONT_HERSHEY_SIMPLEX, 0.4, colour, 1, cv::LINE_AA);
}

// One panel: x the categories, y position RMSE from 0 to y_max.
void panel(cv::Mat& image, int left, const std::string& title, const std::vector<std::string>& categories,
           const std::vector<std::pair<std::size_t, std::size_t>>& points_category_log,
           const std::vector<double>& values, std::size_t logs, double y_max) {
  const int x0 = left + kLeft, x1 = left + kPanelWidth - 10, y0 = kTop + kPanelHeight - kBottom, y1 = kTop;
  cv::rectangle(image, {x0, y1}, {x1, y0}, kBlack, 1);
  text(image, "position RMSE (m) by " + title, {x0, y1 - 8});
  for (int tick = 0; tick <= 4; ++tick) {
    const int y = y0 - (y0 - y1) * tick / 4;
    if (tick > 0 && tick < 4) cv::line(image, {x0 + 1, y}, {x1 - 1, y}, kGrey, 1);
    std::ostringstream label;
    label << std::fixed << std::setprecision(3) << y_max * tick / 4;
    text(image, label.str(), {left + 6, y + 4});
  }
  const double step = static_cast<double>(x1 - x0) / static_cast<double>(categories.size());
  for (std::size_t c = 0; c < categories.size(); ++c) {
    const int centre = x0 + static_cast<int>(step * (static_cast<double>(c) + 0.5));
    text(image, categories[c].substr(0, 14), {centre - 4 * static_cast<int>(std::min<std::size_t>(categories[c].size(), 14)) + 4, y0 + 16});
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto [category, log] = points_category_log[i];
    // Logs side by side within a category, so their points do not hide each other.
    const double spread = logs > 1 ? (static_cast<double>(log) / static_cast<double>(logs - 1) - 0.5) * step * 0.5 : 0.0;
    const int x = x0 + static_cast<int>(step * (static_cast<double>(category) + 0.5) + spread);
    const int y = y0 - static_cast<int>((y0 - y1) * std::min(values[i] / y_max, 1.0));
    cv::circle(image, {x, y}, 4, kLogColours[log % std::size(kLogColours)], cv::FILLED, cv::LINE_AA);
  }
}

}  // namespace sweep_plot_detail

void write_sweep_plot(const SweepTable& table, const std::filesystem::path& png) {
  namespace detail = sweep_plot_detail;
  std::vector<std::string> logs;
  for (const auto& run : table.runs) {
    if (std::find(logs.begin(), logs.end(), run.log) == logs.end()) logs.push_back(run.log);
  }
  // The axes that vary; with none, the logs are the categories.
  std::vector<std::size_t> axes;
  for (std::size_t p = 0; p < table.parameters.size(); ++p) {
    std::vector<std::string> seen;
    for (const auto& run : table.runs) {
      if (std::find(seen.begin(), seen.end(), run.parameters[p]) == seen.end()) seen.push_back(run.parameters[p]);
    }
    if (seen.size() > 1) axes.push_back(p);
  }
  const std::size_t panels = std::max<std::size_t>(axes.size(), 1);
  double y_max = 0;
  for (const auto& run : table.runs) {
    if (run.status == SweepStatus::ok) y_max = std::max(y_max, run.position_rmse_m);
  }
  y_max = y_max > 0 ? y_max * 1.1 : 1.0;
  cv::Mat image(detail::kTop + detail::kPanelHeight + detail::kLegend, static_cast<int>(panels) * detail::kPanelWidth,
                CV_8UC3, cv::Scalar(255, 255, 255));
  for (std::size_t k = 0; k < panels; ++k) {
    std::vector<std::string> categories;
    std::vector<std::pair<std::size_t, std::size_t>> where;
    std::vector<double> values;
    for (const auto& run : table.runs) {
      const std::string& category = axes.empty() ? run.log : run.parameters[axes[k]];
      auto found = std::find(categories.begin(), categories.end(), category);
      if (found == categories.end()) found = categories.insert(categories.end(), category);
      if (run.status != SweepStatus::ok) continue;
      const auto log = static_cast<std::size_t>(std::find(logs.begin(), logs.end(), run.log) - logs.begin());
      where.emplace_back(static_cast<std::size_t>(found - categories.begin()), log);
      values.push_back(run.position_rmse_m);
    }
    detail::panel(image, static_cast<int>(k) * detail::kPanelWidth, axes.empty() ? "log" : "--" + table.parameters[axes[k]],
                  categories, where, values, logs.size(), y_max);
  }
  int x = 10;
  for (std::size_t l = 0; l < logs.size(); ++l) {
    const int y = detail::kTop + detail::kPanelHeight + detail::kLegend / 2;
    cv::circle(image, {x + 4, y - 4}, 4, detail::kLogColours[l % std::size(detail::kLogColours)], cv::FILLED, cv::LINE_AA);
    detail::text(image, logs[l], {x + 12, y});
    x += 20 + 8 * static_cast<int>(logs[l].size());
  }
  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  const auto encoded = playerkit::image::encode_png({rgb.data, rgb.total() * 3}, rgb.cols, rgb.rows, 3);
  files::OutputFile out(png, {.compression = files::Compression::kNone});
  out.stream().write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
  out.check();
  out.commit();
}

}  // namespace playerkit::amcl_offline
