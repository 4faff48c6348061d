// Newell's teapot (Martin Newell, Utah, 1975; with Blinn's bottom), in its original z-up units.
//
// The classic table is 32 bicubic Bezier patches over 306 control points, but only 10 patches are distinct:
// the rim, body (2), lid (2) and bottom are surfaces of revolution, each stored as one quarter (x >= 0,
// y <= 0) and repeated in the four quadrants; the handle (2) and spout (2) are stored as the y <= 0 half and
// mirrored. The quarter of a surface of revolution is the profile curve (r, z) swept with the table's circle
// approximation: columns (r, 0), (r, -0.56 r), (0.56 r, -r), (0, -r). So the table below stores exactly that:
// six profiles and four half-patches; Teapot.cpp expands them to the 32 patches.
//
// Profiles are listed in the same sense along the outer silhouette (from the lid's top outwards and down to
// the bottom's centre), which is what lets Teapot.cpp tell the outer side of each surface (see there).
#pragma once

namespace runtime::teapot {

struct ProfilePoint {
    float r, z;
};

// Cubic Bezier profiles (r, z) of the surfaces of revolution.
inline constexpr ProfilePoint kProfiles[6][4] = {
    {{0.0f, 3.15f}, {0.8f, 3.15f}, {0.0f, 2.85f}, {0.2f, 2.7f}},             // lid: knob
    {{0.2f, 2.7f}, {0.4f, 2.55f}, {1.3f, 2.55f}, {1.3f, 2.4f}},              // lid: outer part
    {{1.4f, 2.4f}, {1.3375f, 2.53125f}, {1.4375f, 2.53125f}, {1.5f, 2.4f}},  // rim
    {{1.5f, 2.4f}, {1.75f, 1.875f}, {2.0f, 1.35f}, {2.0f, 0.9f}},            // body: upper
    {{2.0f, 0.9f}, {2.0f, 0.45f}, {1.5f, 0.225f}, {1.5f, 0.15f}},            // body: lower
    {{1.5f, 0.15f}, {1.5f, 0.075f}, {1.425f, 0.0f}, {0.0f, 0.0f}},           // bottom
};

// The circle approximation of the original control points (0.56 rather than the exact 0.5523 of a
// best-fit quarter circle: reproducing the classic shape matters more than roundness).
inline constexpr float kCircleHandle = 0.56f;

struct ControlPoint {
    float x, y, z;
};

// Half-patches (y <= 0) of the handle and the spout: 4 rows of 4 control points, each row one half
// cross-section of the tube, starting and ending on the plane y = 0.
inline constexpr ControlPoint kTubePatches[4][4][4] = {
    // handle, upper part
    {{{-1.6f, 0.0f, 2.025f}, {-1.6f, -0.3f, 2.025f}, {-1.5f, -0.3f, 2.25f}, {-1.5f, 0.0f, 2.25f}},
     {{-2.3f, 0.0f, 2.025f}, {-2.3f, -0.3f, 2.025f}, {-2.5f, -0.3f, 2.25f}, {-2.5f, 0.0f, 2.25f}},
     {{-2.7f, 0.0f, 2.025f}, {-2.7f, -0.3f, 2.025f}, {-3.0f, -0.3f, 2.25f}, {-3.0f, 0.0f, 2.25f}},
     {{-2.7f, 0.0f, 1.8f}, {-2.7f, -0.3f, 1.8f}, {-3.0f, -0.3f, 1.8f}, {-3.0f, 0.0f, 1.8f}}},
    // handle, lower part
    {{{-2.7f, 0.0f, 1.8f}, {-2.7f, -0.3f, 1.8f}, {-3.0f, -0.3f, 1.8f}, {-3.0f, 0.0f, 1.8f}},
     {{-2.7f, 0.0f, 1.575f}, {-2.7f, -0.3f, 1.575f}, {-3.0f, -0.3f, 1.35f}, {-3.0f, 0.0f, 1.35f}},
     {{-2.5f, 0.0f, 1.125f}, {-2.5f, -0.3f, 1.125f}, {-2.65f, -0.3f, 0.9375f}, {-2.65f, 0.0f, 0.9375f}},
     {{-2.0f, 0.0f, 0.9f}, {-2.0f, -0.3f, 0.9f}, {-1.9f, -0.3f, 0.6f}, {-1.9f, 0.0f, 0.6f}}},
    // spout, lower part
    {{{1.7f, 0.0f, 1.425f}, {1.7f, -0.66f, 1.425f}, {1.7f, -0.66f, 0.6f}, {1.7f, 0.0f, 0.6f}},
     {{2.6f, 0.0f, 1.425f}, {2.6f, -0.66f, 1.425f}, {3.1f, -0.66f, 0.825f}, {3.1f, 0.0f, 0.825f}},
     {{2.3f, 0.0f, 2.1f}, {2.3f, -0.25f, 2.1f}, {2.4f, -0.25f, 2.025f}, {2.4f, 0.0f, 2.025f}},
     {{2.7f, 0.0f, 2.4f}, {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0.0f, 2.4f}}},
    // spout, tip
    {{{2.7f, 0.0f, 2.4f}, {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0.0f, 2.4f}},
     {{2.8f, 0.0f, 2.475f}, {2.8f, -0.25f, 2.475f}, {3.525f, -0.25f, 2.49375f}, {3.525f, 0.0f, 2.49375f}},
     {{2.9f, 0.0f, 2.475f}, {2.9f, -0.15f, 2.475f}, {3.45f, -0.15f, 2.5125f}, {3.45f, 0.0f, 2.5125f}},
     {{2.8f, 0.0f, 2.4f}, {2.8f, -0.15f, 2.4f}, {3.2f, -0.15f, 2.4f}, {3.2f, 0.0f, 2.4f}}},
};

}  // namespace runtime::teapot
