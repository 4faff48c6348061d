// UserFunctionInliner: user-function calls in host-evaluated expressions become expressions (see the
// header). Each parameter and local becomes its value's expression, converted to the declared type by a
// cast, so that `float3 c = 1;` or an int parameter truncates exactly as the function would. An array or
// struct is an aggregate: an InitList whose castType is its type and whose args are its elements or
// members, each such an expression; reading a part picks it (by a select on the index where the index
// reads a parameter), writing one rebuilds the aggregate, and a select between two aggregates is the
// aggregate of the selects of their parts, so that the host evaluator sees no struct, and an array only
// as the initializer list it already reads.
#include "UserFunctionInliner.h"

#include "ComponentWrites.h"
#include "ComposedIntrinsics.h"
#include "ConstantFolding.h"

#include <fx/Diagnostics.h>
#include <fx/Preshader.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace fx::detail {

namespace {

// Functions call functions; a recursive one (which HLSL forbids anyway) must not recurse here.
constexpr int kMaxInlineDepth = 16;
// Every use of a parameter copies its argument, so nested calls grow the expression geometrically; past
// this many nodes in one host expression, the rest of its calls stay calls (and are reported where they
// stand). rgb_to_hsv of FX Composer's colour-space include ends at about 23000 nodes, having copied some
// 70000 on the way.
constexpr int kMaxInlinedNodes = 1 << 18;
// A loop is unrolled for at most this many iterations (fxc's own limit for unrolling was 1024).
constexpr int kMaxLoopIterations = 1024;

class Inliner {
public:
    Inliner(const Effect& effect, DiagnosticSink& diagnostics) : mEffect(effect), mDiagnostics(diagnostics) {}

    // Rewrites a whole host expression (rewrite()), with a budget of its own.
    void rewriteExpression(Expr& e, bool expandStatics) {
        mBudget = kMaxInlinedNodes;
        rewrite(e, 0, expandStatics);
    }

    // Rewrites calls inside `e`, bottom-up, and, if `expandStatics`, names of statics.
    void rewrite(Expr& e, int depth = 0, bool expandStatics = true) {
        if (e.kind == Expr::Kind::Compile) {  // the entry point itself is no call; its arguments are
            for (Expr& arg : e.args) rewrite(arg, depth, expandStatics);
            return;
        }
        if (expandStatics && e.kind == Expr::Kind::Identifier && depth < kMaxInlineDepth) {
            if (const Parameter* computed = staticValue(e.text)) {
                e = cast(computed->type, *computed->initializer, e.loc);
                rewrite(e, depth + 1, expandStatics);
            }
            return;
        }
        for (Expr& arg : e.args) rewrite(arg, depth, expandStatics);
        if (e.kind != Expr::Kind::Call) {
            project(e);
            return;
        }
        if (depth >= kMaxInlineDepth) return;
        const FunctionDecl* function = find(e.text, e.args.size());
        if (!function) {
            if (mEffect.findFunctions(e.text).empty()) expandComposedIntrinsic(e);
            return;
        }
        // A function that writes its arguments is inlined where a statement calls it (hoist()).
        if (writesArguments(*function) || !returnsValue(function->returnType)) return;
        if (depth == 0) mLoopFailure.reset();
        std::optional<Outcome> inlined = expand(*function, e.args, e.loc, depth);
        if (inlined) e = std::move(*inlined->value);
        // A loop no host could unroll: said where the host expression calls the function, naming the loop.
        if (depth == 0 && mLoopFailure) {
            std::vector<std::string> args{e.text, mLoopFailure->loc.str()};
            if (mLoopFailure->id == DiagId::HostLoopIterationLimit)
                args.push_back(std::to_string(kMaxLoopIterations));
            mDiagnostics.report(mLoopFailure->id, e.loc, args);
            mLoopFailure.reset();
        }
    }

private:
    // A `static` global computed from others (`static float2 TexelOffsets = Offset / ScreenSize;`): D3DX
    // recomputed it whenever an input changed, a bound semantic such as VIEWPORTPIXELSIZE included. Its
    // slot holds the value of the defaults only, so a host expression that reads it reads the
    // initializer instead, and the runtime re-runs that expression when an input changes.
    const Parameter* staticValue(const std::string& name) const {
        const Parameter* p = mEffect.findParameter(name);
        if (!p || !p->isStatic || !p->initializer || !p->type.isNumeric() ||
            p->initializer->kind == Expr::Kind::Compile)
            return nullptr;
        return p;
    }

    const FunctionDecl* find(const std::string& name, size_t arguments) const {
        for (const FunctionDecl& f : mEffect.functions)
            if (f.name == name && f.hasBody && !f.straightBody.empty() && f.params.size() == arguments)
                return &f;
        return nullptr;
    }

