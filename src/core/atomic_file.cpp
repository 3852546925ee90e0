#include "core/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "core/file_access.hpp"

namespace glintlab {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  // The rename below would replace whatever the target is (a device, a FIFO, a link): refused.
  check_output_file(target_, "");
  if (target_.has_parent_path()) std::filesystem::create_directories(target_.parent_path());
  // Keep the extension last: image writers pick the format from it.
  temp_ = target_.parent_path() /
          (".tmp-" + std::to_string(::getpid()) + "-" + target_.filename().string());
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
  }
}

void AtomicFile::commit() {
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) throw RuntimeFailure(target_.string() + ": cannot write: " + ec.message());
  committed_ = true;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path(), std::ios::binary);
    out << text;
    if (!out) throw RuntimeFailure(path.string() + ": cannot write");
  }
  file.commit();
}

}  // namespace glintlab
