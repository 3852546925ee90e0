#include "eval/reference_tiles.hpp"

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>

#include "core/error.hpp"
#include "core/image_io.hpp"
#include "eval/outputs.hpp"

namespace glintlab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string hex(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

// A tile's files and what its JSON says.
struct Tile {
  fs::path exr;
  json meta;
  FilmRegion region;
};

// meta[key] as T, or InputError naming the file and key.
template <typename T>
T field(const json& meta, const char* key, const fs::path& file) {
  if (!meta.contains(key)) throw InputError(file.string() + ": no \"" + key + "\"; is it a tile render --reference --tile wrote?");
  try {
    return meta.at(key).get<T>();
  } catch (const json::exception&) {
    throw InputError(file.string() + ": \"" + key + "\" is " + meta.at(key).dump() + ": not what a tile holds");
  }
}

Tile read_tile(const std::string& path) {
  Tile tile{fs::path(path), {}, {}};
  if (tile.exr.extension() != ".exr")
    throw InputError("merge-tiles: " + path + ": allowed: the .exr files that render --reference --tile wrote");
  fs::path sidecar = tile.exr;
  sidecar.replace_extension(".json");
  std::ifstream in(sidecar);
  if (!in) throw InputError("merge-tiles: " + path + ": no " + sidecar.string() + " beside it (render --reference --tile writes both)");
  try {
    tile.meta = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(sidecar.string() + ": not JSON: " + e.what());
  }
  if (!tile.meta.is_object() || tile.meta.value("glintlab", "") != "reference tile")
    throw InputError(sidecar.string() + ": not a reference tile (\"glintlab\": \"reference tile\" missing)");
  const auto r = field<std::vector<int>>(tile.meta, "region", sidecar);
  if (r.size() != 4) throw InputError(sidecar.string() + ": \"region\" has " + std::to_string(r.size()) + " numbers; allowed: x, y, width, height");
  tile.region = {r[0], r[1], r[2], r[3]};
  field<json>(tile.meta, "identity", sidecar);
  return tile;
}

}  // namespace

json reference_tile_identity(Session& session, int frame) {
  const ReferenceSettings& s = session.reference_settings();
  return {{"scene", session.scene().source},
          {"scene_hash", hex(session.scene().content_hash())},
          {"frame", frame},
          {"film", {session.width(), session.height()}},
          {"spp", s.spp},
          {"subpixels", s.subpixels()},
          {"light_samples", s.effective_light_samples()},
          {"filter", s.filter.text()},
          {"backend", session.reference_backend().id()},
          {"estimator", hex(session.reference_backend().estimator_hash())}};
}

void write_reference_tile(const fs::path& dir, const std::string& stem, const ReferenceFrame& reference, const Film& film,
                          const json& identity, const FilmRegion& region, const std::string& devices) {
  write_reference(dir, stem, reference, film);
  const json meta = {{"glintlab", "reference tile"},
                     {"identity", identity},
                     {"region", {region.x, region.y, region.width, region.height}},
                     {"device", devices},
                     {"passes", reference.passes},
                     {"pass_luminance", reference.pass_luminance},
                     {"pass_luminance_specular", reference.pass_luminance_specular},
                     {"exposure", film.exposure},
                     {"bloom", film.bloom}};
  std::ofstream(dir / (stem + ".json")) << meta.dump(2) << "\n";
}

