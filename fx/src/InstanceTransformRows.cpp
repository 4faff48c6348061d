// InstanceTransformRows: see InstanceTransformRows.h.
//
// A mesh holds no per-instance streams, so such rows read constants; read as the constant the input's name
// would give (0, or TEXCOORDn's (0,0,0,1)), the four rows make a singular matrix and every vertex of the
// object lands on one point. Told apart by how the shader uses them, whatever their names, they read the
// identity's rows instead, as a matrix-typed per-instance input does. An input the meshes feed (a normal,
// TEXCOORD0) is per-vertex data and keeps it: a matrix built of such inputs is no instance's transform.
#include "InstanceTransformRows.h"

#include <fx/VertexStreams.h>

#include <optional>

namespace fx::detail {

namespace {

class RowReader {
public:
    RowReader(const Effect& effect, const FunctionDecl& function) : mEffect(effect), mFunction(function) {}

    std::map<std::string, int> read() {
        visit(mFunction.straightBody);
        return mRows;
    }

private:
    void visit(const std::vector<FunctionDecl::Statement>& statements) {
        for (const FunctionDecl::Statement& s : statements) {
            visit(s.target);
            visit(s.value);
            visit(s.then);
            visit(s.otherwise);
        }
    }

    void visit(const Expr& e) {
        if (e.kind == Expr::Kind::Call && e.text == "float4x4" && e.args.size() == 4) {
            std::map<std::string, int> rows;
            for (size_t row = 0; row < 4; ++row) {
                const std::optional<std::string> path = float4Input(e.args[row]);
                if (!path) break;
                rows.emplace(*path, static_cast<int>(row));
            }
            if (rows.size() == 4) mRows.insert(rows.begin(), rows.end());
        }
        for (const Expr& arg : e.args) visit(arg);
    }

    // The path of a float4 vertex input that no mesh stream feeds (`In.vRight`, or a parameter `vRight`),
    // where `e` is one.
    std::optional<std::string> float4Input(const Expr& e) const {
        std::string base, member;
        if (e.kind == Expr::Kind::Identifier) {
            base = e.text;
        } else if (e.kind == Expr::Kind::Member && e.args.size() == 1 &&
                   e.args[0].kind == Expr::Kind::Identifier) {
            base = e.args[0].text;
            member = e.text;
        } else {
            return std::nullopt;
        }
        for (const FunctionParam& p : mFunction.params) {
            if (p.name != base || p.isUniform || p.direction != FunctionParam::Direction::In) continue;
            if (member.empty()) {
                if (!isRowType(p.type) || meshHolds(p.semantic)) return std::nullopt;
                return base;
            }
            if (p.type.base != BaseType::Struct) return std::nullopt;
            const StructDecl* s = mEffect.findStruct(p.type.structName);
            if (!s) return std::nullopt;
            for (const StructMember& m : s->members)
                if (m.name == member && isRowType(m.type) && !meshHolds(m.semantic))
                    return base + "." + member;
            return std::nullopt;
        }
        return std::nullopt;
    }

    static bool isRowType(const TypeDesc& t) {
        return t.shape == Shape::Vector && t.cols == 4 && t.arrayDims.empty();
    }

    // Whether the meshes hold the stream an input of this name reads: position, normal, texture
    // coordinates 0, tangent and binormal. Such an input is per-vertex data, whatever the shader makes of it.
    static bool meshHolds(const std::string& semantic) {
        std::optional<int> location = vertexInputLocation(semantic);
        if (!location) location = vertexStreamByName(semantic);
        const std::optional<VertexStreamSlot> slot = location ? vertexStreamAt(*location) : std::nullopt;
        if (!slot) return false;
        switch (slot->stream) {
            case VertexStream::Position:
            case VertexStream::Normal:
            case VertexStream::Tangent:
            case VertexStream::Binormal:
                return true;
            case VertexStream::Texcoord:
                return slot->index == 0;
            default:
                return false;
        }
    }

    const Effect& mEffect;
    const FunctionDecl& mFunction;
    std::map<std::string, int> mRows;
};

}  // namespace

std::map<std::string, int> instanceTransformRows(const Effect& effect, const FunctionDecl& function) {
    return RowReader(effect, function).read();
}

}  // namespace fx::detail