    static bool writesArguments(const FunctionDecl& function) {
        return std::any_of(function.params.begin(), function.params.end(), [](const FunctionParam& p) {
            return p.direction != FunctionParam::Direction::In;
        });
    }
    static bool returnsValue(const TypeDesc& type) {
        return type.base != BaseType::Void || !type.arrayDims.empty();
    }

    static Expr cast(const TypeDesc& type, Expr value, const SourceLoc& loc) {
        Expr e;
        e.kind = Expr::Kind::Cast;
        e.loc = loc;
        e.castType = type;
        e.args.push_back(std::move(value));
        return e;
    }

    static Expr integer(size_t value, const SourceLoc& loc) {
        Expr e;
        e.kind = Expr::Kind::Number;
        e.number = static_cast<double>(value);
        e.isInteger = true;
        e.loc = loc;
        return e;
    }

    // [SECTION] Aggregates: arrays and structs (see the file's comment)

    static bool isAggregate(const Expr& e) {
        return e.kind == Expr::Kind::InitList &&
               (!e.castType.arrayDims.empty() || e.castType.base == BaseType::Struct);
    }

    // The parts of an array (its elements, named "") or a struct (its members); none for any other type,
    // an unsized array or a struct the effect does not declare.
    std::optional<std::vector<std::pair<std::string, TypeDesc>>> partsOf(const TypeDesc& type) const {
        std::vector<std::pair<std::string, TypeDesc>> parts;
        if (!type.arrayDims.empty()) {
            if (type.arrayDims[0] <= 0) return std::nullopt;
            TypeDesc element = type;
            element.arrayDims.erase(element.arrayDims.begin());
            parts.assign(static_cast<size_t>(type.arrayDims[0]), {"", element});
            return parts;
        }
        const StructDecl* decl =
            type.base == BaseType::Struct ? mEffect.findStruct(type.structName) : nullptr;
        if (!decl || decl->members.empty()) return std::nullopt;
        for (const StructMember& m : decl->members) parts.emplace_back(m.name, m.type);
        return parts;
    }

    static bool isAggregateType(const TypeDesc& type) {
        return !type.arrayDims.empty() || type.base == BaseType::Struct;
    }

    static Expr aggregate(const TypeDesc& type, std::vector<Expr> parts, const SourceLoc& loc) {
        Expr e = exprNode(Expr::Kind::InitList, loc, "", std::move(parts));
        e.castType = type;
        return e;
    }

    // Every number of `type` the scalar `value` (`(S)0`, a local declared without a value).
    std::optional<Expr> broadcast(const TypeDesc& type, const Expr& value, const SourceLoc& loc) {
        if (!isAggregateType(type)) return cast(type, value, loc);
        const auto parts = partsOf(type);
        if (!parts) return std::nullopt;
        std::vector<Expr> pieces;
        for (const auto& part : *parts) {
            std::optional<Expr> piece = broadcast(part.second, value, loc);
            if (!piece) return std::nullopt;
            pieces.push_back(std::move(*piece));
        }
        return aggregate(type, std::move(pieces), loc);
    }

    // `value` as a local of `type` holds it: a number cast to the type; an array or struct an aggregate of
    // its parts, so converted, from an aggregate or initializer list (a flat one too: `float2 w[2] = {1, 2,
    // 3, 4};`), a cast of a scalar, or a parameter's parts where they stand. None where the host cannot
    // take the value apart.
    std::optional<Expr> typed(const TypeDesc& type, Expr value, const SourceLoc& loc) {
        if (!isAggregateType(type)) return cast(type, std::move(value), loc);
        const auto parts = partsOf(type);
        if (!parts) return std::nullopt;
        if (value.kind == Expr::Kind::Cast && value.args.size() == 1 && isAggregateType(value.castType)) {
            // `(S)0` spreads the scalar; `(S)s` converts an aggregate.
            const bool whole = value.args[0].kind == Expr::Kind::InitList;
            std::optional<Expr> converted = whole ? typed(value.castType, value.args[0], loc)
                                                  : broadcast(value.castType, value.args[0], loc);
            if (!converted) return std::nullopt;
            value = std::move(*converted);
        }
        std::vector<Expr> pieces;
        if (value.kind == Expr::Kind::InitList && value.args.size() == parts->size()) {
            pieces = std::move(value.args);
        } else if (value.kind == Expr::Kind::InitList) {
            size_t next = 0;
            for (const auto& part : *parts) {
                const size_t count = static_cast<size_t>(part.second.componentCount());
                if (isAggregateType(part.second) || !part.second.isNumeric() ||
                    next + count > value.args.size())
                    return std::nullopt;
                std::vector<Expr> numbers(value.args.begin() + static_cast<long>(next),
                                          value.args.begin() + static_cast<long>(next + count));
                next += count;
                pieces.push_back(
                    count == 1 ? std::move(numbers[0])
                               : exprNode(Expr::Kind::Call, loc, part.second.hlslName(), std::move(numbers)));
            }
            if (next != value.args.size()) return std::nullopt;
        } else if (value.kind == Expr::Kind::Identifier && mEffect.findParameter(value.text)) {
            for (size_t i = 0; i < parts->size(); ++i)
                pieces.push_back((*parts)[i].first.empty()
                                     ? exprNode(Expr::Kind::Index, loc, "", {value, integer(i, loc)})
                                     : exprNode(Expr::Kind::Member, loc, (*parts)[i].first, {value}));
        } else {
            return std::nullopt;
        }
        for (size_t i = 0; i < pieces.size(); ++i) {
            std::optional<Expr> piece = typed((*parts)[i].second, std::move(pieces[i]), loc);
            if (!piece) return std::nullopt;
            pieces[i] = std::move(*piece);
        }
        return aggregate(type, std::move(pieces), loc);
    }

