// Preprocessor tests: includes (both forms, relative paths, include dirs, missing, recursive), defines,
// #line-correct locations.
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <map>

namespace test_preprocessor {

using namespace fx;

namespace {

ParseOptions memoryOptions(const std::map<std::string, std::string>& files) {
    ParseOptions options;
    options.readFile = [files](const std::string& path) -> std::optional<std::string> {
        auto found = files.find(path);
        if (found == files.end()) return std::nullopt;
        return found->second;
    };
    return options;
}

}  // namespace

TEST(Preprocessor, QuotedAndAngleIncludesWithBackslashes) {
    std::map<std::string, std::string> files = {
        {"fx/lib/common.fxh", "float common1;\n"},
        {"fx/lib/more.fxh", "float more1;\n"},
    };
    DiagnosticList diags;
    auto effect = parseEffectSource("#include \"lib/common.fxh\"\n#include <lib\\more.fxh>\nfloat mine;\n",
                                    "fx/main.fx", memoryOptions(files), diags);
    ASSERT_TRUE(effect) << diags.str();
    ASSERT_TRUE(effect->findParameter("common1"));
    EXPECT_EQ(effect->findParameter("common1")->loc.file, "fx/lib/common.fxh");
    EXPECT_EQ(effect->findParameter("more1")->loc.file, "fx/lib/more.fxh");
    EXPECT_EQ(effect->findParameter("mine")->loc.file, "fx/main.fx");
    EXPECT_EQ(effect->findParameter("mine")->loc.line, 3);
    EXPECT_EQ(effect->includedFiles,
              (std::vector<std::string>{"fx/main.fx", "fx/lib/common.fxh", "fx/lib/more.fxh"}));
}

TEST(Preprocessor, NestedIncludeIsRelativeToIncludingFile) {
    std::map<std::string, std::string> files = {
        {"a/one.fxh", "#include \"../b/two.fxh\"\nfloat one;\n"},
        {"b/two.fxh", "\n\nfloat two;\n"},
    };
    DiagnosticList diags;
    auto effect =
        parseEffectSource("#include \"a/one.fxh\"\nfloat main1;\n", "main.fx", memoryOptions(files), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_EQ(effect->findParameter("two")->loc.file, "b/two.fxh");
    EXPECT_EQ(effect->findParameter("two")->loc.line, 3);
    EXPECT_EQ(effect->findParameter("one")->loc.file, "a/one.fxh");
    EXPECT_EQ(effect->findParameter("one")->loc.line, 2);
    EXPECT_EQ(effect->findParameter("main1")->loc.line, 2);
}

// fxc read a directive on a last line without its line end; glslang's preprocessor wanted the newline.
TEST(Preprocessor, IncludeOnTheLastLineWithoutALineEnd) {
    std::map<std::string, std::string> files = {{"fx/last.fxh", "float fromInclude;\n#define LAST 2"}};
    DiagnosticList diags;
    auto effect =
        parseEffectSource("float mine;\r\n#include <last.fxh>", "fx/main.fx", memoryOptions(files), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(effect->findParameter("fromInclude"));
    EXPECT_TRUE(effect->findParameter("mine"));
}

TEST(Preprocessor, IncludeDirectories) {
    std::map<std::string, std::string> files = {{"/sys/inc/shared.fxh", "float shared1;\n"}};
    ParseOptions options = memoryOptions(files);
    options.includeDirs = {"/nothing", "/sys/inc"};
    DiagnosticList diags;
    auto effect = parseEffectSource("#include <shared.fxh>\n", "dir/main.fx", options, diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_EQ(effect->findParameter("shared1")->loc.file, "/sys/inc/shared.fxh");
}

// A Windows path with a backslash left unescaped (`\D`), in a #define's string and in an annotation's: a
// warning at that backslash, which stays a character, and every other escape read once (`\\`, `\"`),
// as fxc read them. tests/data/fxcomposer/max_texture_paths.fx.
TEST(Preprocessor, UnknownEscapeInAStringKeepsItsBackslashWithAWarning) {
    DiagnosticList diags;
    const std::string path = std::string(SHADOWFX_SOURCE_DIR) + "/tests/data/fxcomposer/max_texture_paths.fx";
    auto effect = parseEffectFile(path, ParseOptions{}, diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    const Parameter* texture = effect->findParameter("BaseTexture");
    ASSERT_TRUE(texture && texture->annotation("ResourceName") && texture->annotation("Folder") &&
                texture->annotation("Quoted"));
    EXPECT_EQ(texture->annotation("ResourceName")->value.text, "C:\\Users\\max\\Desktop\\maps\\base.tga");
    EXPECT_EQ(texture->annotation("Folder")->value.text, "maps\\detail");
    EXPECT_EQ(texture->annotation("Quoted")->value.text, "a\"b\\c");
    // One warning per unknown escape, at its backslash: `\D` on line 3, `\d` on line 5.
    std::vector<std::pair<int, int>> places;
    for (const Diagnostic& d : diags.items()) {
        EXPECT_EQ(d.severity, Severity::Warning) << diags.str();
        if (d.id == DiagId::UnknownEscapeSequence) places.push_back({d.loc.line, d.loc.column});
    }
    EXPECT_EQ(places, (std::vector<std::pair<int, int>>{{3, 33}, {5, 76}})) << diags.str();
}

// A raw control byte 0x01 or 0x02 in a string (the bytes that stand for a backslash and a quote while
// glslang reads the text) is an invalid character at its place, not a backslash or a quote.
TEST(Preprocessor, ControlBytesInAStringAreInvalidCharacters) {
    DiagnosticList diags;
    parseEffectSource(std::string("string A = \"ab\x02"
                                  "cd\";\nstring B = \"x\x01"
                                  "ny\";\n"),
                      "bytes.fx", ParseOptions{}, diags);
    std::vector<std::pair<int, int>> places;
    for (const Diagnostic& d : diags.items())
        if (d.id == DiagId::InvalidCharacter) places.push_back({d.loc.line, d.loc.column});
    EXPECT_EQ(places, (std::vector<std::pair<int, int>>{{1, 15}, {2, 14}})) << diags.str();
    EXPECT_TRUE(diags.hasErrors());
}

TEST(Preprocessor, IncludesFromDisk) {
    ParseOptions options;
    DiagnosticList diags;
    std::string dir = std::string(SHADOWFX_SOURCE_DIR) + "/tests/data/parser/";
    auto effect = parseEffectSource("#include \"outer.fxh\"\n", dir + "main.fx", options, diags);
    ASSERT_TRUE(effect) << diags.str();
    ASSERT_TRUE(effect->findParameter("fromDisk"));
    EXPECT_EQ(effect->findParameter("fromDisk")->semantic, "DISK");
    EXPECT_EQ(effect->findParameter("innerValue")->loc.file, dir + "sub/inner.fxh");
    EXPECT_EQ(effect->includedFiles.size(), 3u);
}

TEST(Preprocessor, MissingInclude) {
    DiagnosticList diags;
    auto effect =
        parseEffectSource("float a;\n#include <missing.fxh>\n", "main.fx", memoryOptions({}), diags);
    EXPECT_FALSE(effect);
    ASSERT_EQ(diags.errorCount(), 1u) << diags.str();
    EXPECT_EQ(diags.items()[0].id, DiagId::IncludeNotFound);
    EXPECT_EQ(diags.items()[0].loc.str(), "main.fx:2:10");
}

TEST(Preprocessor, RecursiveIncludeIsAnError) {
    std::map<std::string, std::string> files = {{"self.fxh", "float s;\n#include \"self.fxh\"\n"}};
    DiagnosticList diags;
    auto effect = parseEffectSource("#include \"self.fxh\"\n", "main.fx", memoryOptions(files), diags);
    EXPECT_FALSE(effect);
    ASSERT_TRUE(diags.hasErrors());
    EXPECT_EQ(diags.items()[0].id, DiagId::IncludeRecursive);
    EXPECT_NE(diags.items()[0].message.find("recursive"), std::string::npos) << diags.str();
    EXPECT_EQ(diags.items()[0].loc.file, "self.fxh");
    EXPECT_EQ(diags.items()[0].loc.line, 2);
}

TEST(Preprocessor, TotalSizeLimit) {
    std::map<std::string, std::string> files = {{"big.fxh", std::string(2000, ' ') + "\nfloat big;\n"}};
    ParseOptions options = memoryOptions(files);
    options.maxSourceBytes = 1000;
    DiagnosticList diags;
    EXPECT_FALSE(parseEffectSource("#include \"big.fxh\"\n", "main.fx", options, diags));
    ASSERT_TRUE(diags.hasErrors());
    EXPECT_NE(diags.items()[0].message.find("1000 bytes"), std::string::npos) << diags.str();
}

TEST(Preprocessor, DefinesAndConditionals) {
    ParseOptions options = memoryOptions({});
    options.defines = {{"QUALITY", "2"}, {"USE_PCF", "1"}};
    DiagnosticList diags;
    auto effect = parseEffectSource(R"(#define SIZE 512
#if QUALITY > 1 && USE_PCF
float pcf = SIZE;
#else
float nopcf;
#endif
#ifdef UNDEFINED_THING
float never;
#endif
float after;
)",
                                    "main.fx", options, diags);
    ASSERT_TRUE(effect) << diags.str();
    ASSERT_TRUE(effect->findParameter("pcf"));
    EXPECT_EQ(effect->findParameter("pcf")->initializer->number, 512);
    EXPECT_FALSE(effect->findParameter("nopcf"));
    EXPECT_FALSE(effect->findParameter("never"));
    EXPECT_EQ(effect->findParameter("after")->loc.line, 10);
}

TEST(Preprocessor, LineDirectiveInSource) {
    DiagnosticList diags;
    auto effect = parseEffectSource("float a;\n#line 100 \"virtual.fx\"\nfloat b;\n", "main.fx",
                                    memoryOptions({}), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_EQ(effect->findParameter("b")->loc.file, "virtual.fx");
    EXPECT_EQ(effect->findParameter("b")->loc.line, 100);
}

TEST(Preprocessor, PragmasAreSkipped) {
    DiagnosticList diags;
    auto effect =
        parseEffectSource("#pragma pack_matrix(row_major)\nfloat a;\n", "main.fx", memoryOptions({}), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(effect->findParameter("a"));
}

// D3DX's stringizing operator, which glslang's (GLSL) preprocessor lacks: NVIDIA's Quad.fxh declares
// render-target formats with `string Format = #PixFmt;`. Token pasting keeps working, and a '#' inside a
// string literal of a macro body is left alone.
TEST(Preprocessor, StringizingInMacroBodies) {
    DiagnosticList diags;
    auto effect = parseEffectSource(R"(#define DECLARE_TARGET(Name, PixFmt) \
texture Name : RENDERCOLORTARGET < string Format = #PixFmt; string Note = "#not"; >;
#define GLUE(a, b) a##b
DECLARE_TARGET(Shadow, R32F)
float GLUE(Bi, as) = 1;
)",
                                    "main.fx", memoryOptions({}), diags);
    ASSERT_TRUE(effect) << diags.str();
    const Parameter* shadow = effect->findParameter("Shadow");
    ASSERT_TRUE(shadow);
    ASSERT_TRUE(shadow->annotation("Format"));
    EXPECT_EQ(shadow->annotation("Format")->value.text, "R32F");
    EXPECT_EQ(shadow->annotation("Note")->value.text, "#not");
    EXPECT_TRUE(effect->findParameter("Bias"));
}

// glslang predefines VULKAN (and GL_* names) for HLSL input; fxc predefined none of them, and engines'
// headers branch on `#if defined(VULKAN)`.
TEST(Preprocessor, NoGlslangPredefines) {
    DiagnosticList diags;
    auto effect = parseEffectSource(R"(#if defined(VULKAN) || defined(GL_SPIRV) || defined(GL_core_profile)
float vulkan;
#elif defined(GL_GOOGLE_include_directive) || defined(GL_ARB_gpu_shader5) || defined(GL_NV_mesh_shader)
float extensions;
#else
float fxc;
#endif
)",
                                    "main.fx", memoryOptions({}), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(effect->findParameter("fxc"));
    EXPECT_FALSE(effect->findParameter("vulkan"));
    EXPECT_FALSE(effect->findParameter("extensions"));
    EXPECT_FALSE(diags.hasErrors());
}

// A condition calling a name that is no function-like macro reads the call as 0 with a warning at the
// name (MonoGame's effect preprocessor), in #if and #elif, in the main file and in includes; a call in a
// condition that is never evaluated warns nothing, and a defined macro is called as usual.
TEST(Preprocessor, UndefinedMacroCallInConditionReadsZero) {
    std::map<std::string, std::string> files = {
        {"inc.fxh", "#if HAS(X)\nfloat inInclude;\n#endif\nfloat incEnd;\n"}};
    DiagnosticList diags;
    auto effect = parseEffectSource(R"(#if foo(1)
float a;
#elif bar(2, 3) || 1
float b;
#else
float c;
#endif
#define twice(x) ((x) * 2)
#if twice(1) == 2 && !foo ( 7 )
float d;
#endif
#if 0
#if never(1)
#endif
#endif
#include "inc.fxh"
float last;
)",
                                    "main.fx", memoryOptions(files), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_FALSE(effect->findParameter("a"));
    EXPECT_TRUE(effect->findParameter("b"));
    EXPECT_FALSE(effect->findParameter("c"));
    EXPECT_TRUE(effect->findParameter("d"));
    EXPECT_FALSE(effect->findParameter("inInclude"));
    // The guards the rewrite adds keep every line where the user wrote it.
    EXPECT_EQ(effect->findParameter("b")->loc.line, 4);
    EXPECT_EQ(effect->findParameter("d")->loc.line, 10);
    EXPECT_EQ(effect->findParameter("last")->loc.line, 17);
    EXPECT_EQ(effect->findParameter("incEnd")->loc.line, 4);
    EXPECT_EQ(effect->findParameter("incEnd")->loc.file, "inc.fxh");
    std::vector<std::string> warnings;
    for (const Diagnostic& d : diags.items()) {
        EXPECT_EQ(d.id, DiagId::UndefinedConditionCall) << d.message;
        EXPECT_EQ(d.severity, Severity::Warning);
        warnings.push_back(d.loc.str() + " " + d.message);
    }
    EXPECT_EQ(warnings,
              (std::vector<std::string>{
                  "main.fx:1:5 'foo' is not a function-like macro here: its call in this condition "
                  "reads as 0",
                  "main.fx:3:7 'bar' is not a function-like macro here: its call in this condition "
                  "reads as 0",
                  "main.fx:9:23 'foo' is not a function-like macro here: its call in this condition "
                  "reads as 0",
                  "inc.fxh:1:5 'HAS' is not a function-like macro here: its call in this condition "
                  "reads as 0"}));
}

// FX11 game code wrote `#include "x.fxh";`: fxc warned about the text after the file name and went on.
// The rewrite above marks its calls with pragmas of its own; an effect that writes such a pragma itself
// (no number, a number past any call, one too long for an integer) keeps it as an ordinary pragma: no
// warning, no exception out of the parser.
TEST(Preprocessor, AnEffectsOwnMarkerPragmaIsAnOrdinaryPragma) {
    DiagnosticList diags;
    auto effect = parseEffectSource(R"(#pragma shadowfx_undefined_condition_call_
#pragma shadowfx_undefined_condition_call_x
#pragma shadowfx_undefined_condition_call_0
#pragma shadowfx_undefined_condition_call_99999999999999999999999
float kept;
)",
                                    "main.fx", memoryOptions({}), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(effect->findParameter("kept"));
    for (const Diagnostic& d : diags.items()) EXPECT_NE(d.id, DiagId::UndefinedConditionCall) << d.message;
}

// fxc (X1519) and MonoGame warned about a macro defined again with another body and took the new one;
// glslang stops with "Macro redefined". Each such #define warns at its name and wins, in the file and in an
// include (before or after the file's own #define), over a command-line define too; the same body again, or
// another body in a branch not taken, says nothing, and every line keeps its number.
TEST(Preprocessor, MacroRedefinedWithAnotherBodyWarnsAndTheNewBodyWins) {
    std::map<std::string, std::string> files = {{"inc.fxh", "#define SIZE 5\nfloat inInclude[SIZE];\n"},
                                                {"first.fxh", "#define MODEL 1\n"}};
    ParseOptions options = memoryOptions(files);
    options.defines = {{"FROM_COMMAND_LINE", "1"}};
    DiagnosticList diags;
    auto effect = parseEffectSource(R"(#define SIZE 2
#define SIZE 2 // the same body: no warning
float two[SIZE];
#define SIZE 3 /* another */
float three[SIZE];
#if 0
#define SIZE 9
#endif
#include "inc.fxh"
#define FROM_COMMAND_LINE 4
#define LONG 1 + \
  1
#define LONG 1 + \
  1 + 1
float four[FROM_COMMAND_LINE];
float last[LONG];
#include "first.fxh"
#define MODEL 2
float model[MODEL];
)",
                                    "main.fx", options, diags);
    ASSERT_TRUE(effect) << diags.str();
    ASSERT_TRUE(effect->findParameter("two") && effect->findParameter("three") &&
                effect->findParameter("inInclude") && effect->findParameter("four") &&
                effect->findParameter("last") && effect->findParameter("model"));
    EXPECT_EQ(effect->findParameter("two")->type.arrayDims, std::vector<int>{2});
    EXPECT_EQ(effect->findParameter("three")->type.arrayDims, std::vector<int>{3});
    EXPECT_EQ(effect->findParameter("inInclude")->type.arrayDims, std::vector<int>{5});
    EXPECT_EQ(effect->findParameter("four")->type.arrayDims, std::vector<int>{4});
    EXPECT_EQ(effect->findParameter("last")->type.arrayDims, std::vector<int>{3});
    EXPECT_EQ(effect->findParameter("model")->type.arrayDims, std::vector<int>{2});
    EXPECT_EQ(effect->findParameter("three")->loc.line, 5);
    EXPECT_EQ(effect->findParameter("inInclude")->loc.line, 2);
    EXPECT_EQ(effect->findParameter("last")->loc.line, 16);
    EXPECT_EQ(effect->findParameter("model")->loc.line, 19);
    std::vector<std::string> warnings;
    for (const Diagnostic& d : diags.items()) {
        EXPECT_EQ(d.id, DiagId::MacroRedefined) << d.message;
        EXPECT_EQ(d.severity, Severity::Warning);
        warnings.push_back(d.loc.str() + " " + d.message);
    }
    EXPECT_EQ(warnings,
              (std::vector<std::string>{
                  "main.fx:4:9 macro 'SIZE' redefined with a different body: the new definition is used",
                  "inc.fxh:1:9 macro 'SIZE' redefined with a different body: the new definition is used",
                  "main.fx:10:9 macro 'FROM_COMMAND_LINE' redefined with a different body: the new "
                  "definition is used",
                  "main.fx:13:9 macro 'LONG' redefined with a different body: the new definition is "
                  "used",
                  "main.fx:18:9 macro 'MODEL' redefined with a different body: the new definition is "
                  "used"}));
}

TEST(Preprocessor, TextAfterIncludeFileNameIsIgnoredWithWarning) {
    std::map<std::string, std::string> files = {{"a.fxh", "float fromA;\n"}, {"b.fxh", "float fromB;\n"}};
    DiagnosticList diags;
    auto effect = parseEffectSource("#include \"a.fxh\" ;\n#include <b.fxh> // a comment\nfloat after;\n",
                                    "main.fx", memoryOptions(files), diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_TRUE(effect->findParameter("fromA"));
    EXPECT_TRUE(effect->findParameter("fromB"));
    EXPECT_EQ(effect->findParameter("after")->loc.line, 3);
    ASSERT_EQ(diags.items().size(), 1u) << diags.str();
    EXPECT_EQ(diags.items()[0].id, DiagId::IncludeTrailingText);
    EXPECT_EQ(diags.items()[0].severity, Severity::Warning);
    EXPECT_EQ(diags.items()[0].loc.str(), "main.fx:1:18");
}
}  // namespace test_preprocessor
