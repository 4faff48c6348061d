// PreshaderIntrinsics: the HLSL intrinsics and constructors a preshader program evaluates on the host
// (see PreshaderEvaluator.h).
#include "PreshaderEvaluator.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fx::detail {

namespace {

float determinantOf(const std::vector<float>& m, int n) {
    if (n == 1) return m[0];
    if (n == 2) return m[0] * m[3] - m[1] * m[2];
    float det = 0.0f;
    for (int c = 0; c < n; ++c) {
        std::vector<float> minor;
        for (int r = 1; r < n; ++r)
            for (int k = 0; k < n; ++k)
                if (k != c) minor.push_back(m[static_cast<size_t>(r * n + k)]);
        float sign = (c % 2 == 0) ? 1.0f : -1.0f;
        det += sign * m[static_cast<size_t>(c)] * determinantOf(minor, n - 1);
    }
    return det;
}

// Inverse by the adjugate: cofactor(r, c) / det, transposed. Fine for the 4x4s effects use.
std::vector<float> inverseOf(const std::vector<float>& m, int n, float det) {
    std::vector<float> out(static_cast<size_t>(n * n));
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            std::vector<float> minor;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    if (i != r && j != c) minor.push_back(m[static_cast<size_t>(i * n + j)]);
            float cof = ((r + c) % 2 == 0 ? 1.0f : -1.0f) * (n == 1 ? 1.0f : determinantOf(minor, n - 1));
            out[static_cast<size_t>(c * n + r)] = cof / det;
        }
    return out;
}

}  // namespace

