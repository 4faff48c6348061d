// StageReads: whether a compiled stage's code reads a name it declares. SPIRV-Cross declares every sampler
// the effect declares in every stage, read or not (glslang keeps them all), so a stage's sampler list says
// what it may read; a read is a second mention of the name in its GLSL.
#pragma once

#include <fx/CompiledEffect.h>

#include <string>

namespace fx {

bool stageReads(const StageProgram& stage, const std::string& identifier);

}  // namespace fx
