// PositionPassThrough: see PositionPassThrough.h.
//
// A D3D10 post-processing pass has a vertex shader of its own (the DirectX SDK's `QuadVS`:
// `Output.Pos = Input.Pos;`), where a D3D9 one had none: its application drew a screen quad in clip
// space through it. The shader says nothing else about the quad, so the compiler reads its body: a
// position that arrives unchanged is such a pass's mark. Read on the effect's own syntax tree, before
// glslang's entry-point wrapper and copies hide it, one component at a time (HDAO's quad shader writes
// `.x`, `.y`, `.z` and `.w` one by one).
#include "PositionPassThrough.h"

#include "CaseFolding.h"

#include <fx/VertexStreams.h>

#include <algorithm>
#include <array>
#include <optional>

namespace fx::detail {

namespace {

bool isPositionOutput(const std::string& semantic) {
    const std::string s = upperCase(semantic);
    return s == "SV_POSITION" || s == "SV_POSITION0" || s == "POSITION" || s == "POSITION0";
}

bool isPositionInput(const std::string& semantic) {
    if (semantic.empty()) return false;
    std::optional<int> location = vertexInputLocation(semantic);
    if (!location) location = vertexStreamByName(semantic);
    return location == 0;
}

// The member of struct `name` that carries the position (the rasterizer's, or the mesh's), or null.
const StructMember* positionMember(const Effect& effect, const std::string& name, bool output) {
    const StructDecl* s = effect.findStruct(name);
    if (!s) return nullptr;
    for (const StructMember& m : s->members)
        if (output ? isPositionOutput(m.semantic) : isPositionInput(m.semantic)) return &m;
    return nullptr;
}

bool isIdentifier(const Expr& e, const std::string& name) {
    return e.kind == Expr::Kind::Identifier && e.text == name;
}

// The variable an l-value expression writes (`o` of `o.Pos.xy`, `a` of `a[i].b`).
const Expr& rootOf(const Expr& e) {
    const Expr* root = &e;
    while ((root->kind == Expr::Kind::Member || root->kind == Expr::Kind::Index) && !root->args.empty())
        root = &root->args[0];
    return *root;
}

// A swizzle's component indices (`xy`, `bgr`), or empty where `text` is none.
std::vector<int> swizzle(const std::string& text) {
    std::vector<int> out;
    if (text.empty() || text.size() > 4) return {};
    for (char c : text) {
        const std::string xyzw = "xyzw", rgba = "rgba";
        size_t at = xyzw.find(c);
        if (at == std::string::npos) at = rgba.find(c);
        if (at == std::string::npos) return {};
        out.push_back(static_cast<int>(at));
    }
    return out;
}

// Where one component of the position comes from.
struct Component {
    enum class Kind { Unknown, Input, Constant };
    Kind kind = Kind::Unknown;
    int index = 0;       // Input: the input position's component
    double value = 0.0;  // Constant
};

class PassThroughReader {
public:
    PassThroughReader(const Effect& effect, const FunctionDecl& function)
        : mEffect(effect), mFunction(function) {
        for (const FunctionParam& p : function.params) {
            if (p.direction == FunctionParam::Direction::Out) {
                if (p.type.base == BaseType::Struct) {
                    if (const StructMember* m = positionMember(effect, p.type.structName, true))
                        mOutputs.push_back({p.name, m->name});
                } else if (isPositionOutput(p.semantic)) {
                    mOutputs.push_back({p.name, ""});
                }
                continue;
            }
            if (p.isUniform) continue;
            if (p.type.base == BaseType::Struct) {
                if (const StructMember* m = positionMember(effect, p.type.structName, false))
                    mInputs.push_back({p.name, m->name, m->type.cols});
            } else if (isPositionInput(p.semantic)) {
                mInputs.push_back({p.name, "", p.type.cols});
            }
            // Any other input may carry the position's parts too: none of them may be written.
            mInputBases.push_back(p.name);
        }
    }

