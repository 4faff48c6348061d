// VisibleSamples: what the camera sees of the scene, reduced from a read-back of the visible surfaces'
// world positions (sample distribution shadow maps, Lauritzen, Salvi & Lefohn 2011, §3-4): the nearest and
// farthest view depth of the visible samples (their tight z-range, which sets cascade splits and the depth
// extent of a focused fit) and their world-space box (a bound of the samples' light-space x/y extent that
// every fit can intersect with the view frustum). The light fits take it through `fitLight(..., visible)`
// (runtime/LightParameterization.h); the effect asks for it with a parameter of semantic
// LightFitVisibleSamples (docs/techniques/light-space-parameterizations.md, "Fits from what the camera
// sees").
#pragma once

#include <runtime/Scene.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace runtime {

struct VisibleSamples {
    float nearDepth = 0.0f;  // the nearest visible sample's view depth (along the camera's view direction)
    float farDepth = 0.0f;   // the farthest one's
    Bounds box;              // the world-space box of the visible samples
    size_t count = 0;        // how many pixels saw a surface
};

// Reduces `positions` (one RGBA float quadruple per pixel: world x, y, z and a coverage flag, > 0 where a
// surface was drawn, 0 for the background) seen by `camera`. nullopt when no pixel saw a surface or a
// position is not finite.
std::optional<VisibleSamples> reduceVisibleSamples(const std::vector<float>& positions, const Camera& camera);

// The fits' inputs over the samples, widened by a small margin so that samples on the boundary stay inside
// after the fits' rounding:
// `camera` with its near and far planes at the samples' depth range (never outside the camera's own);
Camera cameraOverSamples(const Camera& camera, const VisibleSamples& samples);
// the receivers' bounds: the scene bounds intersected with the samples' box.
Bounds receiverBoundsOverSamples(const Bounds& sceneBounds, const VisibleSamples& samples);

}  // namespace runtime
