#pragma once
// The CLI tests' fixture: each test runs the glintlab binary in a scratch directory of its own,
// with its own reference cache, and checks exit codes, messages and what was written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scratch_directory.hpp"

namespace glintlab::test {

namespace fs = std::filesystem;

struct CliResult {
  int code;
  std::string err;
};

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Each test runs glintlab in a scratch directory of its own, with its own reference cache.
class Cli : public ::testing::Test {
 protected:
  CliResult run_glintlab(const std::string& args) const {
    const fs::path err = scratch / "stderr.txt";
    // A hang fails the test (exit 124) instead of stopping the suite.
    const std::string cmd = env + " GLINTLAB_CACHE_DIR='" + cache().string() + "' timeout -k 5 120 '" GLINTLAB_BINARY "' " + args +
                            " >/dev/null 2>'" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_bytes(err)};
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = scratch / name;
    std::ofstream(p) << text;
    return p;
  }

  fs::path cache() const { return scratch / "cache"; }

  void expect_bad_input(const std::string& args, std::initializer_list<const char*> fragments) const {
    const fs::path out = scratch / "out-should-not-exist";
    fs::remove_all(out);
    const CliResult r = run_glintlab(args + " -o '" + out.string() + "'");
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    for (const char* f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "'" << f << "' not in: " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }

  ScratchDirectory scratch;
  std::string env;  ///< variables set for glintlab, "NAME=value ..."
};

}  // namespace glintlab::test