    static Expr equals(const Expr& index, size_t value, const SourceLoc& loc) {
        return exprNode(Expr::Kind::Binary, loc, "==", {index, integer(value, loc)});
    }

    // `condition ? a : b`, part by part where both are aggregates; `a` where both are the same.
    Expr choose(const Expr& condition, Expr a, Expr b, const SourceLoc& loc) {
        if (same(a, b)) return a;
        if (isAggregate(a) && isAggregate(b) && a.args.size() == b.args.size()) {
            for (size_t i = 0; i < a.args.size(); ++i)
                a.args[i] = choose(condition, std::move(a.args[i]), std::move(b.args[i]), loc);
            return a;
        }
        return exprNode(Expr::Kind::Ternary, loc, "", {condition, std::move(a), std::move(b)});
    }

    // Element `index` of the aggregate array `whole`: the element where the index is known, else a chain of
    // selects on its value; none for a known index out of range (the evaluator reports it).
    std::optional<Expr> element(const Expr& whole, const Expr& index, const SourceLoc& loc) {
        double k = 0;
        if (constant(index, k)) {
            if (k < 0 || k >= static_cast<double>(whole.args.size()) || k != std::trunc(k))
                return std::nullopt;
            return whole.args[static_cast<size_t>(k)];
        }
        Expr chosen = whole.args.back();
        for (size_t i = whole.args.size() - 1; i-- > 0;)
            chosen = choose(equals(index, i, loc), whole.args[i], std::move(chosen), loc);
        return counted(std::move(chosen));
    }

    // A part of an aggregate read (`s.colour`, `w[2]`, `w[i]`) becomes that part; a select between two
    // aggregates, the aggregate of the selects.
    void project(Expr& e) {
        if (e.kind == Expr::Kind::Ternary && e.args.size() == 3 && isAggregate(e.args[1]) &&
            isAggregate(e.args[2])) {
            Expr chosen = choose(e.args[0], std::move(e.args[1]), std::move(e.args[2]), e.loc);
            e = std::move(chosen);
            return;
        }
        if (e.args.empty() || !isAggregate(e.args[0])) return;
        Expr& whole = e.args[0];
        if (e.kind == Expr::Kind::Member && whole.castType.arrayDims.empty()) {
            const auto parts = partsOf(whole.castType);
            for (size_t i = 0; parts && i < parts->size(); ++i) {
                if ((*parts)[i].first != e.text) continue;
                Expr part = std::move(whole.args[i]);
                e = std::move(part);
                return;
            }
        } else if (e.kind == Expr::Kind::Index && !whole.castType.arrayDims.empty()) {
            if (std::optional<Expr> part = element(whole, e.args[1], e.loc)) e = std::move(*part);
        }
    }

