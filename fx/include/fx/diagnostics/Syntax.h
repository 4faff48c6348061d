// Diagnostics: Effect syntax. One section of the table that fx/DiagnosticDefs.h includes, in its order;
// FX_DIAGNOSTIC(Id, Severity, "template"). Include DiagnosticDefs.h, never this file alone.
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
