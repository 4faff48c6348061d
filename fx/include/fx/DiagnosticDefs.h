// Every diagnostic the fx library and the runtime can report, with a stable id, a severity and a
// message template ({0}, {1}, ... are filled by Diagnostic::format). Kept in one table, in the manner of
// Slang's *-diagnostic-defs.h, so that tests can name ids and the ids never silently change meaning.
//
// FX_DIAGNOSTIC(Id, Severity, "template")
// Include this file with FX_DIAGNOSTIC defined; it undefines it at the end.

// [SECTION] Input and preprocessing
FX_DIAGNOSTIC(FileNotFound, Error, "cannot open file '{0}'")
FX_DIAGNOSTIC(IncludeNotFound, Error, "cannot open include file '{0}'")
FX_DIAGNOSTIC(IncludeCaseMismatch, Warning,
              "include file '{0}' found as '{1}', which differs in case (names are case-blind on Windows)")
// glslang's preprocessor message, as it words it (#error text, macro errors).
FX_DIAGNOSTIC(PreprocessorError, Error, "{0}")
FX_DIAGNOSTIC(IncludeTrailingText, Warning, "text after the include file name is ignored: '{0}'")
FX_DIAGNOSTIC(UndefinedConditionCall, Warning,
              "'{0}' is not a function-like macro here: its call in this condition reads as 0")
FX_DIAGNOSTIC(SourceTooLarge, Error, "source exceeds {0} bytes")
FX_DIAGNOSTIC(PreprocessingFailed, Error, "preprocessing failed")
FX_DIAGNOSTIC(InvalidCharacter, Error, "invalid character '{0}'")
FX_DIAGNOSTIC(UnterminatedString, Error, "unterminated string literal")
// Attached to a diagnostic at a macro's use (Diagnostic::notes), at the macro's #define.
FX_DIAGNOSTIC(InMacroExpansion, Note, "in expansion of macro '{0}' defined here")
FX_DIAGNOSTIC(TooManyTokens, Error, "effect too large: more than {0} tokens after preprocessing")
// An include the include handler refused, one id per reason ({0}: the name as written).
FX_DIAGNOSTIC(IncludeFileNameEmpty, Error, "cannot include '{0}': empty file name")
FX_DIAGNOSTIC(IncludeDepthExceeded, Error, "cannot include '{0}': include depth exceeds {1}")
FX_DIAGNOSTIC(IncludeRecursive, Error,
              "cannot include '{0}': include depth exceeds {1} (recursive include of '{2}')")
FX_DIAGNOSTIC(IncludeSourcesTooLarge, Error, "cannot include '{0}': sources exceed {1} bytes in total")

// [SECTION] Effect syntax
// {0}: what the grammar expects there, a token, a list of tokens ("',' or '}'") or a syntactic category
// ("an expression", "a type"): one message, the expected symbol named as a parser names it.
FX_DIAGNOSTIC(UnexpectedToken, Error, "expected {0}, found '{1}'")
// At the end of the line whose statement lacks its ';' (the parser goes on as if it were there).
FX_DIAGNOSTIC(MissingSemicolon, Error, "expected ';' after '{0}'")
FX_DIAGNOSTIC(UnclosedBlock, Error, "'{0}' expected (to close '{1}' at line {2})")
FX_DIAGNOSTIC(UnexpectedEndOfFile, Error, "unexpected end of file, expected {0}")
FX_DIAGNOSTIC(UnknownType, Error, "unknown type '{0}'")
FX_DIAGNOSTIC(Redefinition, Error, "redefinition of '{0}'")
FX_DIAGNOSTIC(UnknownState, Error, "unknown state '{0}'")
FX_DIAGNOSTIC(UnknownStateValue, Error, "'{0}' is not a value of state '{1}' (expected one of: {2})")
FX_DIAGNOSTIC(SamplerTextureUndeclared, Warning,
              "sampler '{0}' names texture '{1}', which the effect does not declare: it is declared as a "
              "texture parameter, as MonoGame's effect compiler declared it")
// A technique the compiler leaves out while another runs. Its first error follows as a note of this warning,
// with that error's own id (where every technique is left out the errors are reported as errors instead).
FX_DIAGNOSTIC(TechniqueRefused, Warning,
              "technique '{0}' is left out: it does not compile (its first error follows)")
// fxc's rules for annotations and structs, which glslang's HLSL front end does not enforce.
FX_DIAGNOSTIC(AnnotationNamesAnnotation, Error,
              "annotation '{0}' is initialized from annotation '{1}': an annotation's value must be a "
              "literal")
FX_DIAGNOSTIC(ObjectAnnotation, Error,
              "annotation '{0}' has the object type '{1}': annotations hold numbers, vectors, matrices and "
              "strings")
FX_DIAGNOSTIC(LocalAnnotation, Error,
              "annotations on the local variable '{0}': only parameters, techniques and passes take "
              "annotations")
FX_DIAGNOSTIC(ObjectInStruct, Error,
              "struct member '{0}' has the object type '{1}': an effect's structs hold no textures, "
              "samplers, buffers or states")
FX_DIAGNOSTIC(DynamicShaderLinkage, Error,
              "dynamic shader linkage ('{0}') is not supported: GLSL has no interfaces or classes to bind at "
              "run time")
FX_DIAGNOSTIC(StateObjectArray, Error, "an array of state objects has one dimension")
FX_DIAGNOSTIC(ExpressionTooComplex, Error,
              "expression too complex (more than {0} nested or chained operators)")
FX_DIAGNOSTIC(NestingTooDeep, Error, "nesting deeper than {0} levels")
FX_DIAGNOSTIC(ArraySizeOutOfRange, Error, "array size {0} is outside 1..{1} (all dimensions together)")
FX_DIAGNOSTIC(AsmShader, Error, "asm shaders are not supported")
FX_DIAGNOSTIC(MultisampleTargetWithoutSampleCount, Error,
              "{1} '{0}': a multisample render target needs its sample count (Texture2DMS<float4, 4>)")
FX_DIAGNOSTIC(MultisampleSampleCountInvalid, Error,
              "{1} '{0}': its sample count must be the second template argument, 1..32 "
              "(Texture2DMS<float4, 4>)")
FX_DIAGNOSTIC(WriteMaskTargetNeverBound, Error,
              "RenderTargetWriteMask[{0}] masks a render target the runtime never binds (it draws into four)")
FX_DIAGNOSTIC(StateTakesNoTargetIndex, Error, "{0} takes no render-target index")
// Invalid state values, one id per message ({0}: the state).
FX_DIAGNOSTIC(StateObjectArgumentCount, Error,
              "invalid value for state '{0}': expected {1} argument(s), found {2}")
FX_DIAGNOSTIC(StateObjectOfOtherKind, Error, "invalid value for state '{0}': '{1}' is not a {2}")
FX_DIAGNOSTIC(StateObjectNameExpected, Error, "invalid value for state '{0}': expected the name of a {1}")
FX_DIAGNOSTIC(CullWindingNotConstant, Error,
              "invalid value for state '{0}': must be a constant (it decides which winding is culled)")
FX_DIAGNOSTIC(ShaderStateValueExpected, Error,
              "invalid value for state '{0}': expected 'compile profile Function(...)', a shader variable or "
              "NULL")
FX_DIAGNOSTIC(ShaderStateArgumentCount, Error, "invalid value for state '{0}': expected one shader")
FX_DIAGNOSTIC(SamplerStateValueExpected, Error, "invalid value for state '{0}': expected (samplerName)")
FX_DIAGNOSTIC(SamplerStateNotSampler, Error, "invalid value for state '{0}': '{1}' is a {2}, not a sampler")
FX_DIAGNOSTIC(TextureStateValueExpected, Error, "invalid value for state '{0}': expected <texture>")
FX_DIAGNOSTIC(TextureStateNotTexture, Error,
              "invalid value for state '{0}': '{1}' is a {2} parameter, not a texture")
FX_DIAGNOSTIC(StateValueIsString, Error, "invalid value for state '{0}': expected a value, found a string")
FX_DIAGNOSTIC(PointSpriteEnableNotConstant, Error,
              "invalid value for state 'PointSpriteEnable': must be a constant (it decides what the pixel "
              "shader reads)")
FX_DIAGNOSTIC(FixedFunctionStateNotConstant, Error,
              "invalid value for state '{0}': must be a constant (it chooses the code of the fixed-function "
              "pipeline)")
// Invalid annotations, one id per message.
FX_DIAGNOSTIC(AnnotationStringExpected, Error, "invalid annotation '{0}': expected a string, found '{1}'")
FX_DIAGNOSTIC(AnnotationNumberExpected, Error, "invalid annotation '{0}': expected a number, found a string")
FX_DIAGNOSTIC(CullClosedOnlyInvalid, Error, "invalid annotation 'CullClosedOnly': expected true or false")
FX_DIAGNOSTIC(LeaveOutWhenInvalid, Error,
              "invalid annotation 'LeaveOutWhen': expected \"NoClosedObjects\" or \"NoLightArea\"")
