// Diagnostics: Compiled effect files (fx/CompiledEffectFile.h, docs/compiled-effect.md). One section of the
// table that fx/DiagnosticDefs.h includes, in its order; FX_DIAGNOSTIC(Id, Severity, "template"). Include
// DiagnosticDefs.h, never this file alone.
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
FX_DIAGNOSTIC(CompiledEffectScriptClearTargetOutOfRange, Error,
              "the compiled effect file is corrupt: a script clears a colour target out of range")
FX_DIAGNOSTIC(CompiledEffectScriptTechniqueOutOfRange, Error,
              "the compiled effect file is corrupt: a script names a technique out of range")
FX_DIAGNOSTIC(
    CompiledEffectPreshaderMemberTooWide, Error,
    "the compiled effect file is corrupt: pass '{0}': a preshader program is malformed (a member of "
    "more than 4 components)")
FX_DIAGNOSTIC(CompiledEffectParameterLightOutOfRange, Error,
              "the compiled effect file is corrupt: parameter '{0}' is bound to a light out of range")
FX_DIAGNOSTIC(CompiledEffectMemberBindingOutOfRange, Error,
              "the compiled effect file is corrupt: parameter '{0}' binds a member outside its value or to "
              "a light out of range")
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
FX_DIAGNOSTIC(CompiledEffectParameterBufferTexelInvalid, Error,
              "the compiled effect file is corrupt: parameter '{0}' has buffer texels it cannot have")
FX_DIAGNOSTIC(CompiledEffectPassReadsOutOfRange, Error,
              "the compiled effect file is corrupt: pass '{0}': its list of the parameters it reads is "
              "out of order or names no parameter")
FX_DIAGNOSTIC(CompiledEffectImageWithoutParameter, Error,
              "the compiled effect file is corrupt: pass '{0}': an image binding names no parameter")
FX_DIAGNOSTIC(CompiledEffectImageUnitInvalid, Error,
              "the compiled effect file is corrupt: pass '{0}': an image unit out of range or shared by two "
              "parameters")
