// Checks every field of every struct against the spec's layout table
// (tests/data/wire-format-layout.tsv, transcribed from wire-format.md §5).

#include "protocol/layout.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "protocol/messages/all.hpp"

namespace playerkit::protocol {
namespace layout_test {

struct SpecField {
  std::string name;
  std::size_t offset = 0;
  std::size_t size = 0;
};

struct SpecStruct {
  std::size_t size = 0;
  std::vector<SpecField> fields;
};

std::map<std::string, SpecStruct> load_spec_layouts() {
  std::ifstream in(std::string(PLAYERKIT_TEST_DATA_DIR) + "/wire-format-layout.tsv");
  std::map<std::string, SpecStruct> layouts;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string struct_name, struct_size, field, ctype, array, offset, size;
    std::getline(row, struct_name, '\t');
    std::getline(row, struct_size, '\t');
    std::getline(row, field, '\t');
    std::getline(row, ctype, '\t');
    std::getline(row, array, '\t');
    std::getline(row, offset, '\t');
    std::getline(row, size, '\t');
    auto& entry = layouts[struct_name];
    entry.size = std::stoul(struct_size);
    entry.fields.push_back({field, std::stoul(offset), std::stoul(size)});
  }
  return layouts;
}

struct CodeLayout {
  std::size_t size = 0;
  std::vector<FieldLayout> fields;
};

template <class... T>
std::map<std::string, CodeLayout> code_layouts(TypeList<T...>) {
  std::map<std::string, CodeLayout> out;
  (
      [&] {
        const auto fields = field_layout<T>();
        out[std::string(T::kWireName)] = {T::kWireSize, {fields.begin(), fields.end()}};
      }(),
      ...);
  return out;
}

TEST(Layout, EveryStructOfTheSpecExistsWithTheSameSize) {
  const auto spec = load_spec_layouts();
  const auto code = code_layouts(AllWireStructs{});
  ASSERT_EQ(spec.size(), 111u) << "layout table not found or incomplete";
  EXPECT_EQ(code.size(), spec.size());
  for (const auto& [name, layout] : spec) {
    const auto it = code.find(name);
    ASSERT_NE(it, code.end()) << name << " has no C++ struct";
    EXPECT_EQ(it->second.size, layout.size) << name;
  }
}

TEST(Layout, EveryFieldHasTheSpecNameOffsetAndSize) {
  const auto spec = load_spec_layouts();
  const auto code = code_layouts(AllWireStructs{});
  for (const auto& [name, layout] : spec) {
    const auto& fields = code.at(name).fields;
    ASSERT_EQ(fields.size(), layout.fields.size()) << name;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      SCOPED_TRACE(name + "." + layout.fields[i].name);
      EXPECT_EQ(fields[i].name, layout.fields[i].name);
      EXPECT_EQ(fields[i].offset, layout.fields[i].offset);
      EXPECT_EQ(fields[i].size, layout.fields[i].size);
    }
  }
}

TEST(Layout, ShortFormsOfSection6) {
  // Blobfinder: header block always complete, blob list truncated.
  EXPECT_EQ(kMinWireSize<BlobfinderData>, 132u);
  EXPECT_EQ(kMaxWireSize<BlobfinderData>, 7172u);
  // Localize: 14 + 88 * hypoth_count.
  EXPECT_EQ(kMinWireSize<LocalizeData>, 14u);
  EXPECT_EQ(kMaxWireSize<LocalizeData>, 894u);
  // Comms: any length up to the payload limit.
  EXPECT_EQ(kMinWireSize<CommsData>, 0u);
  EXPECT_EQ(kMaxWireSize<CommsData>, 8160u);
  // Everything else is sent whole, laser included.
  EXPECT_EQ(kMinWireSize<LaserData>, 1213u);
  EXPECT_EQ(kMaxWireSize<LaserData>, 1213u);
}

}  // namespace layout_test
}  // namespace playerkit::protocol
