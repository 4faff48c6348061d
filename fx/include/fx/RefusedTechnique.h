// RefusedTechnique: a technique left out because it uses what shadowfx cannot run on GL (stream output,
// compute, dynamic linkage, an SV_Coverage input, ...) while another technique of the effect can run, as
// D3DX's FindNextValidTechnique passed over a technique that did not validate. The parser leaves out what
// it recognizes (Effect::refusedTechniques), the compiler what the lowering cannot express; the compiled
// effect keeps both (CompiledEffect::refusedTechniques) for the runtime's technique validation.
#pragma once

#include <fx/SourceLoc.h>

#include <string>

namespace fx {

struct RefusedTechnique {
    std::string name;    // "(unnamed)" for a technique without one
    std::string group;   // its D3D11 fxgroup, "" if none
    std::string reason;  // what the warning that left it out says after the name
    SourceLoc loc;       // where the construct that refused it stands
};

}  // namespace fx
