// The reference-backend interface (src/render/reference_backend.hpp): the pass loop is the same
// for every backend, and a backend's id and estimator are part of every reference cache key.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "render/reference_backend.hpp"
#include "render/reference_cache.hpp"
#include "scene/scene_loader.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;

namespace {

/// A CPU backend whose pass is a flat image of a value drawn from the pass's seed: the mean and
/// spread of render_reference() can then be computed here independently.
class FlatPasses final : public ReferenceBackend {
 public:
  explicit FlatPasses(std::string id, std::uint64_t estimator = 1) : id_(std::move(id)), estimator_(estimator) {}
  [[nodiscard]] std::string id() const override { return id_; }
  [[nodiscard]] std::uint64_t estimator_hash() const override { return estimator_; }
  Frame render_pass(const Camera&, int width, int height, const ReferencePass& pass, const ProgressFn&) override {
    seen.push_back(pass);
    const float v = value(pass.seed);
    return {Image(width, height, glm::vec3(v)), Image(width, height, glm::vec3(0.5f * v))};
  }
  static float value(std::uint32_t seed) { return static_cast<float>(seed % 1000u) / 1000.0f; }
  std::vector<ReferencePass> seen;

 private:
  std::string id_;
  std::uint64_t estimator_;
};

}  // namespace

TEST(ReferenceBackend, PassesAreTheSettingsPassesAndTheirMeanIsTheEstimate) {
  FlatPasses backend("flat");
  const ReferenceSettings settings{.spp = 256, .light_samples = 0, .seed = 7};  // 4 passes of 8 x 8
  const ReferenceFrame r = render_reference(backend, Camera{}, 4, 3, settings);
  ASSERT_EQ(backend.seen.size(), 4u);
  double sum = 0.0, squares = 0.0;
  for (int p = 0; p < 4; ++p) {
    const ReferencePass& pass = backend.seen[static_cast<std::size_t>(p)];
    EXPECT_EQ(pass.subpixels, 8);
    EXPECT_EQ(pass.light_samples, 1);
    EXPECT_EQ(pass.seed, reference_pass_seed(7, p));
    EXPECT_EQ(pass.jitter, reference_pass_jitter(7, p));
    sum += FlatPasses::value(pass.seed);
    squares += std::pow(FlatPasses::value(pass.seed), 2);
  }
  const double mean = sum / 4.0, variance = (squares - 4.0 * mean * mean) / 3.0;
  EXPECT_EQ(r.passes, 4);
  EXPECT_EQ(r.spp, 256);
  EXPECT_NEAR(r.mean.total.at(2, 1).x, mean, 1e-6);
  EXPECT_NEAR(r.mean.specular.at(3, 2).y, 0.5 * mean, 1e-6);
  EXPECT_NEAR(r.standard_error.at(0, 0).z, std::sqrt(variance / 4.0), 1e-6);
}

TEST(ReferenceBackend, IdAndEstimatorArePartOfTheCacheKey) {
  const Scene scene = load_scene("builtin:spheres");
  const ReferenceSettings settings{.spp = 64};
  const auto key = [&](const ReferenceBackend& b) {
    return ReferenceCache::key(scene, scene.camera, 32, 32, settings, b, "device");
  };
  EXPECT_EQ(key(FlatPasses("a")), key(FlatPasses("a")));
  EXPECT_NE(key(FlatPasses("a")), key(FlatPasses("b")));
  EXPECT_NE(key(FlatPasses("a", 1)), key(FlatPasses("a", 2)));
}

TEST(ReferenceBackend, PixelFilterIsPartOfTheCacheKeyAndOfEveryPass) {
  const Scene scene = load_scene("builtin:spheres");
  const FlatPasses backend("a");
  const auto key = [&](const std::string& filter) {
    ReferenceSettings settings{.spp = 64};
    settings.filter = PixelFilter::parse(filter);
    return ReferenceCache::key(scene, scene.camera, 32, 32, settings, backend, "device");
  };
  EXPECT_EQ(key("gaussian:0.5"), key("gaussian:0.5"));
  EXPECT_NE(key("box"), key("gaussian:0.5"));
  EXPECT_NE(key("gaussian:0.5"), key("gaussian:0.6"));
  ReferenceSettings settings{.spp = 64};
  settings.filter = PixelFilter::gaussian(0.5f);
  EXPECT_EQ(ReferencePass::of(settings, 2).filter, settings.filter);
}

TEST(ReferenceBackend, CachedFrameIsOnlyFoundUnderItsBackendsKey) {
  const test::ScratchDirectory dir;
  {
    const ReferenceCache cache(dir.path());
    const Scene scene = load_scene("builtin:spheres");
    const ReferenceSettings settings{.spp = 16};
    FlatPasses a("a"), b("b");
    const ReferenceFrame frame = render_reference(a, scene.camera, 4, 4, settings);
    cache.store(ReferenceCache::key(scene, scene.camera, 4, 4, settings, a, "device"), frame);
    const auto hit = cache.load(ReferenceCache::key(scene, scene.camera, 4, 4, settings, a, "device"), 4, 4);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->mean.total.at(1, 1), frame.mean.total.at(1, 1));
    EXPECT_FALSE(cache.load(ReferenceCache::key(scene, scene.camera, 4, 4, settings, b, "device"), 4, 4).has_value());
  }
}

TEST(ReferenceBackend, UnknownIdNamesTheRegisteredBackends) {
  ASSERT_FALSE(reference_backends().empty());
  EXPECT_EQ(reference_backends().front().id, "raster");
  try {
    (void)find_reference_backend("path-tracer-9000");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path-tracer-9000"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("raster"), std::string::npos);
  }
}
