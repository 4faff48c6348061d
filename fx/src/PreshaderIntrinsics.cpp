// PreshaderIntrinsics: the HLSL intrinsics and constructors a preshader program evaluates on the host
// (see PreshaderEvaluator.h).
#include "PreshaderEvaluator.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace fx::detail {

namespace {

// `m`: an n x n matrix (n <= 4) row by row.
float determinantOf(const float* m, int n) {
    if (n == 1) return m[0];
    if (n == 2) return m[0] * m[3] - m[1] * m[2];
    float det = 0.0f;
    for (int c = 0; c < n; ++c) {
        float minor[9];
        int count = 0;
        for (int r = 1; r < n; ++r)
            for (int k = 0; k < n; ++k)
                if (k != c) minor[count++] = m[r * n + k];
        float sign = (c % 2 == 0) ? 1.0f : -1.0f;
        det += sign * m[c] * determinantOf(minor, n - 1);
    }
    return det;
}

// Inverse by the adjugate: cofactor(r, c) / det, transposed, into `out` (n x n). Fine for the 4x4s effects
// use.
void inverseOf(const float* m, int n, float det, float* out) {
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            float minor[9];
            int count = 0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    if (i != r && j != c) minor[count++] = m[i * n + j];
            float cof = ((r + c) % 2 == 0 ? 1.0f : -1.0f) * (n == 1 ? 1.0f : determinantOf(minor, n - 1));
            out[c * n + r] = cof / det;
        }
}

using F1 = float (*)(float);
// The component-wise intrinsics of one argument; null for the others.
F1 unaryFunction(Function function) {
    switch (function) {
        case Function::Abs:
            return [](float x) { return std::fabs(x); };
        case Function::Sqrt:
            return [](float x) { return std::sqrt(x); };
        case Function::Rsqrt:
            return [](float x) { return 1.0f / std::sqrt(x); };
        case Function::Exp:
            return [](float x) { return std::exp(x); };
        case Function::Exp2:
            return [](float x) { return std::exp2(x); };
        case Function::Log:
            return [](float x) { return std::log(x); };
        case Function::Log2:
            return [](float x) { return std::log2(x); };
        case Function::Log10:
            return [](float x) { return std::log10(x); };
        case Function::Sin:
            return [](float x) { return std::sin(x); };
        case Function::Cos:
            return [](float x) { return std::cos(x); };
        case Function::Tan:
            return [](float x) { return std::tan(x); };
        case Function::Asin:
            return [](float x) { return std::asin(x); };
        case Function::Acos:
            return [](float x) { return std::acos(x); };
        case Function::Atan:
            return [](float x) { return std::atan(x); };
        case Function::Radians:
            return [](float x) { return x * 0.017453292519943295f; };
        case Function::Degrees:
            return [](float x) { return x * 57.29577951308232f; };
        case Function::Floor:
            return [](float x) { return std::floor(x); };
        case Function::Ceil:
            return [](float x) { return std::ceil(x); };
        case Function::Round:
            return [](float x) { return std::round(x); };
        case Function::Trunc:
            return [](float x) { return std::trunc(x); };
        case Function::Frac:
            return [](float x) { return x - std::floor(x); };
        case Function::Saturate:
            return [](float x) { return std::clamp(x, 0.0f, 1.0f); };
        case Function::Sign:
            return [](float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); };
        default:
            return nullptr;
    }
}

using F2 = float (*)(float, float);
// The component-wise intrinsics of two arguments; null for the others.
F2 binaryFunction(Function function) {
    switch (function) {
        case Function::Min:
            return [](float x, float y) { return std::min(x, y); };
        case Function::Max:
            return [](float x, float y) { return std::max(x, y); };
        case Function::Pow:
            return [](float x, float y) { return std::pow(x, y); };
        case Function::Atan2:
            return [](float y, float x) { return std::atan2(y, x); };
        case Function::Fmod:
            return [](float x, float y) { return std::fmod(x, y); };
        case Function::Step:
            return [](float edge, float x) { return x >= edge ? 1.0f : 0.0f; };
        default:
            return nullptr;
    }
}

// Half and double results stay so; every other base becomes float.
void makeFloatResult(TypeDesc& type) {
    if (!(type.base == BaseType::Half || type.base == BaseType::Double)) type.base = BaseType::Float;
}

}  // namespace

