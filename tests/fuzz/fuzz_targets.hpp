#pragma once
// Every fuzz target, as an ordinary function: libFuzzer calls one of them per
// binary (libfuzzer_main.cpp), and fuzz_replay_test calls each on its saved
// inputs (corpus/<name>/, regressions/<name>/). A target returns 0 for any
// input; it throws or aborts only on a finding: an exception the parser does
// not document, a broken invariant, or what a sanitizer reports.

#include <cstddef>
#include <cstdint>

namespace playerkit::fuzz {

int frame_reader(const std::uint8_t* data, std::size_t size);
int config_parser(const std::uint8_t* data, std::size_t size);
int player_log_reader(const std::uint8_t* data, std::size_t size);
int carmen_log_reader(const std::uint8_t* data, std::size_t size);
int map_yaml(const std::uint8_t* data, std::size_t size);
int map_image(const std::uint8_t* data, std::size_t size);
int world_file(const std::uint8_t* data, std::size_t size);
int p2os_sip(const std::uint8_t* data, std::size_t size);
int sick_telegram(const std::uint8_t* data, std::size_t size);
int json_line(const std::uint8_t* data, std::size_t size);
int log_input(const std::uint8_t* data, std::size_t size);

// A broken invariant: says which and aborts (a crash for libFuzzer, a dead
// test program for ctest, both naming the target).
[[noreturn]] void invariant_failed(const char* target, const char* what);

}  // namespace playerkit::fuzz
