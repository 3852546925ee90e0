// The precomputed-table cache (src/tables/table_cache.hpp), without GL: a table is generated once
// and then read back bit for bit without running its generator; the key follows the id, the
// generator's version and the settings; a damaged entry is regenerated, never trusted. Each test
// caches into its own temporary directory, removed afterwards.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ranges>

#include "core/hash.hpp"
#include "tables/registry.hpp"
#include "tables/table_cache.hpp"

namespace glintlab {
namespace {

/// A directory of a unique name under the system's temporary directory, removed with everything in it.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "glintlab-tables-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary directory");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// A small table whose generator counts its calls: values i * 0.5 + offset.
struct CountingTable {
  int calls = 0;
  float offset = 1.0f;
  TableSource source() {
    return {.id = "test-ramp",
            .title = "a ramp",
            .version = 3,
            .settings = "count=1000 offset=1",
            .value_count = 1000,
            .generate = [this](const TableProgressFn& progress) {
              ++calls;
              std::vector<float> v(1000);
              for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(i) * 0.5f + offset;
              for (int step = 1; step <= 4; ++step) progress(step, 4);
              return v;
            }};
  }
};

TEST(TableCache, GeneratesOnceThenLoadsTheSameBytesWithoutRunningTheGenerator) {
  TemporaryDirectory dir;
  CountingTable table;
  const TableCache cache(dir.path());
  const BuiltTable first = cache.load_or_generate(table.source());
  EXPECT_TRUE(first.build.generated);
  EXPECT_EQ(table.calls, 1);
  ASSERT_TRUE(std::filesystem::exists(cache.path(table.source())));

  const BuiltTable second = cache.load_or_generate(table.source());
  EXPECT_EQ(table.calls, 1) << "the second call must read the cache, not generate";
  EXPECT_FALSE(second.build.generated);
  ASSERT_EQ(second.values.size(), first.values.size());
  EXPECT_EQ(std::memcmp(second.values.data(), first.values.data(), first.values.size() * sizeof(float)), 0);
  EXPECT_EQ(second.build.generation_ms, first.build.generation_ms) << "the entry records what generating took";
  EXPECT_EQ(cache.cached_generation_ms(table.source()), first.build.generation_ms);
}

TEST(TableCache, TheKeyFollowsTheIdTheGeneratorVersionAndTheSettings) {
  CountingTable table;
  const TableSource base = table.source();
  TableSource other = base;
  other.version = 4;
  EXPECT_NE(table_key(other), table_key(base)) << "version";
  other = base;
  other.settings = "count=1000 offset=2";
  EXPECT_NE(table_key(other), table_key(base)) << "settings";
  other = base;
  other.id = "test-ramp2";
  EXPECT_NE(table_key(other), table_key(base)) << "id";
  other = base;
  other.title = "another title";
  EXPECT_EQ(table_key(other), table_key(base)) << "the title is not content";

  // A new version is generated again, not read from the old entry.
  TemporaryDirectory dir;
  const TableCache cache(dir.path());
  (void)cache.load_or_generate(base);
  other = base;
  other.version = 4;
  (void)cache.load_or_generate(other);
  EXPECT_EQ(table.calls, 2);
  EXPECT_NE(cache.path(other), cache.path(base));
}

/// A cache in `dir` whose warnings are kept in `warnings`.
TableCache cache_keeping_warnings(const TemporaryDirectory& dir, std::vector<std::string>& warnings) {
  return TableCache(dir.path(), {.warning = [&](const TableSource&, const std::string& m) { warnings.push_back(m); }});
}

/// Damages the entry with `damage`, then expects the next call to regenerate (with a warning)
/// the same values and to leave an intact entry that is read again.
void expect_regenerated_after(const std::function<void(const std::filesystem::path&)>& damage, const char* what) {
  TemporaryDirectory dir;
  CountingTable table;
  std::vector<std::string> warnings;
  const TableCache cache = cache_keeping_warnings(dir, warnings);
  const BuiltTable first = cache.load_or_generate(table.source());
  damage(cache.path(table.source()));
  const BuiltTable again = cache.load_or_generate(table.source());
  EXPECT_EQ(table.calls, 2) << what;
  EXPECT_TRUE(again.build.generated) << what;
  EXPECT_EQ(again.values, first.values) << what;
  ASSERT_EQ(warnings.size(), 1u) << what;
  EXPECT_NE(warnings[0].find("regenerating"), std::string::npos) << warnings[0];
  (void)cache.load_or_generate(table.source());
  EXPECT_EQ(table.calls, 2) << what << ": the regenerated entry is read again";
}

TEST(TableCache, ATruncatedOrCorruptEntryIsRegeneratedNotTrusted) {
  expect_regenerated_after(
      [](const auto& file) { std::filesystem::resize_file(file, std::filesystem::file_size(file) - 4); },
      "truncated by one value");
  expect_regenerated_after([](const auto& file) { std::filesystem::resize_file(file, 20); }, "truncated in the header");
  expect_regenerated_after(
      [](const auto& file) {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(-100, std::ios::end);
        f.put('\x7f');
      },
      "a value's byte changed");
  expect_regenerated_after(
      [](const auto& file) { std::ofstream(file, std::ios::binary | std::ios::app) << "trailing"; }, "bytes appended");
  expect_regenerated_after([](const auto& file) { std::ofstream(file, std::ios::binary | std::ios::trunc); }, "empty");
}

TEST(TableCache, AFifoInTheEntrysPlaceIsNeitherOpenedNorReplaced) {
  // Opening a FIFO blocks until a writer comes; the atomic store would replace it with a file.
  TemporaryDirectory dir;
  CountingTable table;
  std::vector<std::string> warnings;
  const TableCache cache = cache_keeping_warnings(dir, warnings);
  const auto file = cache.path(table.source());
  std::filesystem::create_directories(file.parent_path());
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  EXPECT_FALSE(cache.cached_generation_ms(table.source()).has_value());
  const BuiltTable built = cache.load_or_generate(table.source());
  EXPECT_TRUE(built.build.generated);
  EXPECT_TRUE(std::filesystem::is_fifo(file));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("FIFO"), std::string::npos) << warnings[0];
}

TEST(TableCache, ValuesTheTableRejectsAreRegenerated) {
  TemporaryDirectory dir;
  CountingTable table;
  TableSource source = table.source();
  const TableCache cache(dir.path());
  (void)cache.load_or_generate(source);
  source.check = [](std::span<const float> v) { return v[0] == 1.0f ? std::string("rejected") : std::string(); };
  (void)cache.load_or_generate(source);
  EXPECT_EQ(table.calls, 2);
}

TEST(TableCache, AnEmptyDirectoryDisablesTheCache) {
  CountingTable table;
  const TableCache cache({});
  (void)cache.load_or_generate(table.source());
  (void)cache.load_or_generate(table.source());
  EXPECT_EQ(table.calls, 2);
  EXPECT_FALSE(cache.cached_generation_ms(table.source()).has_value());
}

TEST(TableCache, ReportsProgressToItsObserverAndNothingIsCachedBeforeGenerating) {
  TemporaryDirectory dir;
  CountingTable table;
  std::vector<std::pair<int, int>> steps;
  const TableCache cache(dir.path(), {.progress = [&](const TableSource& t, int done, int total) {
                                        EXPECT_EQ(t.id, "test-ramp");
                                        steps.emplace_back(done, total);
                                      }});
  EXPECT_FALSE(cache.cached_generation_ms(table.source()).has_value());
  (void)cache.load_or_generate(table.source());
  EXPECT_EQ(steps, (std::vector<std::pair<int, int>>{{1, 4}, {2, 4}, {3, 4}, {4, 4}}));
  (void)cache.load_or_generate(table.source());
  EXPECT_EQ(steps.size(), 4u) << "loading reports no generation";
}

TEST(TableCache, AGeneratorThatReturnsTheWrongCountIsAnError) {
  CountingTable table;
  TableSource source = table.source();
  source.value_count = 999;
  EXPECT_THROW((void)TableCache({}).load_or_generate(source), std::logic_error);
}

std::uint64_t fnv1a(std::span<const float> values) {
  Hasher h;
  h.bytes(values.data(), values.size_bytes());
  return h.digest();
}

TEST(GlintDictionaryTable, HoldsThePapersDictionaryBitForBitThroughTheCache) {
  // The baseline images depend on every bit of the dictionary: this is the hash of the tables the
  // generator made before it moved onto the table framework (GlintDictionary::generate({})).
  constexpr std::uint64_t kDictionaryHash = 0xf3481c3bc2227e73ull;
  TemporaryDirectory dir;
  const TableSource& source = find_table("glint-dictionary").source;
  EXPECT_EQ(source.settings, "marginals=192 levels=16 texels=64 alpha=0.5 lobe_sigma=0.0199999996 seed=1");
  const TableCache cache(dir.path());
  const BuiltTable generated = cache.load_or_generate(source);
  const BuiltTable loaded = cache.load_or_generate(source);
  EXPECT_TRUE(generated.build.generated);
  EXPECT_FALSE(loaded.build.generated);
  EXPECT_EQ(generated.values.size(), std::size_t{16} * 192 * 64);
  EXPECT_EQ(fnv1a(generated.values), kDictionaryHash);
  EXPECT_EQ(fnv1a(loaded.values), kDictionaryHash);
}

}  // namespace
}  // namespace glintlab
