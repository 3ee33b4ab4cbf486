#include "links/can/can_bus.hpp"

#include "links/exchange.hpp"

namespace playerkit::links::can {

namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

ReplyMatch acknowledgement(std::span<const std::uint8_t> telegram) {
  const std::string_view text = slcan_text(telegram);
  if (text.empty()) return ReplyMatch::mine;
  if (text == std::string_view(&kSlcanRefusal, 1)) return ReplyMatch::refusal;
  return ReplyMatch::not_mine;  // a frame still arriving from before
}

}  // namespace

CanBus::CanBus(ByteLink& link, CanTransport transport)
    : link_(link),
      transport_(transport),
      reader_(link, transport == CanTransport::slcan ? static_cast<const framing::FrameFormat&>(slcan_format_)
                                                     : static_cast<const framing::FrameFormat&>(record_format_),
              transport == CanTransport::slcan ? kLongestSlcanLine : framing::kCanRecordSize) {}

void CanBus::start(int bitrate, std::chrono::milliseconds timeout, std::function<bool()> stopping) {
  if (transport_ != CanTransport::slcan) return;
  const auto rate = slcan_bitrate_command(bitrate);
  if (!rate) throw ExchangeError(ExchangeFailure::refused, "slcan knows no bit rate of " + std::to_string(bitrate));
  Exchanger exchanger(reader_, std::move(stopping), "the slcan adapter on " + link_.describe());
  // CRs first end whatever was half typed; C closes a channel left open
  // (refused by an adapter whose channel is closed: either answer will do).
  (void)exchanger.try_exchange({.name = "C (close)", .bytes = bytes_of("\r\r" + kSlcanClose),
                                .matcher = [](std::span<const std::uint8_t> telegram) {
                                  return acknowledgement(telegram) == ReplyMatch::not_mine ? ReplyMatch::not_mine
                                                                                           : ReplyMatch::mine;
                                },
                                .timeout = timeout});
  (void)exchanger.exchange(
      {.name = rate->substr(0, 2) + " (bit rate)", .bytes = bytes_of(*rate), .matcher = acknowledgement, .timeout = timeout});
  (void)exchanger.exchange(
      {.name = "O (open)", .bytes = bytes_of(kSlcanOpen), .matcher = acknowledgement, .timeout = timeout});
}

void CanBus::stop() noexcept {
  if (transport_ != CanTransport::slcan) return;
  try {
    const auto close = bytes_of(kSlcanClose);
    link_.write_all(close, deadline_in(std::chrono::milliseconds(200)));
  } catch (...) {
    // The adapter has gone: its channel closes with it.
  }
}

void CanBus::send(const framing::CanFrame& frame, Deadline deadline) {
  if (transport_ == CanTransport::slcan) {
    const std::string line = slcan_frame_line(frame);
    link_.write_all(std::span(reinterpret_cast<const std::uint8_t*>(line.data()), line.size()), deadline);
  } else {
    const auto record = framing::encode_can_frame(frame);
    link_.write_all(record, deadline);
  }
}

std::optional<framing::CanFrame> CanBus::receive(Deadline deadline) {
  for (;;) {
    auto telegram = reader_.next(deadline);
    if (!telegram) return std::nullopt;
    if (transport_ == CanTransport::socketcan) {
      if (auto frame = framing::decode_can_frame(*telegram)) return frame;
      continue;
    }
    const std::string_view text = slcan_text(*telegram);
    if (auto frame = parse_slcan_frame(text)) return frame;
    if (text == std::string_view(&kSlcanRefusal, 1)) ++refusals_;
  }
}

}  // namespace playerkit::links::can
