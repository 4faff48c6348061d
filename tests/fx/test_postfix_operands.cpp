// Postfix `++`/`--` before glslang (PostfixOperands.h): written as prefix operators where their value is
// discarded, checked in prefix form where it is used, so that glslang neither drops a statement it cannot
// compile nor crashes on an expression it cannot type.
#include "../../fx/src/HlslToSpirv.h"  // private headers: the rewrite is tested directly
#include "../../fx/src/PostfixOperands.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace fx::test_postfix_operands {
namespace {

detail::PostfixRewrite rewriteText(const std::string& text) {
    return detail::rewritePostfixOperators(text, detail::lexHlslUnit(text));
}

size_t lines(const std::string& text) {
    return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

// No `++` at all (a `--` in a comment), or prefix operators only.
TEST(PostfixOperands, TextWithoutPostfixOperatorsIsReturnedAsIs) {
    for (const char* text : {"float4 PS() : SV_Target { return 1; } // ---- a ruler\n",
                             "void f(inout int n, bool c) { if (c) ++n; n = -(--n) + ++n; }\n"}) {
        const detail::PostfixRewrite rewrite = rewriteText(text);
        EXPECT_EQ(rewrite.text, text);
        EXPECT_FALSE(rewrite.checkText);
    }
}

TEST(PostfixOperands, StatementsAndLoopStepsBecomePrefixOperators) {
    const std::string text =
        "#line 7 \"a.fx\"\n"
        "void f(inout int n, inout float4 v[2]) {\n"
        "    n++;\n"
        "    for (int i = 0; i < 2; i++) v[i].x--;\n"
        "    if (n > 0) v[n - 1]++; else n--;\n"
        "    do n++; while (n < 4);\n"
        "}\n";
    const detail::PostfixRewrite rewrite = rewriteText(text);
    EXPECT_EQ(rewrite.text,
              "#line 7 \"a.fx\"\n"
              "void f(inout int n, inout float4 v[2]) {\n"
              "     ++n  ;\n"
              "    for (int i = 0; i < 2;  ++i  )  --v[i].x  ;\n"
              "    if (n > 0)  ++v[n - 1]  ; else  --n  ;\n"
              "    do  ++n  ; while (n < 4);\n"
              "}\n");
    EXPECT_FALSE(rewrite.checkText);
}

// The value of `x++` used: the text glslang compiles keeps it; the text it checks first increments the same
// operand (`(++x).y`, not `++x.y`), on the same lines.
TEST(PostfixOperands, UsedValuesAreCheckedInPrefixFormOnTheSameLines) {
    const std::string text =
        "float4 g(inout float4 v, inout int i, float4 a[4]) {\n"
        "    float4 w = a[i++] + v++.x;\n"
        "    return\n"
        "        f(s.m[1]--, 2);\n"
        "}\n";
    const detail::PostfixRewrite rewrite = rewriteText(text);
    EXPECT_EQ(rewrite.text, text);
    ASSERT_TRUE(rewrite.checkText);
    EXPECT_EQ(*rewrite.checkText,
              "float4 g(inout float4 v, inout int i, float4 a[4]) {\n"
              "    float4 w = a[ (++i)] +  (++v).x;\n"
              "    return\n"
              "        f( (--s.m[1]), 2);\n"
              "}\n");
    EXPECT_EQ(lines(*rewrite.checkText), lines(text));
}

// A for loop's condition uses its value; a loop step of two expressions is checked too.
TEST(PostfixOperands, LoopConditionsAndCommaStepsAreChecked) {
    const detail::PostfixRewrite rewrite =
        rewriteText("void f(int n) { for (int i = 0; n--; i++, n++) { } }\n");
    ASSERT_TRUE(rewrite.checkText);
    EXPECT_EQ(*rewrite.checkText, "void f(int n) { for (int i = 0;  (--n);  (++i),  (++n)) { } }\n");
}

HlslCompileResult compileFragment(const std::string& body) {
    return compileHlslToSpirv(
        "#line 1 \"t.fx\"\nstruct S { float a; };\nvoid v() {}\n"
        "float4 PS() : SV_Target {\n" +
            body + "\n}\n",
        ShaderStage::Fragment, "PS");
}

bool hasErrorOnLine(const HlslCompileResult& result, int line) {
    return std::any_of(result.messages.begin(), result.messages.end(),
                       [&](const HlslMessage& m) { return m.error && m.file == "t.fx" && m.line == line; });
}

// Each of these crashed glslang's HLSL front end (a null node read by the expression around the postfix
// operator): now each is an error on its line, in this process.
TEST(PostfixOperands, OperandsGlslangCannotIncrementAreErrorsWhereTheValueIsUsed) {
    for (const char* body :
         {"return undeclared++;", "return float--;", "return 1 + v()++;",
          "return sin(float3(1, 1, 1)--).xyzz;", "return float4(int++, 1, 1, 1);",
          "S s; s.a = 0; return s++.a;", "return undeclared++.x;", "return undeclared++ y;",
          "return v()++ 1;", "S s; return (s)++ 1;", "return (v())++ 1;", "return \"a\"++;",
          "return \"a\".x++;", "float4 q = 0; return vector<bool, 4>(q)++;", "float4 q = 0; return q)++;"}) {
        SCOPED_TRACE(body);
        const HlslCompileResult result = compileFragment(body);
        EXPECT_FALSE(result.success);
        EXPECT_TRUE(hasErrorOnLine(result, 4)) << result.log;
    }
}

// glslang compiled these, leaving the statement out: a bool, a struct and a void call cannot be
// incremented.
TEST(PostfixOperands, StatementsGlslangWouldDropAreErrors) {
    for (const char* body :
         {"bool b = true; b++; return 0;", "S s; s.a = 0; s--; return s.a;", "v()++; return 0;"}) {
        SCOPED_TRACE(body);
        const HlslCompileResult result = compileFragment(body);
        EXPECT_FALSE(result.success);
        EXPECT_TRUE(hasErrorOnLine(result, 4)) << result.log;
    }
}

// Prefix operators after a cast, a statement's header and an attribute stay prefix operators.
TEST(PostfixOperands, SoundOperandsCompileWhereverTheyStand) {
    const HlslCompileResult result = compileFragment(
        "float4 c = 0; int i = 0; float a[3] = {1, 2, 3};\n"
        "for (int k = 0; k < 3; k++) c.x += a[i++];\n"
        "c.y = c.x--; c.zw = float2(i--, c.x++);\n"
        "c.x += (float)++i + (float2)--c.y; if (i > 0) ++i; [unroll] for (int j = 0; j < 2;) ++j;\n"
        "return c;");
    EXPECT_TRUE(result.success) << result.log;
}

}  // namespace
}  // namespace fx::test_postfix_operands
