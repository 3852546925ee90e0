#include "core/output_stage.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "core/error.hpp"
#include "core/file_access.hpp"

namespace glintlab {

namespace {

constexpr const char* kStagingPrefix = ".staging-";
constexpr const char* kTempPrefix = ".tmp-";  // AtomicFile's temporaries: .tmp-<pid>-<name>

/// The pid in "<prefix><pid>[-...]", or 0 if the name is not of that form.
long owner_pid(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0) return 0;
  char* end = nullptr;
  const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
  if (end == name.c_str() + prefix.size() || (*end != '\0' && *end != '-')) return 0;
  return pid;
}

bool process_is_gone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace

void remove_stale_temporaries(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const long pid = std::max(owner_pid(name, kStagingPrefix), owner_pid(name, kTempPrefix));
    if (process_is_gone(pid)) std::filesystem::remove_all(entry.path(), ec);
  }
}

OutputStage::OutputStage(std::filesystem::path dir)
    : dir_(std::move(dir)), staging_(dir_ / (kStagingPrefix + std::to_string(::getpid()))) {
  std::filesystem::create_directories(dir_);
  remove_stale_temporaries(dir_);
  std::filesystem::remove_all(staging_);
  std::filesystem::create_directories(staging_);
}

OutputStage::~OutputStage() {
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
}

void OutputStage::publish(const std::vector<std::string>& last) {
  std::vector<std::filesystem::path> first_moves, last_moves;
  for (const auto& entry : std::filesystem::directory_iterator(staging_)) {
    const std::string name = entry.path().filename().string();
    (std::find(last.begin(), last.end(), name) != last.end() ? last_moves : first_moves).push_back(entry.path());
  }
  std::sort(first_moves.begin(), first_moves.end());
  // Checked before the first move, so that a refused target leaves every output as it was.
  for (const auto* moves : {&first_moves, &last_moves})
    for (const auto& from : *moves) {
      const FileKind staged = file_kind(from, false), there = file_kind(dir_ / from.filename(), false);
      if (there != FileKind::missing && there != staged)
        throw InputError((dir_ / from.filename()).string() + ": is " + std::string(describe(there)) +
                         "; allowed: " + std::string(describe(staged)) + " to replace, or nothing");
    }
  for (const auto* moves : {&first_moves, &last_moves})
    for (const auto& from : *moves) {
      std::error_code ec;
      std::filesystem::rename(from, dir_ / from.filename(), ec);
      if (ec) throw RuntimeFailure((dir_ / from.filename()).string() + ": cannot write: " + ec.message());
    }
  published_ = true;
}

}  // namespace glintlab
