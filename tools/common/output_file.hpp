#pragma once
// Where a tool writes its data: lib/files' OutputFile (never over an input,
// through a temporary renamed into place by commit(), gzip for ".gz", "-"
// for standard output) with the tools' error kinds: writing over an input
// is a UsageError (exit 2), any other failure a std::runtime_error naming
// the destination.
//
//   OutputFile output(options.output, out, {options.input});
//   ... output.stream() << ...; output.check(); ...
//   output.commit();   // without it the file is left as it was

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "files/output_file.hpp"

namespace playerkit::tools {

class OutputFile {
 public:
  // Throws UsageError when `path` is one of `inputs` (same file), and
  // std::runtime_error "cannot write PATH: reason" when it cannot be created.
  OutputFile(const std::string& path, std::ostream& standard_out, const std::vector<std::string>& inputs = {},
             files::WriteMode mode = files::WriteMode::kReplaceOnCommit);

  std::ostream& stream() { return file_.stream(); }
  // "stdout" for "-".
  [[nodiscard]] const std::string& name() const { return file_.name(); }
  [[nodiscard]] bool compressed() const { return file_.compressed(); }

  // Throws std::runtime_error "cannot write NAME[: reason]" when a write has failed.
  void check() const { file_.check(); }
  // Pushes buffered data out, then check(): wherever a reader must see the
  // data so far (a recorder that may be killed).
  void flush() { file_.flush(); }
  // The file appears, complete, under its name (see files::OutputFile).
  void commit() { file_.commit(); }

 private:
  files::OutputFile file_;
};

// Throws UsageError when `output` is one of `inputs` (same device and
// inode): for outputs written at the end of long work (amcl-offline map),
// checked before the work starts.
void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs);

}  // namespace playerkit::tools
