#include "files/gzip_write_buffer.hpp"

#include <stdexcept>

#include <zlib.h>

namespace playerkit::files {

struct GzipWriteBuffer::Stream {
  z_stream z{};
};

namespace {
// deflateInit2's window bits: 15 (32 KiB) plus 16 for a gzip header and trailer.
constexpr int kGzipWindowBits = 15 + 16;
constexpr int kMemoryLevel = 8;
}  // namespace

GzipWriteBuffer::GzipWriteBuffer(std::streambuf& sink) : sink_(sink), stream_(std::make_unique<Stream>()) {
  if (deflateInit2(&stream_->z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, kGzipWindowBits, kMemoryLevel,
                   Z_DEFAULT_STRATEGY) != Z_OK) {
    throw std::runtime_error("gzip: cannot set up compression (out of memory)");
  }
  setp(input_.data(), input_.data() + input_.size());
}

GzipWriteBuffer::~GzipWriteBuffer() { deflateEnd(&stream_->z); }

bool GzipWriteBuffer::deflate_pending(int flush) {
  if (failed_) return false;
  auto& z = stream_->z;
  z.next_in = reinterpret_cast<Bytef*>(pbase());
  z.avail_in = static_cast<uInt>(pptr() - pbase());
  int result = Z_OK;
  do {
    z.next_out = reinterpret_cast<Bytef*>(output_.data());
    z.avail_out = static_cast<uInt>(output_.size());
    result = deflate(&z, flush);
    if (result == Z_STREAM_ERROR) {
      failed_ = true;
      break;
    }
    const auto produced = static_cast<std::streamsize>(output_.size() - z.avail_out);
    if (produced > 0 && sink_.sputn(output_.data(), produced) != produced) {
      failed_ = true;
      break;
    }
    // deflate is done with this call when it left room in the output (or,
    // finishing, when it says the stream has ended).
  } while (flush == Z_FINISH ? result != Z_STREAM_END : z.avail_out == 0);
  setp(input_.data(), input_.data() + input_.size());
  return !failed_;
}

GzipWriteBuffer::int_type GzipWriteBuffer::overflow(int_type c) {
  if (finished_ || !deflate_pending(Z_NO_FLUSH)) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int GzipWriteBuffer::sync() {
  if (finished_) return failed_ ? -1 : 0;
  if (!deflate_pending(Z_SYNC_FLUSH)) return -1;
  return sink_.pubsync() == 0 ? 0 : -1;
}

bool GzipWriteBuffer::finish() {
  if (finished_) return !failed_;
  finished_ = true;
  const bool finished = deflate_pending(Z_FINISH);
  setp(nullptr, nullptr);  // nothing more goes in
  return finished && sink_.pubsync() == 0;
}

}  // namespace playerkit::files
