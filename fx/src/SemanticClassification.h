// SemanticClassification: the compiler's reading of a parameter's semantic (fx/ParameterSemantics.h), the
// one place where the runtime's semantics are matched by their text. Private to fx.
#pragma once

#include <fx/CompiledEffect.h>

#include <string>
#include <vector>

namespace fx {

// What the runtime gives `parameter`, with SemanticBinding::light left at -1: `lightName` is set to the
// light whose value it is (its `frustum`/`Object` annotation, or light0 for a light property written
// without one), "" for none; the caller turns it into the index of CompiledEffect::lights.
// `hasInitializer`: the effect gives the parameter a value (a colour named by convention is then its own).
// How an effect numbers the lights whose properties its names carry (ConventionalSemantic::lightNumber):
// the lowest number is its first numbered light (an effect that numbers from 1 means its first light by
// Light1), the scene's light0, or light1 where the effect also reads unnumbered light properties by name
// (`g_LightDir` beside `g_LightDir2`: the unnumbered ones are light0's). Numbered directions point the way
// the light travels (XNA's, D3D9's), unless unnumbered ones beside them point towards it (the D3D samples').
struct LightNumbering {
    int first = 0;
    bool afterUnnumbered = false;
    int sceneLight(int number) const { return number - first + (afterUnnumbered ? 1 : 0); }
};
// The numbering of the effect's parameters; `hasInitializer[i]` as for classifySemantic.
LightNumbering lightNumbering(const std::vector<ParameterInfo>& parameters,
                              const std::vector<bool>& hasInitializer);
// A numbered light's property read by its name is the light `numbering` says, unless an annotation names
// its light.
SemanticBinding classifySemantic(const ParameterInfo& parameter, bool hasInitializer,
                                 const LightNumbering& numbering, std::string& lightName);

// The semantic a parameter written without one is read as, from its name: FX11 and D3DX applications set
// parameters by name (`gWorldViewProj`, `g_mWorldViewProjection`, `World`, `matView`, `g_vEyePt`,
// `g_fTime`), so an effect written for them has no semantics to bind by; these conventional names are read
// as the semantic they spell, where the parameter's type fits it (a matrix for a matrix name, a vector for
// a position, direction or colour, a scalar for a time or a light count). Prefixes `g_`/`g`/`m_` and
// Hungarian `m`/`mat`/`mtx`/`v`/`vec`/`f`/`n`/`i` go, then underscores and case; suffixes `Matrix`,
// `Inv`/`Inverse`, `IT`/`InvTranspose`/`InverseTranspose`, a leading `Inv`; a world-space `W` on a
// position. A light's properties, colours and light counts are read so only without an initializer
// (`hasInitializer`): a value the effect gives is its own. A light's property may carry the light's number
// after `Light` or at the end, as XNA's and MonoGame's stock effects and fixed-function-style effects number
// their lights (`DirLight1Direction`, `DirLight1DiffuseColor`, `g_vLight2Pos`, `LightDir0`). An empty
// semantic for none (a parameter with a semantic keeps it, and parameters named otherwise stay the user's).
struct ConventionalSemantic {
    std::string semantic;
    bool viewSpace = false;   // a light's position or direction in view space (SemanticBinding::viewSpace)
    int lightNumber = -1;     // the number of the light a light's property names, -1 for none
    bool firstLight = false;  // a light's matrix by a name without a number (`LightViewProj`): light0's
};
ConventionalSemantic conventionalSemantic(const ParameterInfo& parameter, bool hasInitializer);

}  // namespace fx
