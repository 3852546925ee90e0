#pragma once
// A reference split into tiles of the film, each rendered by an independent job (`render
// --reference --tile INDEX/COLUMNSxROWS`, run by GNU parallel, over ssh, or as a Slurm array:
// docs/past-one-machine.md), and put back together by `glintlab merge-tiles`. Each tile's EXR has a
// JSON beside it that says what it is a part of (scene, frame, film, sampling, estimator) and holds
// its passes' mean luminances, from which the whole frame's energy error is recomputed.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "eval/session.hpp"
#include "render/reference_backend.hpp"
#include "render/reference_estimate.hpp"

namespace glintlab {

/// What a tile is a part of: tiles merge only when all of these agree.
nlohmann::json reference_tile_identity(Session& session, int frame);

/// Writes <dir>/<stem>.exr and .png (write_reference) and <dir>/<stem>.json: `identity`, the
/// region of the film the frame covers, the devices that rendered it and its passes' luminances.
void write_reference_tile(const std::filesystem::path& dir, const std::string& stem, const ReferenceFrame& reference,
                          const Film& film, const nlohmann::json& identity, const FilmRegion& region,
                          const std::string& devices);

/// `glintlab merge-tiles TILE.exr ... -o OUT`: the whole frame from tiles that cover the film once.
/// Throws InputError (nothing written) naming the tile and key when tiles disagree, overlap or
/// leave a pixel uncovered, or a tile's files are missing or malformed.
void run_merge_tiles(const std::vector<std::string>& tiles, const std::string& out);

}  // namespace glintlab
