#pragma once
// Parameters and citations that several method descriptors share.
#include <string>

#include "core/pixel_filter_width.hpp"
#include "shading/method.hpp"

namespace glintlab {

/// Upper clamp of the slope-space footprint (Kaplanyan et al. 2016's fp_max).
inline ParamDecl fp_max_param() {
  return {"fp_max", 1.0f, 0.01f, 4.0f,
          "upper clamp of the footprint's half extent in slope space (the talk uses 0.1 .. 1)"};
}

/// LEAN + glints (Chermain et al. 2021, sec. 5): the glint lobe widened by the normal map's slope
/// covariance inside the footprint.
inline ParamDecl glint_lean_param(bool on_by_default) {
  return {"lean", on_by_default ? 1.0f : 0.0f, 0.0f, 1.0f,
          "LEAN + glints: add the normal map's slope covariance inside the pixel's footprint to the glint "
          "lobe and shade about the mean normal (chermain2020 keeps only its diagonal)",
          {"off", "on"}};
}

/// How a lobe method integrates lights with extent (docs/methods.md, "Area lights"): the lobe's
/// mass over the light's image with Fresnel and masking at the representative point, or the lobe's
/// linearly transformed cosine integrated over the light's polygon or disk (Heitz et al. 2016).
inline ParamDecl area_lights_param() {
  return {.name = "area_lights",
          .default_value = 1.0f,  // LTC: closer to the reference for every kind and roughness measured
                                  // (docs/results.md, "Area lights: representative point or LTC")
          .min = 0.0f,
          .max = 1.0f,
          .description = "lights with extent: the lobe's mass over the light's image with Fresnel and masking at "
                         "the representative point, or the lobe's LTC integrated over the light's exact shape "
                         "(Heitz et al. 2016; GGX lobes only, Beckmann keeps the representative point)",
          .choices = {"representative-point", "ltc"},
          .compile_time = true,
          .choice_tables = {{}, {"ltc-ggx"}}};
}

/// How the Chermain glint methods shade a light with extent (docs/methods.md, "Area lights: the
/// light's half-vector region as a slope-space kernel"): each cell's slope distribution averaged
/// over the light's half-vector region through the filtered dictionary lookups, or the light as a
/// point at its centre carrying radiance x solid angle (the models' published form).
inline ParamDecl glint_light_extent_param() {
  return {.name = "light_extent",
          .default_value = 1.0f,  // lower RMSE than the centre for every light size measured
                                  // (tests/render/test_chermain_area_lights.cpp, docs/results.md)
          .min = 0.0f,
          .max = 1.0f,
          .description = "lights with extent: each cell's slope distribution averaged over the light's half-vector "
                         "region (an ellipse in slope space, added to the lookups' kernel), or the light as a point "
                         "at its centre carrying radiance x solid angle",
          .choices = {"centre", "half-vector-kernel"},
          .compile_time = true};
}

/// The binomial glints' cell size in pixels (Deliot & Belcour 2023; deliot2023, kneiphof2024).
inline ParamDecl binomial_screen_space_scale_param() {
  return {"screen_space_scale", 1.5f, 0.5f, 8.0f,
          "the glints' smallest size in pixels: grid cells this many pixels across the footprint's minor "
          "axis (1 aliases, at Shannon's limit; the paper recommends 1.5)"};
}

/// The law of the reflecting facets besides the first (docs/methods.md, deliot2023).
inline ParamDecl binomial_remaining_count_param() {
  return {"remaining_count", 0, 0, 1,
          "the law of the reflecting facets besides the first: a lognormal with the binomial's exact "
          "conditional mean and variance (E[D_glint] = D(h) at every density), or the paper's Gaussian "
          "binomial(n - 1, p), clamped to [0, n - 1] (biased up where about one facet reflects)",
          {"lognormal", "gaussian"},
          /*compile_time=*/true};
}

/// The pixel's Gaussian footprint of the methods on normal-map-glints materials (yan2016, deng2022).
inline ParamDecl footprint_sigma_param() {
  return {"footprint_sigma", kPixelFilterSigma, 0.05f, 4.0f,
          "standard deviation of the pixel's Gaussian footprint in pixels, mapped to the normal map's texels "
          "by the uv Jacobian (default " +
              pixel_filter_sigma_text() +
              ": glintlab's one pixel-filter width, about a pixel's box; the reference's --reference-filter "
              "gaussian matches it)"};
}

/// yan2016's and deng2022's: the environment fitted by spherical Gaussian lobes, each shaded by one
/// range query of the footprint's NDF (resource environment-lobes; docs/methods.md#deng2022).
inline ParamDecl environment_lobes_param() {
  return {"environment_lobes", 32.0f, 0.0f, 48.0f,
          "spherical Gaussian lobes the environment is fitted by (Deng et al. 2022 sec. 5.4): on normal-map-glints "
          "materials each one range query of the footprint's NDF over the lobe's half-vector box (0: the "
          "environment as the material's smooth lobe by the split sum; at most 48 within llvmpipe's loop budget)",
          {}, false, {}, /*host_only=*/true, /*integer=*/true};
}

/// How each of those lobes is shaded: as one uniform cone of its solid angle (the paper's one
/// angular range, eq. 8-9), or as three nested cones at its power's quantiles.
inline ParamDecl environment_lobe_cones_param() {
  return {"environment_lobe_cones", 1, 0, 1,
          "how each environment lobe is shaded: one range query over a uniform cone of the lobe's solid angle (the "
          "paper's angular range, eq. 8-9), or three over nested cones at a third, two thirds and 95% of its power "
          "(the lobe's radial profile as a layer cake: 3x the queries; a quarter less error per pixel where footprints hold many glints)",
          {"one", "three"},
          /*compile_time=*/true};
}

inline constexpr const char* kChermain2020Citation =
    "X. Chermain, B. Sauvage, J.-M. Dischler, C. Dachsbacher, Procedural Physically based BRDF for Real-Time "
    "Rendering of Glints, Pacific Graphics 2020 (CGF 39(7))";

/// The three `kaplanyan-*` variants come from one paper and talk.
inline constexpr const char* kKaplanyan2016Citation =
    "A. S. Kaplanyan, S. Hill, A. Patney, A. Lefohn, Filtering Distributions of Normals for Shading "
    "Antialiasing, HPG 2016; Stable Specular Highlights, GDC 2016";

}  // namespace glintlab
