#include "view/frame_json.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace playerkit::view {
namespace {

using nlohmann::json;

// A millimetre is finer than any pixel the page draws; shorter numbers keep
// frames small when many pages are open.
double mm(double metres) { return std::isfinite(metres) ? std::round(metres * 1000.0) / 1000.0 : 0.0; }

json flat(const std::vector<Point>& points) {
  json out = json::array();
  for (const auto& point : points) {
    out.push_back(mm(point.x));
    out.push_back(mm(point.y));
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    std::uint32_t group = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (left > 1) group |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[i + 1])) << 8;
    if (left > 2) group |= static_cast<std::uint8_t>(bytes[i + 2]);
    out += kDigits[(group >> 18) & 63];
    out += kDigits[(group >> 12) & 63];
    out += left > 1 ? kDigits[(group >> 6) & 63] : '=';
    out += left > 2 ? kDigits[group & 63] : '=';
  }
  return out;
}

}  // namespace

std::string colour_text(Colour colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", colour.r, colour.g, colour.b);
  return text;
}

std::string frame_json(const Frame& frame) {
  json out{{"type", "frame"}, {"centre", {mm(frame.centre.x), mm(frame.centre.y)}}};
  json& areas = out["areas"] = json::array();
  for (const auto& area : frame.areas) areas.push_back({{"fill", colour_text(area.fill)}, {"points", flat(area.points)}});
  json& lines = out["lines"] = json::array();
  for (const auto& line : frame.lines) {
    lines.push_back({{"colour", colour_text(line.colour)}, {"points", flat(line.points)}});
  }
  json& dots = out["dots"] = json::array();
  for (const auto& group : frame.dots) {
    dots.push_back(
        {{"colour", colour_text(group.colour)}, {"radius", group.radius_pixels}, {"points", flat(group.points)}});
  }
  json& ellipses = out["ellipses"] = json::array();
  for (const auto& e : frame.ellipses) {
    ellipses.push_back({{"centre", {mm(e.centre.x), mm(e.centre.y)}},
                        {"a", mm(e.semi_major)},
                        {"b", mm(e.semi_minor)},
                        {"angle", mm(e.angle)},
                        {"colour", colour_text(e.colour)}});
  }
  json& bodies = out["bodies"] = json::array();
  for (const auto& body : frame.bodies) {
    bodies.push_back({{"pose", {mm(body.pose.x), mm(body.pose.y), mm(body.pose.yaw)}},
                      {"length", mm(body.length)},
                      {"width", mm(body.width)},
                      {"colour", colour_text(body.colour)},
                      {"filled", body.filled}});
  }
  json& labels = out["labels"] = json::array();
  for (const auto& label : frame.labels) {
    labels.push_back(
        {{"at", {mm(label.at.x), mm(label.at.y)}}, {"text", label.text}, {"colour", colour_text(label.colour)}});
  }
  json& legend = out["legend"] = json::array();
  for (const auto& entry : frame.legend) legend.push_back({{"text", entry.text}, {"colour", colour_text(entry.colour)}});
  return out.dump();
}

std::string map_json(const grid::OccupancyGrid& map) {
  std::string cells;
  cells.reserve(map.cells().size());
  for (const auto state : map.cells()) cells += static_cast<char>(static_cast<int>(state) + 1);
  return json{{"type", "map"},
              {"width", map.width()},
              {"height", map.height()},
              {"resolution", map.resolution()},
              {"origin", {map.origin().x(), map.origin().y()}},
              {"cells", base64(cells)}}
      .dump();
}

}  // namespace playerkit::view
