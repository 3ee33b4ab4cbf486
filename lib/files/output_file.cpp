#include "files/output_file.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <system_error>

#include "files/fd_write_buffer.hpp"
#include "files/gzip_write_buffer.hpp"
#include "files/temporary_cleanup.hpp"

namespace playerkit::files {
namespace {

std::string reason() { return std::strerror(errno); }

// The process's umask, without changing it (umask(2) can only be read by
// setting it, which races with other threads creating files).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
  }
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return mask;
}

// The file a write to `path` must replace: through a symlink, its target, so
// the link stays a link.
std::filesystem::path resolved_target(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_symlink(path, error)) return path;
  auto target = std::filesystem::canonical(path, error);
  return error ? path : target;  // a dangling link is replaced by the file
}

void sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // best effort: the rename is what matters, and it has happened
  ::close(fd);
}

}  // namespace

struct OutputFile::Sink {
  int fd = -1;
  std::filesystem::path target;
  std::filesystem::path temporary;  // empty: writing the target itself
  int cleanup_slot = -1;
  bool regular = true;  // fsync applies
  std::unique_ptr<FdWriteBuffer> file_buffer;
  std::unique_ptr<GzipWriteBuffer> gzip_buffer;
  std::unique_ptr<std::ostream> stream;

  Sink() = default;
  Sink(const Sink&) = delete;
  Sink& operator=(const Sink&) = delete;
  // Reached with a temporary only when the constructor failed half-way.
  ~Sink() {
    stream.reset();
    gzip_buffer.reset();
    close_fd();
    remove_temporary();
  }

  void remove_temporary() {
    if (temporary.empty()) return;
    ::unlink(temporary.c_str());
    forget_temporary(cleanup_slot);
    cleanup_slot = -1;
    temporary.clear();
  }
  void close_fd() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

OutputFile::OutputFile(const std::filesystem::path& path, OutputFileOptions options) : name_(path.string()) {
  if (path == "-" && options.standard_out != nullptr) {
    name_ = "stdout";
    out_ = options.standard_out;
    return;
  }
  refuse_output_over_inputs(path, options.inputs);

  sink_ = std::make_unique<Sink>();
  sink_->target = resolved_target(path);
  struct stat existing {};
  const bool exists = ::stat(sink_->target.c_str(), &existing) == 0;
  sink_->regular = !exists || S_ISREG(existing.st_mode);
  if (exists && S_ISDIR(existing.st_mode)) fail("it is a directory");
  // A read-only file keeps its protection: replacing it through a rename
  // would not ask.
  if (exists && ::access(sink_->target.c_str(), W_OK) != 0) fail(reason());

  if (options.mode == WriteMode::kStreaming || !sink_->regular) {
    sink_->fd = ::open(sink_->target.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (sink_->fd < 0) fail(reason());
  } else {
    std::string pattern = sink_->target.string() + ".tmp-XXXXXX";
    sink_->fd = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (sink_->fd < 0) fail("cannot create a temporary file beside it: " + reason());
    sink_->temporary = pattern;
    sink_->cleanup_slot = remember_temporary(pattern);
    // mkostemp makes 0600; the file gets what a plain create would give, or
    // the mode of the file it replaces.
    const mode_t mode = exists ? (existing.st_mode & 07777) : (0666 & ~current_umask());
    ::fchmod(sink_->fd, mode);
  }

  sink_->file_buffer = std::make_unique<FdWriteBuffer>(sink_->fd);
  std::streambuf* buffer = sink_->file_buffer.get();
  const bool gzip = options.compression == Compression::kGzip ||
                    (options.compression == Compression::kByName && name_.ends_with(".gz"));
  if (gzip) {
    sink_->gzip_buffer = std::make_unique<GzipWriteBuffer>(*sink_->file_buffer);
    buffer = sink_->gzip_buffer.get();
  }
  sink_->stream = std::make_unique<std::ostream>(buffer);
  out_ = sink_->stream.get();
}

OutputFile::~OutputFile() {
  if (!sink_) {
    if (out_ != nullptr) out_->flush();
    return;
  }
  if (committed_) return;
  if (!sink_->temporary.empty()) {
    sink_->close_fd();
    sink_->remove_temporary();
    return;
  }
  // Streaming, or a device: keep what was written, as a whole gzip stream.
  if (sink_->gzip_buffer) sink_->gzip_buffer->finish();
  sink_->file_buffer->pubsync();
  sink_->close_fd();
}

bool OutputFile::compressed() const { return sink_ && sink_->gzip_buffer; }

const std::filesystem::path& OutputFile::temporary() const {
  static const std::filesystem::path none;
  return sink_ ? sink_->temporary : none;
}

void OutputFile::fail(const std::string& why) const { throw OutputError("cannot write " + name_ + ": " + why); }

void OutputFile::check() const {
  if (*out_) return;
  if (sink_ && sink_->file_buffer->error()) fail(*sink_->file_buffer->error());
  if (sink_ && sink_->gzip_buffer && sink_->gzip_buffer->failed()) fail("gzip compression failed");
  throw OutputError("cannot write " + name_);
}

void OutputFile::flush() {
  out_->flush();
  check();
}

void OutputFile::commit() {
  if (committed_) return;
  if (!sink_) {
    flush();
    committed_ = true;
    return;
  }
  if (sink_->gzip_buffer && !sink_->gzip_buffer->finish()) out_->setstate(std::ios::badbit);
  flush();
  // A device or FIFO cannot be synced (EINVAL); that is no failure.
  if (sink_->regular && ::fsync(sink_->fd) != 0 && errno != EINVAL) fail(reason());
  if (::close(sink_->fd) != 0) {
    sink_->fd = -1;
    fail(reason());
  }
  sink_->fd = -1;
  if (!sink_->temporary.empty()) {
    if (::rename(sink_->temporary.c_str(), sink_->target.c_str()) != 0) fail(reason());
    forget_temporary(sink_->cleanup_slot);
    sink_->cleanup_slot = -1;
    sink_->temporary.clear();
    sync_directory(sink_->target.parent_path());
  }
  committed_ = true;
}

}  // namespace playerkit::files
