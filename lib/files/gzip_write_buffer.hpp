#pragma once
// A std::streambuf that gzip-compresses what is written to it into another
// streambuf (a file's): a .gz file any gzip reader takes (zcat, zlib's
// gzread, lib/log's open_log_input). sync() (a stream's flush) makes
// everything written so far decodable (a zlib sync point: a few bytes, and
// some compression lost, each time); finish() writes the end of the stream.

#include <array>
#include <memory>
#include <streambuf>

namespace playerkit::files {

class GzipWriteBuffer : public std::streambuf {
 public:
  explicit GzipWriteBuffer(std::streambuf& sink);
  ~GzipWriteBuffer() override;
  GzipWriteBuffer(const GzipWriteBuffer&) = delete;
  GzipWriteBuffer& operator=(const GzipWriteBuffer&) = delete;

  // Compresses what is left and writes the gzip trailer. False when a write
  // to the sink failed (now or before). Once; later writes fail.
  bool finish();
  [[nodiscard]] bool failed() const { return failed_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  struct Stream;
  // Feeds the buffered input to deflate with `flush` (Z_NO_FLUSH,
  // Z_SYNC_FLUSH, Z_FINISH), writing its output to the sink.
  bool deflate_pending(int flush);

  std::streambuf& sink_;
  std::unique_ptr<Stream> stream_;
  std::array<char, 64 * 1024> input_{};
  std::array<char, 64 * 1024> output_{};
  bool failed_ = false;
  bool finished_ = false;
};

}  // namespace playerkit::files
