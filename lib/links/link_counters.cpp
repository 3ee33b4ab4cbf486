#include "links/link_counters.hpp"

namespace playerkit::links {

namespace {

std::string counted(std::uint64_t count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

}  // namespace

LinkCounterSnapshot operator-(const LinkCounterSnapshot& later, const LinkCounterSnapshot& earlier) {
  return {
      .bytes_in = later.bytes_in - earlier.bytes_in,
      .bytes_out = later.bytes_out - earlier.bytes_out,
      .telegrams = later.telegrams - earlier.telegrams,
      .checksum_errors = later.checksum_errors - earlier.checksum_errors,
      .resyncs = later.resyncs - earlier.resyncs,
      .bytes_dropped = later.bytes_dropped - earlier.bytes_dropped,
      .timeouts = later.timeouts - earlier.timeouts,
      .reconnects = later.reconnects - earlier.reconnects,
      .retries = later.retries - earlier.retries,
  };
}

std::string to_string(const LinkCounterSnapshot& counters) {
  return "in " + std::to_string(counters.bytes_in) + " B, out " + std::to_string(counters.bytes_out) + " B, " +
         counted(counters.telegrams, "telegram", "telegrams") + ", " +
         counted(counters.checksum_errors, "checksum error", "checksum errors") + ", " +
         counted(counters.resyncs, "resync", "resyncs") + " (" + std::to_string(counters.bytes_dropped) +
         " B dropped), " + counted(counters.timeouts, "timeout", "timeouts") + ", " +
         counted(counters.reconnects, "reconnect", "reconnects") + ", " +
         counted(counters.retries, "retry", "retries");
}

LinkCounterSnapshot LinkCounters::snapshot() const {
  return {
      .bytes_in = bytes_in.value(),
      .bytes_out = bytes_out.value(),
      .telegrams = telegrams.value(),
      .checksum_errors = checksum_errors.value(),
      .resyncs = resyncs.value(),
      .bytes_dropped = bytes_dropped.value(),
      .timeouts = timeouts.value(),
      .reconnects = reconnects.value(),
      .retries = retries.value(),
  };
}

}  // namespace playerkit::links