// The result takes the place of the first argument (every intrinsic takes at least one).
bool Evaluator::intrinsic(Function function, const std::string& name, std::span<Value> args,
                          const SourceLoc& loc) {
    auto need = [&](size_t n) -> bool {
        if (args.size() == n) return true;
        fail(DiagId::IntrinsicArgumentCount, loc, {name, std::to_string(n)});
        return false;
    };
    for (const Value& a : args)
        if (a.type.base == BaseType::String) return fail(DiagId::IntrinsicOfString, loc, {name});
    if (const F1 f = unaryFunction(function)) {
        if (!need(1)) return false;
        Value& v = args[0];
        for (float& x : v.data) x = f(x);
        if (function == Function::Sign)
            v.type.base = BaseType::Int;
        else if (function != Function::Abs)
            makeFloatResult(v.type);
        return true;
    }
    if (const F2 f = binaryFunction(function)) {
        if (!need(2) || !broadcast(args[0], args[1], loc)) return false;
        Value& v = args[0];
        if (baseRank(args[1].type.base) > baseRank(v.type.base)) v.type.base = args[1].type.base;
        for (size_t i = 0; i < v.data.size(); ++i) v.data[i] = f(v.data[i], args[1].data[i]);
        if (function != Function::Min && function != Function::Max) makeFloatResult(v.type);
        return true;
    }
    switch (function) {
        case Function::Clamp:
        case Function::Lerp:
        case Function::Smoothstep: {
            if (!need(3)) return false;
            // Broadcast all three to the widest.
            if (!broadcast(args[0], args[1], loc) || !broadcast(args[1], args[2], loc) ||
                !broadcast(args[0], args[2], loc) || !broadcast(args[0], args[1], loc))
                return false;
            Value& v = args[0];
            for (size_t i = 0; i < v.data.size(); ++i) {
                float a = v.data[i], b = args[1].data[i], c = args[2].data[i];
                if (function == Function::Clamp)
                    v.data[i] = std::min(std::max(a, b), c);
                else if (function == Function::Lerp)
                    v.data[i] = a + (b - a) * c;
                else {
                    float t = std::clamp((c - a) / (b - a), 0.0f, 1.0f);
                    v.data[i] = t * t * (3.0f - 2.0f * t);
                }
            }
            // smoothstep's result has the type of its value argument.
            if (function == Function::Smoothstep) {
                v.type = args[2].type;
                v.string = args[2].string;
            }
            if (function != Function::Clamp) makeFloatResult(v.type);
            return true;
        }
        case Function::Dot: {
            if (!need(2) || !broadcast(args[0], args[1], loc)) return false;
            float s = 0.0f;
            for (size_t i = 0; i < args[0].data.size(); ++i) s += args[0].data[i] * args[1].data[i];
            setScalar(args[0], BaseType::Float, s);
            return true;
        }
        case Function::Length:
        case Function::Normalize: {
            if (!need(1)) return false;
            Value& v = args[0];
            float s = 0.0f;
            for (float x : v.data) s += x * x;
            float len = std::sqrt(s);
            if (function == Function::Length) {
                setScalar(v, BaseType::Float, len);
                return true;
            }
            makeFloatResult(v.type);
            for (float& x : v.data) x /= len;
            return true;
        }
        case Function::Distance: {
            if (!need(2) || !broadcast(args[0], args[1], loc)) return false;
            float s = 0.0f;
            for (size_t i = 0; i < args[0].data.size(); ++i) {
                float d = args[0].data[i] - args[1].data[i];
                s += d * d;
            }
            setScalar(args[0], BaseType::Float, std::sqrt(s));
            return true;
        }
        case Function::Cross: {
            if (!need(2)) return false;
            if (args[0].data.size() != 3 || args[1].data.size() != 3)
                return fail(DiagId::CrossArguments, loc);
            const std::vector<float>& a = args[0].data;
            const std::vector<float>& b = args[1].data;
            const float x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2],
                        z = a[0] * b[1] - a[1] * b[0];
            Value& v = args[0];
            setVectorType(v.type, BaseType::Float, 3);
            v.data = {x, y, z};
            v.string.clear();
            return true;
        }
        case Function::Transpose: {
            if (!need(1)) return false;
            Value& m = args[0];
            if (m.type.shape != Shape::Matrix) return true;
            mScratch.assign(m.data.begin(), m.data.end());
            for (int r = 0; r < m.type.rows; ++r)
                for (int c = 0; c < m.type.cols; ++c)
                    m.data[static_cast<size_t>(c * m.type.rows + r)] =
                        mScratch[static_cast<size_t>(r * m.type.cols + c)];
            std::swap(m.type.rows, m.type.cols);
            return true;
        }
        case Function::Determinant:
        case Function::Inverse: {
            if (!need(1)) return false;
            Value& m = args[0];
            int n = m.type.rows;
            if (m.type.shape != Shape::Matrix || m.type.rows != m.type.cols)
                return fail(DiagId::MatrixNotSquare, loc, {name});
            float det = determinantOf(m.data.data(), n);
            if (function == Function::Determinant) {
                setScalar(m, BaseType::Float, det);
                return true;
            }
            if (det == 0.0f) return fail(DiagId::SingularMatrixInverse, loc);
            float inverse[16];
            inverseOf(m.data.data(), n, det, inverse);
            m.data.assign(inverse, inverse + n * n);
            m.string.clear();
            return true;
        }
        case Function::Mul: {
            if (!need(2)) return false;
            Value& a = args[0];
            const Value& b = args[1];
            if (a.data.size() == 1 || b.data.size() == 1) {
                broadcast(a, args[1], loc);
                for (size_t i = 0; i < a.data.size(); ++i) a.data[i] *= b.data[i];
                return true;
            }
            bool am = a.type.shape == Shape::Matrix, bm = b.type.shape == Shape::Matrix;
            // A vector is a 1xN row on the left and an Nx1 column on the right.
            int ar = am ? a.type.rows : 1, ac = am ? a.type.cols : a.type.cols;
            int br = bm ? b.type.rows : b.type.cols, bc = bm ? b.type.cols : 1;
            if (ac != br)
                return fail(DiagId::MulDimensionMismatch, loc, {a.type.hlslName(), b.type.hlslName()});
            mScratch.assign(static_cast<size_t>(ar * bc), 0.0f);
            for (int r = 0; r < ar; ++r)
                for (int c = 0; c < bc; ++c)
                    for (int k = 0; k < ac; ++k)
                        mScratch[static_cast<size_t>(r * bc + c)] +=
                            a.data[static_cast<size_t>(r * ac + k)] * b.data[static_cast<size_t>(k * bc + c)];
            a.data.assign(mScratch.begin(), mScratch.end());
            if (am && bm)
                setType(a.type, BaseType::Float, Shape::Matrix, ar, bc);
            else
                setVectorType(a.type, BaseType::Float, static_cast<int>(a.data.size()));
            a.string.clear();
            return true;
        }
        default:
            return fail(DiagId::FunctionNotHostEvaluable, loc, {name});
    }
}

