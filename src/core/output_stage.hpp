#pragma once
// A set of output files published as a unit. Files are written into a hidden staging folder
// beside them, <dir>/.staging-<pid>/, and publish() moves them into <dir>, the index files (the
// metrics that name the others) last: whoever sees a run's metrics sees every file they name,
// and a run that fails or is interrupted leaves the previous outputs as they were. What a killed
// process left behind (its staging folder, AtomicFile's .tmp-<pid>-* files) is removed the next
// time a stage opens in that folder.
#include <filesystem>
#include <string>
#include <vector>

namespace glintlab {

class OutputStage {
 public:
  /// Creates <dir> and the staging folder; removes stale temporaries of dead processes in <dir>.
  explicit OutputStage(std::filesystem::path dir);
  /// Without publish(), removes the staging folder and everything in it.
  ~OutputStage();
  OutputStage(const OutputStage&) = delete;
  OutputStage& operator=(const OutputStage&) = delete;

  /// Where the run writes its files.
  [[nodiscard]] const std::filesystem::path& path() const { return staging_; }
  /// Moves every staged file into <dir>, replacing files of the same name; the names in `last`
  /// move after all others. Throws RuntimeFailure if a move fails.
  void publish(const std::vector<std::string>& last = {});

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  bool published_ = false;
};

/// Removes, in `dir`, the staging folders and .tmp-<pid>-* files of processes that no longer run.
void remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace glintlab
