// CascadedShadowMaps: the `Cascaded` light parameterization
// (docs/techniques/light-space-parameterizations.md): the camera's view depth range is split into slices, and
// each slice gets its own orthographic shadow map of the same size, so that near receivers get small texels
// and far ones large texels. Lehőcz 2007 (§ "Kaszádolt shadow map-ek" ) describes the idea: one map for the
// viewer's neighbourhood, the next of the same size for twice the distance, and so on; Scherzer 2005 §1 (the
// survey) names it as the simple answer to perspective aliasing. The split schemes below are the
// parallel-split shadow maps' (Zhang et al. 2006, not among the seeds): logarithmic (Lehőcz 2007's constant
// ratio), uniform, and the practical blend of both.
//
// The cascades share one render target, an atlas of `cascadeAtlasGrid(count)` equal tiles;
// RenderPort=lightN.cascadeK renders cascade K into tile K (cascadeViewport).
#pragma once

#include <runtime/LightParameterization.h>

#include <glm/glm.hpp>

#include <vector>

namespace runtime {

constexpr int kMaxCascades = 8;

// The split depths z_0 = nearPlane < z_1 < ... < z_count = farPlane (view-space depths, count + 1 values):
// z_i = λ n (f/n)^(i/N) + (1 - λ) (n + (f - n) i/N), λ = 0 uniform, 1 logarithmic (clamped to [0, 1]).
std::vector<float> cascadeSplitDepths(float nearPlane, float farPlane, int count, float lambda);

// The atlas layout: cols = ceil(sqrt(count)), rows = ceil(count / cols); cascade K in column K % cols,
// row K / cols (row 0 at texture v = 0, the top row in D3D conventions). 4 cascades: 2 x 2.
glm::ivec2 cascadeAtlasGrid(int count);
// Tile K's texels in a width x height atlas: x, y (from row 0), w, h. Equal tiles when the atlas size is a
// multiple of the grid (a 1024² atlas of 4 cascades: 512² tiles).
glm::ivec4 cascadeViewport(int cascade, int count, int width, int height);
// Tile K in texture coordinates: u0, v0, du, dv (cascadeViewport / atlas size, for atlas sizes that are
// multiples of the grid). A cascade's clip position maps to atlas uv as rect.xy + ShadowMapUV(clip) rect.zw.
glm::vec4 cascadeAtlasRect(int cascade, int count);
// The texels of a tile given in texture coordinates on a grid of 1 / du columns and 1 / dv rows: whole
// texels, w = floor(width du), x = column w, as cascadeViewport (a PSMCube face's LightView::atlasRect).
glm::ivec4 atlasViewport(const glm::vec4& rect, int width, int height);
// Sub-view `index` of a fit's `count` cascades or cube faces in a width x height atlas: a PSMCube face's
// own tile (its LightView::atlasRect: the used faces share the atlas), else the cascades' fixed grid
// (cascadeViewport). What RenderPort=lightN.cascadeK renders into and what the aliasing measure assumes.
glm::ivec4 lightViewTile(const LightView& view, int index, int count, int width, int height);

// The Cascaded fit: view and projection are the Focused fit of the whole intersection body (what plain
// RenderPort=lightN renders with), `cascades` holds tunables.cascadeCount sub-views. Each cascade is an
// orthographic fit of its slice of B (view frustum slice ∩ scene bounds; xy from the receivers, depth from
// their extrusion toward the light), stabilized against a moving camera: every cascade shares one light
// view that does not depend on the camera, its square extent is the slice's bounding sphere or the slice
// body's extent rounded up on a geometric ladder, whichever is smaller, and its centre is snapped to
// 1/64 of the extent (whole texels of any tile of 64·k texels). The far end of the depth range,
// min(camera far, the farthest scene bounds corner), is rounded up on a ladder too, so the splits stay put.
// Spot and point lights (and degenerate ones) get view 0, Focused's fit, in every cascade.
// `visible` (may be null): the samples the camera sees (sample distribution shadow maps, Lauritzen et al.
// 2011): the splits then divide their depth range, its ends rounded outward on the same ladder, and each
// slice's receivers are the slice ∩ the samples' box.
LightFit fitCascades(const Scene& scene, const Bounds& sceneBounds, float aspect, const Light& light,
                     const LightTunables& tunables, const VisibleSamples* visible = nullptr);

}  // namespace runtime