    // `old`, a value of `type`, with the part that `path[at..]` names (Member and Index nodes, from the
    // local outwards) replaced by `value`; none where the host cannot say which part that is.
    std::optional<Expr> assignAt(Expr old, const TypeDesc& type, const std::vector<const Expr*>& path,
                                 size_t at, const Expr& value, const std::map<std::string, Expr>& scope,
                                 int depth, const SourceLoc& loc) {
        if (at == path.size()) return typed(type, value, loc);
        const Expr& part = *path[at];
        const auto parts = partsOf(type);
        if (part.kind == Expr::Kind::Member) {
            if (!parts) {
                if (at + 1 != path.size()) return std::nullopt;
                if (type.shape == Shape::Matrix) {
                    std::optional<Expr> written = writeMatrixElements(type, part.text, old, value, loc);
                    if (written) written = counted(std::move(*written));
                    return written;
                }
                return writeComponents(type, part.text, std::move(old), value, loc);
            }
            if (!isAggregate(old) || !type.arrayDims.empty()) return std::nullopt;
            for (size_t i = 0; i < parts->size(); ++i) {
                if ((*parts)[i].first != part.text) continue;
                std::optional<Expr> written =
                    assignAt(old.args[i], (*parts)[i].second, path, at + 1, value, scope, depth, loc);
                if (!written) return std::nullopt;
                old.args[i] = std::move(*written);
                return old;
            }
            return std::nullopt;
        }
        if (part.kind != Expr::Kind::Index) return std::nullopt;
        const Expr index = substitute(part.args[1], scope, depth);
        double k = 0;
        const bool known = constant(index, k);
        if (known && (k < 0 || k != std::trunc(k))) return std::nullopt;
        const size_t written = known ? static_cast<size_t>(k) : 0;
        if (parts && !type.arrayDims.empty()) {  // an array's element
            if (!isAggregate(old) || (known && written >= old.args.size())) return std::nullopt;
            for (size_t i = 0; i < old.args.size(); ++i) {
                if (known && i != written) continue;
                std::optional<Expr> element =
                    assignAt(old.args[i], (*parts)[i].second, path, at + 1, value, scope, depth, loc);
                if (!element) return std::nullopt;
                old.args[i] = counted(
                    known ? std::move(*element)
                          : choose(equals(index, i, loc), std::move(*element), std::move(old.args[i]), loc));
            }
            return old;
        }
        if (type.shape == Shape::Vector && known && written < static_cast<size_t>(type.cols) &&
            at + 1 == path.size())
            return writeComponents(type, std::string(1, "xyzw"[written]), std::move(old), value, loc);
        if (type.shape != Shape::Matrix || (known && written >= static_cast<size_t>(type.rows)))
            return std::nullopt;
        // A matrix's row.
        const TypeDesc row = matrixRowType(type);
        std::vector<Expr> rows = matrixRows(type, old, loc);
        for (size_t r = 0; r < rows.size(); ++r) {
            if (known && r != written) continue;
            std::optional<Expr> changed = assignAt(rows[r], row, path, at + 1, value, scope, depth, loc);
            if (!changed) return std::nullopt;
            rows[r] = known ? std::move(*changed)
                            : choose(equals(index, r, loc), std::move(*changed), std::move(rows[r]), loc);
        }
        return counted(exprNode(Expr::Kind::Call, loc, type.hlslName(), std::move(rows)));
    }

    // `e`'s value where it reads no parameter: exactly as the host evaluates it, or, for the effect's
    // `static const` scalars, as the parser folds them.
    bool constant(const Expr& e, double& out) const {
        const std::optional<Value> value = evaluate(
            e, [](std::string_view) { return nullptr; }, nullptr, nullptr);
        if (value && value->data.size() == 1) {
            out = value->data[0];
            return true;
        }
        return foldConstant(mEffect, e, out);
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
        if (out.kind == Expr::Kind::Call)
            rewrite(out, depth + 1);
        else
            project(out);
        return out;
    }

    // The function's locals (parameters included) as expressions over the call's arguments, with their
    // declared types, and how often a branch assigned each name of the enclosing scope. Inside a loop,
    // `values` are those of the path that has neither left the loop nor skipped to its next iteration:
    // `path` is when that path runs (none: always), `dead` that no path reaches here (after a `break` or
    // `continue` the branch took for certain).
    struct Locals {
        std::map<std::string, Expr> values;
        std::map<std::string, TypeDesc> types;
        std::map<std::string, int> assigned;
        std::optional<Expr> path;
        bool dead = false;
    };

    // Where the paths that left the innermost loop being unrolled went: `break` ends the loop with the
    // values it had, `continue` resumes at the step with them. Each is a select on the path that took it,
    // so that the paths still running keep their own values, a loop counter a literal among them.
    struct Exit {
        std::optional<Expr> taken;  // when some path took it (none: no path did)
        std::map<std::string, Expr> values;
    };
    struct LoopExits {
        Exit broken, continued;
    };

    static bool same(const Expr& a, const Expr& b) {
        if (a.kind != b.kind || a.text != b.text || a.number != b.number || a.isInteger != b.isInteger ||
            a.args.size() != b.args.size() ||
            ((a.kind == Expr::Kind::Cast || a.kind == Expr::Kind::InitList) &&
             (a.castType.hlslName() != b.castType.hlslName() ||
              a.castType.arrayDims != b.castType.arrayDims)))
            return false;
        for (size_t i = 0; i < a.args.size(); ++i)
            if (!same(a.args[i], b.args[i])) return false;
        return true;
    }

    // `copy`, a copy just made, its nodes taken from the budget.
    Expr counted(Expr copy) {
        mBudget -= nodes(copy, std::max(mBudget, 0));
        return copy;
    }

    // `condition ? a : b` (choose()); `a` where both are the same expression (a counter no path changed).
    Expr select(const std::optional<Expr>& condition, Expr a, Expr b, const SourceLoc& loc) {
        if (!condition || same(a, b)) return a;
        return counted(choose(*condition, std::move(a), std::move(b), loc));
    }

    static Expr truth(bool value, const SourceLoc& loc) {
        Expr e;
        e.kind = Expr::Kind::Bool;
        e.number = value ? 1.0 : 0.0;
        e.loc = loc;
        return e;
    }