FX_DIAGNOSTIC(FilterReachTexelsInvalid, Error,
              "invalid annotation 'FilterReachTexels': expected a number of texels")
FX_DIAGNOSTIC(ArraySizeWithoutArray, Error,
              "invalid annotation 'ArraySize': only a texture array has elements")
FX_DIAGNOSTIC(ArraySizeInvalid, Error, "invalid annotation 'ArraySize': must be an integer in 1..2048")
FX_DIAGNOSTIC(ProceduralTextureKind, Error,
              "invalid annotation 'Procedural': only a 2D texture that is not a render target can be "
              "procedural")
FX_DIAGNOSTIC(ProceduralGeneratorUnknown, Error,
              "invalid annotation 'Procedural': '{0}' is not a generator (known: \"noise\")")
FX_DIAGNOSTIC(ProceduralDepthFormat, Error,
              "invalid annotation 'Procedural': a noise texture needs a colour format")
FX_DIAGNOSTIC(ProceduralSeedInvalid, Error,
              "invalid annotation 'Seed': must be an integer between 0 and 4294967295")
FX_DIAGNOSTIC(StreamOutVerticesInvalid, Error,
              "invalid annotation 'StreamOutVertices': expected a whole number of vertices, 1 to 16777216")
FX_DIAGNOSTIC(DrawAutoNotString, Error,
              "invalid annotation 'DrawAuto': expected the name of a pass of technique '{0}' whose geometry "
              "shader streams out (ConstructGSWithSO)")
FX_DIAGNOSTIC(DrawAutoNotStreamingPass, Error,
              "invalid annotation 'DrawAuto': expected the name of a pass of technique '{0}' whose geometry "
              "shader streams out (ConstructGSWithSO); '{1}' is not one")
FX_DIAGNOSTIC(ParameterizationUnknown, Error,
              "invalid annotation 'Parameterization': expected \"Uniform\", \"Focused\", \"LiSPSM\", "
              "\"TSM\", \"PSM\", \"PSMCube\" or \"Cascaded\"")
FX_DIAGNOSTIC(ParameterizationConflict, Error,
              "invalid annotation 'Parameterization': light '{0}' is already parameterized as '{1}'")
FX_DIAGNOSTIC(ExpectationUnknown, Error,
              "invalid annotation '{0}': not an expectation shadowfx check knows (ExpectScenes, "
              "ExpectMisclassifiedBelow, ExpectPenumbraMaeBelow, ExpectAreaRadius, ExpectMapSize, "
              "ExpectShadows)")
FX_DIAGNOSTIC(ExpectationNumberExpected, Error, "invalid annotation '{0}': expected a number")
FX_DIAGNOSTIC(ExpectScenesInvalid, Error,
              "invalid annotation 'ExpectScenes': expected a string of comma-separated scene names or .json "
              "files")
FX_DIAGNOSTIC(ExpectationSceneBoundSyntax, Error,
              "invalid annotation '{0}': expected a number, or per-scene bounds \"SCENE=BOUND, ...\", got "
              "'{1}'")
FX_DIAGNOSTIC(ExpectationSceneNotExpected, Error,
              "invalid annotation '{0}': scene '{1}' is not one of ExpectScenes")
FX_DIAGNOSTIC(ExpectationSceneRepeated, Error, "invalid annotation '{0}': scene '{1}' is given twice")
FX_DIAGNOSTIC(ExpectationSceneMissing, Error,
              "invalid annotation '{0}': no bound for scene '{1}' of ExpectScenes")
FX_DIAGNOSTIC(ExpectAreaRadiusInvalid, Error,
              "invalid annotation 'ExpectAreaRadius': expected a radius above 0")
FX_DIAGNOSTIC(ExpectMapSizeInvalid, Error,
              "invalid annotation 'ExpectMapSize': expected an integer between 1 and 16384")
FX_DIAGNOSTIC(TuneRangeEmpty, Error,
              "invalid annotation 'UIMin': UIMin {0} of '{1}' is above its UIMax {2}: nothing to search")
FX_DIAGNOSTIC(TuneLogScaleMinimum, Error,
              "invalid annotation 'UIScale': a log scale needs UIMin > 0, and '{0}' has UIMin {1}")
FX_DIAGNOSTIC(TuneScaleUnknown, Error,
              "invalid annotation 'UIScale': '{0}' of '{1}' is neither \"linear\" nor \"log\"")
FX_DIAGNOSTIC(StateObjectArrayTooManyBlocks, Error, "'{0}[{1}]' is given more blocks than it has elements")
FX_DIAGNOSTIC(StateObjectIndexOutOfBounds, Error, "index {0} is outside '{1}', which has {2} elements")
FX_DIAGNOSTIC(StateObjectDynamicIndexFields, Error,
              "'{0}' is indexed by a parameter, so its elements must set the same render targets' fields "
              "(element {1} differs from element 0)")
FX_DIAGNOSTIC(StateObjectNotArray, Error, "invalid value for state '{0}': '{1}' is not an array of {2}s")

// The parser's reason to leave a technique out while another runs (TechniqueRefused: the compiler's).
FX_DIAGNOSTIC(
    TechniqueRefusedDynamicLinkage, Warning,
    "technique '{0}' is left out: dynamic shader linkage (BindInterfaces) is not supported: GLSL has "
    "no interfaces to bind at run time")
FX_DIAGNOSTIC(
    AllTechniquesRefusedDynamicLinkage, Error,
    "every technique of the effect is left out (the first: '{0}', dynamic shader linkage "
    "(BindInterfaces) is not supported: GLSL has no interfaces to bind at run time); nothing can run")
FX_DIAGNOSTIC(PassOutsideTechnique, Error,
              "expected a declaration ('pass' belongs inside a technique), found 'pass'")
// Constant sizes and indices out of range, one id per message ({0}: the expression as written).
FX_DIAGNOSTIC(MaxVertexCountInvalid, Error, "expected a vertex count 1..1024, found '{0}'")
FX_DIAGNOSTIC(PatchSizeInvalid, Error, "expected a control point count 1..32, found '{0}'")
FX_DIAGNOSTIC(VectorDimensionInvalid, Error, "expected a dimension 1..4, found '{0}'")
FX_DIAGNOSTIC(ArraySizeNotConstant, Error, "expected a constant array size, found '{0}'")
FX_DIAGNOSTIC(ArraySizeNotWhole, Error, "expected a whole array size, found '{0}'")
FX_DIAGNOSTIC(StateIndexInvalid, Error, "expected a constant index 0..15, found '{0}'")
FX_DIAGNOSTIC(RenderTargetIndexInvalid, Error, "expected a render-target index 0..7, found '{0}'")
FX_DIAGNOSTIC(StateTakesNoIndex, Error, "expected a state without an index, found '{0}'")

// [SECTION] SAS scripts
FX_DIAGNOSTIC(UnknownScriptCommand, Error, "unknown script command '{0}'")
FX_DIAGNOSTIC(ScriptUnknownPass, Error, "script names pass '{0}', which technique '{1}' does not have")
FX_DIAGNOSTIC(ScriptUnknownTarget, Error,
              "script names render target '{0}', which is not a render-target texture")
FX_DIAGNOSTIC(ScriptUnknownTechnique, Warning,
              "script names technique '{0}', which the effect does not have; skipped")
FX_DIAGNOSTIC(ScriptTechniqueFallback, Warning,
              "script names no technique the effect has; running its first technique, '{0}'")
FX_DIAGNOSTIC(ScriptUnbalancedLoop, Error, "LoopByCount without LoopEnd")
FX_DIAGNOSTIC(ScriptLoopEndWithoutLoop, Error, "LoopEnd without LoopByCount")
FX_DIAGNOSTIC(ScriptLoopIndexOutsideLoop, Error, "LoopGetIndex outside a loop")
// Invalid script commands, one id per message.
FX_DIAGNOSTIC(ScriptValueMissing, Error, "invalid script command '{0}': expected '=' and a value")
FX_DIAGNOSTIC(ScriptClearInvalid, Error,
              "invalid script command '{0}': expected Color, Depth, Stencil, DepthStencil or All")
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

// [SECTION] Compiling passes
FX_DIAGNOSTIC(MissingEntryPoint, Error, "entry point '{0}' not found")
FX_DIAGNOSTIC(UnsupportedProfile, Error, "unsupported shader profile '{0}'")
// glslang's own HLSL error and warning text, at the user's line.
FX_DIAGNOSTIC(HlslError, Error, "{0}")
FX_DIAGNOSTIC(HlslWarning, Warning, "{0}")
// {0}: the stage, {1}: the entry point, {2}: the profile, {3}: SPIRV-Cross's message.
FX_DIAGNOSTIC(CrossCompileError, Error,
              "SPIR-V to GLSL: the {0} shader '{1}' ({2}) cannot be written as GLSL (SPIRV-Cross: {3})")
