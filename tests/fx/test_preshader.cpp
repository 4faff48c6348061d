// Preshader: every operator and intrinsic against independent computations (glm, <cmath>), and the
// compiled programs: parameters resolved to slots, constants folded, inputs listed.
#include <fx/Preshader.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace fx::test_preshader {
namespace {

Expr num(double v, bool integer = false) {
    Expr e;
    e.kind = Expr::Kind::Number;
    e.number = v;
    e.isInteger = integer;
    return e;
}
Expr id(const std::string& name) {
    Expr e;
    e.kind = Expr::Kind::Identifier;
    e.text = name;
    return e;
}
Expr call(const std::string& f, std::vector<Expr> args) {
    Expr e;
    e.kind = Expr::Kind::Call;
    e.text = f;
    e.args = std::move(args);
    return e;
}
Expr bin(const std::string& op, Expr a, Expr b) {
    Expr e;
    e.kind = Expr::Kind::Binary;
    e.text = op;
    e.args = {std::move(a), std::move(b)};
    return e;
}
Expr member(Expr a, const std::string& m) {
    Expr e;
    e.kind = Expr::Kind::Member;
    e.text = m;
    e.args = {std::move(a)};
    return e;
}

// Parameters: M (4x4, m[r][c] = r*4+c+1 plus a diagonal), v (float4), a, b (float3).
struct Fixture : ::testing::Test {
    std::map<std::string, Value> params;
    glm::mat4 gm;  // the same matrix in glm (indexed [column][row]): gm[c][r] = M[r][c]
    void SetUp() override {
        std::vector<float> m(16);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                m[r * 4 + c] = static_cast<float>(r * 4 + c + 1) * 0.25f + (r == c ? 3.0f : 0.0f);
                gm[c][r] = m[r * 4 + c];
            }
        params["M"] = Value::matrix(4, 4, m);
        params["v"] = Value::vector({1, -2, 3, 0.5f});
        params["a"] = Value::vector({1, 2, 3});
        params["b"] = Value::vector({-4, 0.5f, 2});
    }
    Value eval(const Expr& e, const TypeDesc* type = nullptr) {
        DiagnosticList diags;
        auto v = evaluate(
            e,
            [&](std::string_view n) -> const Value* {
                auto it = params.find(std::string(n));
                return it == params.end() ? nullptr : &it->second;
            },
            type, &diags);
        EXPECT_TRUE(v) << diags.str();
        return v ? *v : Value{};
    }
};

TEST_F(Fixture, MulRowVectorOnTheLeft) {
    Value r = eval(call("mul", {id("v"), id("M")}));
    glm::vec4 ref = glm::vec4(1, -2, 3, 0.5f) * gm;  // glm's v * m is the row vector times m
    ASSERT_EQ(r.data.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.data[i], ref[i], 1e-4);
}

TEST_F(Fixture, MulColumnVectorOnTheRight) {
    Value r = eval(call("mul", {id("M"), id("v")}));
    glm::vec4 ref = gm * glm::vec4(1, -2, 3, 0.5f);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.data[i], ref[i], 1e-4);
}

TEST_F(Fixture, MulMatrixMatrixAndInverseTranspose) {
    Value r = eval(call("mul", {id("M"), call("inverse", {id("M")})}));
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(r.data[i], (i % 5 == 0) ? 1.0f : 0.0f, 1e-4);
    Value inv = eval(call("inverse", {id("M")}));
    glm::mat4 gi = glm::inverse(gm);
    for (int rr = 0; rr < 4; ++rr)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(inv.data[rr * 4 + c], gi[c][rr], 1e-4);
    Value t = eval(call("transpose", {id("M")}));
    for (int rr = 0; rr < 4; ++rr)
        for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(t.data[rr * 4 + c], params["M"].data[c * 4 + rr]);
    EXPECT_NEAR(eval(call("determinant", {id("M")})).asFloat(), glm::determinant(gm), 1e-2);
    Value ab = eval(call("mul", {id("M"), call("transpose", {id("M")})}));
    glm::mat4 ref = gm * glm::transpose(gm);
    for (int rr = 0; rr < 4; ++rr)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(ab.data[rr * 4 + c], ref[c][rr], 1e-3);
}

