// The malformed-input corpus: every tests/data/malformed/*.fx (and a few inputs generated here because
// they are too large to check in) is parsed and compiled through fx::parseEffectSource + fx::compileEffect.
// Each must report at least one error, must not crash, and its diagnostics (as fx::DiagnosticList::str()
// prints them, paths relative to the repository root, each followed by its stable id in brackets) must
// equal the golden file beside it (NAME.out): a message moved to another id fails as a changed text does.
//
// A missing golden fails. To regenerate the goldens after a deliberate change of messages, run
//     SHADOWFX_UPDATE_GOLDEN=1 build/tests/fx_tests --gtest_filter='*MalformedCorpus*'
//     (or: build/tests/fx_tests --gtest_filter='*MalformedCorpus*' --update)
// from anywhere, then read every changed .out before committing. CI never runs the update mode.
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace test_malformed_corpus {

namespace {

namespace fs = std::filesystem;

const std::string kSourceDir = SHADOWFX_SOURCE_DIR;
const std::string kCorpus =
    "tests/data/malformed";  // relative to the repository root, as diagnostics show it

// "file:line:column: severity: message [Id]", one diagnostic a line, each followed by its notes.
std::string withIds(const fx::DiagnosticList& diagnostics) {
    std::string out;
    const auto line = [](const fx::Diagnostic& d) {
        fx::Diagnostic alone = d;
        alone.notes.clear();
        return fx::renderDiagnostic(alone, false) + " [" + std::string(fx::diagnosticName(d.id)) + "]\n";
    };
    for (const fx::Diagnostic& d : diagnostics.items()) {
        out += line(d);
        for (const fx::Diagnostic& note : d.notes) out += line(note);
    }
    return out;
}

std::optional<std::string> readFile(const std::string& path) {
    std::error_code error;
    if (fs::is_directory(path, error)) return std::nullopt;  // as fx's own reader
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Repository-relative paths read from the source tree, whatever the working directory.
std::optional<std::string> readFromSource(const std::string& path) {
    if (!path.empty() && path[0] == '/') return readFile(path);
    return readFile(kSourceDir + "/" + path);
}

bool updateMode() {
    if (const char* env = std::getenv("SHADOWFX_UPDATE_GOLDEN"); env && std::string(env) == "1") return true;
    for (const std::string& argument : ::testing::internal::GetArgvs())
        if (argument == "--update") return true;
    return false;
}

// One corpus entry: a checked-in file (source empty, read from `path`) or an input generated here.
struct Case {
    std::string name;                                  // test name
    std::string path;                                  // repository-relative .fx path the diagnostics name
    std::function<std::string()> generate;             // null for checked-in files
    std::function<void(fx::ParseOptions&)> configure;  // optional: limits under test
};

// Failures name the file rather than dumping the struct's bytes.
void PrintTo(const Case& c, std::ostream* out) {
    *out << c.path;
}

std::string testName(const std::string& stem) {
    std::string name;
    for (char c : stem) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return name;
}

// Wraps `body` in a technique that compiles, so that only `body` is wrong.
const char* kShaders =
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS() : COLOR { return 1; }\n";

std::vector<Case> generatedCases() {
    std::vector<Case> cases;
    auto add = [&](const std::string& name, std::function<std::string()> generate,
                   std::function<void(fx::ParseOptions&)> configure = nullptr) {
        cases.push_back(Case{"generated_" + name, kCorpus + "/generated/" + name + ".fx", std::move(generate),
                             std::move(configure)});
    };
    // A 10 MB line: an initializer of five million additions, then a missing ';'.
    add("line_10mb", [] {
        std::string text = "// One line of 10 MB.\nfloat Values[4] = {1";
        text.reserve(10u << 20);
        while (text.size() < (10u << 20)) text += ", 1.000000000000000000000000000000000000000000000";
        return text + "\nfloat Next = 2;\n";
    });
    // More tokens than the lexer accepts (2 MB of `+1`); the same text in 10 MB took 2.6 GB before.
    add("too_many_tokens", [] {
        std::string text = "float Sum = 1";
        while (text.size() < (2u << 20) + 100) text += "+1";
        return text + ";\n";
    });
    // A 10 MB comment line followed by an error: the lexer must not go quadratic on it.
    add("comment_line_10mb", [] { return "// " + std::string(10u << 20, 'x') + "\nfloat Bias = ;\n"; });
    // 100,000 '(' in a parameter initializer.
    add("parentheses_100k", [] { return "float Deep = " + std::string(100000, '(') + "1;\n"; });
    // 100,000 '{' in a braced initializer.
    add("braces_100k_initializer", [] { return "float Deep = " + std::string(100000, '{') + "1;\n"; });
    // 100,000 '{' in a function body: glslang's recursive HLSL parser must not see them.
    add("braces_100k_function",
        [] { return std::string(kShaders) + "float4 Deep() : COLOR " + std::string(100000, '{') + "\n"; });
    // 100,000 nested blocks in a pass.
    add("braces_100k_pass", [] { return "technique t { pass p " + std::string(100000, '{') + "\n"; });
    // 100,000 '<' in an annotation.
    add("angles_100k_annotation", [] { return "float Bias " + std::string(100000, '<') + "\n"; });
    // Unary minus 100,000 times.
    add("unary_100k", [] { return "float Deep = " + std::string(100000, '-') + "1;\n"; });
    // A source larger than ParseOptions::maxSourceBytes (lowered to 1 MB here).
    add(
        "source_too_large", [] { return "// 2 MB of comment.\n//" + std::string(2u << 20, 'x') + "\n"; },
        [](fx::ParseOptions& options) { options.maxSourceBytes = 1u << 20; });
    // Includes that add up to more than maxSourceBytes: 1 MB limit, four 400 kB includes.
    add(
        "includes_too_large",
        [] {
            return "// Four includes of 400 kB each.\n#include \"include/big.fxh\"\n#include "
                   "\"include/big.fxh\"\n"
                   "#include \"include/big.fxh\"\n#include \"include/big.fxh\"\n";
        },
        [](fx::ParseOptions& options) {
            options.maxSourceBytes = 1u << 20;
            options.readFile = [](const std::string& path) -> std::optional<std::string> {
                if (path.find("include/big.fxh") != std::string::npos)
                    return "//" + std::string(400u << 10, 'x') + "\n";
                return readFromSource(path);
            };
        });
    // An include chain deeper than ParseOptions::maxIncludeDepth (lowered to 4), each file distinct.
    add(
        "include_depth",
        [] {
            return "// Includes level1.fxh, which includes level2.fxh, ...\n#include "
                   "\"include/level1.fxh\"\n";
        },
        [](fx::ParseOptions& options) {
            options.maxIncludeDepth = 4;
            options.readFile = [](const std::string& path) -> std::optional<std::string> {
                const std::string prefix = kCorpus + "/generated/include/level";
                if (path.rfind(prefix, 0) == 0) {
                    int level = std::atoi(path.c_str() + prefix.size());
                    return "#include \"level" + std::to_string(level + 1) + ".fxh\"\n";
                }
                return readFromSource(path);
            };
        });
    return cases;
}

std::vector<Case> allCases() {
    std::vector<Case> cases;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kSourceDir + "/" + kCorpus))
        if (entry.is_regular_file() && entry.path().extension() == ".fx") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files)
        cases.push_back(
            Case{testName(file.stem().string()), kCorpus + "/" + file.filename().string(), nullptr, nullptr});
    for (Case& c : generatedCases()) cases.push_back(std::move(c));
    return cases;
}