// {0}: the signal that ended the worker.
FX_DIAGNOSTIC(HlslCompilerCrashed, Error, "the HLSL compiler crashed on this shader (signal {0})")
FX_DIAGNOSTIC(HlslCompilerTimedOut, Error,
              "the HLSL compiler did not finish this shader within {0} ms and was stopped")
// {0}: the worker program, {1}: the system call that failed, {2}: the system's message.
FX_DIAGNOSTIC(CompileWorkerFailed, Error, "cannot start the HLSL compiler's worker '{0}' ({1}: {2})")
// {0}: the worker's exit status (kWorkerSanitizerExitStatus).
FX_DIAGNOSTIC(
    CompileWorkerSanitizerReport, Error,
    "the HLSL compiler's worker process stopped on a sanitizer report (exit status {0}); the report "
    "is on standard error")
FX_DIAGNOSTIC(CompileWorkerNotFound, Warning,
              "no shadowfx-compile-worker found (set SHADOWFX_COMPILE_WORKER); compiling in this process, "
              "where a crash of the HLSL compiler ends the program")
FX_DIAGNOSTIC(UnknownIdentifier, Error, "unknown identifier '{0}'")
FX_DIAGNOSTIC(VertexInputConstant, Note,
              "vertex input '{0}' matches no mesh stream by its name; it reads the constant {1}")
// glslang's "mul() matrix size mismatch" said as fxc said it: both truncate the larger operand.
FX_DIAGNOSTIC(ImplicitTruncation, Warning,
              "implicit truncation of vector type (fxc's X3206): mul() of a vector and a matrix that differ "
              "in size reads only the rows or columns both have")
// The pass's shader stages, as the stage wrappers and the pass compiler take them.
FX_DIAGNOSTIC(HullWithoutDomain, Error,
              "a hull shader needs a domain shader in the same pass (SetDomainShader)")
FX_DIAGNOSTIC(DomainWithoutHull, Error,
              "a domain shader needs a hull shader in the same pass (SetHullShader)")
FX_DIAGNOSTIC(
    GeometryAfterTessellationInput, Error,
    "a geometry shader after tessellation takes 'triangle' input: the domain shader outputs triangles")
FX_DIAGNOSTIC(VertexInputNestedTooDeeply, Error, "vertex input '{0}' is nested too deeply")
FX_DIAGNOSTIC(PixelInputSemanticUnsupported, Error, "pixel input semantic '{0}' is not supported")
FX_DIAGNOSTIC(VertexOutputSemanticUnsupported, Error, "vertex output semantic '{0}' is not supported")
FX_DIAGNOSTIC(PixelOutputSemanticUnsupported, Error, "pixel output semantic '{0}' is not supported")
FX_DIAGNOSTIC(GeometryStreamElementNotStruct, Error,
              "the element of geometry shader stream '{0}' must be a struct")
FX_DIAGNOSTIC(
    GeometryOutputNotVector, Error,
    "geometry shader output '{0}' must be a scalar or a vector (structs, arrays and matrices are not "
    "supported)")
FX_DIAGNOSTIC(GeometryIntegerOutputInterpolated, Error,
              "geometry shader output '{0}' of an integer type must be 'nointerpolation'")
FX_DIAGNOSTIC(GeometryOutputSemanticUnsupported, Error,
              "geometry shader output semantic '{0}' is not supported")
FX_DIAGNOSTIC(GeometryMaxVertexCountMissing, Error,
              "geometry shader '{0}' has no [maxvertexcount(n)] attribute")
FX_DIAGNOSTIC(GeometryStreamRepeated, Error, "geometry shader '{0}' has more than one output stream")
FX_DIAGNOSTIC(GeometryInputPrimitiveRepeated, Error,
              "geometry shader '{0}' has more than one input primitive")
FX_DIAGNOSTIC(GeometryParameterUnsupported, Error,
              "geometry shader parameter '{0}' is not supported (expected the input primitive, the output "
              "stream, SV_PrimitiveID or a uniform)")
FX_DIAGNOSTIC(GeometryInputOrStreamMissing, Error,
              "geometry shader '{0}' needs an input primitive ('triangle T input[3]') and an output stream "
              "('inout TriangleStream<T> stream')")
FX_DIAGNOSTIC(GeometryLineAdjacencyInput, Error,
              "geometry shader input primitive 'lineadj' is not supported: a mesh's triangles define no line "
              "strips, so an edge has no single continuation at either end")
FX_DIAGNOSTIC(GeometryInputPrimitiveUnsupported, Error,
              "geometry shader input primitive '{0}' is not supported")
FX_DIAGNOSTIC(GeometryInputArraySize, Error,
              "geometry shader input '{0}' must be an array of {1} vertices ('{2} T {0}[{1}]')")
FX_DIAGNOSTIC(GeometryStreamNotInout, Error, "geometry shader stream '{0}' must be 'inout'")
FX_DIAGNOSTIC(GeometryInputSemanticUnsupported, Error,
              "geometry shader input semantic '{0}' is not supported")
FX_DIAGNOSTIC(ControlPointSemanticUnsupported, Error, "control point semantic '{0}' is not supported")
FX_DIAGNOSTIC(PatchConstantsNotStruct, Error,
              "the patch constants must be a struct with SV_TessFactor and SV_InsideTessFactor members")
FX_DIAGNOSTIC(PatchConstantSemanticRepeated, Error, "semantic '{0}' is used twice")
FX_DIAGNOSTIC(PatchConstantSemanticUnsupported, Error, "patch constant semantic '{0}' is not supported")
FX_DIAGNOSTIC(PatchConstantsWithoutTessFactor, Error,
              "the patch constants '{0}' have no SV_TessFactor member")
FX_DIAGNOSTIC(HullAttributeMissing, Error, "hull shader '{0}' has no [{1}(...)] attribute")
FX_DIAGNOSTIC(PatchConstantFunctionUndefined, Error,
              "patch-constant function '{0}' of hull shader '{1}' is not defined")
FX_DIAGNOSTIC(OutputControlPointsInvalid, Error, "[outputcontrolpoints] takes a number 1..32")
FX_DIAGNOSTIC(HullParameterUnsupported, Error,
              "hull shader parameter '{0}' is not supported (expected one InputPatch<T, 3>, "
              "SV_OutputControlPointID, SV_PrimitiveID or a uniform)")
FX_DIAGNOSTIC(HullInputPatchMissing, Error,
              "hull shader '{0}' needs an input patch ('InputPatch<T, 3> patch')")
FX_DIAGNOSTIC(InputPatchSizeUnsupported, Error,
              "an input patch of {0} control points is not supported: shadowfx draws a mesh's triangles as "
              "patches, which 'InputPatch<T, 3>' takes")
FX_DIAGNOSTIC(HullReturnsNoControlPoint, Error, "hull shader '{0}' must return its output control point")
FX_DIAGNOSTIC(OutputPatchReadsUnwritten, Error,
              "the output patch '{0}' of '{1}' reads a semantic that hull shader '{2}' does not write")
FX_DIAGNOSTIC(PatchConstantParameterUnsupported, Error,
              "patch-constant function parameter '{0}' is not supported (expected the hull shader's "
              "InputPatch<T, 3>, an OutputPatch<T, {1}> or SV_PrimitiveID)")
FX_DIAGNOSTIC(PatchConstantsNotReturnedAsStruct, Error,
              "patch-constant function '{0}' must return its patch constants as a struct")
FX_DIAGNOSTIC(DomainAttributeMissing, Error, "domain shader '{0}' has no [domain(...)] attribute")
FX_DIAGNOSTIC(DomainMismatch, Error,
              "domain shader '{0}' is for the '{1}' domain, hull shader '{2}' for '{3}'")
FX_DIAGNOSTIC(OutputPatchSizeMismatch, Error,
              "the output patch of domain shader '{0}' has {1} control points, hull shader '{2}' writes {3}")
FX_DIAGNOSTIC(
    DomainParameterUnsupported, Error,
    "domain shader parameter '{0}' is not supported (expected the patch constants, SV_DomainLocation, "
    "an OutputPatch, SV_PrimitiveID, an output or a uniform)")
FX_DIAGNOSTIC(GeometryOutputArrayLocationsApart, Error,
              "geometry shader output array '{0}' needs its elements' varyings at consecutive locations, "
              "and its semantic's names do not get them ('{1}' is not at the location after '{2}': "
              "free-named varyings take locations in their names' sorted order, the first eight 24..31); "
              "declare the elements as members of their own or give the array a semantic of fewer elements")