    bool read() {
        const FunctionDecl& function = mFunction;
        const std::vector<FunctionDecl::Statement>& body = function.straightBody;
        if (mInputs.empty() || body.empty()) return false;
        using Kind = FunctionDecl::Statement::Kind;
        const FunctionDecl::Statement& last = body.back();
        if (last.kind != Kind::Return) return false;
        const Expr* returned = nullptr;  // a position returned as the function's value
        if (last.hasValue) {
            if (writesInput(last.value)) return false;
            if (isPositionOutput(function.returnSemantic)) {
                returned = &last.value;
            } else if (function.returnType.base == BaseType::Struct &&
                       last.value.kind == Expr::Kind::Identifier) {
                const StructMember* m = positionMember(mEffect, function.returnType.structName, true);
                if (!m) return false;
                mOutputs.push_back({last.value.text, m->name});
            } else {
                return false;
            }
        }
        // Exactly one place the position leaves by.
        if (mOutputs.size() + (returned ? 1 : 0) != 1) return false;
        for (size_t i = 0; i + 1 < body.size(); ++i) {
            const FunctionDecl::Statement& s = body[i];
            if (s.kind == Kind::Declare) {
                if (isInputBase(s.name) || (s.hasValue && writesInput(s.value))) return false;
                if (!mOutputs.empty() && s.name == mOutputs.front().base) mPosition = {};
                continue;
            }
            if (s.kind != Kind::Assign || !write(s)) return false;
        }
        if (returned) {
            const std::optional<std::vector<Component>> parts = components(*returned);
            if (!parts || parts->size() != 4) return false;
            std::copy(parts->begin(), parts->end(), mPosition.begin());
        }
        return passedThrough();
    }

private:
    struct Place {
        std::string base;
        std::string member;  // "" for the whole variable
        int cols = 0;        // an input's components
    };

    // Whether `e` names the place: the variable, or its member.
    static bool names(const Expr& e, const Place& place) {
        if (place.member.empty()) return isIdentifier(e, place.base);
        return e.kind == Expr::Kind::Member && e.text == place.member && e.args.size() == 1 &&
               isIdentifier(e.args[0], place.base);
    }

    bool isInputBase(const std::string& name) const {
        return std::find(mInputBases.begin(), mInputBases.end(), name) != mInputBases.end();
    }

    // Whether `e` hands an input to one of the effect's functions, which may write it (`inout`).
    bool writesInput(const Expr& e) const {
        if (e.kind == Expr::Kind::Call && !mEffect.findFunctions(e.text).empty())
            for (const Expr& arg : e.args)
                if (const Expr& root = rootOf(arg);
                    root.kind == Expr::Kind::Identifier && isInputBase(root.text))
                    return true;
        for (const Expr& arg : e.args)
            if (writesInput(arg)) return true;
        return false;
    }

    bool isPosition(const Expr& e) const { return names(e, mOutputs.front()); }

    // Follows an assignment: false where it writes an input; what it writes of the position, component
    // by component (a component it writes otherwise than from the input or a constant becomes Unknown).
    bool write(const FunctionDecl::Statement& s) {
        const Expr& root = rootOf(s.target);
        if (root.kind == Expr::Kind::Identifier && isInputBase(root.text)) return false;
        if (writesInput(s.value)) return false;
        if (mOutputs.empty()) return true;
        const Place& out = mOutputs.front();
        std::vector<int> written;     // the position's components this statement writes
        bool followed = s.op == "=";  // whether the value written is read (else the components are Unknown)
        if (isPosition(s.target)) {
            written = {0, 1, 2, 3};
        } else if (s.target.kind == Expr::Kind::Member && s.target.args.size() == 1 &&
                   isPosition(s.target.args[0])) {
            written = swizzle(s.target.text);
            if (written.empty()) {  // not a swizzle
                written = {0, 1, 2, 3};
                followed = false;
            }
        } else if (isIdentifier(root, out.base)) {
            // The struct holding the position written whole (`o = (VSOut)0;`), a part of the position
            // indexed (`o.Pos[0]`), or another member of the struct (`o.Tex = ...`).
            const bool otherMember = !out.member.empty() && s.target.kind != Expr::Kind::Identifier &&
                                     !writesPositionMember(s.target);
            if (!otherMember) set({0, 1, 2, 3}, std::nullopt);
            return true;
        } else {
            return true;  // another variable
        }
        set(written, followed ? components(s.value) : std::nullopt);
        return true;
    }

