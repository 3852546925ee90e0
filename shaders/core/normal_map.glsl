// The material's normal map as a surface of texels (texel i's centre at i + 0.5; the surface
// repeats over the normal-map coordinates' unit square): the stored map itself, or, with
// MATERIAL_WANG_TILES, the implicit surface of its Wang tiles (Deng et al. 2022 sec. 5.5): P x P
// tiles of T^2 texels, each cell's tile chosen by the hashed lattice (core/wang_tiles.glsl), read
// from the 4 x 4 atlas of the 16 tiles that the texture holds (T = its side / 4). Everything that
// reads the surface texel by texel (the references, yan2016's elements) reads it here, so that
// they all see the same surface; a filtered lookup (a method's textureGrad) reads the atlas at the
// point's tile, which blends a tile's border with its atlas neighbours (the approximation hardware
// filtering of an atlas makes; docs/methods.md#wang-tiles).
#ifndef CORE_NORMAL_MAP_GLSL
#define CORE_NORMAL_MAP_GLSL

#include "core/wang_tiles.glsl"  // (never inside an #if: the library expands each file once, where first included)
#include "core/wrap.glsl"

struct NormalMapSurface {
  ivec2 size;    // texels along u and v (P T with Wang tiles)
  int tileSize;  // T (0: a plain map)
  int tiles;     // P
  uint seed;     // the lattice's hash seed
};

NormalMapSurface normalMapSurface() {
  NormalMapSurface s;
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  MaterialData m = materials[uMaterial];
  s.tileSize = textureSize(uNormalMap, 0).x / 4;
  s.tiles = int(normalMapGlintsWangTiles(m) + 0.5);
  s.seed = uint(normalMapGlintsWangSeed(m) + 0.5);
  s.size = ivec2(s.tiles * s.tileSize);
#else
  s.size = textureSize(uNormalMap, 0);
  s.tileSize = 0;
  s.tiles = 0;
  s.seed = 0u;
#endif
  return s;
}

// Texels along u and v of the surface.
ivec2 normalMapSize() { return normalMapSurface().size; }

// Where texel i of the surface (any integers: the surface repeats) is stored.
ivec2 normalMapStoredTexel(NormalMapSurface s, ivec2 i) {
  i = floorMod(i, s.size);
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  return wangAtlasTexel(i, s.tileSize, s.tiles, s.seed);
#else
  return i;
#endif
}

vec3 normalMapTexel(NormalMapSurface s, ivec2 i) { return texelFetch(uNormalMap, normalMapStoredTexel(s, i), 0).xyz; }

// The surface at normal-map coordinates uv, bilinear between texel centres at level 0 (not
// renormalised): what a plain map's textureLod(uv, 0) returns.
vec3 normalMapAtPoint(vec2 uv) {
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  NormalMapSurface s = normalMapSurface();
  vec2 x = fract(uv) * vec2(s.size) - 0.5;
  ivec2 i = ivec2(floor(x));
  vec2 f = x - vec2(i);
  return mix(mix(normalMapTexel(s, i), normalMapTexel(s, i + ivec2(1, 0)), f.x),
             mix(normalMapTexel(s, i + ivec2(0, 1)), normalMapTexel(s, i + ivec2(1, 1)), f.x), f.y);
#else
  return textureLod(uNormalMap, uv, 0.0).xyz;
#endif
}

// The coordinates of a filtered lookup at uv in the textures made from the map (its normals, its
// slope moments), and the derivatives scaled alike: with Wang tiles, uv's texel in its tile's place
// in the atlas, the derivatives times P T / (4 T).
vec2 normalMapFilterCoordinates(vec2 uv, inout vec2 dUVdx, inout vec2 dUVdy) {
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  NormalMapSurface s = normalMapSurface();
  vec2 x = fract(uv) * vec2(s.size);
  ivec2 i = min(ivec2(floor(x)), s.size - 1);
  float scale = float(s.tiles) / 4.0;
  dUVdx *= scale;
  dUVdy *= scale;
  return (vec2(wangAtlasTexel(i, s.tileSize, s.tiles, s.seed)) + (x - vec2(i))) / vec2(4 * s.tileSize);
#else
  return uv;
#endif
}

#endif