void run_merge_tiles(const std::vector<std::string>& paths, const std::string& out) {
  if (paths.empty()) throw InputError("merge-tiles: no tiles given; allowed: the .exr files render --reference --tile wrote");
  const FrameOutput target = frame_output(out, "reference");
  std::vector<Tile> tiles;
  for (const std::string& path : paths) {
    tiles.push_back(read_tile(path));
    if (fs::weakly_canonical(tiles.back().exr) == fs::weakly_canonical(target.dir / (target.stem + ".exr")))
      throw InputError("merge-tiles: -o " + out + " would overwrite the tile " + path);
  }

  // Every tile a part of the same reference.
  const Tile& first = tiles.front();
  const json& identity = first.meta.at("identity");
  const int passes = field<int>(first.meta, "passes", first.exr);
  for (const Tile& tile : tiles) {
    for (const auto& [key, value] : identity.items())
      if (!tile.meta.at("identity").contains(key) || tile.meta.at("identity").at(key) != value)
        throw InputError("merge-tiles: " + tile.exr.string() + ": " + key + " " +
                         tile.meta.at("identity").value(key, json()).dump() + ", but " + first.exr.string() + " has " +
                         value.dump() + "; the tiles of one reference share scene, frame, film, sampling and estimator");
    if (field<int>(tile.meta, "passes", tile.exr) != passes)
      throw InputError("merge-tiles: " + tile.exr.string() + ": " + std::to_string(field<int>(tile.meta, "passes", tile.exr)) +
                       " passes, but " + first.exr.string() + " has " + std::to_string(passes));
  }
  const auto film_size = identity.at("film").get<std::vector<int>>();
  const int width = film_size.at(0), height = film_size.at(1);

  // The tiles cover the film once.
  std::vector<int> owner(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const FilmRegion& r = tiles[i].region;
    if (r.empty() || r.x < 0 || r.y < 0 || r.x + r.width > width || r.y + r.height > height)
      throw InputError("merge-tiles: " + tiles[i].exr.string() + ": region " + std::to_string(r.x) + "," +
                       std::to_string(r.y) + " " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                       " is not inside the " + std::to_string(width) + "x" + std::to_string(height) + " film");
    for (int y = r.y; y < r.y + r.height; ++y)
      for (int x = r.x; x < r.x + r.width; ++x) {
        int& o = owner[static_cast<std::size_t>(y) * width + x];
        if (o >= 0)
          throw InputError("merge-tiles: " + tiles[static_cast<std::size_t>(o)].exr.string() + " and " +
                           tiles[i].exr.string() + " both cover pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")");
        o = static_cast<int>(i);
      }
  }
  if (const auto gap = std::find(owner.begin(), owner.end(), -1); gap != owner.end()) {
    const auto at = static_cast<int>(gap - owner.begin());
    throw InputError("merge-tiles: pixel (" + std::to_string(at % width) + ", " + std::to_string(at / width) + ") is in no tile; " +
                     std::to_string(std::count(owner.begin(), owner.end(), -1)) + " of the " + std::to_string(width) + "x" +
                     std::to_string(height) + " film's pixels are missing");
  }

  // The frame: pixels from their tiles; each pass's mean luminance the tiles' weighted by area.
  ReferenceFrame merged;
  merged.mean = {Image(width, height), Image(width, height)};
  merged.standard_error = Image(width, height);
  merged.passes = passes;
  merged.spp = identity.at("spp").get<int>();
  merged.pass_luminance.assign(static_cast<std::size_t>(passes), 0.0);
  merged.pass_luminance_specular.assign(static_cast<std::size_t>(passes), 0.0);
  std::set<std::string> devices;
  const double film_pixels = static_cast<double>(width) * height;
  for (const Tile& tile : tiles) {
    const FilmRegion& r = tile.region;
    const Image total = read_exr(tile.exr), specular = read_exr(tile.exr, "specular"),
                error = read_exr(tile.exr, "standard_error");
    for (const Image* layer : {&total, &specular, &error})
      if (layer->width() != r.width || layer->height() != r.height)
        throw InputError("merge-tiles: " + tile.exr.string() + " is " + std::to_string(layer->width()) + "x" +
                         std::to_string(layer->height()) + ", but its JSON says its region is " + std::to_string(r.width) +
                         "x" + std::to_string(r.height));
    if (total.count_non_finite() + specular.count_non_finite() + error.count_non_finite() > 0)
      throw InputError("merge-tiles: " + tile.exr.string() + " holds NaN or Inf");
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        merged.mean.total.at(r.x + x, r.y + y) = total.at(x, y);
        merged.mean.specular.at(r.x + x, r.y + y) = specular.at(x, y);
        merged.standard_error.at(r.x + x, r.y + y) = error.at(x, y);
      }
    const auto luminance = field<std::vector<double>>(tile.meta, "pass_luminance", tile.exr);
    const auto luminance_specular = field<std::vector<double>>(tile.meta, "pass_luminance_specular", tile.exr);
    if (luminance.size() != static_cast<std::size_t>(passes) || luminance_specular.size() != luminance.size())
      throw InputError("merge-tiles: " + tile.exr.string() + ": " + std::to_string(luminance.size()) +
                       " pass luminances for " + std::to_string(passes) + " passes");
    const double share = static_cast<double>(r.width) * r.height / film_pixels;
    for (int p = 0; p < passes; ++p) {
      merged.pass_luminance[static_cast<std::size_t>(p)] += share * luminance[static_cast<std::size_t>(p)];
      merged.pass_luminance_specular[static_cast<std::size_t>(p)] += share * luminance_specular[static_cast<std::size_t>(p)];
    }
    devices.insert(tile.meta.value("device", ""));
  }
  merged.even_passes = merged.odd_passes = merged.mean.total;  // not kept by tiles

  std::string device_list;
  for (const std::string& d : devices) device_list += (device_list.empty() ? "" : "; ") + d;
  const Film film{.width = width,
                  .height = height,
                  .exposure = first.meta.value("exposure", 0.0f),
                  .bloom = first.meta.value("bloom", 0.0f)};
  write_reference_tile(target.dir, target.stem, merged, film, identity, {0, 0, width, height}, device_list);
  std::cout << describe_reference(merged) << ", merged from " << tiles.size() << " tiles\n"
            << "written " << (target.dir / target.stem).string() << ".exr, .png and .json\n";
}

}  // namespace glintlab
