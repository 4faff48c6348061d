// Diagnostics: Effect pools (runtime/EffectPool.h, docs/api.md). One section of the table that
// fx/DiagnosticDefs.h includes, in its order; FX_DIAGNOSTIC(Id, Severity, "template"). Include
// DiagnosticDefs.h, never this file alone.
FX_DIAGNOSTIC(PoolSharedTypeMismatch, Error,
              "shared parameter '{0}' is a {1} here but a {2} in the effects already in its pool")
