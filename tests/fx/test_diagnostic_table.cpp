// The diagnostic table's rules (docs/diagnostics.md): one id per message, whose arguments are names, values
// or a quoted third-party message, never shadowfx's own sentence; every id documented with its message. What
// of that a machine can check is checked here.
#include <fx/Diagnostics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fx::test_diagnostic_table {
namespace {

constexpr DiagId kAllIds[] = {
#define FX_DIAGNOSTIC(id, severity, text) DiagId::id,
#include <fx/DiagnosticDefs.h>
};

// The ids whose whole message is another tool's: glslang's preprocessor and HLSL front end, whose words
// stand at the user's line as a compiler's do.
const std::set<DiagId> kWholeMessageQuoted = {DiagId::PreprocessorError, DiagId::HlslError,
                                              DiagId::HlslWarning};

// The ids whose last argument quotes a library, the GL driver or the system; their template says first what
// failed.
const std::set<DiagId> kMessageQuotedAfterStage = {
    DiagId::CrossCompileError,   DiagId::CrossCompileCombinedSampler,
    DiagId::LinkError,           DiagId::GlDebugMessage,
    DiagId::DriverShaderLog,     DiagId::DriverFixedFunctionLog,
    DiagId::DriverLinkLog,       DiagId::ImplicitVectorTruncation,
    DiagId::SceneSyntaxError,    DiagId::SceneReadFailed,
    DiagId::HostValueUnreadable, DiagId::TextureFileUnreadable,
    DiagId::MeshImportError,     DiagId::MeshModuleUnloadable,
    DiagId::CompileWorkerFailed};

// The numbers of the placeholders ({0}, {1}, ...) of a template, in order of appearance.
std::vector<int> placeholders(std::string_view text) {
    std::vector<int> numbers;
    for (size_t i = 0; i + 2 < text.size(); ++i)
        if (text[i] == '{' && text[i + 2] == '}' && text[i + 1] >= '0' && text[i + 1] <= '9')
            numbers.push_back(text[i + 1] - '0');
    return numbers;
}

TEST(DiagnosticTable, OnlyAnotherToolsMessageIsABareArgument) {
    for (DiagId id : kAllIds) {
        const std::string_view text = diagnosticTemplate(id);
        EXPECT_EQ(text == "{0}", kWholeMessageQuoted.count(id) == 1)
            << diagnosticName(id) << ": \"" << text
            << "\": a message of shadowfx's own is the template's text, not an argument";
    }
}

TEST(DiagnosticTable, AQuotedMessageFollowsWhatFailed) {
    for (DiagId id : kMessageQuotedAfterStage) {
        const std::string_view text = diagnosticTemplate(id);
        const std::vector<int> numbers = placeholders(text);
        ASSERT_FALSE(numbers.empty()) << diagnosticName(id);
        const std::string last =
            "{" + std::to_string(*std::max_element(numbers.begin(), numbers.end())) + "}";
        const size_t at = text.rfind(last);
        EXPECT_GE(at, 8u) << diagnosticName(id) << ": \"" << text << "\" names no stage before the quote";
        EXPECT_TRUE(text.substr(at - 2, 2) == ": " || text[at - 1] == ' ' || text[at - 1] == '(')
            << diagnosticName(id) << ": \"" << text << "\"";
    }
}

TEST(DiagnosticTable, PlaceholdersAreNumberedFromZeroWithoutGaps) {
    for (DiagId id : kAllIds) {
        std::vector<int> numbers = placeholders(diagnosticTemplate(id));
        std::sort(numbers.begin(), numbers.end());
        numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
        for (size_t i = 0; i < numbers.size(); ++i)
            EXPECT_EQ(numbers[i], static_cast<int>(i))
                << diagnosticName(id) << ": " << diagnosticTemplate(id);
    }
}

TEST(DiagnosticTable, NamesAreFoundAgain) {
    for (DiagId id : kAllIds) EXPECT_EQ(findDiagnostic(diagnosticName(id)), id) << diagnosticName(id);
}

// docs/diagnostics.md lists every id as a table row "| `Id` | severity | `template` |", and no other.
TEST(DiagnosticTable, EveryIdIsDocumentedWithItsMessage) {
    std::ifstream in(std::string(SHADOWFX_SOURCE_DIR) + "/docs/diagnostics.md");
    ASSERT_TRUE(in) << "docs/diagnostics.md";
    std::set<std::string> rows;
    std::set<std::string> documented;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("| `", 0) != 0) continue;
        rows.insert(line);
        const size_t end = line.find('`', 3);
        if (end != std::string::npos) documented.insert(line.substr(3, end - 3));
    }
    std::set<std::string> names;
    for (DiagId id : kAllIds) {
        const std::string name(diagnosticName(id));
        names.insert(name);
        const std::string row = "| `" + name + "` | " + std::string(severityName(defaultSeverity(id))) +
                                " | `" + std::string(diagnosticTemplate(id)) + "` |";
        EXPECT_EQ(rows.count(row), 1u) << "docs/diagnostics.md lacks the row\n" << row;
    }
    for (const std::string& name : documented)
        EXPECT_EQ(names.count(name), 1u) << "docs/diagnostics.md documents '" << name << "', which is no id";
}

}  // namespace
}  // namespace fx::test_diagnostic_table