// Stream output (ConstructGSWithSO) that GL's transform feedback cannot capture.
FX_DIAGNOSTIC(
    StreamOutOtherStreams, Error,
    "stream output of a geometry shader's streams 1 to 3 is not supported: shadowfx captures stream 0")
FX_DIAGNOSTIC(StreamOutEmpty, Error, "stream output with an empty declaration captures nothing")
FX_DIAGNOSTIC(
    StreamOutPartialOutput, Error,
    "stream-output entry '{0}' captures part of an output; GL captures whole outputs ({1} components "
    "here)")
FX_DIAGNOSTIC(
    StreamOutOtherVertexShader, Error,
    "ConstructGSWithSO names vertex shader '{0}' but the pass sets '{1}'; the pass's vertex shader is "
    "the one streamed out")
FX_DIAGNOSTIC(StreamOutEntryNotCapturable, Error,
              "stream-output entry '{0}' names no output of the {1} shader that GL can capture whole")
// Evaluating an expression on the host (preshaders: initializers, state values, annotations).
FX_DIAGNOSTIC(NotAValue, Error, "'{0}' is not a value")
FX_DIAGNOSTIC(ExpectedString, Error, "expected a string")
FX_DIAGNOSTIC(CannotEvaluateType, Error, "cannot evaluate a {0}")
FX_DIAGNOSTIC(ExpectedNumber, Error, "expected a number, found a string")
FX_DIAGNOSTIC(CannotConvertType, Error, "cannot convert {0} to {1}")
FX_DIAGNOSTIC(ComponentCountMismatch, Error, "cannot convert {0} components to {1} ({2} components)")
FX_DIAGNOSTIC(OperandsMismatch, Error, "operands {0} and {1} do not match")
FX_DIAGNOSTIC(UnaryOperatorOnString, Error, "operator on a string")
FX_DIAGNOSTIC(BinaryOperatorOnString, Error, "operator '{0}' on a string")
FX_DIAGNOSTIC(IntegerDivisionByZero, Error, "integer division by zero")
FX_DIAGNOSTIC(IntegerModuloByZero, Error, "integer modulo by zero")
FX_DIAGNOSTIC(OperatorNotHostEvaluable, Error, "operator '{0}' cannot be evaluated on the host")
FX_DIAGNOSTIC(ConditionSizeMismatch, Error, "condition size does not match")
FX_DIAGNOSTIC(InvalidMatrixMember, Error, "invalid matrix member '{0}'")
FX_DIAGNOSTIC(MatrixMemberOutOfRange, Error, "matrix member '{0}' out of range")
FX_DIAGNOSTIC(InvalidSwizzle, Error, "invalid swizzle '{0}'")
FX_DIAGNOSTIC(InvalidSwizzleOnType, Error, "invalid swizzle '{0}' on {1}")
FX_DIAGNOSTIC(IndexOutOfRange, Error, "index out of range")
FX_DIAGNOSTIC(MatrixRowIndexOutOfRange, Error, "matrix row index out of range")
FX_DIAGNOSTIC(VectorIndexOutOfRange, Error, "vector index out of range")
FX_DIAGNOSTIC(ScalarIndexed, Error, "cannot index a scalar")
FX_DIAGNOSTIC(IntrinsicArgumentCount, Error, "{0}() takes {1} argument(s)")
FX_DIAGNOSTIC(IntrinsicOfString, Error, "{0}() of a string")
FX_DIAGNOSTIC(CrossArguments, Error, "cross() takes two float3")
FX_DIAGNOSTIC(MatrixNotSquare, Error, "{0}() takes a square matrix")
FX_DIAGNOSTIC(SingularMatrixInverse, Error, "inverse() of a singular matrix")
FX_DIAGNOSTIC(MulDimensionMismatch, Error, "mul({0}, {1}): inner dimensions differ")
FX_DIAGNOSTIC(FunctionNotHostEvaluable, Error, "function '{0}' cannot be evaluated on the host")
FX_DIAGNOSTIC(ConstructorComponentCount, Error, "{0} constructor needs {1} components, got {2}")
FX_DIAGNOSTIC(StringInInitializerList, Error, "string in an initializer list")
// A loop in a function a host expression calls, which the host unrolls as fxc did (the call stands at the
// location; {1}: where the loop's condition is).
FX_DIAGNOSTIC(HostLoopUnbounded, Error,
              "function '{0}' cannot be evaluated on the host: the loop at {1} has no count known when the "
              "effect is compiled")
FX_DIAGNOSTIC(HostLoopIterationLimit, Error,
              "function '{0}' cannot be evaluated on the host: the loop at {1} runs more than {2} iterations")
// Compute passes (SetComputeShader; docs/d3d10.md, "Compute shaders and read-write resources").
FX_DIAGNOSTIC(ComputeNumThreadsMissing, Error, "compute shader '{0}' has no [numthreads(x, y, z)] attribute")
FX_DIAGNOSTIC(ComputeParameterUnsupported, Error,
              "compute shader parameter '{0}' is not supported (expected SV_DispatchThreadID, SV_GroupID, "
              "SV_GroupThreadID, SV_GroupIndex or a uniform)")
// A vector assigned, returned or passed where a smaller one or a scalar is expected: fxc truncated it with
// warning X3206, glslang truncates it silently (HlslToSpirv's kImplicitTruncationPrefix).
FX_DIAGNOSTIC(ImplicitVectorTruncation, Warning,
              "implicit truncation of vector type (fxc's X3206): {0}, the first components kept")

// What the fixed-function pipeline generated for a pass cannot run (docs/fixed-function.md).
FX_DIAGNOSTIC(FixedFunctionVertexBlending, Error,
              "the fixed-function pipeline generated for this pass cannot run WorldTransform[{0}] (vertex "
              "blending) (docs/fixed-function.md)")
FX_DIAGNOSTIC(
    FixedFunctionLightBeyondEighth, Error,
    "the fixed-function pipeline generated for this pass cannot run light {0} (D3D9 lit with lights "
    "0-7) (docs/fixed-function.md)")
FX_DIAGNOSTIC(FixedFunctionLightType, Error,
              "the fixed-function pipeline generated for this pass cannot run light type {0} "
              "(docs/fixed-function.md)")
FX_DIAGNOSTIC(
    FixedFunctionTextureStageBeyondSecond, Error,
    "the fixed-function pipeline generated for this pass cannot run texture stage {0} (stages 0 and "
    "1 are generated) (docs/fixed-function.md)")
FX_DIAGNOSTIC(FixedFunctionTexCoordIndex, Error,
              "the fixed-function pipeline generated for this pass cannot run TexCoordIndex {0} (texture "
              "coordinate sets 0 and 1) (docs/fixed-function.md)")
FX_DIAGNOSTIC(FixedFunctionStageArgument, Error,
              "the fixed-function pipeline generated for this pass cannot run the argument {0} of texture "
              "stage {1} (docs/fixed-function.md)")
FX_DIAGNOSTIC(FixedFunctionStageOperation, Error,
              "the fixed-function pipeline generated for this pass cannot run the operation {0} of texture "
              "stage {1} (docs/fixed-function.md)")
// Invalid compile expressions, one id per message.
FX_DIAGNOSTIC(CompileTooManyArguments, Error,
              "invalid compile expression: '{0}' has {1} uniform parameter(s), {2} argument(s) given")
FX_DIAGNOSTIC(CompileArgumentMissing, Error,
              "invalid compile expression: no argument for uniform parameter '{0}' of '{1}'")
FX_DIAGNOSTIC(CompileTextureArgumentNotTexture, Error,
              "invalid compile expression: argument for texture parameter '{0}' must name an effect texture")
FX_DIAGNOSTIC(CompileSamplerArgumentNotSampler, Error,
              "invalid compile expression: argument for sampler parameter '{0}' must name an effect sampler")
FX_DIAGNOSTIC(CompileUniformTypeUnsupported, Error,
              "invalid compile expression: uniform parameter '{0}' of type {1} is not supported")
FX_DIAGNOSTIC(CompileShaderArrayIndexOutOfRange, Error,
              "invalid compile expression: index {0} is outside shader array '{1}'")
FX_DIAGNOSTIC(NotCompileExpression, Error, "invalid compile expression: '{0}' is not a compile expression")
FX_DIAGNOSTIC(CompileShaderCallInvalid, Error,
              "invalid compile expression: expected CompileShader(profile, Function(...))")
FX_DIAGNOSTIC(ConstructGSWithSOCallInvalid, Error,
              "invalid compile expression: expected ConstructGSWithSO(shader, \"declaration\") or "
              "ConstructGSWithSO(shader, \"stream0\", \"stream1\", \"stream2\", \"stream3\", "
              "rasterizedStream)")
FX_DIAGNOSTIC(ProfileOfOtherStage, Error,
              "invalid compile expression: '{0}' is a {1}-shader profile, used for the {2} shader")
