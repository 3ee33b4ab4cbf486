#pragma once
// How player-cat and player-log print a data message: human text, JSON lines, CSV, or the
// lines of a Player 1.5 text log. Formatters only write; the caller decodes
// the message, checks --field and watches its streams.
//
//   text  laser:0 t=1086000000.250000 max_angle=9000 min_angle=-9000 ... ranges=[1000,1500]
//   json  {"data":{...},"device":"laser","index":0,"time":...,"timestamp":...,"type":"data"}
//   csv   time,timestamp,device,index,max_angle,...,ranges.0,ranges.1
//   log   1086000000.250 localhost 6665 laser 00 1086000000.200 -1.5708 ...

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "client/endpoint.hpp"
#include "field_path.hpp"
#include "protocol/message.hpp"

namespace playerkit::tools {

// -t as in candump: absolute, delta since the previous line, zero-based.
enum class TimeStyle { kAbsolute, kDelta, kZero };

// The time a line shows for a message, by -t.
class TimeColumn {
 public:
  explicit TimeColumn(TimeStyle style) : style_(style) {}
  // Call once per printed line, in order.
  double next(protocol::Timestamp time);

 private:
  TimeStyle style_;
  std::optional<double> first_;
  std::optional<double> previous_;
};

// "%.6f": times keep their microseconds.
std::string format_seconds(double seconds);

struct DataRecord {
  const protocol::Message& message;
  const nlohmann::json& json;  // message_to_json (or _si_json): type, device, index, time, timestamp, data
  double shown_time;           // by -t
};

// A CSV row that does not fit the header written from the device's first message.
class CsvShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Formatter {
 public:
  virtual ~Formatter() = default;
  // Writes one line (or row) for a data message and flushes it.
  virtual void data(const DataRecord& record) = 0;
  // The SYNCH that ends a data round.
  virtual void synch(const protocol::Message& /*synch*/) {}
};

std::unique_ptr<Formatter> make_text_formatter(std::ostream& out, std::vector<FieldPath> fields);
std::unique_ptr<Formatter> make_json_formatter(std::ostream& out, std::vector<FieldPath> fields);
// Writes the log header at once; a "sync" line for each SYNCH once data has been written.
std::unique_ptr<Formatter> make_log_formatter(std::ostream& out, client::ServerEndpoint server);
// One CSV table per device, each to its own stream. Throws CsvShapeError.
std::unique_ptr<Formatter> make_csv_formatter(std::map<protocol::DeviceAddress, std::ostream*> sinks,
                                              std::vector<FieldPath> fields);

// The data columns of a record, as text and CSV show them: every field (CSV
// flattens arrays, text keeps them whole) or just the --field ones.
std::vector<NamedValue> data_columns(const nlohmann::json& data, const std::vector<FieldPath>& fields,
                                     bool flatten_arrays);

// One CSV cell: numbers and booleans as JSON writes them, strings quoted when
// they must be (RFC 4180), null as an empty cell.
std::string csv_cell(const nlohmann::json& value);

}  // namespace playerkit::tools