    // `a && b`, `a || b` over paths, where none is "always".
    std::optional<Expr> both(const std::optional<Expr>& a, Expr b, const SourceLoc& loc) {
        if (!a) return b;
        return counted(exprNode(Expr::Kind::Binary, loc, "&&", {*a, std::move(b)}));
    }
    std::optional<Expr> either(const std::optional<Expr>& a, const std::optional<Expr>& b,
                               const SourceLoc& loc) {
        if (!a || !b) return std::nullopt;
        return counted(exprNode(Expr::Kind::Binary, loc, "||", {*a, *b}));
    }

    // A path of `locals` leaves by `exit` (a `break` or `continue`): where the path runs, the exit's
    // values become its values. The path ends here.
    void leave(Exit& exit, Locals& locals, const SourceLoc& loc) {
        ++mExitsTaken;
        if (!exit.taken) {
            exit.values = locals.values;
            for (const auto& [name, value] : exit.values) mBudget -= nodes(value, std::max(mBudget, 0));
            exit.taken = locals.path ? *locals.path : truth(true, loc);
        } else {
            for (auto& [name, value] : exit.values) {
                auto current = locals.values.find(name);
                if (current != locals.values.end())
                    value = select(locals.path, current->second, std::move(value), loc);
            }
            exit.taken = locals.path ? either(exit.taken, locals.path, loc) : truth(true, loc);
        }
        locals.dead = true;
    }

    // `name` after `if (condition) then else otherwise`: `condition ? then : otherwise`. When one branch
    // only wrote some components, once (`if (h.x < 0) h.x += 1;`), the condition joins that write's mask
    // instead, so the old value is copied once rather than on both sides: chains of such branches
    // (rgb_to_hsv) would otherwise grow as a power of two.
    Expr merge(const Expr& condition, const std::string& name, Locals& then, Locals& otherwise,
               const SourceLoc& loc) {
        const auto once = [&](const Locals& branch) {
            auto it = branch.assigned.find(name);
            return it != branch.assigned.end() && it->second == 1;
        };
        const auto untouched = [&](const Locals& branch) { return !branch.assigned.count(name); };
        for (const bool inThen : {true, false}) {
            Locals& written = inThen ? then : otherwise;
            Expr& value = written.values[name];
            if (!once(written) || !untouched(inThen ? otherwise : then) ||
                value.kind != Expr::Kind::Ternary || value.text != kComponentSelect)
                continue;
            Expr taken = condition;
            if (!inThen) taken = exprNode(Expr::Kind::Unary, loc, "!", {std::move(taken)});
            value.args[0] =
                exprNode(Expr::Kind::Binary, loc, "&&", {std::move(value.args[0]), std::move(taken)});
            return value;
        }
        return choose(condition, then.values[name], otherwise.values[name], loc);
    }

    // [SECTION] Statements

    // What an inlined call gives: its value (none for a void function) and the last values of its `out`
    // and `inout` parameters.
    struct Outcome {
        std::optional<Expr> value;
        std::map<std::string, Expr> outs;
    };

    // `target op= value` over `locals`: the local the target names, or its part, written.
    bool assign(const Expr& target, const std::string& op, Expr value, Locals& locals,
                const std::set<std::string>& declaredHere, int depth, const SourceLoc& loc) {
        std::vector<const Expr*> path;
        const Expr* root = &target;
        for (; root->kind == Expr::Kind::Member || root->kind == Expr::Kind::Index; root = &root->args[0])
            path.insert(path.begin(), root);
        if (root->kind != Expr::Kind::Identifier) return false;
        const auto type = locals.types.find(root->text);
        if (type == locals.types.end()) return false;  // a global: not ours to fold
        if (op != "=")
            value = exprNode(Expr::Kind::Binary, loc, op.substr(0, 1),
                             {substitute(target, locals.values, depth), std::move(value)});
        std::optional<Expr> whole =
            assignAt(locals.values[root->text], type->second, path, 0, value, locals.values, depth, loc);
        if (!whole) return false;
        locals.values[root->text] = std::move(*whole);
        if (!declaredHere.count(root->text)) ++locals.assigned[root->text];
        return true;
    }

    // `e`'s value over `locals`. Its calls of functions that write their arguments run first, in order,
    // writing the locals they name (hoist()); none where one cannot be inlined.
    std::optional<Expr> valueOf(const Expr& e, Locals& locals, const std::set<std::string>& declaredHere,
                                int depth) {
        Expr hoisted = e;
        std::vector<std::string> results;
        const bool ran = hoist(hoisted, locals, declaredHere, results, depth);
        std::optional<Expr> value;
        if (ran) value = substitute(hoisted, locals.values, depth);
        for (const std::string& name : results) {
            locals.values.erase(name);
            locals.types.erase(name);
        }
        return value;
    }