// Invalid stream-output declaration entries, one id per message ({0}: the entry).
FX_DIAGNOSTIC(StreamOutSlotInvalid, Error,
              "invalid stream-output declaration entry '{0}': the output slot is not one of 0..3")
FX_DIAGNOSTIC(StreamOutSemanticMissing, Error,
              "invalid stream-output declaration entry '{0}': it names no semantic")
FX_DIAGNOSTIC(StreamOutSemanticNameInvalid, Error,
              "invalid stream-output declaration entry '{0}': '{1}' is not a semantic name with an optional "
              "index")
FX_DIAGNOSTIC(StreamOutMaskInvalid, Error,
              "invalid stream-output declaration entry '{0}': '{1}' is not a component mask (contiguous "
              "components of xyzw)")
FX_DIAGNOSTIC(StreamOutOutputMissing, Error,
              "invalid stream-output declaration entry '{0}': '{1}' writes no output '{2}'")
// {3}: the output's component count and the word, "1 component" or "3 components".
FX_DIAGNOSTIC(StreamOutMaskBeyondOutput, Error,
              "invalid stream-output declaration entry '{0}': output '{1}' of '{2}' has {3}")
// glslang's error in the code shadowfx generated around an entry point ({1}), not in the user's.
FX_DIAGNOSTIC(HlslErrorInGeneratedCode, Error, "{0} (in the code generated for '{1}')")
// SPIRV-Cross's "Cannot find mapping for combined sampler", said in the effect's terms (as
// CrossCompileError).
FX_DIAGNOSTIC(
    CrossCompileCombinedSampler, Error,
    "SPIR-V to GLSL: a texture object's Sample or Gather method is given a D3D9 sampler (sampler2D, "
    "samplerCUBE, or a sampler the code also reads with tex2D and its kin), where it takes a SamplerState; "
    "the {0} shader '{1}' ({2}) cannot be written as GLSL (SPIRV-Cross: {3})")
FX_DIAGNOSTIC(StreamOutPartialPosition, Error,
              "stream-output entry '{0}' captures part of an output; GL captures whole outputs (4 components "
              "here, the position)")
FX_DIAGNOSTIC(StreamOutPartialFloat4Varying, Error,
              "stream-output entry '{0}' captures part of an output; GL captures whole outputs (4 components "
              "here, a float4 varying)")
// A compile worker that stopped or failed without answering (fx/src/CompileWorkers.cpp).
FX_DIAGNOSTIC(HlslCompilerExited, Error,
              "the HLSL compiler's worker exited with status {0} on this shader without answering")
FX_DIAGNOSTIC(CompileWorkerExitedWhileIdle, Error,
              "the HLSL compiler's worker exited with status {0} while idle, before this shader was sent")
FX_DIAGNOSTIC(CompileWorkerConnectionClosed, Error,
              "the HLSL compiler's worker closed its connection without answering")
FX_DIAGNOSTIC(CompileWorkerRefusedRequest, Error, "the HLSL compiler's worker does not accept requests")
FX_DIAGNOSTIC(CompileWorkerReplyUnreadable, Error,
              "the HLSL compiler's worker answered something unreadable (a worker from another build?)")
// {0}: the worker's exit status (kWorkerSanitizerExitStatus), found when the next shader was sent.
FX_DIAGNOSTIC(
    CompileWorkerSanitizerReportWhileIdle, Error,
    "the HLSL compiler's worker process stopped on a sanitizer report while idle (exit status {0}), "
    "before this shader was sent; the report is on standard error")

// [SECTION] Resources and execution
FX_DIAGNOSTIC(TextureFileNotFound, Warning, "cannot load texture '{0}'; using a neutral texture")
FX_DIAGNOSTIC(TextureCaseMismatch, Warning,
              "texture file '{0}' found as '{1}', which differs in case (names are case-blind on Windows)")
// An image file stb_image refuses; {1}: its reason.
FX_DIAGNOSTIC(TextureFileUnreadable, Error, "cannot read texture file '{0}' (stb_image: {1})")
FX_DIAGNOSTIC(InvalidTextureFormat, Error, "unknown texture format '{0}'")
FX_DIAGNOSTIC(SampleCountReduced, Warning,
              "'{0}' has {1} samples per texel; this OpenGL holds at most {2}, which it gets instead")
FX_DIAGNOSTIC(UnknownTechnique, Error, "effect has no technique named '{0}'")
FX_DIAGNOSTIC(NoTechniques, Error, "the file has no techniques")
FX_DIAGNOSTIC(UnknownParameter, Error, "effect has no parameter named '{0}'")
// {1}: the GL driver's link log.
FX_DIAGNOSTIC(LinkError, Error, "GL program link failed: pass '{0}': {1}")
// The GL driver's KHR_debug message.
FX_DIAGNOSTIC(GlDebugMessage, Note, "OpenGL: {0}")
// What the GL driver said, compiling or linking a program that worked, about the GLSL shadowfx generated:
// its line numbers are the generated GLSL's (`shadowfx compile` prints it), not the effect's.
// {0}: the stage, {1}: the entry point, {2}: the pass, {3}: a line of the driver's log.
FX_DIAGNOSTIC(DriverShaderLog, Note,
              "the GL driver on the generated GLSL of {0} shader '{1}' of pass '{2}': {3}")
FX_DIAGNOSTIC(UnboundSemantic, Warning,
              "parameter '{0}' has semantic '{1}', which shadowfx does not bind: it keeps its default value "
              "(shadowfx info lists the semantics shadowfx binds)")
FX_DIAGNOSTIC(ParameterBoundByName, Note,
              "parameter '{0}' has no semantic; bound as '{1}' by its name, as an application setting it by "
              "name would")
FX_DIAGNOSTIC(ParameterNamesMissingLight, Note,
              "parameter '{0}' names light '{1}', which the scene does not have; it keeps its value")
FX_DIAGNOSTIC(PassWithoutShaders, Warning, "pass '{0}' draws but has no vertex and pixel shader; skipped")
FX_DIAGNOSTIC(
    DepthTargetSmaller, Warning,
    "pass '{0}' tests depth or stencil in a {1} colour target with a smaller {2} depth-stencil target: "
    "only their overlap is drawn (D3D9 requires the depth-stencil surface to be at least as large; set "
    "RenderDepthStencilTarget to one of the colour target's size)")
FX_DIAGNOSTIC(DepthBiasClampUnavailable, Warning,
              "DepthBiasClamp is not applied: this OpenGL has no glPolygonOffsetClamp (GL 4.6 or "
              "ARB_polygon_offset_clamp); the depth bias is unbounded")
FX_DIAGNOSTIC(BufferElementUnsupported, Error,
              "Buffer<{0}>: GL buffer textures hold 32-bit float, int and uint elements of 1 to 4 components")
FX_DIAGNOSTIC(ParameterNotSettableFromCommandLine, Error,
              "parameter '{0}' of type {1} cannot be set from the command line")
FX_DIAGNOSTIC(ParameterValueInvalid, Error, "'{0}' is not a value of type {1} for parameter '{2}'")
FX_DIAGNOSTIC(ParameterValueCount, Error, "parameter '{0}' of type {1} needs {2} values, got {3}")
FX_DIAGNOSTIC(LispsmChoiceInvalid, Error,
              "'{0}' is not a choice of LiSPSM's n for parameter '{1}' (expected \"Scherzer2005\", "
              "\"Wimmer2004\" or \"Lloyd2006\")")
// Data an application passes for a parameter (EffectResources::setTexture, setBuffer).
FX_DIAGNOSTIC(SetTextureNotReadTexture, Error,
              "setTexture: parameter {0} is not a 2D, cube or array texture that passes only read")
FX_DIAGNOSTIC(SetTextureDataSize, Error,
              "setTexture: '{0}' ({1}) needs width x height x elements RGBA texels")
FX_DIAGNOSTIC(SetCubeTextureDataSize, Error,
              "setTexture: '{0}' ({1}) needs width x height x 6 faces x elements RGBA texels, square faces")
FX_DIAGNOSTIC(SetBufferNotBuffer, Error,
              "setBuffer: parameter {0} is not a Buffer, StructuredBuffer or ByteAddressBuffer")
FX_DIAGNOSTIC(SetBufferByteCount, Error, "setBuffer: '{0}' ({1}) got no bytes or too many")
FX_DIAGNOSTIC(SetBufferElementSize, Error, "setBuffer: '{0}' ({1}) takes elements of {2} bytes")
FX_DIAGNOSTIC(SetBufferWholeWords, Error, "setBuffer: '{0}' ({1}) takes whole 32-bit words")
FX_DIAGNOSTIC(SetBufferPackedElementSize, Error,
              "setBuffer: '{0}' ({1}) takes elements of {2} bytes (its members packed as D3D packs them)")
