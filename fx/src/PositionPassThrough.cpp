// PositionPassThrough: see PositionPassThrough.h.
//
// A D3D10 post-processing pass has a vertex shader of its own (the DirectX SDK's `QuadVS`:
// `Output.Pos = Input.Pos;`), where a D3D9 one had none: its application drew a screen quad in clip
// space through it. The shader says nothing else about the quad, so the compiler reads its body: a
// position that arrives unchanged is such a pass's mark. Read on the effect's own syntax tree, before
// glslang's entry-point wrapper and copies hide it.
#include "PositionPassThrough.h"

#include "CaseFolding.h"

#include <fx/VertexStreams.h>

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

// The member of struct `name` that carries `semantic`'s kind of position, or null.
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

bool isMemberOf(const Expr& e, const std::string& base, const std::string& member) {
    return e.kind == Expr::Kind::Member && e.text == member && e.args.size() == 1 &&
           isIdentifier(e.args[0], base);
}

class PassThroughReader {
public:
    PassThroughReader(const Effect& effect, const FunctionDecl& function) : mEffect(effect) {
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
        }
    }

    bool read(const FunctionDecl& function) {
        const std::vector<FunctionDecl::Statement>& body = function.straightBody;
        if (mInputs.empty() || body.empty()) return false;
        using Kind = FunctionDecl::Statement::Kind;
        const FunctionDecl::Statement& last = body.back();
        if (last.kind != Kind::Return) return false;
        if (last.hasValue) {
            if (isPositionOutput(function.returnSemantic)) {
                mReturned = &last.value;
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
        if (mOutputs.size() + (mReturned ? 1 : 0) != 1) return false;
        for (size_t i = 0; i + 1 < body.size(); ++i) {
            const FunctionDecl::Statement& s = body[i];
            if (s.kind == Kind::Declare) {
                if (!mOutputs.empty() && s.name == mOutputs.front().base) mWritten = nullptr;
                continue;
            }
            if (s.kind != Kind::Assign || !write(s)) return false;
        }
        const Expr* position = mReturned ? mReturned : mWritten;
        return position && passedThrough(*position);
    }

private:
    struct Place {
        std::string base;
        std::string member;  // "" for the whole variable
        int cols = 0;        // an input's components
    };

    // Records an assignment to the position output; false where one writes part of it (or the whole
    // struct holding it), which this reader does not follow.
    bool write(const FunctionDecl::Statement& s) {
        if (mOutputs.empty()) return true;
        const Place& out = mOutputs.front();
        const bool whole = out.member.empty() ? isIdentifier(s.target, out.base)
                                              : isMemberOf(s.target, out.base, out.member);
        if (whole) {
            if (s.op != "=") return false;
            mWritten = &s.value;
            return true;
        }
        // Another variable, or another member of the struct holding the position, may be written; not
        // the struct as a whole (`o = (VSOut)0;`) nor a part of the position (`o.Pos.z = 0;`).
        const Expr* root = &s.target;
        const Expr* rootMember = nullptr;  // the member of the root variable the target lies in
        while ((root->kind == Expr::Kind::Member || root->kind == Expr::Kind::Index) && !root->args.empty()) {
            if (root->kind == Expr::Kind::Member) rootMember = root;
            root = &root->args[0];
        }
        if (!isIdentifier(*root, out.base)) return true;
        return !out.member.empty() && rootMember && rootMember->text != out.member;
    }

    const Place* input(const Expr& e) const {
        for (const Place& in : mInputs)
            if (in.member.empty() ? isIdentifier(e, in.base) : isMemberOf(e, in.base, in.member)) return &in;
        return nullptr;
    }

    // The input position whole (a float4: HLSL widens no float3 to it), or its leading components
    // completed by constants in a float4 constructor.
    bool passedThrough(const Expr& e) const {
        if (const Place* in = input(e)) return in->cols == 4;
        if (e.kind != Expr::Kind::Call || e.text != "float4" || e.args.empty()) return false;
        int components = 0;
        const Expr& first = e.args[0];
        if (const Place* in = input(first)) {
            components = in->cols;
        } else if (first.kind == Expr::Kind::Member && first.args.size() == 1 && input(first.args[0]) &&
                   (first.text == "xy" || first.text == "xyz" || first.text == "rg" || first.text == "rgb")) {
            components = static_cast<int>(first.text.size());
        } else {
            return false;
        }
        for (size_t i = 1; i < e.args.size(); ++i) {
            if (e.args[i].kind != Expr::Kind::Number) return false;
            ++components;
        }
        return components == 4;
    }

    const Effect& mEffect;
    std::vector<Place> mInputs;
    std::vector<Place> mOutputs;
    const Expr* mReturned = nullptr;  // a position returned as the function's value
    const Expr* mWritten = nullptr;   // the last value written to the position output
};

}  // namespace

bool passesPositionThrough(const Effect& effect, const FunctionDecl& function) {
    PassThroughReader reader(effect, function);
    return reader.read(function);
}

}  // namespace fx::detail