TEST_F(Fixture, MatrixMembersAndSwizzles) {
    EXPECT_FLOAT_EQ(eval(member(id("M"), "_13")).asFloat(), params["M"].data[0 * 4 + 2]);
    EXPECT_FLOAT_EQ(eval(member(id("M"), "_m21")).asFloat(), params["M"].data[2 * 4 + 1]);
    Value diag = eval(member(id("M"), "_11_22_33"));
    EXPECT_EQ(diag.data,
              (std::vector<float>{params["M"].data[0], params["M"].data[5], params["M"].data[10]}));
    EXPECT_EQ(eval(member(id("v"), "wzyx")).data, (std::vector<float>{0.5f, 3, -2, 1}));
    EXPECT_EQ(eval(member(id("a"), "bgr")).data, (std::vector<float>{3, 2, 1}));
    Expr row;
    row.kind = Expr::Kind::Index;
    row.args = {id("M"), num(3, true)};
    EXPECT_EQ(eval(row).data, std::vector<float>(params["M"].data.begin() + 12, params["M"].data.end()));
}

TEST_F(Fixture, OperatorsBroadcastAndConvert) {
    EXPECT_EQ(eval(bin("*", id("a"), num(2))).data, (std::vector<float>{2, 4, 6}));
    EXPECT_EQ(eval(bin("-", num(1), id("a"))).data, (std::vector<float>{0, -1, -2}));
    EXPECT_EQ(eval(bin("/", num(7, true), num(2, true))).asFloat(), 3.0f);  // integer division
    EXPECT_FLOAT_EQ(eval(bin("/", num(130944, true), num(16.0))).asFloat(), 8184.0f);
    EXPECT_EQ(eval(bin("<", id("a"), id("b"))).data, (std::vector<float>{0, 0, 0}));
    EXPECT_EQ(eval(bin("&&", num(1), num(0))).asBool(), false);
    EXPECT_FLOAT_EQ(eval(bin("%", num(7.5), num(2))).asFloat(), std::fmod(7.5f, 2.0f));
    Expr list;
    list.kind = Expr::Kind::InitList;
    list.args = {num(1), num(2), num(3), num(4)};
    TypeDesc f4;
    f4.shape = Shape::Vector;
    f4.cols = 4;
    EXPECT_EQ(eval(list, &f4).data, (std::vector<float>{1, 2, 3, 4}));
    TypeDesc b;
    b.base = BaseType::Bool;
    EXPECT_EQ(eval(num(3), &b).data, std::vector<float>{1});
    EXPECT_EQ(eval(call("float3", {num(1), call("float2", {num(2), num(3)})})).data,
              (std::vector<float>{1, 2, 3}));
    Expr tern;
    tern.kind = Expr::Kind::Ternary;
    tern.args = {num(0), num(5), num(6)};
    EXPECT_EQ(eval(tern).asFloat(), 6.0f);
}

TEST_F(Fixture, Intrinsics) {
    glm::vec3 a(1, 2, 3), b(-4, 0.5f, 2);
    EXPECT_NEAR(eval(call("dot", {id("a"), id("b")})).asFloat(), glm::dot(a, b), 1e-5);
    Value c = eval(call("cross", {id("a"), id("b")}));
    glm::vec3 gc = glm::cross(a, b);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c.data[i], gc[i], 1e-5);
    Value n = eval(call("normalize", {id("a")}));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(n.data[i], glm::normalize(a)[i], 1e-5);
    EXPECT_NEAR(eval(call("length", {id("a")})).asFloat(), glm::length(a), 1e-5);
    auto scalar1 = [&](const char* f, float x) { return eval(call(f, {num(x)})).asFloat(); };
    EXPECT_FLOAT_EQ(scalar1("abs", -2.5f), 2.5f);
    EXPECT_FLOAT_EQ(scalar1("sqrt", 2.0f), std::sqrt(2.0f));
    EXPECT_FLOAT_EQ(scalar1("rsqrt", 4.0f), 0.5f);
    EXPECT_FLOAT_EQ(scalar1("exp", 1.5f), std::exp(1.5f));
    EXPECT_FLOAT_EQ(scalar1("log", 1.5f), std::log(1.5f));
    EXPECT_FLOAT_EQ(scalar1("sin", 0.7f), std::sin(0.7f));
    EXPECT_FLOAT_EQ(scalar1("cos", 0.7f), std::cos(0.7f));
    EXPECT_FLOAT_EQ(scalar1("tan", 0.7f), std::tan(0.7f));
    EXPECT_FLOAT_EQ(scalar1("asin", 0.3f), std::asin(0.3f));
    EXPECT_FLOAT_EQ(scalar1("acos", 0.3f), std::acos(0.3f));
    EXPECT_FLOAT_EQ(scalar1("atan", 0.3f), std::atan(0.3f));
    EXPECT_NEAR(scalar1("radians", 180.0f), glm::radians(180.0f), 1e-6);
    EXPECT_NEAR(scalar1("degrees", 1.0f), glm::degrees(1.0f), 1e-4);
    EXPECT_FLOAT_EQ(scalar1("floor", -1.5f), -2.0f);
    EXPECT_FLOAT_EQ(scalar1("ceil", -1.5f), -1.0f);
    EXPECT_FLOAT_EQ(scalar1("frac", -1.25f), glm::fract(-1.25f));
    EXPECT_FLOAT_EQ(scalar1("saturate", 1.5f), 1.0f);
    EXPECT_FLOAT_EQ(scalar1("sign", -3.0f), -1.0f);
    auto scalar2 = [&](const char* f, float x, float y) { return eval(call(f, {num(x), num(y)})).asFloat(); };
    EXPECT_FLOAT_EQ(scalar2("min", 1, 2), 1.0f);
    EXPECT_FLOAT_EQ(scalar2("max", 1, 2), 2.0f);
    EXPECT_FLOAT_EQ(scalar2("pow", 2, 10), 1024.0f);
    EXPECT_FLOAT_EQ(scalar2("atan2", 1, -1), std::atan2(1.0f, -1.0f));
    EXPECT_FLOAT_EQ(scalar2("fmod", -7, 3), std::fmod(-7.0f, 3.0f));
    EXPECT_FLOAT_EQ(scalar2("step", 0.5f, 0.4f), 0.0f);
    EXPECT_FLOAT_EQ(eval(call("clamp", {num(5), num(0), num(2)})).asFloat(), 2.0f);
    EXPECT_FLOAT_EQ(eval(call("lerp", {num(2), num(4), num(0.25)})).asFloat(), glm::mix(2.0f, 4.0f, 0.25f));
    EXPECT_FLOAT_EQ(eval(call("smoothstep", {num(0), num(2), num(0.5)})).asFloat(),
                    glm::smoothstep(0.0f, 2.0f, 0.5f));
}

