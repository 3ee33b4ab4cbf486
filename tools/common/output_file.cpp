#include "output_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace playerkit::tools {

OutputFile::OutputFile(const std::string& path, std::ostream& standard_out) : name_(path), out_(&standard_out) {
  if (path == "-") {
    name_ = "stdout";
    return;
  }
  file_ = std::make_unique<std::ofstream>(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!*file_) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  out_ = file_.get();
}

void OutputFile::check() const {
  // errno says why only right after the failing call; a later check has no reason to give.
  if (!*out_) throw std::runtime_error("cannot write " + name_);
}

void OutputFile::flush() {
  out_->flush();
  check();
}

}  // namespace playerkit::tools
