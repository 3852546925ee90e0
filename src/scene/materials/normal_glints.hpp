#pragma once
// The normal-map-glints material's host-side quantities (Yan et al. 2016's microsurface: the
// normal map itself, each point's projected normal Gaussian about the map's with deviation sigma_r).
#include "scene/normal_maps/normal_map.hpp"

namespace glintlab {

/// The Beckmann alpha of the whole microsurface, for Smith masking-shadowing only:
/// sqrt(E[|b|^2] + 2 sigma_r^2), b = n.xy / n.z the slope of each texel's normal (the mean over the
/// texels; a Beckmann lobe of alpha has E[|b|^2] = alpha^2, and the intrinsic Gaussian adds
/// 2 sigma_r^2 to it at small slopes).
float normal_glint_masking_alpha(const NormalMap& map, float intrinsic_roughness);

}  // namespace glintlab
