#pragma once
// Where a tool writes its data: a file (created or truncated) or, for "-",
// standard output. Write errors (a full disk, a closed pipe) surface as
// exceptions naming the destination instead of a silently short file.

#include <fstream>
#include <memory>
#include <ostream>
#include <string>

namespace playerkit::tools {

class OutputFile {
 public:
  // Throws std::runtime_error "cannot write PATH: reason" when the file
  // cannot be opened.
  OutputFile(const std::string& path, std::ostream& standard_out);

  std::ostream& stream() { return *out_; }
  // "stdout" for "-".
  const std::string& name() const { return name_; }

  // Throws std::runtime_error "cannot write NAME" when a write has failed.
  void check() const;
  // Pushes buffered data out, then check(): at the end, and wherever a
  // reader must see the data so far (a recorder that may be killed).
  void flush();

 private:
  std::string name_;
  std::unique_ptr<std::ofstream> file_;
  std::ostream* out_;
};

}  // namespace playerkit::tools
