// ScriptInterpreter: executes SAS scripts (the STANDARDSGLOBAL, technique and pass `Script` annotations)
// against a ScriptTarget that does the GL work. Keeping GL out of here makes the control flow (technique
// selection, Pass=, loops, the defaults for effects without scripts) testable on its own.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Value.h>

#include <string>
#include <vector>

namespace runtime {

// What a script asks for. The interpreter calls these in script order.
class ScriptTarget {
public:
    virtual ~ScriptTarget() = default;
    virtual void beginPass(const fx::CompiledPass& pass) = 0;
    virtual void setColorTarget(int index, const std::string& texture) = 0;  // "" = the frame's colour target
    virtual void setDepthTarget(const std::string& texture) = 0;             // "" = the frame's depth target
    // "" = the camera; `cascade` >= 0: that sub-view of the light (RenderPort=light0.cascade2); `loc` is
    // the command's, for errors only the frame can find (a light or cascade the scene does not have).
    virtual void setRenderPort(const std::string& light, int cascade, const fx::SourceLoc& loc) = 0;
    virtual void setClearColor(const fx::Value& color) = 0;
    virtual void setClearDepth(float depth) = 0;
    virtual void setClearStencil(int stencil) = 0;
    virtual void clear(fx::ScriptCommand::ClearWhat what) = 0;
    virtual void draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) = 0;
    // ScriptExternal=color: the host draws the scene into the current targets (HostScene.h).
    virtual void drawScene(const fx::ScriptCommand& command) = 0;
    // Parameter access for Loop*/ClearSet*/Technique= selectors.
    virtual const fx::Value* parameter(const std::string& name) const = 0;
    virtual void setParameter(const std::string& name, const fx::Value& value) = 0;
};

class ScriptInterpreter {
public:
    // The technique a frame runs: `requested` if given, else the STANDARDSGLOBAL script's Technique=
    // (with Cond?A:B selectors), else the first. nullptr (with UnknownTechnique) if it does not exist.
    static const fx::CompiledTechnique* selectTechnique(const fx::CompiledEffect& effect,
                                                        const std::string& requested,
                                                        const ScriptTarget& target,
                                                        fx::DiagnosticSink& diagnostics);

    // Runs the technique's script (or, without one, every pass in order), each pass's script (or, without
    // one, Draw=Geometry). Before a technique whose scripts never clear the frame's colour target, the host
    // clears the frame (HostScene.h). A LoopByCount over `maxLoopCount` iterations (the effect's
    // CompiledEffect::maxScriptLoopCount) is reported and the script stops, never a hang. Returns false if
    // the script could not run to its end.
    static bool run(const fx::CompiledTechnique& technique, int maxLoopCount, ScriptTarget& target,
                    fx::DiagnosticSink& diagnostics);

    // Whether the technique's scripts clear the frame's own colour target (a Clear=Color while
    // RenderColorTarget0 is the frame), as FX Composer's scene effects do; material effects do not.
    static bool clearsFrame(const fx::CompiledTechnique& technique);

private:
    static bool runCommands(const std::vector<fx::ScriptCommand>& commands,
                            const fx::CompiledTechnique& technique, const fx::CompiledPass* pass,
                            int maxLoopCount, ScriptTarget& target, fx::DiagnosticSink& diagnostics);
};

}  // namespace runtime
