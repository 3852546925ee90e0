// `glintlab report` as a person uses it: tiny compare, animate and bench outputs made by glintlab,
// the report opened in Debian's chromium (headless) with #selftest, which checks that every image
// and video loads and the slider moves (a report with an image removed must FAIL it), and a
// screenshot that is not blank. Each crop cell, as the page's data places and labels it, holds the
// pixels of its method's image, and the strip names each crop in a band below it. Bad input: exit
// 2, a message naming the file and key, no output, an old report left whole. The plots' geometry
// against the values drawn.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "core/image_io.hpp"
#include "eval/report_svg.hpp"
#include "scratch_directory.hpp"

namespace fs = std::filesystem;
using glintlab::test::ScratchDirectory;

namespace {

struct Ran {
  int code;
  std::string out, err;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quoted(const std::string& p) { return "'" + p + "'"; }
std::string quoted(const fs::path& p) { return quoted(p.string()); }

/// Runs a shell command with HOME and the caches in `home`, stdout and stderr kept.
Ran shell(const std::string& command, const fs::path& home) {
  const fs::path out = home / "stdout.txt", err = home / "stderr.txt";
  fs::create_directories(home);
  const std::string cmd = "HOME=" + quoted(home) + " XDG_CONFIG_HOME=" + quoted(home / "config") +
                          " XDG_CACHE_HOME=" + quoted(home / "cache") + " " + command + " >" + quoted(out) + " 2>" +
                          quoted(err);
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}

Ran run_glintlab(const std::string& args, const fs::path& home) { return shell("'" GLINTLAB_BINARY "' " + args, home); }

const std::string kTiny = "-q --scene builtin:spheres --width 48 --height 32 --methods conventional,vlachos ";

/// compare, animate (3 frames) and bench of two methods on a 48x32 film, under `dir`.
void make_outputs(const fs::path& dir, const fs::path& home, bool all) {
  Ran r = run_glintlab("compare " + kTiny + "--spp 4 -o " + quoted(dir / "compare"), home);
  ASSERT_EQ(r.code, 0) << r.err;
  if (!all) return;
  r = run_glintlab("animate " + kTiny + "--spp 4 --frames 3 -o " + quoted(dir / "animate"), home);
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_glintlab("bench " + kTiny + "--bench-frames 2 --warmup 0 -o " + quoted(dir / "bench"), home);
  ASSERT_EQ(r.code, 0) << r.err;
}

/// index.html#selftest in headless chromium: the self-test's line, chromium's log; a screenshot.
struct BrowserResult {
  std::string selftest;
  std::string log;
  int code;
  bool started;  ///< chromium ran and printed a page
};

BrowserResult open_selftest(const fs::path& report, const fs::path& home, const fs::path& screenshot) {
  const Ran r = shell(
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --allow-file-access-from-files "
      "--user-data-dir=" +
          quoted(home / "profile") +
          " --enable-logging=stderr --v=0 --virtual-time-budget=60000 --window-size=1280,900"
          " --screenshot=" +
          quoted(screenshot) + " --dump-dom " +
          quoted("file://" + fs::absolute(report / "index.html").string() + "#selftest"),
      home);
  std::smatch m;
  std::string line;
  if (std::regex_search(r.out, m, std::regex("<pre id=\"selftest\">([^<]*)</pre>"))) line = m[1];
  return {line, r.err, r.code, r.code == 0 && r.out.find("<html") != std::string::npos};
}

/// The standard deviation of a screenshot's luminance: 0 for a blank page.
double luminance_spread(const fs::path& png) {
  const glintlab::Image image = glintlab::read_ldr_image(png);
  double sum = 0, squares = 0;
  for (const auto& p : image.pixels()) {
    const double y = 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
    sum += y;
    squares += y * y;
  }
  const double n = static_cast<double>(image.pixel_count());
  return std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n)));
}