// FX Composer's texture functions (`string function = "f";` on a texture, docs/fxcomposer.md).
FX_DIAGNOSTIC(TextureFunctionTarget, Error,
              "'{0}' cannot be filled by a function: only a 2D, volume or cube colour texture that is not a "
              "render target can")
FX_DIAGNOSTIC(TextureFunctionUndefined, Error, "texture function {0} is not a function of the effect")
FX_DIAGNOSTIC(
    TextureFunctionParameter, Error,
    "texture function '{0}': parameter '{1}' ({2}) is not an input a texture function takes (float, "
    "float2 or float3 with semantic POSITION or PSIZE)")
FX_DIAGNOSTIC(TextureFunctionReturn, Error,
              "texture function '{0}' returns {1}; it must return a colour (float to float4)")
FX_DIAGNOSTIC(TextureFunctionSamples, Error,
              "texture function '{0}' reads '{1}'; a texture function is drawn when the effect is created, "
              "from parameter values alone, and reads no texture, sampler or buffer")
// Running compute passes (EffectPass::dispatch, the SAS script's Dispatch=).
FX_DIAGNOSTIC(DispatchNotCompute, Error, "dispatch: pass '{0}' has no compute shader")
FX_DIAGNOSTIC(DispatchGroupCount, Error,
              "dispatch: pass '{0}' asks for {1} thread groups; this OpenGL dispatches at most {2} per "
              "dimension")
FX_DIAGNOSTIC(ElementCountInvalid, Error,
              "ElementCount of '{0}' is {1}; a storage buffer holds 1 to 268435456 elements")
FX_DIAGNOSTIC(ViewOfUnknownResource, Error,
              "'{0}' is a view of '{1}', which is no buffer or read-write texture parameter of the effect")
FX_DIAGNOSTIC(ImageFormatUnsupported, Error,
              "'{0}' ({1}) is an image of format '{2}'; shadowfx makes float and unorm images (float1, 2, 4 "
              "elements, unorm4)")

// Sizes out of range, one id per message.
FX_DIAGNOSTIC(RenderTargetSizeOutOfRange, Error,
              "invalid render-target size: {0}x{1} (each side must be 1..{2})")
FX_DIAGNOSTIC(ViewportRatioOutOfRange, Error, "invalid render-target size: ViewPortRatio must be in (0, 16]")
FX_DIAGNOSTIC(VolumeDepthOutOfRange, Error, "invalid render-target size: a volume's depth must be 1..2048")
// {1}: the image's width, width x height or width x height x depth.
FX_DIAGNOSTIC(ImageSizeOutOfRange, Error, "invalid render-target size: {0} is {1}")

// A frame that could not run on GL.
// {1}: the status glCheckFramebufferStatus gave (GL_FRAMEBUFFER_UNSUPPORTED, ...).
FX_DIAGNOSTIC(PassTargetsUnbindable, Error,
              "OpenGL: the targets of pass '{0}' make an incomplete framebuffer ({1})")
FX_DIAGNOSTIC(ScriptTargetsUnbindable, Error,
              "OpenGL: the script's targets make an incomplete framebuffer ({0})")
FX_DIAGNOSTIC(GlErrorDuringFrame, Error, "OpenGL: GL error during the frame")
// As DriverShaderLog, for the pixel stage shadowfx generated for a fixed-function pass ({0}), {1}: the log
// line.
FX_DIAGNOSTIC(DriverFixedFunctionLog, Note,
              "the GL driver on the generated GLSL of the fixed-function pixel stage of pass '{0}': {1}")
// As DriverShaderLog, for what the driver said linking the program of pass {0}.
FX_DIAGNOSTIC(DriverLinkLog, Note, "the GL driver on the generated GLSL of pass '{0}', linking: {1}")
// A DDS file the texture reader refuses (runtime/gl/src/TextureFile.cpp); {0}: the file as the effect names
// it.
FX_DIAGNOSTIC(TextureFileUnopenable, Error, "cannot open texture file '{0}'")
FX_DIAGNOSTIC(TextureFileNotDds, Error,
              "texture file '{0}' is not a DDS file (no \"DDS \" magic and 124-byte header)")
FX_DIAGNOSTIC(TextureFileDx10HeaderTruncated, Error, "texture file '{0}' ends inside its DX10 header")
FX_DIAGNOSTIC(
    TextureFileDxgiFormatUnsupported, Error,
    "texture file '{0}': DXGI format {1} is not read (the 8-, 16- and 32-bit UNORM and FLOAT colour "
    "formats and BC1-5 are)")
FX_DIAGNOSTIC(TextureFileDimensionNotTexture, Error,
              "texture file '{0}': DX10 resource dimension {1} is not a texture")
// {1}: the FourCC's four characters ('?' for one that does not print), {2}: its value.
FX_DIAGNOSTIC(
    TextureFileFourCCUnsupported, Error,
    "texture file '{0}': pixel format '{1}' (FourCC {2}) is not read (DXT1-5, ATI1/ATI2 and the D3D9 "
    "float and 16-bit formats are)")
FX_DIAGNOSTIC(
    TextureFilePixelFormatUnsupported, Error,
    "texture file '{0}': pixel format flags {1} with {2} bits per texel are not read (RGB, luminance "
    "and alpha masks of 8 to 32 bits are)")
FX_DIAGNOSTIC(TextureFileCubeFacesMissing, Error,
              "texture file '{0}' is a cube map with fewer than six faces, which is not read")
// {1}x{2}x{3}: width, height and depth the header gives, {4}: its elements, {5}: the largest side read.
FX_DIAGNOSTIC(TextureFileHeaderMalformed, Error,
              "texture file '{0}' has a malformed header: {1}x{2}x{3}, {4} elements (sides up to {5}, square "
              "cube faces)")
FX_DIAGNOSTIC(TextureFileElementTruncated, Error, "texture file '{0}' ends inside element {1}'s data")
FX_DIAGNOSTIC(TextureFileTexelsTruncated, Error,
              "texture file '{0}' ends inside its texel data ({1} of {2} bytes)")
// A target the framebuffer cache refuses before GL sees it (runtime/gl/src/Framebuffer.cpp).
FX_DIAGNOSTIC(ColorTargetHasDepthFormat, Error,
              "OpenGL: colour target {0} has a depth format and cannot be drawn to")
FX_DIAGNOSTIC(DepthTargetHasColorFormat, Error,
              "OpenGL: the depth-stencil target has a colour format and cannot be drawn to")

// [SECTION] Scenes (runtime/assets/src/SceneFile.cpp, MeshImporter.cpp)
FX_DIAGNOSTIC(SceneSyntaxError, Error, "invalid JSON: {0}")
FX_DIAGNOSTIC(SceneUnknownKey, Warning, "{0}: unknown key '{1}' (ignored)")
FX_DIAGNOSTIC(MeshFileNotFound, Error, "cannot open mesh file '{0}'")
// {1}: assimp's reason.
FX_DIAGNOSTIC(MeshImportError, Error, "cannot import mesh '{0}' (assimp: {1})")
FX_DIAGNOSTIC(UnknownScene, Error, "no built-in scene named '{0}' (known: {1})")
// Invalid values in a scene file, one id per message ({0}: the key).
FX_DIAGNOSTIC(SceneObjectExpected, Error, "{0}: expected an object, found {1}")
FX_DIAGNOSTIC(SceneNumberExpected, Error, "{0}: expected a number, found {1}")
FX_DIAGNOSTIC(SceneNumberOutOfRange, Error, "{0}: value {1} out of range [{2}, {3}]")
FX_DIAGNOSTIC(SceneIntegerExpected, Error, "{0}: expected an integer in [{1}, {2}]")
FX_DIAGNOSTIC(SceneBoolExpected, Error, "{0}: expected true or false, found {1}")
FX_DIAGNOSTIC(SceneStringExpected, Error, "{0}: expected a string, found {1}")
FX_DIAGNOSTIC(SceneVectorExpected, Error, "{0}: expected an array of 3 numbers, found {1}")
FX_DIAGNOSTIC(SceneVectorOrNumberExpected, Error,
              "{0}: expected an array of 3 numbers or a number, found {1}")
FX_DIAGNOSTIC(SceneMeshFileExpected, Error, "{0}: expected a mesh file name")
FX_DIAGNOSTIC(
    SceneMeshSourceMissing, Error,
    "{0}: a mesh needs \"file\" or \"primitive\" (plane, box, sphere, torus, teapot, cylinder, cone)")
FX_DIAGNOSTIC(ScenePlaneSizeInvalid, Error, "{0}: expected a number or an array of 2 numbers [x, z]")
FX_DIAGNOSTIC(SceneUnknownPrimitive, Error,
              "{0}: unknown primitive '{1}' (plane, box, sphere, torus, teapot, cylinder, cone)")
