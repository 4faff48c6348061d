// Diagnostics: Compiling passes. One section of the table that fx/DiagnosticDefs.h includes, in its order;
// FX_DIAGNOSTIC(Id, Severity, "template"). Include DiagnosticDefs.h, never this file alone.
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
FX_DIAGNOSTIC(VertexInputMatrixIdentity, Note,
              "vertex input '{0}' is a matrix, which no mesh stream holds (a per-instance transform, which "
              "each object's World carries here); it reads the identity matrix")
FX_DIAGNOSTIC(
    VertexInputInstanceRow, Note,
    "vertex input '{0}' is row {1} of a per-instance transform the vertex shader assembles, which no "
    "mesh stream holds (each object's World carries it here); it reads the identity's row {2}")
FX_DIAGNOSTIC(PositionBesideSvPosition, Note,
              "'{0}' is read as user data between the stages, as under D3D10: its struct's SV_Position "
              "member '{1}' is the position")
FX_DIAGNOSTIC(SamplerReadsHostPicture, Note,
              "sampler '{0}' of the full-screen pass '{1}' has no texture in the effect (its application "
              "bound one); drawn by a host, it reads the host's picture of the scene")
FX_DIAGNOSTIC(TextureReadsHostPicture, Note,
              "texture '{0}', sampled through '{1}' in the full-screen pass '{2}', has no contents in the "
              "effect (its application bound them); drawn by a host, it reads the host's picture of the "
              "scene")
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
              "patches, which 'InputPatch<T, 3>' takes, or 'InputPatch<T, 4>' as quads with the third corner "
              "twice")
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
FX_DIAGNOSTIC(CompileNoOverloadFits, Error,
              "invalid compile expression: no overload of '{0}' takes {1} uniform argument(s) (its overloads "
              "have {2} uniform parameter(s))")
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
