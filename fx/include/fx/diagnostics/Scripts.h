// Diagnostics: SAS scripts. One section of the table that fx/DiagnosticDefs.h includes, in its order;
// FX_DIAGNOSTIC(Id, Severity, "template"). Include DiagnosticDefs.h, never this file alone.
FX_DIAGNOSTIC(UnknownScriptCommand, Error, "unknown script command '{0}'")
FX_DIAGNOSTIC(ScriptUnknownPass, Error, "script names pass '{0}', which technique '{1}' does not have")
FX_DIAGNOSTIC(ScriptUnknownTarget, Error,
              "script names render target '{0}', which is not a render-target texture")
FX_DIAGNOSTIC(ScriptUnknownTechnique, Warning,
              "script names technique '{0}', which the effect does not have; skipped")
FX_DIAGNOSTIC(ScriptTechniqueFallback, Warning,
              "script names no technique the effect has; running the first technique that draws, '{0}'")
FX_DIAGNOSTIC(ScriptUnbalancedLoop, Error, "LoopByCount without LoopEnd")
FX_DIAGNOSTIC(ScriptLoopEndWithoutLoop, Error, "LoopEnd without LoopByCount")
FX_DIAGNOSTIC(ScriptLoopIndexOutsideLoop, Error, "LoopGetIndex outside a loop")
// Invalid script commands, one id per message.
FX_DIAGNOSTIC(ScriptValueMissing, Error, "invalid script command '{0}': expected '=' and a value")
FX_DIAGNOSTIC(ScriptClearInvalid, Error,
              "invalid script command '{0}': expected Color, Depth, Stencil, DepthStencil or All")
FX_DIAGNOSTIC(ScriptClearTargetBeyond, Warning,
              "script command '{0}': colour target {1} is beyond the {2} a script binds "
              "(RenderColorTarget0..{3}); nothing is cleared")
FX_DIAGNOSTIC(ScriptDrawInvalid, Error, "invalid script command '{0}': expected Geometry or Buffer")
FX_DIAGNOSTIC(ScriptValueEmpty, Error, "invalid script command '{0}': expected a value")
FX_DIAGNOSTIC(ScriptTechniqueNameExpected, Error, "invalid script command '{0}': expected a technique name")
FX_DIAGNOSTIC(ScriptTechniqueConditionInvalid, Error,
              "invalid script command '{0}': expected Condition?TechniqueA:TechniqueB")
FX_DIAGNOSTIC(ScriptRenderPortInvalid, Error,
              "invalid script command '{0}': expected lightN, lightN.cascadeK or lightN.faceK, K a sub-view "
              "index, not '{1}'")
FX_DIAGNOSTIC(ScriptLoopCountNotWhole, Error,
              "invalid script command 'LoopByCount': '{0}' is not a non-negative whole count")
FX_DIAGNOSTIC(ScriptLoopCountTooLarge, Error,
              "invalid script command 'LoopByCount': {0} iterations exceed the limit of {1}")
FX_DIAGNOSTIC(
    ScriptDispatchCountsInvalid, Error,
    "invalid script command 'Dispatch': expected 1 to 3 thread-group counts, each a whole number or "
    "a parameter, not '{0}'")
FX_DIAGNOSTIC(ScriptClearValueInvalid, Error,
              "invalid script command '{0}': '{1}' is neither a parameter nor a number")
FX_DIAGNOSTIC(ScriptDrawInTechniqueScript, Error,
              "invalid script command 'Draw': a technique script draws through Pass=, not Draw=")
FX_DIAGNOSTIC(ScriptDispatchInTechniqueScript, Error,
              "invalid script command 'Dispatch': a technique script dispatches through Pass=, not Dispatch=")
FX_DIAGNOSTIC(ScriptDispatchValueInvalid, Error,
              "invalid script command 'Dispatch': '{0}' is not 1 to 3 non-negative counts")
FX_DIAGNOSTIC(ScriptLoopCountNegative, Error,
              "invalid script command 'LoopByCount': '{0}' is not a non-negative count")

// Commands FX Composer warned about and skipped, one id per reason ({0}: the command).
FX_DIAGNOSTIC(ScriptClearNamesNoBuffer, Warning,
              "script command '{0}' is ignored: it names no buffer (Color, Depth, Stencil, DepthStencil or "
              "All); nothing is cleared")
FX_DIAGNOSTIC(ScriptClearValueIgnored, Warning,
              "script command '{0}' is ignored: '{1}' is neither a parameter nor a number; the clear value "
              "stays as it was")
FX_DIAGNOSTIC(
    ScriptColorTargetNotTarget, Warning,
    "script command '{0}' is ignored: '{1}' is not a render-target texture; the pass draws into the "
    "target bound before")
FX_DIAGNOSTIC(ScriptDepthTargetNotTarget, Warning,
              "script command '{0}' is ignored: '{1}' is not a depth-stencil-target texture; the pass draws "
              "into the target bound before")
// A RenderPort the scene cannot give (runtime: the frame's scene decides).
FX_DIAGNOSTIC(RenderPortLightNotInScene, Error,
              "RenderPort names light '{0}', which scene '{1}' does not have")
FX_DIAGNOSTIC(
    RenderPortLightWithoutCascades, Error,
    "RenderPort names cascade {0} of light '{1}', which has no cascades (its Parameterization is not "
    "\"Cascaded\" or \"PSMCube\")")
FX_DIAGNOSTIC(RenderPortCascadeOutOfRange, Error,
              "RenderPort names cascade {0} of light '{1}', which has {2} (CascadeCount)")