FX_DIAGNOSTIC(SceneUnknownMesh, Error, "{0}: no mesh named '{1}' in \"meshes\"")
FX_DIAGNOSTIC(SceneMeshExpected, Error, "{0}: expected a mesh name or a mesh definition, found {1}")
FX_DIAGNOSTIC(SceneObjectWithoutMesh, Error, "{0}: an object needs a \"mesh\"")
FX_DIAGNOSTIC(SceneInstancesExpected, Error, "{0}: expected an array of transforms, found {1}")
FX_DIAGNOSTIC(SceneCameraFarNotBeyondNear, Error, "camera.far: must be greater than camera.near")
FX_DIAGNOSTIC(SceneCameraTargetAtPosition, Error, "camera.target: must differ from camera.position")
FX_DIAGNOSTIC(SceneUnknownLightType, Error, "{0}: unknown light type '{1}' (directional, spot, point)")
FX_DIAGNOSTIC(SceneLightDirectionZero, Error, "{0}: must not be zero")
FX_DIAGNOSTIC(SceneArrayExpected, Error, "{0}: expected an array, found {1}")
FX_DIAGNOSTIC(SceneWithoutObjects, Error, "objects: the scene has no objects")
FX_DIAGNOSTIC(SceneBoundsIncomplete, Error, "bounds: needs \"min\" and \"max\"")
FX_DIAGNOSTIC(SceneBoundsInverted, Error, "bounds: min must not exceed max")
FX_DIAGNOSTIC(SceneViewportHintInvalid, Error, "hints.viewport: expected [width, height], positive integers")
// nlohmann-json's own text, where a value had a type the reader did not check first.
FX_DIAGNOSTIC(SceneReadFailed, Error, "(scene): {0}")
// Invalid values in a host file ({0}: the JSON pointer), one id per message.
FX_DIAGNOSTIC(HostFrameMissing, Error,
              "{0}: frame: a host file needs a \"frame\": the steps the application draws")
FX_DIAGNOSTIC(HostFrameNotSteps, Error, "{0}: frame: expected a non-empty array of steps")
FX_DIAGNOSTIC(HostObjectExpected, Error, "{0}: expected an object, found {1}")
FX_DIAGNOSTIC(HostStringExpected, Error, "{0}: expected a string, found {1}")
FX_DIAGNOSTIC(HostTargetNamedFrame, Error, "{0}: 'frame' is the application's frame, not a target it creates")
FX_DIAGNOSTIC(
    HostTargetFormatInvalid, Error,
    "{0}: '{1}' is not a colour format (R32F, A8R8G8B8, A16B16G16R16F, G32R32F, ...; every target has "
    "a depth buffer of its own)")
FX_DIAGNOSTIC(HostTargetSizeInvalid, Error, "{0}: expected [width, height], whole numbers from 1 to 16384")
FX_DIAGNOSTIC(HostLightValueNotPositive, Error, "{0}: {1}: expected a number > 0")
FX_DIAGNOSTIC(HostLightFovTooWide, Error, "{0}: fovY: expected degrees below 180")
FX_DIAGNOSTIC(HostLightFarNotBeyondNear, Error, "{0}: far: expected more than near")
FX_DIAGNOSTIC(
    HostValueUnknown, Error,
    "{0}: '{1}' is not a matrix (World, View, Projection, WorldView, ViewProjection, "
    "WorldViewProjection, with Inverse and Transpose forms, after 'camera.' or a light's name), a "
    "light's Position, ViewPosition, Direction, ViewDirection, Color or CosHalfAngle, ObjectColor or "
    "ViewportSize")
FX_DIAGNOSTIC(HostProductNotMatrix, Error, "{0}: a product takes matrices only")
FX_DIAGNOSTIC(HostParameterValueExpected, Error,
              "{0}: expected what the parameter is (a string, an array of matrices or of numbers, a number, "
              "true or false), found {1}")
FX_DIAGNOSTIC(HostStepWithoutTechnique, Error, "{0}: a step needs a \"technique\"")
FX_DIAGNOSTIC(HostStepUnknownTarget, Error,
              "{0}: no target named '{1}' (\"targets\" creates them; \"frame\" is the application's frame)")
FX_DIAGNOSTIC(HostClearColorInvalid, Error, "{0}: expected [r, g, b, a]")
FX_DIAGNOSTIC(HostClearDepthInvalid, Error, "{0}: expected a number from 0 to 1")
FX_DIAGNOSTIC(HostStepDrawInvalid, Error, "{0}: expected \"geometry\", \"quad\" or \"nothing\", found '{1}'")
FX_DIAGNOSTIC(HostVisibilityValueInvalid, Error, "{0}: expected a number, true, false or an array of numbers")
FX_DIAGNOSTIC(
    HostUnshadowedMissing, Error,
    "{0}: expected \"unshadowed\": the targets (shadow maps) that light everything when left cleared")
FX_DIAGNOSTIC(HostUnshadowedUnknownTarget, Error, "{0}: no target named '{1}'")
FX_DIAGNOSTIC(HostTargetKindInvalid, Error,
              "{0}: expected \"2d\", \"cube\", \"array\" or \"volume\", found '{1}'")
FX_DIAGNOSTIC(HostTargetLayersInvalid, Error,
              "{0}: expected a whole number from 1 to 2048 (an array's elements or a volume's slices)")
FX_DIAGNOSTIC(HostTargetLayersWithoutLayers, Error,
              "{0}: a {1} target has no \"layers\" (only an array or a volume does; a cube has six faces)")
FX_DIAGNOSTIC(
    HostStepViewportsInvalid, Error,
    "{0}: expected 1 to 16 viewports, each [x, y, width, height] in pixels, width and height above 0")
FX_DIAGNOSTIC(HostStepDispatchInvalid, Error,
              "{0}: expected 1 to 3 group counts, each a whole number or a parameter's name")
// A host file checked against the effect it drives (fx::checkHostFile).
FX_DIAGNOSTIC(HostParameterUnknown, Error, "{0}: the effect has no parameter '{1}'")
FX_DIAGNOSTIC(HostParameterNotNumeric, Error, "{0}: '{1}' is a {2}, not a number, vector or matrix")
FX_DIAGNOSTIC(HostValueSizeMismatch, Error,
              "{0}: '{1}' is a {2} ({3} components), which this value ({4}) does not fit")
FX_DIAGNOSTIC(HostTargetTextureUnknown, Error, "{0}: the effect has no texture parameter '{1}'")
FX_DIAGNOSTIC(HostStepTechniqueUnknown, Error, "{0}: the effect has no technique '{1}'")
FX_DIAGNOSTIC(HostStepPassUnknown, Error, "{0}: technique '{1}' has no pass '{2}'")
FX_DIAGNOSTIC(HostTargetTextureKindMismatch, Error,
              "{0}: a {1} target cannot be given to '{2}', a {3} (a 2d target goes to a Texture2D or "
              "texture, a cube to a TextureCube, an array to a Texture2DArray, a volume to a Texture3D)")
// Drawing a host file's frame (runtime::HostFrame).
FX_DIAGNOSTIC(HostLightNotInScene, Error, "light: the scene has no light named '{0}'")
// {0}: the step's target, {1}: the status glCheckFramebufferStatus gave.
FX_DIAGNOSTIC(HostTargetUnbindable, Error, "target: '{0}' makes an incomplete framebuffer in OpenGL ({1})")
// A mesh file assimp read that holds nothing to draw (MeshImporter.cpp).
FX_DIAGNOSTIC(MeshWithoutTriangles, Error, "cannot import mesh '{0}': the file has no triangles")
// A mesh of a Debian package ({1}) that is not installed.
FX_DIAGNOSTIC(
    MeshFileNotInstalled, Error,
    "cannot open mesh file '{0}' (installed by the Debian package '{1}': apt-get install {1}, or run "
    "scripts/install-deps.sh)")
// The mesh import module (runtime/RuntimeModules.h) that could not be opened; {1}: its file.
FX_DIAGNOSTIC(MeshModuleMissing, Error,
              "cannot import mesh '{0}': the mesh import (assimp) module {1} is missing: looked for {2} "
              "(SHADOWFX_MODULE_DIR names the folder that holds it)")
// {2}: the dynamic loader's reason.
FX_DIAGNOSTIC(
    MeshModuleUnloadable, Error,
    "cannot import mesh '{0}': the dynamic loader refused the mesh import (assimp) module {1} ({2})")
FX_DIAGNOSTIC(
    MeshModuleEntryMissing, Error,
    "cannot import mesh '{0}': the mesh import (assimp) module {1} has no entry point '{2}': it was "
    "built from another version of shadowfx")