    // Inlines each call in `e` of a function with `out` or `inout` parameters (or none to return): its
    // arguments written to the caller's locals, the call replaced by a name (`results`) bound to its value.
    bool hoist(Expr& e, Locals& locals, const std::set<std::string>& declaredHere,
               std::vector<std::string>& results, int depth) {
        for (Expr& arg : e.args)
            if (!hoist(arg, locals, declaredHere, results, depth)) return false;
        if (e.kind != Expr::Kind::Call) return true;
        const FunctionDecl* function = find(e.text, e.args.size());
        if (!function) {  // one of ours that cannot be inlined must not lose what it writes
            const std::vector<const FunctionDecl*> ours = mEffect.findFunctions(e.text);
            return std::none_of(ours.begin(), ours.end(),
                                [](const FunctionDecl* f) { return writesArguments(*f); });
        }
        if (!writesArguments(*function) && returnsValue(function->returnType)) return true;  // substitute()'s
        if (depth + 1 >= kMaxInlineDepth) return false;
        std::vector<Expr> arguments;
        for (const Expr& arg : e.args) arguments.push_back(substitute(arg, locals.values, depth));
        std::optional<Outcome> outcome = expand(*function, arguments, e.loc, depth + 1);
        if (!outcome) return false;
        for (size_t i = 0; i < e.args.size(); ++i) {
            const FunctionParam& p = function->params[i];
            if (p.direction != FunctionParam::Direction::In &&
                !assign(e.args[i], "=", outcome->outs[p.name], locals, declaredHere, depth, e.loc))
                return false;
        }
        const std::string name = "$call" + std::to_string(results.size());
        locals.values[name] = outcome->value ? std::move(*outcome->value) : integer(0, e.loc);
        locals.types[name] = function->returnType;
        results.push_back(name);
        Expr result;
        result.kind = Expr::Kind::Identifier;
        result.text = name;
        result.loc = e.loc;
        e = std::move(result);
        return true;
    }

    // Runs `statements` (none of them a return) over `locals`; false if one cannot become an expression.
    bool execute(const std::vector<FunctionDecl::Statement>& statements, Locals& locals, const SourceLoc& loc,
                 int depth) {
        using Statement = FunctionDecl::Statement;
        std::set<std::string> declaredHere;
        for (const Statement& statement : statements) {
            if (mBudget <= 0) return false;
            if (locals.dead) break;  // what follows a `break` or `continue` runs on no path
            switch (statement.kind) {
                case Statement::Kind::Declare: {
                    // A name declared again in a branch would hide the outer one: not worth following.
                    if (locals.types.count(statement.name) && !declaredHere.count(statement.name))
                        return false;
                    // An uninitialized local reads 0 here; HLSL leaves it undefined until written.
                    std::optional<Expr> value = statement.hasValue
                                                    ? valueOf(statement.value, locals, declaredHere, depth)
                                                    : std::optional<Expr>(integer(0, loc));
                    if (value)
                        value = statement.hasValue ? typed(statement.type, std::move(*value), loc)
                                                   : broadcast(statement.type, *value, loc);
                    if (!value) return false;
                    locals.values[statement.name] = std::move(*value);
                    locals.types[statement.name] = statement.type;
                    declaredHere.insert(statement.name);
                    break;
                }
                case Statement::Kind::Assign: {
                    std::optional<Expr> value = valueOf(statement.value, locals, declaredHere, depth);
                    if (!value || !assign(statement.target, statement.op, std::move(*value), locals,
                                          declaredHere, depth, loc))
                        return false;
                    break;
                }
                case Statement::Kind::Evaluate:
                    if (!valueOf(statement.value, locals, declaredHere, depth)) return false;
                    break;
                case Statement::Kind::If: {
                    // Both branches run on copies; what either assigns becomes `condition ? then : else`,
                    // which the host evaluates as the branch taken (PreshaderProgram's Select).
                    const std::optional<Expr> tested = valueOf(statement.value, locals, declaredHere, depth);
                    if (!tested) return false;
                    const Expr& condition = *tested;
                    Locals then = locals, otherwise = locals;
                    then.assigned.clear();
                    otherwise.assigned.clear();
                    if (mLoop) {  // only a `break` or `continue` reads which path runs
                        then.path = both(locals.path, condition, loc);
                        otherwise.path =
                            both(locals.path, exprNode(Expr::Kind::Unary, loc, "!", {condition}), loc);
                    }
                    const int exitsBefore = mExitsTaken;
                    if (!execute(statement.then, then, loc, depth) ||
                        !execute(statement.otherwise, otherwise, loc, depth))
                        return false;
                    if (then.dead || otherwise.dead) {
                        // Only the other branch goes on: its values are the running path's, unselected.
                        Locals& alive = then.dead ? otherwise : then;
                        locals.dead = alive.dead;
                        locals.path = alive.path;
                        for (auto& [name, value] : locals.values) value = alive.values[name];
                        for (const auto& [name, count] : alive.assigned)
                            if (locals.values.count(name) && !declaredHere.count(name))
                                ++locals.assigned[name];
                        break;
                    }
                    // A branch that left the loop on some of its paths narrowed its own path.
                    if (mExitsTaken != exitsBefore)
                        locals.path = select(condition, then.path ? *then.path : truth(true, loc),
                                             otherwise.path ? *otherwise.path : truth(true, loc), loc);
                    std::set<std::string> changed;
                    for (const Locals* branch : {&then, &otherwise})
                        for (const auto& [name, count] : branch->assigned) changed.insert(name);
                    for (const std::string& name : changed) {
                        // What the branches built is counted already; the merge adds the copies.
                        const int before = nodes(locals.values[name], mBudget);
                        locals.values[name] = merge(condition, name, then, otherwise, loc);
                        mBudget -= std::max(0, nodes(locals.values[name], mBudget) - before);
                        if (!declaredHere.count(name)) ++locals.assigned[name];
                    }
                    break;
                }
                case Statement::Kind::Loop:
                    if (!unroll(statement, locals, declaredHere, loc, depth)) return false;
                    break;
                case Statement::Kind::Break:
                case Statement::Kind::Continue:
                    if (!mLoop) return false;
                    leave(statement.kind == Statement::Kind::Break ? mLoop->broken : mLoop->continued, locals,
                          loc);
                    break;
                case Statement::Kind::Return:
                    return false;
            }
        }
        return true;
    }

