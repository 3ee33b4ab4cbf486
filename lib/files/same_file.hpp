#pragma once
// Whether an output names one of a program's inputs: the same device and
// inode (stat), so `./a.log`, a symlink or a hard link to the input count as
// the input, whatever the spelling.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace playerkit::files {

class OutputIsInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// True when both exist and are the same file. "-" is standard input.
[[nodiscard]] bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Throws OutputIsInputError "cannot write OUT: it is the input IN (the same
// file)" when `output` is an existing regular file that one of `inputs` also
// names. "-" as an input is standard input; "-" as the output (standard
// output) and outputs that are not regular files (/dev/null, a FIFO) are
// never refused: writing them destroys nothing.
void refuse_output_over_inputs(const std::filesystem::path& output,
                               const std::vector<std::filesystem::path>& inputs);

}  // namespace playerkit::files
