#include "output_file.hpp"

#include "exit_status.hpp"

namespace playerkit::tools {
namespace {

std::vector<std::filesystem::path> as_paths(const std::vector<std::string>& names) {
  return {names.begin(), names.end()};
}

files::OutputFile open_output(const std::string& path, std::ostream& standard_out,
                              const std::vector<std::string>& inputs, files::WriteMode mode) {
  try {
    return files::OutputFile(path, {.inputs = as_paths(inputs), .mode = mode, .standard_out = &standard_out});
  } catch (const files::OutputIsInputError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace

OutputFile::OutputFile(const std::string& path, std::ostream& standard_out, const std::vector<std::string>& inputs,
                       files::WriteMode mode)
    : file_(open_output(path, standard_out, inputs, mode)) {}

void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs) {
  try {
    files::refuse_output_over_inputs(output, as_paths(inputs));
  } catch (const files::OutputIsInputError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace playerkit::tools
