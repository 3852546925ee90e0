#pragma once
// One rule for every file glintlab reads and every file it writes (docs/bad-input.md, "Special
// files"), applied here rather than per loader.
// - Reads: regular files only (a symbolic link to one is one), opened without blocking, never
//   more bytes than the reader's stated limit. A FIFO, a device, a socket or a directory is an
//   InputError naming the file and what it is, before a byte is read: nothing can hang on a FIFO
//   or read /dev/zero until memory runs out.
// - Writes: a target that exists must be a regular file. A directory, a FIFO, a device, a socket
//   or a symbolic link is refused before any work, so that a write-then-rename never replaces
//   /dev/full with a JSON file, and no output is written through a link to elsewhere.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace glintlab {

enum class FileKind { missing, regular, directory, fifo, character_device, block_device, socket, symlink, other };

/// What `path` is, following symbolic links (`follow_links`) or not.
[[nodiscard]] FileKind file_kind(const std::filesystem::path& path, bool follow_links = true);
/// "a directory", "a FIFO (named pipe)", "a character device", ...: for messages.
[[nodiscard]] std::string_view describe(FileKind kind);

/// Throws InputError "`what` PATH: is a FIFO ...; allowed: a regular file" unless `path` is (a link
/// to) a regular file; "does not exist" for a missing one.
void require_regular_file(const std::filesystem::path& path, std::string_view what);

/// The whole of a regular file of at most `max_bytes` bytes. The file is opened without blocking
/// and checked on the open descriptor (a FIFO put in its place after a check cannot block).
/// Throws InputError naming `what` and the path for a file that is not regular, too large or
/// unreadable.
[[nodiscard]] std::string read_regular_file(const std::filesystem::path& path, std::string_view what,
                                            std::uintmax_t max_bytes);

/// Throws InputError naming `flag` and the path unless `path` may be written: absent or a regular
/// file (not a link), with every existing folder above it a folder. Call it before any work.
void check_output_file(const std::filesystem::path& path, std::string_view flag);

/// Throws InputError naming `flag` if `dir` (an output directory, created if missing) or a folder
/// above it exists and is not a directory.
void check_output_directory(const std::filesystem::path& dir, std::string_view flag = "-o");

/// The size limits of the files glintlab reads; a reader names its own.
inline constexpr std::uintmax_t kMaxTextFileBytes = 64ull << 20;    ///< scene files, scripts, JSON, OBJ
inline constexpr std::uintmax_t kMaxBinaryFileBytes = 2ull << 30;   ///< images, glTF buffers, caches

}  // namespace glintlab