std::optional<Value> Evaluator::intrinsic(const std::string& name, std::vector<Value>& args,
                                          const SourceLoc& loc) {
    auto need = [&](size_t n) -> bool {
        if (args.size() == n) return true;
        fail(DiagId::IntrinsicArgumentCount, loc, {name, std::to_string(n)});
        return false;
    };
    for (const Value& a : args)
        if (a.type.base == BaseType::String) return fail(DiagId::IntrinsicOfString, loc, {name});
    auto floatResult = [](Value v) {
        if (!(v.type.base == BaseType::Half || v.type.base == BaseType::Double))
            v.type.base = BaseType::Float;
        return v;
    };
    using F1 = float (*)(float);
    static const std::map<std::string, F1> kUnary = {
        {"abs", [](float x) { return std::fabs(x); }},
        {"sqrt", [](float x) { return std::sqrt(x); }},
        {"rsqrt", [](float x) { return 1.0f / std::sqrt(x); }},
        {"exp", [](float x) { return std::exp(x); }},
        {"exp2", [](float x) { return std::exp2(x); }},
        {"log", [](float x) { return std::log(x); }},
        {"log2", [](float x) { return std::log2(x); }},
        {"log10", [](float x) { return std::log10(x); }},
        {"sin", [](float x) { return std::sin(x); }},
        {"cos", [](float x) { return std::cos(x); }},
        {"tan", [](float x) { return std::tan(x); }},
        {"asin", [](float x) { return std::asin(x); }},
        {"acos", [](float x) { return std::acos(x); }},
        {"atan", [](float x) { return std::atan(x); }},
        {"radians", [](float x) { return x * 0.017453292519943295f; }},
        {"degrees", [](float x) { return x * 57.29577951308232f; }},
        {"floor", [](float x) { return std::floor(x); }},
        {"ceil", [](float x) { return std::ceil(x); }},
        {"round", [](float x) { return std::round(x); }},
        {"trunc", [](float x) { return std::trunc(x); }},
        {"frac", [](float x) { return x - std::floor(x); }},
        {"saturate", [](float x) { return std::clamp(x, 0.0f, 1.0f); }},
        {"sign", [](float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); }},
    };
    if (auto it = kUnary.find(name); it != kUnary.end()) {
        if (!need(1)) return std::nullopt;
        Value v = args[0];
        for (float& x : v.data) x = it->second(x);
        if (name == "sign")
            v.type.base = BaseType::Int;
        else if (name != "abs")
            v = floatResult(std::move(v));
        return v;
    }
    using F2 = float (*)(float, float);
    static const std::map<std::string, F2> kBinary = {
        {"min", [](float x, float y) { return std::min(x, y); }},
        {"max", [](float x, float y) { return std::max(x, y); }},
        {"pow", [](float x, float y) { return std::pow(x, y); }},
        {"atan2", [](float y, float x) { return std::atan2(y, x); }},
        {"fmod", [](float x, float y) { return std::fmod(x, y); }},
        {"step", [](float edge, float x) { return x >= edge ? 1.0f : 0.0f; }},
    };
    if (auto it = kBinary.find(name); it != kBinary.end()) {
        if (!need(2) || !broadcast(args[0], args[1], loc)) return std::nullopt;
        Value v = args[0];
        if (baseRank(args[1].type.base) > baseRank(v.type.base)) v.type.base = args[1].type.base;
        for (size_t i = 0; i < v.data.size(); ++i) v.data[i] = it->second(args[0].data[i], args[1].data[i]);
        if (name != "min" && name != "max") v = floatResult(std::move(v));
        return v;
    }
    if (name == "clamp" || name == "lerp" || name == "smoothstep") {
        if (!need(3)) return std::nullopt;
        // Broadcast all three to the widest.
        if (!broadcast(args[0], args[1], loc) || !broadcast(args[1], args[2], loc) ||
            !broadcast(args[0], args[2], loc) || !broadcast(args[0], args[1], loc))
            return std::nullopt;
        Value v = name == "smoothstep" ? args[2] : args[0];
        for (size_t i = 0; i < v.data.size(); ++i) {
            float a = args[0].data[i], b = args[1].data[i], c = args[2].data[i];
            if (name == "clamp")
                v.data[i] = std::min(std::max(a, b), c);
            else if (name == "lerp")
                v.data[i] = a + (b - a) * c;
            else {
                float t = std::clamp((c - a) / (b - a), 0.0f, 1.0f);
                v.data[i] = t * t * (3.0f - 2.0f * t);
            }
        }
        return name == "clamp" ? v : floatResult(std::move(v));
    }
    if (name == "dot") {
        if (!need(2) || !broadcast(args[0], args[1], loc)) return std::nullopt;
        float s = 0.0f;
        for (size_t i = 0; i < args[0].data.size(); ++i) s += args[0].data[i] * args[1].data[i];
        return Value::scalar(s);
    }
    if (name == "length" || name == "normalize") {
        if (!need(1)) return std::nullopt;
        float s = 0.0f;
        for (float x : args[0].data) s += x * x;
        float len = std::sqrt(s);
        if (name == "length") return Value::scalar(len);
        Value v = floatResult(args[0]);
        for (float& x : v.data) x /= len;
        return v;
    }
    if (name == "distance") {
        if (!need(2) || !broadcast(args[0], args[1], loc)) return std::nullopt;
        float s = 0.0f;
        for (size_t i = 0; i < args[0].data.size(); ++i) {
            float d = args[0].data[i] - args[1].data[i];
            s += d * d;
        }
        return Value::scalar(std::sqrt(s));
    }
    if (name == "cross") {
        if (!need(2)) return std::nullopt;
        if (args[0].data.size() != 3 || args[1].data.size() != 3) return fail(DiagId::CrossArguments, loc);
        const auto& a = args[0].data;
        const auto& b = args[1].data;
        return Value::vector(
            {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]});
    }
    if (name == "transpose") {
        if (!need(1)) return std::nullopt;
        const Value& m = args[0];
        if (m.type.shape != Shape::Matrix) return m;
        Value v = m;
        std::swap(v.type.rows, v.type.cols);
        for (int r = 0; r < m.type.rows; ++r)
            for (int c = 0; c < m.type.cols; ++c)
                v.data[static_cast<size_t>(c * m.type.rows + r)] =
                    m.data[static_cast<size_t>(r * m.type.cols + c)];
        return v;
    }
    if (name == "determinant" || name == "inverse") {
        if (!need(1)) return std::nullopt;
        const Value& m = args[0];
        int n = m.type.rows;
        if (m.type.shape != Shape::Matrix || m.type.rows != m.type.cols)
            return fail(DiagId::MatrixNotSquare, loc, {name});
        float det = determinantOf(m.data, n);
        if (name == "determinant") return Value::scalar(det);
        if (det == 0.0f) return fail(DiagId::SingularMatrixInverse, loc);
        return makeValue(m.type, inverseOf(m.data, n, det));
    }
    if (name == "mul") {
        if (!need(2)) return std::nullopt;
        const Value& a = args[0];
        const Value& b = args[1];
        if (a.data.size() == 1 || b.data.size() == 1) {
            Value x = a, y = b;
            broadcast(x, y, loc);
            for (size_t i = 0; i < x.data.size(); ++i) x.data[i] *= y.data[i];
            return x;
        }
        bool am = a.type.shape == Shape::Matrix, bm = b.type.shape == Shape::Matrix;
        // A vector is a 1xN row on the left and an Nx1 column on the right.
        int ar = am ? a.type.rows : 1, ac = am ? a.type.cols : a.type.cols;
        int br = bm ? b.type.rows : b.type.cols, bc = bm ? b.type.cols : 1;
        if (ac != br) return fail(DiagId::MulDimensionMismatch, loc, {a.type.hlslName(), b.type.hlslName()});
        std::vector<float> out(static_cast<size_t>(ar * bc), 0.0f);
        for (int r = 0; r < ar; ++r)
            for (int c = 0; c < bc; ++c)
                for (int k = 0; k < ac; ++k)
                    out[static_cast<size_t>(r * bc + c)] +=
                        a.data[static_cast<size_t>(r * ac + k)] * b.data[static_cast<size_t>(k * bc + c)];
        if (am && bm) return makeValue(makeType(BaseType::Float, Shape::Matrix, ar, bc), std::move(out));
        return makeValue(vectorType(BaseType::Float, static_cast<int>(out.size())), std::move(out));
    }
    return fail(DiagId::FunctionNotHostEvaluable, loc, {name});
}

// A constructor: the arguments' components in order, or one scalar broadcast.
std::optional<Value> Evaluator::construct(const TypeDesc& type, const std::vector<Value>& args,
                                          const SourceLoc& loc) {
    std::vector<float> flat;
    for (const Value& a : args) flat.insert(flat.end(), a.data.begin(), a.data.end());
    size_t want = componentCount(type);
    if (flat.size() == 1) flat.assign(want, flat[0]);
    if (flat.size() != want)
        return fail(DiagId::ConstructorComponentCount, loc,
                    {type.hlslName(), std::to_string(want), std::to_string(flat.size())});
    for (float& x : flat) x = normalizeComponent(type.base, x);
    return makeValue(type, std::move(flat));
}

std::optional<Value> Evaluator::initList(const std::vector<Value>& args, const SourceLoc& loc) {
    std::vector<float> flat;
    for (const Value& v : args) {
        if (v.type.base == BaseType::String) return fail(DiagId::StringInInitializerList, loc);
        flat.insert(flat.end(), v.data.begin(), v.data.end());
    }
    return makeValue(vectorType(BaseType::Float, static_cast<int>(flat.size())), std::move(flat));
}

}  // namespace fx::detail