    // Unrolled, as fxc unrolled a loop it could bound: the condition must fold to a constant before every
    // iteration on the path still running (the counter's value is an expression of literals). A path that
    // took a `break` runs no further iteration; after the loop, each name is the value of the break taken,
    // or of the running path where none was.
    bool unroll(const FunctionDecl::Statement& loop, Locals& locals,
                const std::set<std::string>& declaredHere, const SourceLoc& loc, int depth) {
        LoopExits exits;
        LoopExits* const outer = std::exchange(mLoop, &exits);
        // Paths inside are counted from the loop's entry: its exits select only among the values of the
        // path that entered it, and an outer loop's path copied into every exit of an inner one would
        // grow as a power of the iterations (a `return` inside nested loops).
        const std::optional<Expr> pathBefore = std::exchange(locals.path, std::nullopt);
        bool unrolled = true;
        for (int iteration = 0;; ++iteration) {
            double going = 0;
            const bool bounded = mBudget > 0 && iteration <= kMaxLoopIterations &&
                                 constant(substitute(loop.value, locals.values, depth), going);
            if (!bounded) {
                if (mBudget > 0 && !mLoopFailure)
                    mLoopFailure = LoopFailure{iteration > kMaxLoopIterations ? DiagId::HostLoopIterationLimit
                                                                              : DiagId::HostLoopUnbounded,
                                               loop.value.loc};
                unrolled = false;
                break;
            }
            if (going == 0) break;
            // The body's own declarations are its own, every iteration again.
            Locals inner = locals;
            inner.assigned.clear();
            exits.continued = {};
            mLoop = &exits;
            if (!execute(loop.then, inner, loc, depth)) {
                unrolled = false;
                break;
            }
            // The paths that continued rejoin the running one before the step.
            if (exits.continued.taken) {
                for (auto& [name, value] : exits.continued.values)
                    if (locals.values.count(name))
                        inner.values[name] = inner.dead ? std::move(value)
                                                        : select(inner.path, inner.values[name], value, loc);
                inner.path =
                    inner.dead ? exits.continued.taken : either(inner.path, exits.continued.taken, loc);
                inner.dead = false;
            }
            if (inner.dead) {  // every path took a `break`
                locals.dead = true;
                break;
            }
            mLoop = nullptr;  // the step is no body: a `break` there is not parsed
            if (!execute(loop.otherwise, inner, loc, depth)) {
                unrolled = false;
                break;
            }
            for (auto& [name, value] : locals.values) {
                value = std::move(inner.values[name]);
                // A counter stays a literal, not a chain of every step before.
                double number = 0;
                const TypeDesc& type = locals.types[name];
                if (type.shape == Shape::Scalar && type.arrayDims.empty() && type.isNumeric() &&
                    constant(value, number)) {
                    Expr literal;
                    literal.kind = Expr::Kind::Number;
                    literal.number = number;
                    literal.isInteger = number == std::trunc(number);
                    literal.loc = loc;
                    value = cast(type, std::move(literal), loc);
                }
            }
            locals.path = inner.path;
            for (const auto& [name, count] : inner.assigned)
                if (locals.values.count(name) && !declaredHere.count(name)) ++locals.assigned[name];
        }
        mLoop = outer;
        if (!unrolled) return false;
        if (exits.broken.taken) {
            for (auto& [name, value] : locals.values) {
                auto atBreak = exits.broken.values.find(name);
                if (atBreak == exits.broken.values.end()) continue;
                value =
                    locals.dead ? atBreak->second : select(exits.broken.taken, atBreak->second, value, loc);
                if (!declaredHere.count(name)) ++locals.assigned[name];
            }
        }
        // Every path leaves the loop: after it, the path is the one that entered it.
        locals.dead = false;
        locals.path = pathBefore;
        return true;
    }

