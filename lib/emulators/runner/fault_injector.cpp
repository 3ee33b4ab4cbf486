#include "emulators/runner/fault_injector.hpp"

namespace playerkit::emulators {

FaultInjector::FaultInjector(FaultPlan plan) : plan_(plan), random_(plan.seed) {}

bool FaultInjector::happens(double probability) {
  if (probability <= 0.0) return false;
  return std::uniform_real_distribution<double>(0.0, 1.0)(random_) < probability;
}

std::vector<std::vector<std::uint8_t>> FaultInjector::apply(const Telegram& telegram) {
  std::vector<std::vector<std::uint8_t>> chunks;
  if (happens(plan_.garbage)) {
    const auto count = std::uniform_int_distribution<std::size_t>(1, 16)(random_);
    std::vector<std::uint8_t> noise(count);
    for (auto& byte : noise) byte = static_cast<std::uint8_t>(std::uniform_int_distribution<int>(0, 255)(random_));
    chunks.push_back(std::move(noise));
    ++counts_.garbage_runs;
  }
  std::vector<std::uint8_t> bytes = telegram.bytes;
  if (telegram.has_checksum && !bytes.empty() && happens(plan_.bad_checksum)) {
    bytes.back() = static_cast<std::uint8_t>(bytes.back() ^ 0x5A);
    ++counts_.bad_checksums;
  }
  if (bytes.size() > 1 && happens(plan_.truncate)) {
    bytes.resize(std::uniform_int_distribution<std::size_t>(1, bytes.size() - 1)(random_));
    ++counts_.truncated;
  }
  if (!bytes.empty()) chunks.push_back(std::move(bytes));
  if (plan_.drop > 0.0) {
    // Per byte, garbage included: the line loses bytes, it does not know telegrams.
    for (auto& chunk : chunks) {
      std::erase_if(chunk, [this](std::uint8_t) {
        const bool lost = happens(plan_.drop);
        if (lost) ++counts_.dropped_bytes;
        return lost;
      });
    }
    std::erase_if(chunks, [](const std::vector<std::uint8_t>& chunk) { return chunk.empty(); });
  }
  return chunks;
}

std::string describe(const InjectedFaults& faults) {
  std::string text;
  const auto item = [&text](std::uint64_t count, const char* what) {
    if (count > 0) text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
  };
  item(faults.bad_checksums, "bad checksums");
  item(faults.garbage_runs, "garbage runs");
  item(faults.truncated, "truncated");
  item(faults.dropped_bytes, "bytes dropped");
  item(faults.dropped_while_dead, "dropped while the line was dead");
  return text;
}

}  // namespace playerkit::emulators
