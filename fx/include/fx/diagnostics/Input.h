// Diagnostics: Input and preprocessing. One section of the table that fx/DiagnosticDefs.h includes, in its
// order; FX_DIAGNOSTIC(Id, Severity, "template"). Include DiagnosticDefs.h, never this file alone.
FX_DIAGNOSTIC(FileNotFound, Error, "cannot open file '{0}'")
FX_DIAGNOSTIC(IncludeNotFound, Error, "cannot open include file '{0}'")
FX_DIAGNOSTIC(IncludeCaseMismatch, Warning,
              "include file '{0}' found as '{1}', which differs in case (names are case-blind on Windows)")
// glslang's preprocessor message, as it words it (#error text, macro errors).
FX_DIAGNOSTIC(PreprocessorError, Error, "{0}")
FX_DIAGNOSTIC(IncludeTrailingText, Warning, "text after the include file name is ignored: '{0}'")
FX_DIAGNOSTIC(UndefinedConditionCall, Warning,
              "'{0}' is not a function-like macro here: its call in this condition reads as 0")
FX_DIAGNOSTIC(MacroRedefined, Warning,
              "macro '{0}' redefined with a different body: the new definition is used")
FX_DIAGNOSTIC(SourceTooLarge, Error, "source exceeds {0} bytes")
FX_DIAGNOSTIC(PreprocessingFailed, Error, "preprocessing failed")
FX_DIAGNOSTIC(InvalidCharacter, Error, "invalid character '{0}'")
FX_DIAGNOSTIC(UnterminatedString, Error, "unterminated string literal")
FX_DIAGNOSTIC(UnknownEscapeSequence, Warning,
              "unknown escape sequence '\\{0}' in a string: the backslash is kept, as fxc kept it")
// Attached to a diagnostic at a macro's use (Diagnostic::notes), at the macro's #define.
FX_DIAGNOSTIC(InMacroExpansion, Note, "in expansion of macro '{0}' defined here")
FX_DIAGNOSTIC(TooManyTokens, Error, "effect too large: more than {0} tokens after preprocessing")
// An include the include handler refused, one id per reason ({0}: the name as written).
FX_DIAGNOSTIC(IncludeFileNameEmpty, Error, "cannot include '{0}': empty file name")
FX_DIAGNOSTIC(IncludeDepthExceeded, Error, "cannot include '{0}': include depth exceeds {1}")
FX_DIAGNOSTIC(IncludeRecursive, Error,
              "cannot include '{0}': include depth exceeds {1} (recursive include of '{2}')")
FX_DIAGNOSTIC(IncludeSourcesTooLarge, Error, "cannot include '{0}': sources exceed {1} bytes in total")
