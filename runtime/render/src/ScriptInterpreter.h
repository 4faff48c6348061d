// ScriptInterpreter: executes SAS scripts (the STANDARDSGLOBAL, technique and pass `Script` annotations)
// against a ScriptTarget that does the GL work. Keeping GL out of here makes the control flow (technique
// selection, Pass=, loops, the defaults for effects without scripts) testable on its own.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Value.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace runtime {

// What a script asks for. The interpreter calls these in script order.
class ScriptTarget {
public:
    virtual ~ScriptTarget() = default;
    virtual void beginPass(const fx::CompiledPass& pass) = 0;
    // `texture`: the name the script wrote ("" = the frame's colour or depth target), for messages;
    // `parameter` the parameter it names (fx::ScriptCommand::parameter, -1 if none).
    virtual void setColorTarget(int index, const std::string& texture, int parameter) = 0;
    virtual void setDepthTarget(const std::string& texture, int parameter) = 0;
    // "" = the camera; `lightSlot` the light's SemanticBinder::lightSlot (its fx::CompiledEffect::lights
    // index, fx::ScriptCommand::light); `cascade` >= 0: that sub-view of
    // the light (RenderPort=light0.cascade2); `loc` is the command's, for errors only the frame can find (a
    // light or cascade the scene does not have).
    virtual void setRenderPort(const std::string& light, int lightSlot, int cascade,
                               const fx::SourceLoc& loc) = 0;
    virtual void setClearColor(const fx::Value& color) = 0;
    virtual void setClearDepth(float depth) = 0;
    virtual void setClearStencil(int stencil) = 0;
    // `colorTarget` >= 0: a colour clear of that target alone (Clear=SV_TARGETn); -1: every bound one.
    virtual void clear(fx::ScriptCommand::ClearWhat what, int colorTarget) = 0;
    virtual void draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) = 0;
    // Dispatch=x,y,z in a compute pass's script (ComputeDispatch.h); `loc` is the command's.
    virtual void dispatch(const fx::CompiledPass& pass, const std::array<uint32_t, 3>& groups,
                          const fx::SourceLoc& loc) = 0;
    // ScriptExternal=color: the host draws the scene into the current targets (HostScene.h).
    virtual void drawScene(const fx::ScriptCommand& command) = 0;
    // Parameter access for Loop*/ClearSet* values, by index.
    virtual const fx::Value* parameter(size_t index) const = 0;
    // LoopGetIndex: the current iteration `index` stored in the parameter the command names (`name` as
    // written, `parameter` its index or -1 where the effect has none).
    virtual void setLoopIndex(const std::string& name, int parameter, int index) = 0;
};

// A LoopByCount the script is inside.
struct ScriptLoop {
    size_t body;                            // index of the first command inside the loop
    int remaining;                          // iterations still to run after this one
    int index;                              // current iteration
    const fx::ScriptCommand* indexCommand;  // its LoopGetIndex, or null
};
// The loops open while a script runs, kept by the caller between runs: once it has held the deepest
// nesting a script reaches, running that script again allocates nothing.
using ScriptLoopStack = std::vector<ScriptLoop>;

class ScriptInterpreter {
public:
    // The technique a frame runs: `requested` if given, else the STANDARDSGLOBAL script's Technique=
    // (with Cond?A:B selectors, the condition's value from `values`, by the indices the compiler
    // resolved), else the first. nullptr (with UnknownTechnique) if `requested` does not exist.
    static const fx::CompiledTechnique* selectTechnique(const fx::CompiledEffect& effect,
                                                        const std::string& requested,
                                                        const std::vector<fx::Value>& values,
                                                        fx::DiagnosticSink& diagnostics);
    // True if selectTechnique's answer for `requested` can depend on a parameter's value (a Technique=
    // Cond?A:B selector): otherwise it can be kept for the effect's lifetime.
    static bool selectionReadsParameters(const fx::CompiledEffect& effect, const std::string& requested);

    // Runs the technique's script (or, without one, every pass in order), each pass's script (or, without
    // one, Draw=Geometry). Before a technique whose scripts never clear the frame's colour target, the host
    // clears the frame (HostScene.h), unless `keepFrame`: the frame holds what a scene effect left in it in
    // the last frame, which FX Composer kept for it (fx::CompiledEffect::sceneClass). A LoopByCount over
    // `maxLoopCount` iterations (the effect's CompiledEffect::maxScriptLoopCount) is reported and the script
    // stops, never a hang. Returns false if the script could not run to its end. `loops` is the caller's kept
    // stack (emptied first).
    static bool run(const fx::CompiledTechnique& technique, int maxLoopCount, bool keepFrame,
                    ScriptLoopStack& loops, ScriptTarget& target, fx::DiagnosticSink& diagnostics);

    // Whether the technique's scripts clear the frame's own colour target (a Clear=Color while
    // RenderColorTarget0 is the frame), as FX Composer's scene effects do; material effects do not.
    static bool clearsFrame(const fx::CompiledTechnique& technique);

private:
    static bool runPass(const fx::CompiledPass& pass, const fx::CompiledTechnique& technique,
                        int maxLoopCount, ScriptLoopStack& loops, ScriptTarget& target,
                        fx::DiagnosticSink& diagnostics);
    // A pass script's loops go on the stack above its technique script's open ones.
    static bool runCommands(const std::vector<fx::ScriptCommand>& commands,
                            const fx::CompiledTechnique& technique, const fx::CompiledPass* pass,
                            int maxLoopCount, ScriptLoopStack& loops, ScriptTarget& target,
                            fx::DiagnosticSink& diagnostics);
};

}  // namespace runtime
