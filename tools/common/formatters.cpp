#include "formatters.hpp"

#include <cstdio>
#include <unordered_map>
#include <utility>

#include "log/text_log_writer.hpp"

namespace playerkit::tools {
namespace {

std::string device_name(const protocol::Message& message) { return protocol::to_string(message.device()); }

class TextFormatter final : public Formatter {
 public:
  TextFormatter(std::ostream& out, std::vector<FieldPath> fields) : out_(out), fields_(std::move(fields)) {}

  void data(const DataRecord& record) override {
    std::string line = device_name(record.message);
    line += " t=";
    line += format_seconds(record.shown_time);
    for (const auto& [name, value] : data_columns(record.json.at("data"), fields_, false)) {
      line += ' ';
      line += name;
      line += '=';
      line += value.dump();
    }
    line += '\n';
    out_ << line << std::flush;
  }

 private:
  std::ostream& out_;
  std::vector<FieldPath> fields_;
};

class JsonFormatter final : public Formatter {
 public:
  JsonFormatter(std::ostream& out, std::vector<FieldPath> fields) : out_(out), fields_(std::move(fields)) {}

  void data(const DataRecord& record) override {
    nlohmann::json line = record.json;
    line["time"] = record.shown_time;
    if (!fields_.empty()) {
      nlohmann::json kept = nlohmann::json::object();
      for (auto& [name, value] : select_fields(record.json.at("data"), fields_))
        kept[name] = std::move(value);
      line["data"] = std::move(kept);
    }
    out_ << line.dump() << '\n' << std::flush;
  }

 private:
  std::ostream& out_;
  std::vector<FieldPath> fields_;
};

class LogFormatter final : public Formatter {
 public:
  LogFormatter(std::ostream& out, client::ServerEndpoint server) : out_(out), server_(std::move(server)) {
    out_ << log::log_file_header() << std::flush;
  }

  void data(const DataRecord& record) override {
    out_ << log::format_data_line(record.message, server_.host, server_.port) << std::flush;
    wrote_data_ = true;
  }

  // readlog paces its replay by sync lines, as writelog wrote one per cycle.
  void synch(const protocol::Message& synch) override {
    if (!wrote_data_) return;
    out_ << log::format_sync_line(synch.time().seconds(), server_.host, server_.port) << std::flush;
  }

 private:
  std::ostream& out_;
  client::ServerEndpoint server_;
  bool wrote_data_ = false;
};

// One device's CSV: the header comes from its first message and stays.
class CsvTable {
 public:
  explicit CsvTable(std::ostream& out) : out_(out) {}

  void write(const DataRecord& record, const std::vector<NamedValue>& data_cells) {
    std::vector<NamedValue> cells{
        {"time", format_seconds(record.shown_time)},
        {"timestamp", format_seconds(record.message.timestamp().seconds())},
        {"device", record.json.at("device")},
        {"index", record.json.at("index")},
    };
    cells.insert(cells.end(), data_cells.begin(), data_cells.end());
    if (columns_.empty()) write_header(cells);

    std::vector<const nlohmann::json*> row(columns_.size(), nullptr);
    for (const auto& [name, value] : cells) {
      const auto column = column_of_.find(name);
      if (column == column_of_.end()) {
        throw CsvShapeError(device_name(record.message) + ": column '" + name +
                            "' is not in the CSV header written from the device's first message "
                            "(its data changed shape); use --format json, or --field to choose columns");
      }
      row[column->second] = &value;
    }
    std::string line;
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i > 0) line += ',';
      if (row[i]) line += csv_cell(*row[i]);
    }
    out_ << line << '\n' << std::flush;
  }

 private:
  void write_header(const std::vector<NamedValue>& cells) {
    std::string line;
    for (const auto& [name, value] : cells) {
      if (!columns_.empty()) line += ',';
      column_of_.emplace(name, columns_.size());
      columns_.push_back(name);
      line += csv_cell(name);
    }
    out_ << line << '\n';
  }

  std::ostream& out_;
  std::vector<std::string> columns_;
  std::unordered_map<std::string, std::size_t> column_of_;
};

class CsvFormatter final : public Formatter {
 public:
  CsvFormatter(const std::map<protocol::DeviceAddress, std::ostream*>& sinks, std::vector<FieldPath> fields)
      : fields_(std::move(fields)) {
    for (const auto& [device, out] : sinks) tables_.emplace(device, CsvTable(*out));
  }

  void data(const DataRecord& record) override {
    const auto table = tables_.find(record.message.device());
    if (table == tables_.end()) {
      throw std::logic_error("CSV: no output for " + device_name(record.message));
    }
    table->second.write(record, data_columns(record.json.at("data"), fields_, true));
  }

 private:
  std::vector<FieldPath> fields_;
  std::map<protocol::DeviceAddress, CsvTable> tables_;
};

}  // namespace

double TimeColumn::next(protocol::Timestamp time) {
  const double seconds = time.seconds();
  if (!first_) first_ = seconds;
  double shown = seconds;
  if (style_ == TimeStyle::kZero) shown = seconds - *first_;
  if (style_ == TimeStyle::kDelta) shown = previous_ ? seconds - *previous_ : 0.0;
  previous_ = seconds;
  return shown;
}

std::string format_seconds(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", seconds);
  return text;
}

std::vector<NamedValue> data_columns(const nlohmann::json& data, const std::vector<FieldPath>& fields,
                                     bool flatten_arrays) {
  std::vector<NamedValue> columns;
  if (fields.empty()) {
    if (flatten_arrays) return flatten(data);
    if (!data.is_object()) return {{"data", data}};
    for (const auto& [key, value] : data.items()) columns.emplace_back(key, value);
    return columns;
  }
  for (auto& [name, value] : select_fields(data, fields)) {
    if (flatten_arrays && value.is_structured()) {
      auto leaves = flatten(value, name);
      columns.insert(columns.end(), std::make_move_iterator(leaves.begin()),
                     std::make_move_iterator(leaves.end()));
    } else {
      columns.emplace_back(std::move(name), std::move(value));
    }
  }
  return columns;
}

std::string csv_cell(const nlohmann::json& value) {
  if (value.is_null()) return {};
  if (!value.is_string()) return value.dump();
  const auto& text = value.get_ref<const std::string&>();
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

std::unique_ptr<Formatter> make_text_formatter(std::ostream& out, std::vector<FieldPath> fields) {
  return std::make_unique<TextFormatter>(out, std::move(fields));
}

std::unique_ptr<Formatter> make_json_formatter(std::ostream& out, std::vector<FieldPath> fields) {
  return std::make_unique<JsonFormatter>(out, std::move(fields));
}

std::unique_ptr<Formatter> make_log_formatter(std::ostream& out, client::ServerEndpoint server) {
  return std::make_unique<LogFormatter>(out, std::move(server));
}

std::unique_ptr<Formatter> make_csv_formatter(std::map<protocol::DeviceAddress, std::ostream*> sinks,
                                              std::vector<FieldPath> fields) {
  return std::make_unique<CsvFormatter>(sinks, std::move(fields));
}

}  // namespace playerkit::tools