// A host file's value of a type the reader did not check first (as SceneReadFailed); {0}: nlohmann-json's
// message.
FX_DIAGNOSTIC(HostValueUnreadable, Error, "a value of the host file cannot be read (nlohmann-json: {0})")

// [SECTION] Compiled effect files (fx/CompiledEffectFile.h, docs/compiled-effect.md)
FX_DIAGNOSTIC(
    CompiledEffectNewerFormat, Error,
    "the compiled effect file has format version {0}, newer than this shadowfx reads ({1}): use the "
    "shadowfx that wrote it, or compile the effect again")
FX_DIAGNOSTIC(
    CompiledEffectOlderFormat, Error,
    "the compiled effect file has format version {0}, which this shadowfx no longer reads (it reads "
    "{1}): compile the effect again")
FX_DIAGNOSTIC(NotCompiledEffect, Error,
              "not a compiled effect file (shadowfx compile EFFECT.fx --out EFFECT.sfxo writes one)")
FX_DIAGNOSTIC(CompiledEffectWriteFailed, Error, "cannot write compiled effect file '{0}'")

FX_DIAGNOSTIC(CompiledEffectHeaderTruncated, Error,
              "the compiled effect file is truncated: its header ends after {0} of {1} bytes")
FX_DIAGNOSTIC(CompiledEffectContentTruncated, Error,
              "the compiled effect file is truncated: {0} of {1} bytes of content")
FX_DIAGNOSTIC(CompiledEffectTrailingBytes, Error,
              "the compiled effect file is corrupt: {0} bytes follow the content")
FX_DIAGNOSTIC(CompiledEffectHashMismatch, Error,
              "the compiled effect file is corrupt: its content does not match its hash")
// What the reader could not decode (fx/src/BinaryArchive.h), one id per reason; the last argument: the byte
// of the content where the read stood.
FX_DIAGNOSTIC(
    CompiledEffectFlagInvalid, Error,
    "the compiled effect file is corrupt: a flag that is neither 0 nor 1 at byte {0} of the content")
FX_DIAGNOSTIC(
    CompiledEffectEnumeratorUnknown, Error,
    "the compiled effect file is corrupt: an enumerator this shadowfx does not know ('{0}') at byte "
    "{1} of the content")
FX_DIAGNOSTIC(CompiledEffectEnumeratorOutOfRange, Error,
              "the compiled effect file is corrupt: an enumerator out of range ({0}) at byte {1} of the "
              "content")
// {0}: the kind of value being read ("a flag", "an integer", "a list").
FX_DIAGNOSTIC(CompiledEffectContentEndsInValue, Error,
              "the compiled effect file is corrupt: the content ends inside {0} at byte {1} of the content")
FX_DIAGNOSTIC(CompiledEffectLengthBeyondContent, Error,
              "the compiled effect file is corrupt: the length of {0} ({1}) exceeds the bytes left at byte "
              "{2} of the content")
FX_DIAGNOSTIC(CompiledEffectTypeTooLarge, Error,
              "the compiled effect file is corrupt: a type with more than 4 rows or columns at byte {0} of "
              "the content")
FX_DIAGNOSTIC(CompiledEffectArrayDimensionOutOfRange, Error,
              "the compiled effect file is corrupt: an array dimension out of range at byte {0} of the "
              "content")
FX_DIAGNOSTIC(CompiledEffectArrayTooLarge, Error,
              "the compiled effect file is corrupt: an array of more than 2^20 elements at byte {0} of the "
              "content")
FX_DIAGNOSTIC(CompiledEffectContentLeftOver, Error,
              "the compiled effect file is corrupt: content left over at byte {0} of the content")
// Checks the runtime relies on (a reference pointing nowhere, a size out of range), one id per check.
FX_DIAGNOSTIC(CompiledEffectInitialValueCount, Error,
              "the compiled effect file is corrupt: initial values and parameters differ in number")
FX_DIAGNOSTIC(CompiledEffectStructOrder, Error,
              "the compiled effect file is corrupt: struct '{0}' holds a struct not listed before it")
FX_DIAGNOSTIC(CompiledEffectParameterTooLarge, Error,
              "the compiled effect file is corrupt: parameter '{0}' holds more than 2^24 numbers")
FX_DIAGNOSTIC(CompiledEffectTextureWithoutParameter, Error,
              "the compiled effect file is corrupt: a texture names no parameter")
FX_DIAGNOSTIC(CompiledEffectSamplerWithoutParameter, Error,
              "the compiled effect file is corrupt: a sampler names no parameter")
FX_DIAGNOSTIC(CompiledEffectScriptPassOutOfRange, Error,
              "the compiled effect file is corrupt: a script names a pass out of range")
FX_DIAGNOSTIC(CompiledEffectFillArgumentMissing, Error,
              "the compiled effect file is corrupt: a texture function's fill pass: no fill argument")
FX_DIAGNOSTIC(CompiledEffectFillSizeOutOfRange, Error,
              "the compiled effect file is corrupt: a texture function's texture size out of range")
// {0}: the pass ("fill F" for the pass that fills a texture with function F).
FX_DIAGNOSTIC(CompiledEffectPreshaderConstantOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (a constant "
              "out of range)")
FX_DIAGNOSTIC(CompiledEffectPreshaderErrorOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (an error "
              "out of range)")
FX_DIAGNOSTIC(CompiledEffectPreshaderStackUnderflow, Error,
              "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (an "
              "instruction takes more operands than the stack holds)")
FX_DIAGNOSTIC(
    CompiledEffectPreshaderResultCount, Error,
    "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (the program "
    "leaves other than one value)")
FX_DIAGNOSTIC(CompiledEffectPreshaderInputOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (an input "
              "slot out of range)")
FX_DIAGNOSTIC(CompiledEffectUniformWithoutSource, Error,
              "the compiled effect file is corrupt: pass '{0}': a uniform block member names no parameter or "
              "argument")
FX_DIAGNOSTIC(CompiledEffectSamplerBindingWithoutParameter, Error,
              "the compiled effect file is corrupt: pass '{0}': a sampler binding names no parameter")
FX_DIAGNOSTIC(CompiledEffectSamplerBindingWithoutTexture, Error,
              "the compiled effect file is corrupt: pass '{0}': a sampler binding names no texture parameter")
FX_DIAGNOSTIC(CompiledEffectSamplerBindingWithoutPassSampler, Error,
              "the compiled effect file is corrupt: pass '{0}': a sampler binding names no pass sampler "
              "state")
FX_DIAGNOSTIC(CompiledEffectStorageBufferWithoutParameter, Error,
              "the compiled effect file is corrupt: pass '{0}': a storage buffer names no parameter")
FX_DIAGNOSTIC(CompiledEffectStreamOutSlotInvalid, Error,
              "the compiled effect file is corrupt: pass '{0}': a stream-output element names no slot")
FX_DIAGNOSTIC(CompiledEffectStreamOutStrideOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': a stream-output stride out of range")
FX_DIAGNOSTIC(CompiledEffectStreamOutCapacityOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': a stream-output capacity out of range")
FX_DIAGNOSTIC(CompiledEffectDrawAutoOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': DrawAuto names a pass out of range")
FX_DIAGNOSTIC(CompiledEffectScriptParameterOutOfRange, Error,
              "the compiled effect file is corrupt: a script names a parameter out of range")
FX_DIAGNOSTIC(CompiledEffectScriptLightOutOfRange, Error,
              "the compiled effect file is corrupt: a script names a light out of range")
FX_DIAGNOSTIC(CompiledEffectScriptTechniqueOutOfRange, Error,
              "the compiled effect file is corrupt: a script names a technique out of range")
FX_DIAGNOSTIC(
    CompiledEffectPreshaderMemberTooWide, Error,
    "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (a member of "
    "more than 4 components)")
FX_DIAGNOSTIC(CompiledEffectParameterLightOutOfRange, Error,
              "the compiled effect file is corrupt: parameter '{0}' is bound to a light out of range")
FX_DIAGNOSTIC(CompiledEffectClipDistancesOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': a stage writes clip distances out of range")
FX_DIAGNOSTIC(CompiledEffectParameterViewOutOfRange, Error,
              "the compiled effect file is corrupt: parameter '{0}' is a view of no buffer or read-write "
              "texture")
FX_DIAGNOSTIC(CompiledEffectParameterStorageSizeOutOfRange, Error,
              "the compiled effect file is corrupt: parameter '{0}': an element count or image size out of "
              "range")
FX_DIAGNOSTIC(CompiledEffectParameterImageFormatInvalid, Error,
              "the compiled effect file is corrupt: parameter '{0}' has an image format it cannot have")

// [SECTION] Effect pools (runtime/EffectPool.h, docs/api.md)
FX_DIAGNOSTIC(PoolSharedTypeMismatch, Error,
              "shared parameter '{0}' is a {1} here but a {2} in the effects already in its pool")

#undef FX_DIAGNOSTIC