class MalformedCorpus : public ::testing::TestWithParam<Case> {};

TEST_P(MalformedCorpus, ReportsTheGoldenDiagnostics) {
    const Case& c = GetParam();
    std::string source;
    if (c.generate) {
        source = c.generate();
    } else {
        std::optional<std::string> text = readFromSource(c.path);
        ASSERT_TRUE(text) << "cannot read " << c.path;
        source = std::move(*text);
    }

    fx::ParseOptions options;
    options.readFile = readFromSource;  // includes resolve in the source tree only
    if (c.configure) c.configure(options);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectSource(source, c.path, options, diagnostics);
    if (effect) {
        fx::CompileOptions compileOptions;
        std::unique_ptr<fx::CompiledEffect> compiled = fx::compileEffect(effect, compileOptions, diagnostics);
        EXPECT_EQ(compiled == nullptr, diagnostics.hasErrors())
            << "compileEffect's result disagrees with its diagnostics";
    }
    const std::string actual = withIds(diagnostics);
    EXPECT_TRUE(diagnostics.hasErrors())
        << c.path << " is accepted, but the corpus is for inputs that must fail:\n"
        << actual;

    const std::string golden = c.path.substr(0, c.path.size() - 3) + ".out";
    const std::string goldenFile = kSourceDir + "/" + golden;
    if (updateMode()) {
        fs::create_directories(fs::path(goldenFile).parent_path());
        std::ofstream(goldenFile, std::ios::binary) << actual;
        return;
    }
    std::optional<std::string> expected = readFile(goldenFile);
    ASSERT_TRUE(expected) << "missing golden " << golden
                          << " (run with SHADOWFX_UPDATE_GOLDEN=1 to create it); "
                          << "the diagnostics were:\n"
                          << actual;
    EXPECT_EQ(actual, *expected) << "diagnostics of " << c.path << " differ from " << golden;
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedCorpus, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// Every golden has its input: a stale .out (its .fx renamed or deleted) would otherwise linger unnoticed.
TEST(MalformedCorpusFiles, EveryGoldenHasAnInput) {
    std::vector<std::string> expected;
    for (const Case& c : allCases())
        expected.push_back(kSourceDir + "/" + c.path.substr(0, c.path.size() - 3) + ".out");
    for (const auto& entry : fs::recursive_directory_iterator(kSourceDir + "/" + kCorpus)) {
        if (entry.path().extension() != ".out") continue;
        EXPECT_NE(std::find(expected.begin(), expected.end(), entry.path().string()), expected.end())
            << entry.path() << " has no input";
    }
    EXPECT_GE(expected.size(), 60u);
}

}  // namespace
}  // namespace test_malformed_corpus