    // Whether an l-value under the position's struct reaches the position member.
    bool writesPositionMember(const Expr& target) const {
        for (const Expr* e = &target; !e->args.empty(); e = &e->args[0])
            if (e->kind == Expr::Kind::Member && isPosition(*e)) return true;
        return false;
    }

    // Gives `written` the components of `value` (one each, or one broadcast); Unknown without.
    void set(const std::vector<int>& written, const std::optional<std::vector<Component>>& value) {
        for (size_t i = 0; i < written.size(); ++i) {
            Component c;
            if (value && value->size() == written.size())
                c = (*value)[i];
            else if (value && value->size() == 1)
                c = value->front();
            mPosition[static_cast<size_t>(written[i])] = c;
        }
    }

    const Place* input(const Expr& e) const {
        for (const Place& in : mInputs)
            if (names(e, in)) return &in;
        return nullptr;
    }

    // Where each component of `e` comes from: the input position, its swizzle, a number, or a vector
    // constructor of those; nullopt for anything else.
    std::optional<std::vector<Component>> components(const Expr& e) const {
        if (const Place* in = input(e)) {
            std::vector<Component> out;
            for (int i = 0; i < in->cols; ++i) out.push_back({Component::Kind::Input, i, 0.0});
            return out;
        }
        if (e.kind == Expr::Kind::Member && e.args.size() == 1) {
            const Place* in = input(e.args[0]);
            const std::vector<int> indices = swizzle(e.text);
            if (!in || indices.empty()) return std::nullopt;
            std::vector<Component> out;
            for (int i : indices) {
                if (i >= in->cols) return std::nullopt;
                out.push_back({Component::Kind::Input, i, 0.0});
            }
            return out;
        }
        if (e.kind == Expr::Kind::Number)
            return std::vector<Component>{{Component::Kind::Constant, 0, e.number}};
        if (e.kind == Expr::Kind::Call && (e.text == "float2" || e.text == "float3" || e.text == "float4")) {
            std::vector<Component> out;
            for (const Expr& arg : e.args) {
                const std::optional<std::vector<Component>> part = components(arg);
                if (!part) return std::nullopt;
                out.insert(out.end(), part->begin(), part->end());
            }
            if (out.size() != static_cast<size_t>(e.text.back() - '0')) return std::nullopt;
            return out;
        }
        return std::nullopt;
    }

    // x and y the input's; z the input's or a depth in [0, 1]; w the input's or 1.
    bool passedThrough() const {
        const auto from = [this](size_t i) {
            return mPosition[i].kind == Component::Kind::Input && mPosition[i].index == static_cast<int>(i);
        };
        const auto constant = [this](size_t i, double lo, double hi) {
            return mPosition[i].kind == Component::Kind::Constant && mPosition[i].value >= lo &&
                   mPosition[i].value <= hi;
        };
        return from(0) && from(1) && (from(2) || constant(2, 0.0, 1.0)) && (from(3) || constant(3, 1.0, 1.0));
    }

    const Effect& mEffect;
    const FunctionDecl& mFunction;
    std::vector<Place> mInputs;
    std::vector<std::string> mInputBases;  // every varying input parameter's name
    std::vector<Place> mOutputs;
    std::array<Component, 4> mPosition{};  // the position output's components, as last written
};

}  // namespace

bool passesPositionThrough(const Effect& effect, const FunctionDecl& function) {
    return PassThroughReader(effect, function).read();
}

}  // namespace fx::detail