/// Chromium's log lines that report a page problem: console messages (the page logs nothing
/// itself), uncaught exceptions, failed loads.
std::vector<std::string> page_problems(const std::string& log) {
  std::vector<std::string> found;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos || line.find("Uncaught") != std::string::npos ||
        line.find("net::ERR_") != std::string::npos || line.find("Not allowed to load") != std::string::npos)
      found.push_back(line);
  return found;
}

}  // namespace

TEST(Report, ChromiumLoadsEveryImageAndVideoAndTheSliderMoves) {
  const ScratchDirectory scratch;
  const fs::path home = scratch / "home";
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "chromium is not installed";
  make_outputs(scratch / "runs", home, true);
  const Ran made = run_glintlab("report -o " + quoted(scratch / "report") + " " + quoted(scratch / "runs"), home);
  ASSERT_EQ(made.code, 0) << made.err;

  // What the page holds: copies of the PNGs and MP4s it shows, never an EXR, no path of this machine.
  int pngs = 0, mp4s = 0;
  for (const auto& e : fs::recursive_directory_iterator(scratch / "report" / "assets")) {
    EXPECT_NE(e.path().extension(), ".exr") << e.path();
    pngs += e.path().extension() == ".png";
    mp4s += e.path().extension() == ".mp4";
  }
  const auto crops = nlohmann::json::parse(read_text(scratch / "runs" / "compare" / "metrics.json"))["crops"].size();
  // The reference, each method with its error map and FLIP map, the strips.
  EXPECT_EQ(pngs, 1 + 2 * 3 + static_cast<int>(crops));
  EXPECT_EQ(mp4s, 3);                                    // reference and both methods
  const std::string page = read_text(scratch / "report" / "index.html");
  EXPECT_EQ(page.find(scratch.path().string()), std::string::npos) << "the page names a path of this machine";
  const std::regex url("https?://(?!www\\.w3\\.org/2000/svg)");
  EXPECT_FALSE(std::regex_search(page, url)) << "the page names a network URL";

  const BrowserResult ok = open_selftest(scratch / "report", home, scratch / "shot.png");
  if (!ok.started)
    GTEST_SKIP() << "chromium --headless does not start (exit " << ok.code << "): " << ok.log.substr(0, 600);
  ASSERT_EQ(ok.selftest.rfind("PASS", 0), 0u) << ok.selftest << "\n" << ok.log;
  EXPECT_NE(ok.selftest.find("runs=3 "), std::string::npos) << ok.selftest;
  EXPECT_NE(ok.selftest.find("sliders=1 "), std::string::npos) << ok.selftest;
  EXPECT_NE(ok.selftest.find("crop-labels=" + std::to_string(3 * crops)), std::string::npos) << ok.selftest;
  for (const auto& line : page_problems(ok.log)) ADD_FAILURE() << "chromium: " << line;
  ASSERT_TRUE(fs::exists(scratch / "shot.png")) << ok.log;
  EXPECT_GT(luminance_spread(scratch / "shot.png"), 0.05) << "the screenshot is blank";

  // The self-test can fail: the same report without one method's image.
  fs::copy(scratch / "report", scratch / "broken", fs::copy_options::recursive);
  fs::remove(scratch / "broken" / "assets" / "compare" / "vlachos.png");
  const BrowserResult broken = open_selftest(scratch / "broken", home, scratch / "broken.png");
  EXPECT_EQ(broken.selftest.rfind("FAIL", 0), 0u) << broken.selftest;
  EXPECT_NE(broken.selftest.find("vlachos.png"), std::string::npos) << broken.selftest;

  // Every video was played unless the browser cannot decode H.264: then the self-test says so.
  if (const auto at = ok.selftest.find("LIMITATION"); at != std::string::npos)
    GTEST_SKIP() << "videos not checked: " << ok.selftest.substr(at);
  EXPECT_NE(ok.selftest.find("videos=3 "), std::string::npos) << ok.selftest;
}

