// Diagnostics: Resources and execution. One section of the table that fx/DiagnosticDefs.h includes, in its
// order; FX_DIAGNOSTIC(Id, Severity, "template"). Include DiagnosticDefs.h, never this file alone.
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
FX_DIAGNOSTIC(EmptyTechniqueSkipped, Note,
              "technique '{0}' has no passes and no script; the first technique that draws, '{1}', runs")
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
FX_DIAGNOSTIC(ParameterBoundBySpelling, Note,
              "parameter '{0}' has semantic '{1}', which is no standard semantic; bound as '{2}' by what it "
              "spells, as its application would set it")
FX_DIAGNOSTIC(MemberBoundByName, Note,
              "member '{0}' of struct parameter '{1}' has no semantic; bound as '{2}' by its name in a {3} "
              "struct, as an application setting it would")
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
FX_DIAGNOSTIC(
    ResourceRenamedInGlsl, Error,
    "'{0}' is a name GLSL reserves or changes (a keyword such as 'output', or '__' in it), so its unit "
    "cannot be declared in the generated GLSL: rename the resource")
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
