#include "files/same_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <optional>

namespace playerkit::files {
namespace {

std::optional<struct stat> status_of(const std::filesystem::path& path) {
  struct stat status {};
  const int result = path == "-" ? ::fstat(STDIN_FILENO, &status) : ::stat(path.c_str(), &status);
  if (result != 0) return std::nullopt;
  return status;
}

bool same_identity(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

}  // namespace

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto first = status_of(a);
  const auto second = status_of(b);
  return first && second && same_identity(*first, *second);
}

void refuse_output_over_inputs(const std::filesystem::path& output,
                               const std::vector<std::filesystem::path>& inputs) {
  if (output == "-") return;
  const auto written = status_of(output);
  if (!written || !S_ISREG(written->st_mode)) return;
  for (const auto& input : inputs) {
    const auto read = status_of(input);
    if (read && same_identity(*written, *read)) {
      const std::string what = input == "-" ? "standard input" : "the input " + input.string();
      throw OutputIsInputError("cannot write " + output.string() + ": it is " + what +
                               " (the same file); write to another file");
    }
  }
}

}  // namespace playerkit::files
