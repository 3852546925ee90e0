#pragma once
// Writes go to a temporary sibling and are renamed into place on commit(), so a failure never
// leaves a partial output file (README.md, "Use": outputs are written to a temporary name and renamed).
#include <filesystem>

namespace glintlab {

class AtomicFile {
 public:
  /// Throws InputError if the target exists and is not a regular file (core/file_access.hpp).
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Where the writer must write.
  [[nodiscard]] const std::filesystem::path& temp_path() const { return temp_; }
  /// Renames the temporary file onto the target. Throws RuntimeFailure on failure.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

/// Writes text atomically.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace glintlab