TEST(Report, BadInputExitsTwoNamingTheFileAndKeyAndLeavesTheOldReport) {
  const ScratchDirectory scratch;
  const fs::path home = scratch / "home", runs = scratch / "runs", out = scratch / "report";
  make_outputs(runs, home, false);
  const fs::path metrics = runs / "compare" / "metrics.json";
  const std::string good_metrics = read_text(metrics);

  auto expect_refused = [&](const std::string& inputs, std::initializer_list<std::string> fragments) {
    const std::string before = fs::exists(out / "index.html") ? read_text(out / "index.html") : "";
    const Ran r = run_glintlab("report -o " + quoted(out) + " " + inputs, home);
    EXPECT_EQ(r.code, 2) << inputs << "\n" << r.err;
    for (const auto& f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "'" << f << "' not in: " << r.err;
    if (before.empty())
      EXPECT_FALSE(fs::exists(out)) << "partial output for " << inputs;
    else
      EXPECT_EQ(read_text(out / "index.html"), before) << "the old report changed";
  };
  auto with_metrics = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = nlohmann::json::parse(good_metrics);
    edit(j);
    std::ofstream(metrics) << j.dump(2);
  };

  expect_refused(quoted(scratch / "nowhere"), {(scratch / "nowhere").string(), "no such directory"});
  std::ofstream(metrics) << good_metrics.substr(0, good_metrics.size() / 2);
  expect_refused(quoted(runs), {metrics.string(), "not valid JSON"});
  with_metrics([](nlohmann::json& j) { j["methods"][1].erase("rmse"); });
  expect_refused(quoted(runs), {metrics.string(), "'methods[1].rmse'", "missing"});
  // A method's file name (a variant's "vlachos.scale=4") is a path inside the run's folder; outputs
  // from before variants have none, and the method's name is its file name.
  with_metrics([](nlohmann::json& j) { j["methods"][0]["file"] = "../../etc"; });
  expect_refused(quoted(runs), {metrics.string(), "'methods[0].file'", "../../etc"});
  with_metrics([](nlohmann::json& j) {
    j["methods"][0].erase("file");
    j["methods"][0]["method"] = "../../etc";
  });
  expect_refused(quoted(runs), {metrics.string(), "'methods[0].method'", "../../etc"});
  with_metrics([](nlohmann::json& j) { j["crops"][0]["cell"] = 100; });
  expect_refused(quoted(runs), {(runs / "compare" / "worst-region-1.png").string(), "100 px"});

  // Values no glintlab run writes: a negative error.
  with_metrics([](nlohmann::json& j) { j["methods"][0]["rmse"] = -1e308; });
  expect_refused(quoted(runs), {metrics.string(), "'methods[0].rmse'", "a finite number >= 0"});
  std::ofstream(metrics) << good_metrics;

  // A report reads only the run's own regular files: an image that is a link to elsewhere is
  // refused, not copied; a file that does not decode is refused before anything is published.
  const fs::path image = runs / "compare" / "conventional.png";
  fs::rename(image, scratch / "aside.png");
  std::ofstream(scratch / "secret.txt") << "not for the report\n";
  fs::create_symlink(scratch / "secret.txt", image);
  expect_refused(quoted(runs), {image.string(), "symbolic link", "regular file inside the run's folder"});
  fs::remove(image);
  std::ofstream(image) << "text, not a PNG\n";
  expect_refused(quoted(runs), {image.string(), "PNG"});
  fs::remove(image);
  fs::rename(scratch / "aside.png", image);

  // A bench.json by hand: a negative time, a frame count past the CLI's limit.
  const fs::path bench = runs / "bench-by-hand" / "bench.json";
  fs::create_directories(bench.parent_path());
  auto write_bench = [&](const std::string& frames, const std::string& wall_ms) {
    std::ofstream(bench) << R"({"scene": "builtin:spheres", "width": 48, "height": 32, "frames": )" << frames
                         << R"(, "methods": [{"method": "conventional", "gpu_ms_median": 1.0, "wall_ms_median": )"
                         << wall_ms << "}]}";
  };
  write_bench("2", "-3");
  expect_refused(quoted(runs), {bench.string(), "'methods[0].wall_ms_median'", "-3"});
  write_bench("1000000000", "3");
  expect_refused(quoted(runs), {bench.string(), "'frames'", "1 to 100000"});
  fs::remove_all(bench.parent_path());

  // A good report, then bad input again: the report stays as it was.
  std::ofstream(metrics) << good_metrics;
  ASSERT_EQ(run_glintlab("report -o " + quoted(out) + " " + quoted(runs), home).code, 0);
  fs::rename(runs / "compare" / "vlachos-error.png", scratch / "aside.png");
  expect_refused(quoted(runs), {(runs / "compare" / "vlachos-error.png").string(), "missing"});
  EXPECT_TRUE(fs::exists(out / "assets" / "compare" / "vlachos-error.png"));
  fs::rename(scratch / "aside.png", runs / "compare" / "vlachos-error.png");

  // Metrics of no known kind are skipped with a warning; a report of nothing is refused.
  fs::create_directories(runs / "other");
  std::ofstream(runs / "other" / "metrics.json") << R"({"rank": 8})";
  const Ran skipped = run_glintlab("report -o " + quoted(out) + " " + quoted(runs), home);
  EXPECT_EQ(skipped.code, 0) << skipped.err;
  EXPECT_NE(skipped.err.find((runs / "other" / "metrics.json").string()), std::string::npos) << skipped.err;
  EXPECT_NE(skipped.err.find("skipped"), std::string::npos) << skipped.err;
  fs::remove_all(out);
  expect_refused(quoted(runs / "other"), {(runs / "other").string(), "no compare, animate, bench or converge output"});
}

