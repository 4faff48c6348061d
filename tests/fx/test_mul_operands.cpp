// mul() with an operand of one dimension (MulOperands.h): refused before glslang's HLSL front end, which
// crashes on it, sees it; every other mul() left to glslang.
#include "../../fx/src/HlslToSpirv.h"  // private headers: the check is tested directly
#include "../../fx/src/MulOperands.h"

#include <gtest/gtest.h>

#include <string>

namespace fx::test_mul_operands {
namespace {

const std::string kDeclarations =
    "#line 1 \"t.fx\"\n"
    "float4x4 m; float3x3 n; float1 a, b = 2; int1x3 r; typedef half3x1 Column; Column c;\n"
    "struct S { float1 depth, height; float3 normal; };\n"
    "vector<float, 1> w; matrix<float, 4, 1> k; float1 f() { return 1; }\n";

std::vector<HlslMessage> check(const std::string& body) {
    return detail::mulCallsGlslangCannotCompile(
        detail::lexHlslUnit(kDeclarations + "float4 PS(S s) : SV_Target {\n" + body + "\n}\n"));
}

TEST(MulOperands, EachOperandOfOneDimensionIsRefusedAtItsCall) {
    for (const char* body :
         {"return mul(a, m)[0];", "return mul(b, m)[0];", "return mul(n, s.depth).xyzz;",
          "return mul(s.height * 2, n).xyzz;", "return mul(r, n)[0];", "return mul(c, 1).xxxx;",
          "return mul(w, m);", "return mul(m, k).xxxx;", "return mul(f(), m);", "return mul(float1(2), m);",
          "return mul((float3x1)n, m);", "return mul(((a)), m);"}) {
        SCOPED_TRACE(body);
        const std::vector<HlslMessage> errors = check(body);
        ASSERT_EQ(errors.size(), 1u);
        EXPECT_TRUE(errors[0].error);
        EXPECT_EQ(errors[0].file, "t.fx");
        EXPECT_EQ(errors[0].line, 5);
        EXPECT_EQ(errors[0].column, static_cast<int>(std::string(body).find("mul(")) + 1);
        EXPECT_EQ(errors[0].column, static_cast<int>(std::string(body).find("mul(")) + 1);
        EXPECT_EQ(errors[0].text.rfind("'mul' : an operand has a dimension of one", 0), 0u) << errors[0].text;
    }
}

// A name of one dimension inside a constructor's or a call's arguments, a struct's member of that name read
// as a variable (a local of another type), operands of full size.
TEST(MulOperands, OperandsOfFullSizeAreLeftToGlslang) {
    EXPECT_TRUE(check("float4 depth = 1;\n"
                      "return mul(float4(s.normal, a), m) + mul(s.normal, n).xyzz + mul(2, m)[1] + "
                      "mul(m, m)[0] + mul(depth, m) + mul(float4(f(), 0, 0, 1), m) + mul(m[0], m) + a.x;")
                    .empty());
}

// The call that crashed glslang (a fuzzer's find): now an error on its line, in this process.
TEST(MulOperands, TheCrashingCallIsAnErrorOfTheCompile) {
    const HlslCompileResult result = compileHlslToSpirv(
        "#line 1 \"t.fx\"\nfloat3x3 world;\nfloat4 PS(float1 normal : TEXCOORD0) : SV_Target {\n"
        "    return float4(mul(normal, world), 1);\n}\n",
        ShaderStage::Fragment, "PS");
    EXPECT_FALSE(result.success);
    ASSERT_EQ(result.messages.size(), 1u);
    EXPECT_EQ(result.messages[0].line, 3);
}

}  // namespace
}  // namespace fx::test_mul_operands
