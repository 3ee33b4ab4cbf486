#include "sweep_spec.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "exit_status.hpp"

namespace playerkit::amcl_offline {
namespace sweep_spec_detail {

// ordered_json: the grid's axes keep the spec's order (the run ids and the
// table's columns follow it).
using Json = nlohmann::ordered_json;

class SpecReader {
 public:
  explicit SpecReader(std::string source, std::filesystem::path base) : source_(std::move(source)), base_(std::move(base)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw tools::UsageError(source_ + ": " + field + ": " + message);
  }

  void only_fields(const Json& object, const std::string& where, std::initializer_list<const char*> known) const {
    for (const auto& item : object.items()) {
      if (std::none_of(known.begin(), known.end(), [&](const char* name) { return item.key() == name; })) {
        fail(where + "." + item.key(), "unknown field");
      }
    }
  }

  std::string text(const Json& value, const std::string& field) const {
    if (!value.is_string() || value.get<std::string>().empty()) fail(field, "must be a non-empty string");
    return value.get<std::string>();
  }

  std::uint64_t count(const Json& value, const std::string& field) const {
    if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0)) {
      fail(field, "must be a non-negative integer");
    }
    return value.get<std::uint64_t>();
  }

  // Made absolute here, not by the jobs: they may run anywhere.
  std::filesystem::path path(const Json& value, const std::string& field) const {
    const std::filesystem::path given = text(value, field);
    return (given.is_absolute() ? given : std::filesystem::absolute(base_ / given)).lexically_normal();
  }

  SweepStart start(const Json& value, const std::string& field) const {
    const std::string name = text(value, field);
    if (name == "truth") return SweepStart::truth;
    if (name == "global") return SweepStart::global;
    fail(field, "must be \"truth\" or \"global\", not \"" + name + "\"");
  }

