#pragma once
// The form factor of a spherical cap clipped to the horizon: what the "clipless" LTC evaluation
// of spheres and disks (and of polygons by their vector form factor; Heitz & Hill 2017) looks up
// in layer 1 .z of the ltc-ggx table.
//
// A cap of angular radius sigma whose centre has elevation cosine z (relative to the normal) has
// the vector form factor F of length |F| = sin^2(sigma) and F.z = |F| z; unclipped, its form factor
// is F.z. Clipped to the upper hemisphere it is |F| S(z, |F|) with
//
//   S = (1/pi) int_{cap, w.z > 0} w.z dw / |F|,
//
// which is z for a cap wholly above the horizon and 0 for one wholly below.
namespace glintlab {

/// (1/pi) * the integral of max(0, w.z) over the cap (the clipped form factor). Exact in azimuth
/// about the cap's centre and Gauss-Legendre in the polar angle, split where the rings start to
/// cross the horizon: accurate to ~1e-11.
double clipped_cap_form_factor(double z, double sin2_sigma);

/// S(z, |F|) = clipped_cap_form_factor(z, |F|) / |F|; its limit max(z, 0) at |F| = 0.
double clipped_cap_ratio(double z, double form_factor_length);

}  // namespace glintlab