// A constructor: the arguments' components in order, or one scalar broadcast.
bool Evaluator::construct(const TypeDesc& type, std::span<Value> args, Value& out, const SourceLoc& loc) {
    if (args.empty()) out.data.clear();
    for (size_t i = 1; i < args.size(); ++i)
        out.data.insert(out.data.end(), args[i].data.begin(), args[i].data.end());
    size_t want = componentCount(type);
    if (out.data.size() == 1) {
        const float x = out.data[0];
        out.data.assign(want, x);
    }
    if (out.data.size() != want)
        return fail(DiagId::ConstructorComponentCount, loc,
                    {type.hlslName(), std::to_string(want), std::to_string(out.data.size())});
    for (float& x : out.data) x = normalizeComponent(type.base, x);
    out.type = type;
    out.string.clear();
    return true;
}

bool Evaluator::initList(std::span<Value> args, Value& out, const SourceLoc& loc) {
    for (const Value& v : args)
        if (v.type.base == BaseType::String) return fail(DiagId::StringInInitializerList, loc);
    if (args.empty()) out.data.clear();
    for (size_t i = 1; i < args.size(); ++i)
        out.data.insert(out.data.end(), args[i].data.begin(), args[i].data.end());
    setVectorType(out.type, BaseType::Float, static_cast<int>(out.data.size()));
    out.string.clear();
    return true;
}

}  // namespace fx::detail