TEST(Report, EachCropCellShowsTheMethodItIsLabelledWith) {
  const ScratchDirectory scratch;
  const fs::path home = scratch / "home", report = scratch / "report";
  make_outputs(scratch / "runs", home, false);
  ASSERT_EQ(run_glintlab("report -o " + quoted(report) + " " + quoted(scratch / "runs"), home).code, 0);
  // The page's own data: the label of each column and the window each cell shows of a strip.
  const std::string page = read_text(report / "index.html");
  const std::string open = "<script type=\"application/json\" id=\"report-data\">";
  const auto begin = page.find(open) + open.size();
  const auto run = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin))["runs"][0];
  ASSERT_EQ(run["kind"], "compare");
  ASSERT_FALSE(run["regions"].empty());
  for (const auto& region : run["regions"]) {
    const glintlab::Image strip = glintlab::read_ldr_image(report / region["strip"].get<std::string>());
    const int cell = region["cell"], gap = region["gap"], size = region["size"], x0 = region["x"], y0 = region["y"];
    for (std::size_t column = 0; column < run["columns"].size(); ++column) {
      const std::string label = run["columns"][column];
      const glintlab::Image image = glintlab::read_ldr_image(report / "assets" / "compare" / (label + ".png"));
      int differing = 0;
      for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) {
          const auto shown = strip.at(static_cast<int>(column) * (cell + gap) + x, y);
          const auto source = image.at(x0 + x * size / cell, y0 + y * size / cell);
          differing += shown != source;
        }
      EXPECT_EQ(differing, 0) << label << "'s cell of " << region["strip"];
    }
  }
  // The strips compare wrote carry each crop's name in a band below it (the page hides the band).
  const auto crops = nlohmann::json::parse(read_text(scratch / "runs" / "compare" / "metrics.json"))["crops"];
  for (const auto& c : crops) {
    const glintlab::Image strip = glintlab::read_ldr_image(scratch / "runs" / "compare" / c["file"].get<std::string>());
    const int cell = c["cell"], gap = c["gap"], band = c["label_height"];
    ASSERT_GT(band, 0) << c["file"] << ": no label band (is fonts-dejavu-core installed?)";
    ASSERT_EQ(strip.height(), cell + band) << c["file"];
    for (std::size_t column = 0; column < run["columns"].size(); ++column) {
      int ink = 0;
      for (int y = cell; y < cell + band; ++y)
        for (int x = 0; x < cell; ++x) ink += strip.at(static_cast<int>(column) * (cell + gap) + x, y).r < 0.5f;
      EXPECT_GT(ink, 20) << "no name under column " << column << " of " << c["file"];
    }
  }
}

