// StageWrapper: the generated entry point `fx_main` of one stage's unit (see PassLowering.h): D3D9-semantic
// inputs at fixed locations, the user's structs rebuilt, the user's function called with the compile
// expression's uniform arguments, its results written to SV_Position, varyings and SV_Target n.
// WrapperBuilder::build() picks the stage's builder: vertex and pixel shaders in StageWrapper.cpp, geometry
// shaders in GeometryWrapper.cpp, hull and domain shaders in TessellationWrappers.cpp, compute shaders in
// ComputeWrapper.cpp. Private to fx.
#pragma once

#include "PassLowering.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace fx {

// One leaf of a (possibly nested) struct: where it lives and what semantic it carries.
struct Field {
    std::string lvalue;  // "fx_p0.Position"
    TypeDesc type;
    std::string semantic;  // canonical
    std::string interpolation;
    SourceLoc loc;
    // A matrix's column: D3D9 gives a matrix varying or input one register per column (its default
    // column_major packing), at consecutive semantic indices. lvalue names the whole matrix then, and
    // type is the column's vector.
    int column = -1;
};

// The value a field holds, for an output: the column of a matrix or the lvalue itself.
std::string fieldValue(const Field& f);
void gatherFields(const Effect& effect, const TypeDesc& type, const std::string& semantic,
                  const std::string& interpolation, const std::string& lvalue, const SourceLoc& loc,
                  std::vector<Field>& out, int depth = 0);
int fieldComponents(const Field& f);
// `expr` (a float4) narrowed to the field's type: ".x", ".xy", ".xyz", with a cast for ints/bools.
std::string narrowTo(const Field& f, const std::string& expr);
// The statement that stores `source` (a float4) into a field: the whole lvalue, or each row's element of
// a matrix column.
std::string assignField(const Field& f, const std::string& source);
// "float4(v, 0, 1)": a varying of n components read as the float4 the field assignments take.
std::string widenToFloat4(const std::string& name, int components);

class WrapperBuilder {
public:
    WrapperBuilder(const Effect& effect, const FunctionDecl& fn, const Expr& compile, ShaderStage stage,
                   std::vector<LoweredArgument>& arguments, DiagnosticSink& diagnostics,
                   const std::map<int, TypeDesc>* previousOutputs, const FunctionDecl* hull)
        : mEffect(effect),
          mFn(fn),
          mCompile(compile),
          mStage(stage),
          mArguments(arguments),
          mDiagnostics(diagnostics),
          mPreviousOutputs(previousOutputs),
          mHull(hull) {}

    bool build(std::string& globals, std::string& wrapper);
    void setStreamOut(const StageStreamOut& streamOut) { mStreamOut = streamOut; }

    // A geometry shader's output stream element: its name and its redeclaration with varying locations.
    const std::string& streamStruct() const { return mStreamStruct; }
    const std::string& streamStructText() const { return mStreamStructText; }
    const std::map<int, TypeDesc>& varyingOutputs() const { return mVaryingOutputs; }
    // A hull shader's control points per input patch and its patch-constant function.
    int patchVertices() const { return mPatchVertices; }
    CompiledPass::DrawPrimitive primitive() const { return mPrimitive; }
    const std::string& patchConstantFunction() const { return mPatchConstantFunction; }
    const std::string& streamType() const { return mStreamType; }
    int positionVarying() const { return mPositionVarying; }

private:
    bool fail(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
        mDiagnostics.report(id, loc, args);
        return false;
    }
    bool uniformArgument(const FunctionParam& p, size_t argIndex, std::string& value, std::string& globals);
    // False (reported at CompileShader) when the call gives more arguments than the `uniformCount`
    // uniform parameters of the function took.
    bool everyArgumentTaken(size_t uniformCount);
    bool vertexInputs(const std::vector<Field>& fields, std::string& params, std::string& body);
    bool pixelInputs(const std::vector<Field>& fields, std::string& params, std::string& body);
    bool vertexOutputs(const std::vector<Field>& fields, std::string& members, std::string& body);
    bool pixelOutputs(const std::vector<Field>& fields, std::string& members, std::string& body);
    bool buildGeometry(std::string& globals, std::string& wrapper);
    bool streamElement(const FunctionParam& stream);
    bool buildHull(std::string& globals, std::string& wrapper);
    bool buildDomain(std::string& globals, std::string& wrapper);
    bool buildCompute(std::string& globals, std::string& wrapper);
    bool readControlPoints(const FunctionParam& patch, const std::string& local, const std::string& source,
                           std::set<int>& varyings, std::string& locals, std::string& body);
    bool patchConstants(const TypeDesc& type, const SourceLoc& loc, bool write, const std::string& value,
                        std::string& members, std::string& body);

    const Effect& mEffect;
    const FunctionDecl& mFn;
    const Expr& mCompile;
    ShaderStage mStage;
    std::vector<LoweredArgument>& mArguments;
    DiagnosticSink& mDiagnostics;
    const std::map<int, TypeDesc>* mPreviousOutputs;
    const FunctionDecl* mHull;
    int mPatchVertices = 0;
    CompiledPass::DrawPrimitive mPrimitive = CompiledPass::DrawPrimitive::Triangles;
    std::string mPatchConstantFunction;
    std::string mStreamStruct;
    std::string mStreamStructText;
    std::map<int, TypeDesc> mVaryingOutputs;
    StageStreamOut mStreamOut;
    std::string mStreamType;
    int mPositionVarying = -1;
    // The attribute location feeding a vertex input: the capture's element (StageStreamOut::capturedInputs)
    // or the mesh stream its name points to; nullopt where it reads a constant.
    std::optional<int> inputAttribute(const std::string& semantic) const;
    // Whether a vertex input field reads the identity matrix's column rather than an attribute.
    bool readsIdentity(const Field& f) const;
    // The row of a per-instance transform that a vertex input field is (fx/src/InstanceTransformRows.h),
    // or -1; such an input reads the identity's row.
    int instanceRow(const Field& f) const;
    // The vertex shader's instance-transform rows by the wrapper's l-values (`fx_p0.vRight`).
    std::map<std::string, int> mInstanceRows;
};

}  // namespace fx
