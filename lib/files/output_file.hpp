#pragma once
// A file a program writes (a log, a CSV, a map image), such that writing it
// never destroys data:
//
// * it refuses to write over one of the program's inputs (same device and
//   inode: `./a.log`, symlinks and hard links count), before anything is
//   written;
// * by default it writes to NAME.tmp-XXXXXX beside the target and commit()
//   renames that into place: until then the previous file is untouched, and
//   without commit() (an error, an exception) the temporary is removed. A
//   fatal signal removes it too (temporary_cleanup.hpp);
// * a name ending in ".gz" is written gzip-compressed;
// * "-" writes to the standard output given (no temporary, no compression).
//
//   files::OutputFile output(path, {.inputs = {log}, .standard_out = &std::cout});
//   output.stream() << ...;
//   output.check();      // wherever a failed write should stop the work early
//   output.commit();     // the file appears, complete, under its name
//
// Recorders that must show their data under the final name while they run
// (tail -f, a live `player-log info`) use WriteMode::kStreaming: the file is
// created (truncated) at once and written in place; commit() or destruction
// finishes it, keeping everything written. Symlinked outputs are written
// through (the link stays a link); outputs that are not regular files
// (/dev/null, a FIFO, a terminal) are written directly.

#include <filesystem>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "files/same_file.hpp"

namespace playerkit::files {

// "cannot write NAME: reason".
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Compression {
  kByName,  // gzip when the name ends in ".gz"
  kNone,
  kGzip,
};

enum class WriteMode {
  kReplaceOnCommit,  // a temporary beside the target, renamed by commit()
  kStreaming,        // the target itself, created at once
};

struct OutputFileOptions {
  // Files the output must not be (refused with OutputIsInputError); "-" is stdin.
  std::vector<std::filesystem::path> inputs{};
  Compression compression = Compression::kByName;
  WriteMode mode = WriteMode::kReplaceOnCommit;
  // Where "-" writes. Null: "-" is a file of that name.
  std::ostream* standard_out = nullptr;
};

class OutputFile {
 public:
  // Throws OutputIsInputError, or OutputError when the file (or its
  // temporary) cannot be created.
  explicit OutputFile(const std::filesystem::path& path, OutputFileOptions options = {});
  // Without commit(): kReplaceOnCommit removes the temporary (the previous
  // file stays as it was); kStreaming finishes the file as written so far.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return *out_; }
  // The path as given; "stdout" for "-".
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] bool compressed() const;
  // Where the data goes until commit(); empty when it goes to the target itself.
  [[nodiscard]] const std::filesystem::path& temporary() const;

  // Throws OutputError when a write has failed.
  void check() const;
  // Pushes the data written so far into the file (gzip: a sync point), then
  // check(): for a recorder that may be killed.
  void flush();
  // Ends the stream (the gzip trailer), flushes and fsyncs the file, renames
  // the temporary into place. Throws OutputError; the temporary is then
  // removed by the destructor and the previous file kept.
  void commit();
  [[nodiscard]] bool committed() const { return committed_; }

 private:
  struct Sink;
  [[noreturn]] void fail(const std::string& reason) const;

  std::string name_;
  std::unique_ptr<Sink> sink_;  // null for "-"
  std::ostream* out_ = nullptr;
  bool committed_ = false;
};

}  // namespace playerkit::files