  SweepLog log(const Json& entry, const std::string& where, SweepStart default_start) const {
    if (!entry.is_object()) fail(where, "must be an object with log, map (and name, truth, ...)");
    only_fields(entry, where, {"name", "log", "map", "truth", "scale", "negate", "origin", "perturb_seed", "start"});
    SweepLog result;
    if (!entry.contains("log")) fail(where + ".log", "missing");
    if (!entry.contains("map")) fail(where + ".map", "missing");
    result.log = path(entry["log"], where + ".log");
    result.map = path(entry["map"], where + ".map");
    result.truth = entry.contains("truth") ? path(entry["truth"], where + ".truth") : result.log;
    if (entry.contains("name")) {
      result.name = text(entry["name"], where + ".name");
    } else {
      // "orebro-corrected.log.gz" -> "orebro-corrected"
      result.name = result.log.filename().string();
      result.name = result.name.substr(0, result.name.find('.'));
    }
    const bool plain = !result.name.empty() && std::all_of(result.name.begin(), result.name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '.';
    });
    if (!plain) fail(where + ".name", "\"" + result.name + "\": only letters, digits, '-' and '.' (it names files)");
    if (entry.contains("scale")) {
      if (!entry["scale"].is_number()) fail(where + ".scale", "must be a number (metres per pixel)");
      result.scale = entry["scale"].get<double>();
    }
    if (entry.contains("negate")) {
      if (!entry["negate"].is_boolean()) fail(where + ".negate", "must be true or false");
      result.negate = entry["negate"].get<bool>();
    }
    if (entry.contains("origin")) result.origin = text(entry["origin"], where + ".origin");
    if (entry.contains("perturb_seed")) result.perturb_seed = count(entry["perturb_seed"], where + ".perturb_seed");
    result.start = entry.contains("start") ? start(entry["start"], where + ".start") : default_start;
    return result;
  }

  // A value as localize's command line takes it: 0.1 -> "0.1", "100,5000" as is.
  std::string parameter_value(const std::string& name, const Json& value, const std::string& field) const {
    if (is_boolean_sweep_parameter(name)) {
      if (!value.is_boolean()) fail(field, "must be true or false (--" + name + " is a flag)");
      return value.get<bool>() ? "true" : "false";
    }
    if (value.is_string()) return text(value, field);
    if (value.is_number()) return value.dump();
    fail(field, "must be a number or a string");
  }

  SweepParameter parameter(const std::string& key, const Json& values) const {
    const std::string field = "parameters." + key;
    std::string name = key;
    if (name.starts_with("--")) name = name.substr(2);
    const auto& known = sweep_parameter_names();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(field, "not a localize flag a sweep may vary (" + list + ")");
    }
    if (!values.is_array() || values.empty()) fail(field, "must be a non-empty list of values");
    SweepParameter result{name, {}};
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::string at = field + "[" + std::to_string(i) + "]";
      std::string value = parameter_value(name, values[i], at);
      if (std::find(result.values.begin(), result.values.end(), value) != result.values.end()) fail(at, "repeats " + value);
      result.values.push_back(std::move(value));
    }
    return result;
  }

  SweepSpec spec(const Json& root) const {
    if (!root.is_object()) fail("(top)", "must be an object with logs, parameters and seeds");
    only_fields(root, "(top)", {"logs", "start", "parameters", "seeds"});
    SweepSpec result;
    const SweepStart default_start = root.contains("start") ? start(root["start"], "start") : SweepStart::truth;
    if (!root.contains("logs") || !root["logs"].is_array() || root["logs"].empty()) fail("logs", "must be a non-empty list");
    for (std::size_t i = 0; i < root["logs"].size(); ++i) {
      const std::string where = "logs[" + std::to_string(i) + "]";
      result.logs.push_back(log(root["logs"][i], where, default_start));
      for (std::size_t j = 0; j < i; ++j) {
        if (result.logs[j].name == result.logs[i].name) fail(where + ".name", "\"" + result.logs[i].name + "\" is also logs[" + std::to_string(j) + "]'s name");
      }
    }
    if (root.contains("parameters")) {
      if (!root["parameters"].is_object()) fail("parameters", "must be an object: flag name -> list of values");
      for (const auto& item : root["parameters"].items()) {
        SweepParameter axis = parameter(item.key(), item.value());
        for (const auto& other : result.parameters) {
          if (other.name == axis.name) fail("parameters." + item.key(), "given twice");
        }
        result.parameters.push_back(std::move(axis));
      }
    }
    if (!root.contains("seeds")) {
      result.seeds = {0};  // localize's default seed
    } else {
      if (!root["seeds"].is_array() || root["seeds"].empty()) fail("seeds", "must be a non-empty list of integers");
      for (std::size_t i = 0; i < root["seeds"].size(); ++i) {
        const std::string at = "seeds[" + std::to_string(i) + "]";
        const std::uint64_t seed = count(root["seeds"][i], at);
        if (std::find(result.seeds.begin(), result.seeds.end(), seed) != result.seeds.end()) fail(at, "repeats " + std::to_string(seed));
        result.seeds.push_back(seed);
      }
    }
    return result;
  }

 private:
  std::string source_;
  std::filesystem::path base_;
};

// nlohmann reports a byte offset; an editor wants line and column.
std::string position_of(std::string_view text, std::size_t byte) {
  byte = std::min(byte, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < byte; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace sweep_spec_detail

const std::vector<std::string>& sweep_parameter_names() {
  static const std::vector<std::string> names{"particles",  "model",      "laser-beams",   "alpha-slow",
                                              "alpha-fast", "odom-noise", "update-thresh", "sigma-hit",
                                              "init-var",   "every-reading"};
  return names;
}

bool is_boolean_sweep_parameter(std::string_view name) { return name == "every-reading"; }

SweepSpec parse_sweep_spec(std::string_view text, const std::string& source, const std::filesystem::path& base_dir) {
  sweep_spec_detail::Json root;
  try {
    root = sweep_spec_detail::Json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ...": keep the reason.
    std::string reason = e.what();
    if (const auto colon = reason.find(": "); colon != std::string::npos) reason = reason.substr(colon + 2);
    throw tools::UsageError(source + ":" + sweep_spec_detail::position_of(text, e.byte) + ": " + reason);
  }
  return sweep_spec_detail::SpecReader(source, base_dir).spec(root);
}

SweepSpec read_sweep_spec(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw tools::UsageError("cannot read the sweep spec " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return parse_sweep_spec(text.str(), file.string(), std::filesystem::absolute(file).parent_path());
}

}  // namespace playerkit::amcl_offline
