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
FX_DIAGNOSTIC(IncludeFailed, Error, "cannot include '{0}': {1}")
FX_DIAGNOSTIC(PreprocessingFailed, Error, "preprocessing failed")
FX_DIAGNOSTIC(InvalidCharacter, Error, "invalid character '{0}'")
FX_DIAGNOSTIC(UnterminatedString, Error, "unterminated string literal")
// Attached to a diagnostic at a macro's use (Diagnostic::notes), at the macro's #define.
FX_DIAGNOSTIC(InMacroExpansion, Note, "in expansion of macro '{0}' defined here")

// [SECTION] Effect syntax
FX_DIAGNOSTIC(UnexpectedToken, Error, "expected {0}, found '{1}'")
// At the end of the line whose statement lacks its ';' (the parser goes on as if it were there).
FX_DIAGNOSTIC(MissingSemicolon, Error, "expected ';' after '{0}'")
FX_DIAGNOSTIC(UnclosedBlock, Error, "'{0}' expected (to close '{1}' at line {2})")
FX_DIAGNOSTIC(UnexpectedEndOfFile, Error, "unexpected end of file, expected {0}")
FX_DIAGNOSTIC(UnknownType, Error, "unknown type '{0}'")
FX_DIAGNOSTIC(Redefinition, Error, "redefinition of '{0}'")
FX_DIAGNOSTIC(UnknownState, Error, "unknown state '{0}'")
FX_DIAGNOSTIC(UnknownStateValue, Error, "'{0}' is not a value of state '{1}' (expected one of: {2})")
FX_DIAGNOSTIC(InvalidStateValue, Error, "invalid value for state '{0}': {1}")
FX_DIAGNOSTIC(InvalidAnnotation, Error, "invalid annotation '{0}': {1}")
FX_DIAGNOSTIC(InvalidInitializer, Error, "invalid initializer for '{0}': {1}")
FX_DIAGNOSTIC(TechniqueRefused, Warning, "technique '{0}' is left out: {1}")
FX_DIAGNOSTIC(AllTechniquesRefused, Error,
              "every technique of the effect is left out (the first: '{0}', {1}); nothing can run")
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

// [SECTION] SAS scripts
FX_DIAGNOSTIC(UnknownScriptCommand, Error, "unknown script command '{0}'")
FX_DIAGNOSTIC(InvalidScriptCommand, Error, "invalid script command '{0}': {1}")
FX_DIAGNOSTIC(ScriptUnknownPass, Error, "script names pass '{0}', which technique '{1}' does not have")
FX_DIAGNOSTIC(ScriptUnknownTarget, Error,
              "script names render target '{0}', which is not a render-target texture")
FX_DIAGNOSTIC(ScriptCommandIgnored, Warning, "script command '{0}' is ignored: {1}")
FX_DIAGNOSTIC(ScriptUnknownTechnique, Warning,
              "script names technique '{0}', which the effect does not have; skipped")
FX_DIAGNOSTIC(ScriptTechniqueFallback, Warning,
              "script names no technique the effect has; running its first technique, '{0}'")
FX_DIAGNOSTIC(ScriptUnbalancedLoop, Error, "LoopByCount without LoopEnd")
FX_DIAGNOSTIC(ScriptLoopEndWithoutLoop, Error, "LoopEnd without LoopByCount")
FX_DIAGNOSTIC(ScriptLoopIndexOutsideLoop, Error, "LoopGetIndex outside a loop")
FX_DIAGNOSTIC(ScriptUnknownRenderPort, Error, "RenderPort names {0}")

// [SECTION] Compiling passes
FX_DIAGNOSTIC(MissingEntryPoint, Error, "entry point '{0}' not found")
FX_DIAGNOSTIC(InvalidCompileExpression, Error, "invalid compile expression: {0}")
FX_DIAGNOSTIC(InvalidStreamOutDeclaration, Error, "invalid stream-output declaration entry '{0}': {1}")
FX_DIAGNOSTIC(UnsupportedProfile, Error, "unsupported shader profile '{0}'")
// glslang's own HLSL error and warning text.
FX_DIAGNOSTIC(HlslError, Error, "{0}")
FX_DIAGNOSTIC(HlslWarning, Warning, "{0}")
FX_DIAGNOSTIC(CrossCompileError, Error, "SPIR-V to GLSL: {0}")
FX_DIAGNOSTIC(HlslCompilerCrashed, Error, "the HLSL compiler crashed on this shader ({0})")
FX_DIAGNOSTIC(HlslCompilerTimedOut, Error,
              "the HLSL compiler did not finish this shader within {0} ms and was stopped")