TEST(Preshader, ErrorsAreReported) {
    DiagnosticList diags;
    EXPECT_FALSE(evaluate(id("nope"), nullptr, nullptr, &diags));
    ASSERT_EQ(diags.items().size(), 1u);
    EXPECT_EQ(diags.items()[0].id, DiagId::UnknownIdentifier);
    diags.clear();
    EXPECT_FALSE(evaluate(call("noise", {num(1)}), nullptr, nullptr, &diags));
    EXPECT_EQ(diags.items().at(0).id, DiagId::FunctionNotHostEvaluable);
}

Expr ternary(Expr c, Expr a, Expr b) {
    Expr e;
    e.kind = Expr::Kind::Ternary;
    e.args = {std::move(c), std::move(a), std::move(b)};
    return e;
}

// The compiled form runs over slots, not names: renaming nothing, a program reads what its slots hold.
TEST(PreshaderProgram, ReadsSlotsResolvedAtCompileTime) {
    const SlotResolver slots = [](std::string_view name) -> std::optional<size_t> {
        if (name == "Scale") return 2;
        if (name == "Offset") return 0;
        return std::nullopt;
    };
    const PreshaderProgram program = compilePreshader(
        bin("+", bin("*", id("Scale"), num(2)), bin("-", id("Offset"), id("Scale"))), slots, nullptr);
    EXPECT_EQ(program.inputs(), (std::vector<size_t>{0, 2}));  // sorted, each once
    EXPECT_FALSE(program.isConstant());
    const std::vector<Value> values = {Value::scalar(10.0f), Value::scalar(-1.0f), Value::scalar(3.0f)};
    EXPECT_FLOAT_EQ(program.run(values, nullptr)->asFloat(), 3.0f * 2.0f + (10.0f - 3.0f));
    const std::vector<Value> changed = {Value::scalar(1.0f), Value::scalar(-1.0f), Value::scalar(0.5f)};
    EXPECT_FLOAT_EQ(program.run(changed, nullptr)->asFloat(), 0.5f * 2.0f + (1.0f - 0.5f));
}

TEST(PreshaderProgram, FoldsWhatReadsNoParameterAndConvertsToTheTargetType) {
    TypeDesc float3;
    float3.shape = Shape::Vector;
    float3.cols = 3;
    const PreshaderProgram program =
        compilePreshader(call("normalize", {call("float3", {num(3), num(0), num(4)})}), nullptr, &float3);
    ASSERT_TRUE(program.isConstant());
    EXPECT_TRUE(program.inputs().empty());
    const std::vector<float> expected = {0.6f, 0.0f, 0.8f};
    EXPECT_EQ(program.constant().data, expected);
    EXPECT_EQ(program.constant().type.cols, 3);
}

