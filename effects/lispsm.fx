// lispsm.fx: light space perspective shadow maps (Wimmer et al. 2004; Scherzer 2005 §4.4 and Lehőcz 2007):
// the focused fit of focused.fx followed by a perspective warp along the view
// direction made perpendicular to the light, with n_opt = (z_n + sqrt(z_n (z_n + Δz))) / sin γ. Near the
// viewer it spends more texels, far away fewer; as the light turns parallel to the view (γ -> 0) the warp
// fades out and the map becomes focused.fx's (docs/techniques/light-space-parameterizations.md).
#define LIGHT_PARAMETERIZATION "LiSPSM"
#include "include/lightspace.fxh"

// Pancaking (Scherzer 2005 §4.1): the map's depth range spans the receivers only; casters before them are
// clamped onto its near plane by the map pass's DepthClipEnable = false (lightspace.fxh).
bool Pancake : LightPancaking
<
    string UIName = "Pancake casters (depth range of receivers only)";
> = false;

// n_opt x this: 1 is the optimum of eq. 1, larger is a weaker warp (toward focused.fx), smaller a stronger.
float NScale : LiSPSMNScale
<
    string UIWidget = "slider";
    string UIName = "LiSPSM n / n_opt";
    float UIMin = 0.25;
    float UIMax = 8.0;
> = 1.0;

// V_P from B's middle vector (Scherzer 2005 §4.4, the paper's own choice) instead of eq. 3's view direction.
bool MiddleVector : LiSPSMMiddleVector
<
    string UIName = "LiSPSM middle vector";
> = false;

technique bilinear
<
    // Measured by `shadowfx stress` (docs/measurement.md, "shadowfx stress"); reported as xfail.
    string StressExpectedFailures = "near-far-huge [uniform]: z_n = 0.001 makes n_opt of eq. 1 tiny: the "
                                    "warp leaves the far receivers few texels (0.76 %, the uniform map 0.03 "
                                    "%)";
    string Script = "Pass=RenderShadowMap; Pass=RenderScene;";
    string ExpectScenes = "dual-l,teapot";
    float ExpectMisclassifiedBelow = 0.12;  // measured 0.031 % on dual-l, 0.061 % on teapot (hard truth)
    int ExpectMapSize = 1024;
>
{
    LIGHTSPACE_PASSES
}
