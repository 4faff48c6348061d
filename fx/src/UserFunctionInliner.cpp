// UserFunctionInliner: user-function calls in host-evaluated expressions become expressions (see the
// header). Each parameter and local becomes its value's expression, converted to the declared type by a
// cast, so that `float3 c = 1;` or an int parameter truncates exactly as the function would.
#include "UserFunctionInliner.h"

#include "ConstantFolding.h"

#include <fx/Preshader.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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
    explicit Inliner(const Effect& effect) : mEffect(effect) {}

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
        if (e.kind != Expr::Kind::Call || depth >= kMaxInlineDepth) return;
        const FunctionDecl* function = find(e.text, e.args.size());
        if (!function) {
            if (mEffect.findFunctions(e.text).empty()) expandIntrinsic(e);
            return;
        }
        std::optional<Expr> inlined = expand(*function, e, depth);
        if (inlined) e = std::move(*inlined);
    }

private:
    // The intrinsics that D3DX's preshaders ran as a sequence of their instructions, written with those the
    // host evaluator has (HLSL's definitions): ldexp, rcp, mad, sinh, cosh, tanh, reflect, faceforward,
    // any, all and lit. Any other call stays as it is.
    static void expandIntrinsic(Expr& e) {
        const SourceLoc loc = e.loc;
        auto number = [&](double value) {
            Expr n;
            n.kind = Expr::Kind::Number;
            n.number = value;
            n.loc = loc;
            return n;
        };
        auto binary = [&](const char* op, Expr a, Expr b) {
            return node(Expr::Kind::Binary, loc, op, {std::move(a), std::move(b)});
        };
        auto call = [&](const char* name, std::vector<Expr> args) {
            return node(Expr::Kind::Call, loc, name, std::move(args));
        };
        auto negated = [&](Expr a) { return node(Expr::Kind::Unary, loc, "-", {std::move(a)}); };
        const std::vector<Expr>& a = e.args;
        const std::string& name = e.text;
        if (name == "ldexp" && a.size() == 2) {
            e = binary("*", a[0], call("exp2", {a[1]}));
        } else if (name == "rcp" && a.size() == 1) {
            e = binary("/", number(1), a[0]);
        } else if (name == "mad" && a.size() == 3) {
            e = binary("+", binary("*", a[0], a[1]), a[2]);
        } else if ((name == "sinh" || name == "cosh") && a.size() == 1) {
            e = binary("*",
                       binary(name == "sinh" ? "-" : "+", call("exp", {a[0]}), call("exp", {negated(a[0])})),
                       number(0.5));
        } else if (name == "tanh" && a.size() == 1) {
            // 1 - 2 / (e^2x + 1): ±1 where e^2x overflows or vanishes, not inf / inf.
            e = binary(
                "-", number(1),
                binary("/", number(2), binary("+", call("exp", {binary("*", number(2), a[0])}), number(1))));
        } else if (name == "reflect" && a.size() == 2) {
            e = binary("-", a[0], binary("*", binary("*", number(2), call("dot", {a[0], a[1]})), a[1]));
        } else if (name == "faceforward" && a.size() == 3) {
            e = binary("*", negated(a[0]), call("sign", {call("dot", {a[1], a[2]})}));
        } else if ((name == "any" || name == "all") && a.size() == 1) {
            // Over the components that are not zero (1) or are (0): any sums the first, all the second.
            Expr nonZero = call("abs", {call("sign", {a[0]})});
            Expr counted = name == "any" ? nonZero : binary("-", number(1), nonZero);
            Expr sum = call("dot", {counted, counted});
            e = name == "any" ? binary(">", std::move(sum), number(0))
                              : binary("==", std::move(sum), number(0));
        } else if (name == "lit" && a.size() == 3) {
            // As the shaders' replacement (HlslRewriting.h): the specular term is 0 where either cosine is.
            Expr specular = node(Expr::Kind::Ternary, loc, "",
                                 {binary("||", binary("<", a[0], number(0)), binary("<", a[1], number(0))),
                                  number(0), call("pow", {call("max", {a[1], number(0)}), a[2]})});
            e = call("float4", {number(1), call("max", {a[0], number(0)}), std::move(specular), number(1)});
        }
    }

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
        for (const FunctionDecl& f : mEffect.functions) {
            if (f.name != name || !f.hasBody || f.straightBody.empty() || f.params.size() != arguments)
                continue;
            bool plain = true;
            for (const FunctionParam& p : f.params)
                plain = plain && p.direction == FunctionParam::Direction::In;
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
        if (out.kind == Expr::Kind::Call) rewrite(out, depth + 1);
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

    // Marks the per-component selects assignComponents builds: (mask, new components, old value).
    static constexpr const char* kComponentSelect = "components";

    static Expr node(Expr::Kind kind, const SourceLoc& loc, std::string text, std::vector<Expr> args) {
        Expr e;
        e.kind = kind;
        e.loc = loc;
        e.text = std::move(text);
        e.args = std::move(args);
        return e;
    }

    static bool same(const Expr& a, const Expr& b) {
        if (a.kind != b.kind || a.text != b.text || a.number != b.number || a.isInteger != b.isInteger ||
            a.args.size() != b.args.size() ||
            (a.kind == Expr::Kind::Cast && (a.castType.hlslName() != b.castType.hlslName() ||
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

    // `condition ? a : b`; `a` where both are the same expression (a counter no path changed).
    Expr select(const std::optional<Expr>& condition, Expr a, Expr b, const SourceLoc& loc) {
        if (!condition || same(a, b)) return a;
        return counted(node(Expr::Kind::Ternary, loc, "", {*condition, std::move(a), std::move(b)}));
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
        return counted(node(Expr::Kind::Binary, loc, "&&", {*a, std::move(b)}));
    }
    std::optional<Expr> either(const std::optional<Expr>& a, const std::optional<Expr>& b,
                               const SourceLoc& loc) {
        if (!a || !b) return std::nullopt;
        return counted(node(Expr::Kind::Binary, loc, "||", {*a, *b}));
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

    // `local.member = value` (`dir.x = ...`, `c.rgb += ...`): the local becomes a per-component select
    // between the value, widened to the local's type, and its old value.
    std::optional<Expr> assignComponents(const TypeDesc& type, const std::string& member, Expr old,
                                         Expr value, const SourceLoc& loc) {
        if (!type.arrayDims.empty() || (type.shape != Shape::Vector && type.shape != Shape::Scalar))
            return std::nullopt;
        const int columns = type.shape == Shape::Scalar ? 1 : type.cols;
        std::vector<int> written;
        for (char c : member) {
            const char* at = std::strchr("xyzw", c);
            const char* colour = std::strchr("rgba", c);
            const int index = c == '\0' ? -1
                              : at      ? static_cast<int>(at - "xyzw")
                              : colour  ? static_cast<int>(colour - "rgba")
                                        : -1;
            if (index < 0 || index >= columns) return std::nullopt;
            written.push_back(index);
        }
        TypeDesc component = type;
        component.shape = Shape::Scalar;
        component.cols = 1;
        std::vector<Expr> spread, mask;
        for (int i = 0; i < columns; ++i) {
            const auto k = std::find(written.begin(), written.end(), i);
            Expr flag;
            flag.kind = Expr::Kind::Bool;
            flag.loc = loc;
            flag.number = k != written.end() ? 1.0 : 0.0;
            mask.push_back(std::move(flag));
            Expr zero;
            zero.kind = Expr::Kind::Number;
            zero.loc = loc;
            spread.push_back(
                k == written.end() ? std::move(zero)
                : written.size() == 1
                    ? cast(component, value, loc)
                    : node(Expr::Kind::Member, loc, std::string(1, "xyzw"[k - written.begin()]), {value}));
        }
        if (columns == 1) return cast(type, std::move(value), loc);
        TypeDesc boolean = type;
        boolean.base = BaseType::Bool;
        return node(Expr::Kind::Ternary, loc, kComponentSelect,
                    {node(Expr::Kind::Call, loc, boolean.hlslName(), std::move(mask)),
                     node(Expr::Kind::Call, loc, type.hlslName(), std::move(spread)), std::move(old)});
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
            if (!inThen) taken = node(Expr::Kind::Unary, loc, "!", {std::move(taken)});
            value.args[0] = node(Expr::Kind::Binary, loc, "&&", {std::move(value.args[0]), std::move(taken)});
            return value;
        }
        return node(Expr::Kind::Ternary, loc, "", {condition, then.values[name], otherwise.values[name]});
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
                    Expr zero;
                    zero.kind = Expr::Kind::Number;
                    zero.loc = loc;
                    // An uninitialized local reads 0 here; HLSL leaves it undefined until written.
                    locals.values[statement.name] = cast(
                        statement.type,
                        statement.hasValue ? substitute(statement.value, locals.values, depth) : zero, loc);
                    locals.types[statement.name] = statement.type;
                    declaredHere.insert(statement.name);
                    break;
                }
                case Statement::Kind::Assign: {
                    auto type = locals.types.find(statement.name);
                    if (type == locals.types.end()) return false;  // assigns a global: not ours to fold
                    Expr old = locals.values[statement.name];
                    Expr value = substitute(statement.value, locals.values, depth);
                    if (statement.op != "=") {
                        Expr target = statement.member.empty()
                                          ? old
                                          : node(Expr::Kind::Member, loc, statement.member, {old});
                        value = node(Expr::Kind::Binary, loc, statement.op.substr(0, 1),
                                     {std::move(target), std::move(value)});
                    }
                    if (statement.member.empty()) {
                        locals.values[statement.name] = cast(type->second, std::move(value), loc);
                    } else {
                        std::optional<Expr> whole = assignComponents(type->second, statement.member,
                                                                     std::move(old), std::move(value), loc);
                        if (!whole) return false;
                        locals.values[statement.name] = std::move(*whole);
                    }
                    if (!declaredHere.count(statement.name)) ++locals.assigned[statement.name];
                    break;
                }
                case Statement::Kind::If: {
                    // Both branches run on copies; what either assigns becomes `condition ? then : else`,
                    // which the host evaluates as the branch taken (PreshaderProgram's Select).
                    const Expr condition = substitute(statement.value, locals.values, depth);
                    Locals then = locals, otherwise = locals;
                    then.assigned.clear();
                    otherwise.assigned.clear();
                    if (mLoop) {  // only a `break` or `continue` reads which path runs
                        then.path = both(locals.path, condition, loc);
                        otherwise.path =
                            both(locals.path, node(Expr::Kind::Unary, loc, "!", {condition}), loc);
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
        const std::optional<Expr> pathBefore = locals.path;
        bool unrolled = true;
        for (int iteration = 0;; ++iteration) {
            double going = 0;
            if (iteration > kMaxLoopIterations || mBudget <= 0 ||
                !constant(substitute(loop.value, locals.values, depth), going)) {
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
                if (type.shape == Shape::Scalar && type.arrayDims.empty() && constant(value, number)) {
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

    std::optional<Expr> expand(const FunctionDecl& function, const Expr& call, int depth) {
        if (mBudget <= 0 || function.straightBody.empty()) return std::nullopt;
        // A function called inside a loop's body is not in that loop.
        LoopExits* const callersLoop = std::exchange(mLoop, nullptr);
        std::optional<Expr> value = expandBody(function, call, depth);
        mLoop = callersLoop;
        return value;
    }

    std::optional<Expr> expandBody(const FunctionDecl& function, const Expr& call, int depth) {
        Locals locals;
        for (size_t i = 0; i < function.params.size(); ++i) {
            const FunctionParam& p = function.params[i];
            locals.values[p.name] = cast(p.type, call.args[i], call.loc);
            locals.types[p.name] = p.type;
        }
        std::optional<Expr> value =
            result(function.straightBody, function.returnType, locals, call.loc, depth);
        if (!value || mBudget <= 0) return std::nullopt;
        return value;
    }

    // What `statements` return, every path of which ends in a return (the parser's endsInReturns): the
    // last statement's value, or, for an `if` whose branches return, `condition ? then : otherwise`.
    std::optional<Expr> result(const std::vector<FunctionDecl::Statement>& statements, const TypeDesc& type,
                               Locals locals, const SourceLoc& loc, int depth) {
        using Statement = FunctionDecl::Statement;
        if (statements.empty()) return std::nullopt;
        const std::vector<Statement> body(statements.begin(), statements.end() - 1);
        if (!execute(body, locals, loc, depth)) return std::nullopt;
        const Statement& last = statements.back();
        if (last.kind == Statement::Kind::Return)
            return cast(type, substitute(last.value, locals.values, depth), loc);
        if (last.kind != Statement::Kind::If) return std::nullopt;
        Expr condition = substitute(last.value, locals.values, depth);
        std::optional<Expr> then = result(last.then, type, locals, loc, depth);
        std::optional<Expr> otherwise =
            then ? result(last.otherwise, type, locals, loc, depth) : std::nullopt;
        if (!otherwise) return std::nullopt;
        return node(Expr::Kind::Ternary, loc, "",
                    {std::move(condition), std::move(*then), std::move(*otherwise)});
    }

    const Effect& mEffect;
    int mBudget = kMaxInlinedNodes;
    LoopExits* mLoop = nullptr;  // the loop whose body is being unrolled
    int mExitsTaken = 0;         // `break`s and `continue`s unrolled so far
};

}  // namespace

void inlineUserFunctionCalls(Effect& effect) {
    Inliner inliner(effect);
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