// An error stands for a value: it fails the program only if the result needs it, as when the expression
// tree was walked lazily (a scalar condition evaluates one branch).
TEST(PreshaderProgram, AnErrorInTheBranchNotTakenIsNone) {
    const SlotResolver slots = [](std::string_view name) -> std::optional<size_t> {
        return name == "UseA" ? std::optional<size_t>(0) : std::nullopt;
    };
    const PreshaderProgram program =
        compilePreshader(ternary(id("UseA"), num(1), id("Missing")), slots, nullptr);
    DiagnosticList diags;
    EXPECT_FLOAT_EQ(program.run({Value::boolean(true)}, &diags)->asFloat(), 1.0f);
    EXPECT_TRUE(diags.items().empty());
    EXPECT_FALSE(program.run({Value::boolean(false)}, &diags));
    ASSERT_EQ(diags.items().size(), 1u);
    EXPECT_EQ(diags.items()[0].id, DiagId::UnknownIdentifier);
    EXPECT_NE(diags.items()[0].message.find("Missing"), std::string::npos);
}

// Registers kept between runs (as the runtime keeps one per pass for all its programs) hold the last
// program's values: a run on them must give exactly what a run on fresh registers gives, whatever ran
// before, on every shape (a wider value before a narrower, a string before a number, an array's type before
// a vector's).
TEST(PreshaderProgram, RegistersKeptBetweenRunsGiveWhatFreshOnesGive) {
    const std::vector<std::string> names = {"M", "v", "a", "b", "s", "t", "arr", "flag"};
    const SlotResolver slots = [&](std::string_view name) -> std::optional<size_t> {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return i;
        return std::nullopt;
    };
    Expr index;
    index.kind = Expr::Kind::Index;
    index.args = {id("arr"), num(1, true)};
    Expr matrixRow = index;
    matrixRow.args = {id("M"), num(2, true)};
    Expr list;
    list.kind = Expr::Kind::InitList;
    list.args = {id("a"), num(7)};
    const std::vector<Expr> expressions = {
        call("mul", {id("v"), id("M")}),
        call("inverse", {id("M")}),
        member(call("transpose", {id("M")}), "_11_23_m30"),
        call("float4", {member(id("a"), "zyx"), num(2)}),
        ternary(call("float3", {num(1), num(0), id("flag")}), id("a"), id("b")),
        ternary(id("flag"), call("cross", {id("a"), id("b")}), call("normalize", {id("b")})),
        bin("==", id("s"), id("t")),
        index,
        matrixRow,
        list,
        call("smoothstep", {num(0, true), id("v"), member(id("v"), "wzyx")}),
        bin("%", call("int3", {id("a")}), num(2, true)),
        call("determinant", {id("M")}),
        call("lerp", {id("a"), id("b"), num(0.25)}),
    };
    std::vector<PreshaderProgram> programs;
    for (const Expr& e : expressions) programs.push_back(compilePreshader(e, slots, nullptr));

    TypeDesc arrayType;
    arrayType.shape = Shape::Vector;
    arrayType.cols = 2;
    arrayType.arrayDims = {3};
    Value array = zeroValue(arrayType);
    for (size_t i = 0; i < array.data.size(); ++i) array.data[i] = 0.5f * static_cast<float>(i) - 1.0f;
    std::vector<float> m(16);
    for (size_t i = 0; i < 16; ++i) m[i] = static_cast<float>(i % 5) + (i % 5 == 0 ? 2.0f : 0.25f);
    const std::vector<Value> first = {Value::matrix(4, 4, m),
                                      Value::vector({1, -2, 3, 0.5f}),
                                      Value::vector({1, 2, 3}),
                                      Value::vector({-4, 0.5f, 2}),
                                      Value::text("shadow"),
                                      Value::text("shadow"),
                                      array,
                                      Value::boolean(true)};
    std::vector<Value> second = first;
    second[1] = Value::vector({0.25f, 4, -1, 2});
    second[2] = Value::vector({-3, 5, 0.125f});
    second[5] = Value::text("light");
    second[7] = Value::boolean(false);

    PreshaderProgram::Registers registers;
    const std::vector<const std::vector<Value>*> runs = {&first, &second, &first};
    for (const std::vector<Value>* values : runs) {
        for (size_t i = 0; i < programs.size(); ++i) {
            SCOPED_TRACE("expression " + std::to_string(i));
            const std::optional<Value> fresh = programs[i].run(*values, nullptr);
            const Value* kept = programs[i].run(*values, registers, nullptr);
            ASSERT_TRUE(fresh);
            ASSERT_TRUE(kept);
            EXPECT_EQ(kept->data, fresh->data);
            EXPECT_EQ(kept->string, fresh->string);
            EXPECT_EQ(kept->type.hlslName(), fresh->type.hlslName());
            EXPECT_EQ(kept->type.arrayDims, fresh->type.arrayDims);
        }
    }
}

}  // namespace
}  // namespace fx::test_preshader