TEST(Report, ANewReportReplacesTheAssetsOfTheOld) {
  const ScratchDirectory scratch;
  const fs::path home = scratch / "home";
  make_outputs(scratch / "a", home, false);
  fs::create_directories(scratch / "b");
  fs::copy(scratch / "a" / "compare", scratch / "b" / "other", fs::copy_options::recursive);
  ASSERT_EQ(run_glintlab("report -o " + quoted(scratch / "r") + " " + quoted(scratch / "a"), home).code, 0);
  const Ran second = run_glintlab("report -o " + quoted(scratch / "r") + " " + quoted(scratch / "b"), home);
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_FALSE(fs::exists(scratch / "r" / "assets" / "compare"));
  EXPECT_TRUE(fs::exists(scratch / "r" / "assets" / "other" / "reference.png"));
  for (const auto& e : fs::directory_iterator(scratch / "r"))
    EXPECT_TRUE(e.path().filename() == "index.html" || e.path().filename() == "assets") << e.path();
}

namespace {
/// The numbers of an SVG attribute, in order: points="x,y x,y" or y1="..".
std::vector<double> numbers_in(const std::string& text) {
  std::vector<double> v;
  const std::regex number("-?[0-9]+(\\.[0-9]+)?");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    v.push_back(std::stod(it->str()));
  return v;
}
std::string first_match(const std::string& text, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(pattern)) ? m[1].str() : "";
}
}  // namespace

TEST(ReportSvg, LinesAndBarsAreProportionalToTheirValuesAndFloorsAtTheirHeight) {
  const std::string plot = glintlab::line_plot_svg("t", "RMSE", {{"a<b", {0.0, 1.0, 3.0}}}, {{"floor", 1.0}});
  const std::vector<double> p = numbers_in(first_match(plot, "points=\"([^\"]*)\""));
  ASSERT_EQ(p.size(), 6u);
  // y grows downward: the value 1 sits a third of the way from 0 to 3, and the floor of 1 with it.
  EXPECT_NEAR((p[1] - p[3]) / (p[1] - p[5]), 1.0 / 3.0, 1e-3);
  EXPECT_NEAR(p[2] - p[0], p[4] - p[2], 1e-6);  // frames evenly spaced
  const std::string floor_y = first_match(plot, "<g class=\"mark\">.*?y1=\"([^\"]*)\"");
  ASSERT_FALSE(floor_y.empty()) << plot;
  EXPECT_NEAR(std::stod(floor_y), p[3], 0.05);
  EXPECT_NE(plot.find("a&lt;b"), std::string::npos) << "a name is written escaped";

  const std::string bars = glintlab::bar_chart_svg("t", "ms", {{"x", 2.0, "", false, 0}, {"y", 5.0, "", false, 1}}, {});
  std::vector<double> widths;
  const std::regex rect("<rect [^>]*width=\"([0-9.]+)\"");
  for (auto it = std::sregex_iterator(bars.begin(), bars.end(), rect); it != std::sregex_iterator(); ++it)
    widths.push_back(std::stod((*it)[1].str()));
  ASSERT_EQ(widths.size(), 2u);
  EXPECT_NEAR(widths[0] / widths[1], 2.0 / 5.0, 1e-3);
}

TEST(ReportSvg, LogLogPointsSitAtTheirLogarithms) {
  // A power law is a straight line: error 1, 0.1, 0.01 at 1, 10, 100 seconds, evenly spaced on both axes.
  const std::string plot =
      glintlab::log_log_plot_svg("t", "seconds", "RMSE", {{"a", {{1.0, 1.0, ""}, {10.0, 0.1, ""}, {100.0, 0.01, ""}}}},
                                 {{"floor", 0.1}});
  const std::vector<double> p = numbers_in(first_match(plot, "points=\"([^\"]*)\""));
  ASSERT_EQ(p.size(), 6u);
  EXPECT_NEAR(p[2] - p[0], p[4] - p[2], 0.11);
  EXPECT_NEAR(p[3] - p[1], p[5] - p[3], 0.11);
  EXPECT_GT(p[3], p[1]);  // lower error, lower on the page (y grows downward)
  const std::string floor_y = first_match(plot, "<g class=\"mark\">.*?y1=\"([^\"]*)\"");
  ASSERT_FALSE(floor_y.empty()) << plot;
  EXPECT_NEAR(std::stod(floor_y), p[3], 0.11);  // the floor of 0.1 at the second point's height
}

