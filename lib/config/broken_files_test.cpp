// One defect per file in tests/data/config/broken-*.cfg; each must be reported
// with the exact location and wording a user would see.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <string>
#include <utility>

#include "config/config_file.hpp"
#include "config/test_support.hpp"

namespace playerkit::config {
namespace broken_files_test {

using testing::data_path;
using testing::error_of;

struct BrokenFile {
  const char* file;
  // "{file}" stands for the broken file's absolute path, "{data}" for tests/data/config.
  const char* expected;
};

std::string expand(std::string text, const std::string& file) {
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"{file}", data_path(file)}, {"{data}", data_path()}}) {
    for (auto at = text.find(key); at != std::string::npos; at = text.find(key)) {
      text.replace(at, key.size(), value);
    }
  }
  return text;
}

class BrokenFiles : public ::testing::TestWithParam<BrokenFile> {};

TEST_P(BrokenFiles, ReportTheDefectWhereItIs) {
  const BrokenFile& broken = GetParam();
  EXPECT_EQ(error_of([&] { (void)ConfigFile::load(data_path(broken.file)); }),
            expand(broken.expected, broken.file));
}

constexpr BrokenFile kBrokenFiles[] = {
    {"broken-bad-character.cfg", "{file}:3:8: syntax error: unexpected character '='"},
    {"broken-unterminated-string.cfg",
     "{file}:3:8: unterminated string: missing closing '\"' on this line"},
    {"broken-unmatched-open.cfg",
     "{file}:2:9: unmatched '(': section 'laser:0' is not closed with ')'"},
    {"broken-unmatched-close.cfg", "{file}:3:3: unmatched ')'"},
    {"broken-value-next-line.cfg",
     "{file}:2:3: missing value for 'port': a property's value must be on the same line as its "
     "name"},
    {"broken-missing-paren.cfg",
     "{file}:1:8: syntax error: expected a value or '(' after 'laser:0', found newline"},
    {"broken-unquoted-string.cfg",
     "{file}:1:18: syntax error: expected a value or '(' after 'driver', found word 'sicklms200'"},
    {"broken-unknown-interface.cfg",
     "{file}:2:1: unknown interface 'lazer' (did you mean 'laser'?)"},
    {"broken-undeclarable-interface.cfg",
     "{file}:2:1: interface 'player' cannot be declared in a config file"},
    {"broken-unknown-driver.cfg",
     "{file}:3:10: unknown driver 'sicklms2000' for laser:0 (did you mean 'sicklms200'?)"},
    {"broken-bad-index.cfg",
     "{file}:1:1: invalid index 'x' in 'laser:x' (expected a number from 0 to 65535)"},
    {"broken-robot-without-port.cfg",
     "{file}:1:1: robot section without a port: auto-assigning ports is not supported (write "
     "robot:<port> or robot:<port>:<name>)"},
    {"broken-robot-port.cfg",
     "{file}:1:1: invalid port 'bob' in 'robot:bob' (expected a number from 1 to 65535)"},
    {"broken-include-missing.cfg",
     "{file}:2:9: cannot read include file 'includes/no-such-file.cfg': no such file (looked for "
     "{data}/includes/no-such-file.cfg)"},
    {"broken-include-cycle.cfg",
     "{data}/includes/back-to-broken.cfg:2:9: include cycle: broken-include-cycle.cfg -> "
     "back-to-broken.cfg -> broken-include-cycle.cfg"},
    {"broken-global-property.cfg",
     "{file}:2:1: property 'port' is outside any section (only unit_length and unit_angle may be "
     "set at global level)"},
    {"broken-unit-length.cfg",
     "{file}:1:13: unknown unit_length \"inch\" (expected \"m\", \"cm\" or \"mm\")"},
    {"broken-unit-angle.cfg",
     "{file}:2:12: unknown unit_angle \"grad\" (expected \"degrees\" or \"radians\")"},
    {"broken-exponent.cfg",
     "{file}:1:38: malformed number '5e-2': a number may only contain digits, '.', '+' and '-'"},
    {"broken-tuple-newline.cfg",
     "{file}:2:8: unmatched '[': the tuple of 'pose' must end with ']' on the same line"},
    {"broken-tuple-word.cfg",
     "{file}:1:20: syntax error: expected a number or a string in the tuple of 'pose', found word "
     "'zero'"},
    {"broken-glued-bracket.cfg",
     "{file}:1:20: syntax error: expected a property or a section, found number '0'"},
    {"broken-define-in-section.cfg", "{file}:2:3: 'define' is only allowed at global level"},
    {"broken-define-syntax.cfg",
     "{file}:1:17: syntax error: expected the type of macro 'pioneer2' after its name, found '('"},
    {"broken-macro-redefined.cfg", "{file}:2:8: macro 'pioneer2' is already defined at {file}:1:8"},
};

// "broken-bad-character.cfg" -> "BadCharacter"
std::string test_name(const ::testing::TestParamInfo<BrokenFile>& info) {
  std::string name;
  bool upper = true;
  for (const char c : std::string(info.param.file).substr(7)) {
    if (c == '.') break;
    if (c == '-') {
      upper = true;
    } else {
      name += upper ? static_cast<char>(c - 'a' + 'A') : c;
      upper = false;
    }
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Config, BrokenFiles, ::testing::ValuesIn(kBrokenFiles), test_name);

TEST(BrokenFilesSuite, CoversEveryBrokenFile) {
  std::size_t on_disk = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data_path())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("broken-", 0) != 0) continue;
    ++on_disk;
    const bool listed = std::any_of(std::begin(kBrokenFiles), std::end(kBrokenFiles),
                                    [&](const BrokenFile& b) { return name == b.file; });
    EXPECT_TRUE(listed) << name << " has no expected error";
  }
  EXPECT_EQ(on_disk, std::size(kBrokenFiles));
}

}  // namespace broken_files_test
}  // namespace playerkit::config
