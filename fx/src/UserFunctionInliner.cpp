// UserFunctionInliner: user-function calls in host-evaluated expressions become expressions (see the
// header). Each parameter and local becomes its value's expression, converted to the declared type by a
// cast, so that `float3 c = 1;` or an int parameter truncates exactly as the function would.
#include "UserFunctionInliner.h"

#include <map>

namespace fx::detail {

namespace {

// Functions call functions; a recursive one (which HLSL forbids anyway) must not recurse here.
constexpr int kMaxInlineDepth = 16;
// Every use of a parameter copies its argument, so nested calls grow the expression geometrically; past
// this many nodes in all, the rest of the calls stay calls (and are reported where they stand).
constexpr int kMaxInlinedNodes = 1 << 16;

class Inliner {
public:
    explicit Inliner(const Effect& effect) : mEffect(effect) {}

    // Rewrites calls inside `e`, bottom-up.
    void rewrite(Expr& e, int depth = 0) {
        if (e.kind == Expr::Kind::Compile) {  // the entry point itself is no call; its arguments are
            for (Expr& arg : e.args) rewrite(arg, depth);
            return;
        }
        for (Expr& arg : e.args) rewrite(arg, depth);
        if (e.kind != Expr::Kind::Call || depth >= kMaxInlineDepth) return;
        const FunctionDecl* function = find(e.text, e.args.size());
        if (!function) return;
        std::optional<Expr> inlined = expand(*function, e, depth);
        if (inlined) e = std::move(*inlined);
    }

private:
    const FunctionDecl* find(const std::string& name, size_t arguments) const {
        for (const FunctionDecl& f : mEffect.functions) {
            if (f.name != name || !f.hasBody || f.straightBody.empty() || f.params.size() != arguments)
                continue;
            bool plain = true;
            for (const FunctionParam& p : f.params)
                plain = plain && p.direction == FunctionParam::Direction::In && !p.isUniform;
            if (plain) return &f;
        }
        return nullptr;
    }

    static Expr cast(const TypeDesc& type, Expr value, const SourceLoc& loc) {
        Expr e;
        e.kind = Expr::Kind::Cast;
        e.loc = loc;
        e.castType = type;
        e.args.push_back(std::move(value));
        return e;
    }

    // The nodes of `e`, counted up to `limit`.
    static int nodes(const Expr& e, int limit) {
        int count = 1;
        for (const Expr& arg : e.args) {
            if (count > limit) break;
            count += nodes(arg, limit - count);
        }
        return count;
    }

    // `e` with every name bound in `scope` replaced by its expression, and calls inlined.
    Expr substitute(const Expr& e, const std::map<std::string, Expr>& scope, int depth) {
        --mBudget;
        if (e.kind == Expr::Kind::Identifier) {
            auto bound = scope.find(e.text);
            if (bound != scope.end()) {
                mBudget -= nodes(bound->second, mBudget);
                return bound->second;
            }
        }
        Expr out = e;
        for (size_t i = 0; i < out.args.size(); ++i) out.args[i] = substitute(e.args[i], scope, depth);
        if (out.kind == Expr::Kind::Call) rewrite(out, depth + 1);
        return out;
    }

    std::optional<Expr> expand(const FunctionDecl& function, const Expr& call, int depth) {
        using Statement = FunctionDecl::Statement;
        if (mBudget <= 0) return std::nullopt;
        std::map<std::string, Expr> scope;
        std::map<std::string, TypeDesc> types;
        for (size_t i = 0; i < function.params.size(); ++i) {
            const FunctionParam& p = function.params[i];
            scope[p.name] = cast(p.type, call.args[i], call.loc);
            types[p.name] = p.type;
        }
        for (const Statement& statement : function.straightBody) {
            switch (statement.kind) {
                case Statement::Kind::Declare:
                    if (!statement.hasValue) return std::nullopt;  // an uninitialized local: not a value
                    scope[statement.name] =
                        cast(statement.type, substitute(statement.value, scope, depth), call.loc);
                    types[statement.name] = statement.type;
                    break;
                case Statement::Kind::Assign: {
                    auto type = types.find(statement.name);
                    if (type == types.end()) return std::nullopt;  // assigns a global: not ours to fold
                    Expr value = substitute(statement.value, scope, depth);
                    if (statement.op != "=") {
                        Expr combined;
                        combined.kind = Expr::Kind::Binary;
                        combined.loc = call.loc;
                        combined.text = statement.op.substr(0, 1);
                        combined.args.push_back(scope[statement.name]);
                        combined.args.push_back(std::move(value));
                        value = std::move(combined);
                    }
                    scope[statement.name] = cast(type->second, std::move(value), call.loc);
                    break;
                }
                case Statement::Kind::Return: {
                    Expr result =
                        cast(function.returnType, substitute(statement.value, scope, depth), call.loc);
                    if (mBudget <= 0) return std::nullopt;
                    return result;
                }
            }
        }
        return std::nullopt;
    }

    const Effect& mEffect;
    int mBudget = kMaxInlinedNodes;
};

}  // namespace

void inlineUserFunctionCalls(Effect& effect) {
    Inliner inliner(effect);
    for (Technique& technique : effect.techniques)
        for (Pass& pass : technique.passes)
            for (StateAssignment& state : pass.states) inliner.rewrite(state.value);
    for (Parameter& parameter : effect.parameters)
        if (parameter.initializer && parameter.type.isShader()) inliner.rewrite(*parameter.initializer);
}

}  // namespace fx::detail
