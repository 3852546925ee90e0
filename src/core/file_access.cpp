#include "core/file_access.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace glintlab {

namespace {

FileKind kind_of(mode_t mode) {
  if (S_ISREG(mode)) return FileKind::regular;
  if (S_ISDIR(mode)) return FileKind::directory;
  if (S_ISFIFO(mode)) return FileKind::fifo;
  if (S_ISCHR(mode)) return FileKind::character_device;
  if (S_ISBLK(mode)) return FileKind::block_device;
  if (S_ISSOCK(mode)) return FileKind::socket;
  if (S_ISLNK(mode)) return FileKind::symlink;
  return FileKind::other;
}

std::string subject(std::string_view what, const std::filesystem::path& path) {
  return (what.empty() ? std::string() : std::string(what) + " ") + path.string();
}

/// Closes a descriptor on every path out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

/// Throws InputError "FLAG SHOWN: P is a file, not a directory" for the first of `folder` and the
/// folders above it that exists and is not a directory.
void require_folders_above(const std::filesystem::path& shown, const std::filesystem::path& folder,
                           std::string_view flag) {
  for (std::filesystem::path p = folder; !p.empty(); p = p.parent_path()) {
    const FileKind kind = file_kind(p);
    if (kind != FileKind::missing && kind != FileKind::directory)
      throw InputError(std::string(flag) + (flag.empty() ? "" : " ") + shown.string() + ": " + p.string() + " is " +
                       (kind == FileKind::regular ? std::string("a file") : std::string(describe(kind))) +
                       ", not a directory; allowed: a path whose folders are directories (created if missing)");
    if (p == p.parent_path()) break;
  }
}

}  // namespace

FileKind file_kind(const std::filesystem::path& path, bool follow_links) {
  struct stat st {};
  const int rc = follow_links ? ::stat(path.c_str(), &st) : ::lstat(path.c_str(), &st);
  return rc == 0 ? kind_of(st.st_mode) : FileKind::missing;
}

std::string_view describe(FileKind kind) {
  switch (kind) {
    case FileKind::missing: return "missing";
    case FileKind::regular: return "a regular file";
    case FileKind::directory: return "a directory";
    case FileKind::fifo: return "a FIFO (named pipe)";
    case FileKind::character_device: return "a character device";
    case FileKind::block_device: return "a block device";
    case FileKind::socket: return "a socket";
    case FileKind::symlink: return "a symbolic link";
    case FileKind::other: break;
  }
  return "not a regular file";
}

void require_regular_file(const std::filesystem::path& path, std::string_view what) {
  const FileKind kind = file_kind(path);
  if (kind == FileKind::regular) return;
  if (kind == FileKind::missing)
    throw InputError(subject(what, path) + ": does not exist (or cannot be reached); allowed: a regular file");
  throw InputError(subject(what, path) + ": is " + std::string(describe(kind)) + "; allowed: a regular file");
}

std::string read_regular_file(const std::filesystem::path& path, std::string_view what, std::uintmax_t max_bytes) {
  require_regular_file(path, what);
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw InputError(subject(what, path) + ": cannot be read: " + std::strerror(errno));
  struct stat st {};
  if (::fstat(file.fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw InputError(subject(what, path) + ": is " + std::string(describe(kind_of(st.st_mode))) +
                     "; allowed: a regular file");
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes)
    throw InputError(subject(what, path) + ": " + std::to_string(size) + " bytes; allowed: at most " +
                     std::to_string(max_bytes) + " bytes");
  std::string bytes(size, '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(file.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(subject(what, path) + ": cannot be read: " + std::strerror(errno));
    if (n == 0) break;  // shrank while read: what is there is what it holds
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

void check_output_file(const std::filesystem::path& path, std::string_view flag) {
  const std::string prefix = std::string(flag) + (flag.empty() ? "" : " ") + path.string();
  if (path.empty() || path.filename().empty() || path.filename() == "." || path.filename() == "..")
    throw InputError(prefix + ": names a directory; allowed: a file name to write");
  const FileKind kind = file_kind(path, false);
  if (kind != FileKind::missing && kind != FileKind::regular)
    throw InputError(prefix + ": is " + std::string(describe(kind)) + "; allowed: a new file or a regular file to replace");
  require_folders_above(path, path.parent_path(), flag);
}

void check_output_directory(const std::filesystem::path& dir, std::string_view flag) {
  require_folders_above(dir, dir, flag);
}

}  // namespace glintlab