    std::optional<Outcome> expand(const FunctionDecl& function, const std::vector<Expr>& arguments,
                                  const SourceLoc& loc, int depth) {
        if (mBudget <= 0 || function.straightBody.empty()) return std::nullopt;
        // A function called inside a loop's body is not in that loop.
        LoopExits* const callersLoop = std::exchange(mLoop, nullptr);
        std::optional<Outcome> outcome = expandBody(function, arguments, loc, depth);
        mLoop = callersLoop;
        return outcome;
    }

    std::optional<Outcome> expandBody(const FunctionDecl& function, const std::vector<Expr>& arguments,
                                      const SourceLoc& loc, int depth) {
        Locals locals;
        for (size_t i = 0; i < function.params.size(); ++i) {
            const FunctionParam& p = function.params[i];
            // An `out` parameter starts as a local declared without a value.
            std::optional<Expr> value = p.direction == FunctionParam::Direction::Out
                                            ? broadcast(p.type, integer(0, loc), loc)
                                            : typed(p.type, arguments[i], loc);
            if (!value) return std::nullopt;
            locals.values[p.name] = std::move(*value);
            locals.types[p.name] = p.type;
        }
        std::optional<Outcome> outcome =
            result(function, function.straightBody, std::move(locals), loc, depth);
        if (!outcome || mBudget <= 0) return std::nullopt;
        return outcome;
    }

    // What `statements` give, every path of which ends in a return (the parser's endsInReturns): the last
    // statement's value and the parameters written, or, for an `if` whose branches return, the selects
    // of the two.
    std::optional<Outcome> result(const FunctionDecl& function,
                                  const std::vector<FunctionDecl::Statement>& statements, Locals locals,
                                  const SourceLoc& loc, int depth) {
        using Statement = FunctionDecl::Statement;
        if (statements.empty()) return std::nullopt;
        const std::vector<Statement> body(statements.begin(), statements.end() - 1);
        if (!execute(body, locals, loc, depth)) return std::nullopt;
        const Statement& last = statements.back();
        const std::set<std::string> none;
        if (last.kind == Statement::Kind::Return) {
            Outcome outcome;
            if (last.hasValue != returnsValue(function.returnType)) return std::nullopt;
            if (last.hasValue) {
                std::optional<Expr> value = valueOf(last.value, locals, none, depth);
                if (value) outcome.value = typed(function.returnType, std::move(*value), loc);
                if (!outcome.value) return std::nullopt;
            }
            for (const FunctionParam& p : function.params)
                if (p.direction != FunctionParam::Direction::In) outcome.outs[p.name] = locals.values[p.name];
            return outcome;
        }
        if (last.kind != Statement::Kind::If) return std::nullopt;
        const std::optional<Expr> condition = valueOf(last.value, locals, none, depth);
        if (!condition) return std::nullopt;
        std::optional<Outcome> then = result(function, last.then, locals, loc, depth);
        std::optional<Outcome> otherwise =
            then ? result(function, last.otherwise, locals, loc, depth) : std::nullopt;
        if (!otherwise) return std::nullopt;
        if (then->value)
            then->value = choose(*condition, std::move(*then->value), std::move(*otherwise->value), loc);
        for (auto& [name, value] : then->outs)
            value = choose(*condition, std::move(value), std::move(otherwise->outs[name]), loc);
        return then;
    }

    const Effect& mEffect;
    DiagnosticSink& mDiagnostics;
    // The first loop of the expression being rewritten that could not be unrolled, and why.
    struct LoopFailure {
        DiagId id;
        SourceLoc loc;
    };
    std::optional<LoopFailure> mLoopFailure;
    int mBudget = kMaxInlinedNodes;
    LoopExits* mLoop = nullptr;  // the loop whose body is being unrolled
    int mExitsTaken = 0;         // `break`s and `continue`s unrolled so far
};

}  // namespace

void inlineUserFunctionCalls(Effect& effect, DiagnosticSink& diagnostics) {
    Inliner inliner(effect, diagnostics);
    // Initializers first, so that a static's expansion carries its calls inlined. They are evaluated in
    // declaration order over the values before them, so their own static names stay names.
    for (Parameter& parameter : effect.parameters)
        if (parameter.initializer && parameter.type.isNumeric())
            inliner.rewriteExpression(*parameter.initializer, false);
    for (Technique& technique : effect.techniques)
        for (Pass& pass : technique.passes)
            for (StateAssignment& state : pass.states) inliner.rewriteExpression(state.value, true);
    for (Parameter& parameter : effect.parameters)
        if (parameter.initializer && parameter.type.isShader())
            inliner.rewriteExpression(*parameter.initializer, true);
}

}  // namespace fx::detail