TEST(Report, AConvergeRunShowsItsCurvesAndTheirTimeToTheTarget) {
  const ScratchDirectory scratch;
  const fs::path home = scratch / "home";
  Ran r = run_glintlab("converge -q --scene builtin:spheres --width 24 --height 16 --spp 64 --backends "
                       "raster,path-unshadowed --steps 1,4 -o " + quoted(scratch / "runs" / "converge"),
                       home);
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_glintlab("report -o " + quoted(scratch / "report") + " " + quoted(scratch / "runs"), home);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = read_text(scratch / "report" / "index.html");
  for (const char* part : {"\"kind\":\"converge\"", "\"seconds_to_target\"", "path-unshadowed",
                           "error against time, builtin:spheres", "error against samples, builtin:spheres"})
    EXPECT_NE(page.find(part), std::string::npos) << part;
}

TEST(Report, ACompareRunCarriesFlipTheSparkleDistanceAndFlipMapsWhereItMeasuredThem) {
  const ScratchDirectory scratch;
  const fs::path home = scratch / "home", runs = scratch / "runs";
  make_outputs(runs, home, false);
  auto compare_of = [&](const fs::path& report) {
    const std::string page = read_text(report / "index.html");
    const std::string open = "<script type=\"application/json\" id=\"report-data\">";
    const auto begin = page.find(open) + open.size();
    const auto data = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
    for (const auto& run : data["runs"])
      if (run["kind"] == "compare") return run;
    return nlohmann::json();
  };
  auto table_of = [&](const fs::path& report) { return compare_of(report)["table"]; };
  ASSERT_EQ(run_glintlab("report -o " + quoted(scratch / "report") + " " + quoted(runs), home).code, 0);
  const nlohmann::json table = table_of(scratch / "report");
  // Each method's FLIP map is offered beside its error map, copied with the report.
  for (const auto& m : compare_of(scratch / "report")["images"]["methods"]) {
    ASSERT_TRUE(m.contains("flip")) << m.dump();
    EXPECT_TRUE(fs::is_regular_file(scratch / "report" / m["flip"].get<std::string>())) << m.dump();
  }
  const auto metrics = nlohmann::json::parse(read_text(runs / "compare" / "metrics.json"));
  std::set<std::string> columns;
  for (const auto& c : table["columns"]) columns.insert(c["key"].get<std::string>());
  for (const char* key : {"flip_ldr", "flip_hdr", "sparkle_distance"}) {
    EXPECT_TRUE(columns.count(key)) << key;
    for (std::size_t i = 0; i < table["rows"].size(); ++i)
      EXPECT_EQ(table["rows"][i][key], metrics["methods"][i][key]) << key;
  }
  // Outputs from before these metrics: the same report without their columns.
  auto old = metrics;
  old.erase("reference_floor");
  for (auto& m : old["methods"])
    for (const char* key : {"flip_ldr", "flip_hdr", "sparkle_distance"}) m.erase(key);
  std::ofstream(runs / "compare" / "metrics.json") << old.dump(2);
  ASSERT_EQ(run_glintlab("report -o " + quoted(scratch / "old-report") + " " + quoted(runs), home).code, 0);
  for (const auto& c : table_of(scratch / "old-report")["columns"]) EXPECT_NE(c["key"], "flip_ldr");
  for (const auto& m : compare_of(scratch / "old-report")["images"]["methods"]) EXPECT_FALSE(m.contains("flip"));
}
