// Every diagnostic the fx library and the runtime can report, with a stable id, a severity and a
// message template ({0}, {1}, ... are filled by Diagnostic::format). Kept in one table, in the manner of
// Slang's *-diagnostic-defs.h, so that tests can name ids and the ids never silently change meaning.
//
// FX_DIAGNOSTIC(Id, Severity, "template")
// Include this file with FX_DIAGNOSTIC defined; it undefines it at the end. The table is kept in sections,
// one file each in fx/diagnostics/, in the order below (the order of DiagId).

#include <fx/diagnostics/Input.h>
#include <fx/diagnostics/Syntax.h>
#include <fx/diagnostics/Scripts.h>
#include <fx/diagnostics/Passes.h>
#include <fx/diagnostics/Execution.h>
#include <fx/diagnostics/Scenes.h>
#include <fx/diagnostics/CompiledFiles.h>
#include <fx/diagnostics/Pools.h>

#undef FX_DIAGNOSTIC