FX_DIAGNOSTIC(CompileWorkerFailed, Error, "the HLSL compiler's worker process failed: {0}")
FX_DIAGNOSTIC(CompileWorkerSanitizerReport, Error,
              "the HLSL compiler's worker process stopped on a sanitizer report ({0}); the report is on "
              "standard error")
FX_DIAGNOSTIC(CompileWorkerNotFound, Warning,
              "no shadowfx-compile-worker found (set SHADOWFX_COMPILE_WORKER); compiling in this process, "
              "where a crash of the HLSL compiler ends the program")
FX_DIAGNOSTIC(UnknownIdentifier, Error, "unknown identifier '{0}'")
FX_DIAGNOSTIC(TypeMismatch, Error, "{0}")
FX_DIAGNOSTIC(UnsupportedFeature, Error, "{0}")
FX_DIAGNOSTIC(VertexInputConstant, Note,
              "vertex input '{0}' matches no mesh stream by its name; it reads the constant {1}")
// glslang's "mul() matrix size mismatch" said as fxc said it: both truncate the larger operand.
FX_DIAGNOSTIC(ImplicitTruncation, Warning,
              "implicit truncation of vector type (fxc's X3206): mul() of a vector and a matrix that differ "
              "in size reads only the rows or columns both have")

// [SECTION] Resources and execution
FX_DIAGNOSTIC(TextureFileNotFound, Warning, "cannot load texture '{0}'; using a neutral texture")
FX_DIAGNOSTIC(TextureCaseMismatch, Warning,
              "texture file '{0}' found as '{1}', which differs in case (names are case-blind on Windows)")
FX_DIAGNOSTIC(TextureFileUnreadable, Error, "cannot read texture file '{0}': {1}")
FX_DIAGNOSTIC(InvalidTextureFormat, Error, "unknown texture format '{0}'")
FX_DIAGNOSTIC(InvalidDimensions, Error, "invalid render-target size: {0}")
FX_DIAGNOSTIC(SampleCountReduced, Warning,
              "'{0}' has {1} samples per texel; this OpenGL holds at most {2}, which it gets instead")
FX_DIAGNOSTIC(UnknownTechnique, Error, "effect has no technique named '{0}'")
FX_DIAGNOSTIC(NoTechniques, Error, "the file has no techniques")
FX_DIAGNOSTIC(UnknownParameter, Error, "effect has no parameter named '{0}'")
FX_DIAGNOSTIC(LinkError, Error, "GL program link failed: {0}")
FX_DIAGNOSTIC(GlError, Error, "OpenGL: {0}")
FX_DIAGNOSTIC(GlDebugMessage, Note, "OpenGL: {0}")
// What the GL driver said, compiling or linking a program that worked, about the GLSL shadowfx generated:
// its line numbers are the generated GLSL's (`shadowfx compile` prints it), not the effect's.
FX_DIAGNOSTIC(DriverShaderLog, Note, "the GL driver on the generated GLSL of {0}: {1}")
FX_DIAGNOSTIC(UnboundSemantic, Warning,
              "parameter '{0}' has semantic '{1}', which shadowfx does not bind: it keeps its default value "
              "(shadowfx info lists the semantics shadowfx binds)")
FX_DIAGNOSTIC(ParameterBoundByName, Note,
              "parameter '{0}' has no semantic; bound as '{1}' by its name, as an application setting it by "
              "name would")
FX_DIAGNOSTIC(ParameterNamesMissingLight, Note,
              "parameter '{0}' names light '{1}', which the scene does not have; it keeps its value")

// [SECTION] Scenes (runtime/assets/src/SceneFile.cpp, MeshImporter.cpp)
FX_DIAGNOSTIC(SceneSyntaxError, Error, "invalid JSON: {0}")
FX_DIAGNOSTIC(SceneInvalidValue, Error, "{0}: {1}")
FX_DIAGNOSTIC(SceneUnknownKey, Warning, "{0}: unknown key '{1}' (ignored)")
FX_DIAGNOSTIC(MeshFileNotFound, Error, "cannot open mesh file '{0}'{1}")
FX_DIAGNOSTIC(MeshImportError, Error, "cannot import mesh '{0}': {1}")
FX_DIAGNOSTIC(UnknownScene, Error, "no built-in scene named '{0}' (known: {1})")

// [SECTION] Compiled effect files (fx/CompiledEffectFile.h, docs/compiled-effect.md)
FX_DIAGNOSTIC(CompiledEffectTruncated, Error, "the compiled effect file is truncated: {0}")
FX_DIAGNOSTIC(CompiledEffectCorrupt, Error, "the compiled effect file is corrupt: {0}")
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

#undef FX_DIAGNOSTIC
