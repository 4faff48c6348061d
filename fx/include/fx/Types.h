// Types: the HLSL types of effect parameters and values (BaseType, Shape, TypeDesc), shared by the syntax
// tree (Effect.h) and the compiled effect the runtime reads (CompiledEffect.h), which must not need the
// syntax tree.
#pragma once

#include <string>
#include <vector>

namespace fx {

enum class BaseType {
    Void,
    Bool,
    Int,
    UInt,
    Half,
    Float,
    Double,
    String,
    Texture,  // untyped D3D9 `texture`
    Texture1D,
    Texture2D,
    Texture3D,
    TextureCube,
    // D3D10 resources that GL holds as array, multisample or buffer textures and storage buffers; their
    // template arguments ("float4", "float4, 4", "Particle") are TypeDesc::templateArgs.
    Texture1DArray,
    Texture2DArray,
    TextureCubeArray,
    Texture2DMS,        // Texture2DMS<T, N>: N samples per texel
    Texture2DMSArray,   // Texture2DMSArray<T, N>: elements of N samples per texel
    Buffer,             // Buffer<T>: typed elements (a GL buffer texture)
    StructuredBuffer,   // StructuredBuffer<T>: a GL shader storage block of T
    ByteAddressBuffer,  // raw 32-bit words: a GL shader storage block of uint
    // D3D11's read-write forms (docs/d3d10.md, "Compute shaders and read-write resources"): storage blocks...
    RWStructuredBuffer,
    RWByteAddressBuffer,
    AppendStructuredBuffer,   // a storage block of T and a counter the shader increments
    ConsumeStructuredBuffer,  // the same, the counter decremented
    // ...and GL images (image load/store), their format from the element type.
    RWTexture1D,
    RWTexture2D,
    RWTexture3D,
    RWTexture2DArray,
    RWBuffer,
    Sampler,  // untyped `sampler`
    Sampler1D,
    Sampler2D,
    Sampler3D,
    SamplerCube,
    SamplerState,            // D3D10 `SamplerState`
    SamplerComparisonState,  // D3D10 `SamplerComparisonState`
    VertexShader,            // `vertexshader vs = compile vs_3_0 ...;`
    PixelShader,
    GeometryShader,  // D3D10 shader variables of the stages GL runs only through other means
    HullShader,
    DomainShader,
    ComputeShader,
    RasterizerState,  // D3D10 state objects: `RasterizerState rs { CullMode = NONE; };`
    DepthStencilState,
    BlendState,
    RenderTargetView,  // FX10's view variables: an application sets them; nothing in an effect reads them
    DepthStencilView,
    Struct,
};

enum class Shape { Scalar, Vector, Matrix };

struct TypeDesc {
    BaseType base = BaseType::Float;
    Shape shape = Shape::Scalar;
    int rows = 1;                // matrices: rows (float4x3: 4)
    int cols = 1;                // vectors: component count; matrices: columns (float4x3: 3)
    std::vector<int> arrayDims;  // float4 a[3][2] -> {3, 2}; empty when not an array
    std::string structName;      // base == Struct
    bool rowMajor = false;       // declared `row_major` (HLSL default is column_major)
    // The template arguments of a D3D10 texture or buffer resource as written, without the angle brackets
    // ("float4, 4"; "float2" of a Texture2D<float2>, whose Sample returns a float2 as fxc's did); empty
    // elsewhere.
    std::string templateArgs;

    bool isNumeric() const;      // bool/int/uint/half/float/double
    bool isTexture() const;      // Texture..Texture2DMSArray: what TextureDesc describes
    bool isBuffer() const;       // Buffer, StructuredBuffer, ByteAddressBuffer and the read-write buffers
    bool isImage() const;        // RWTexture1D..RWBuffer: a GL image
    bool isSampler() const;      // Sampler..SamplerComparisonState
    bool isStateObject() const;  // RasterizerState, DepthStencilState, BlendState
    bool isShader() const;       // VertexShader..ComputeShader
    int componentCount() const;  // rows*cols, times array elements
    // HLSL spelling: "float4x4", "float3", "bool", "sampler2D", "MyStruct" (without array dims).
    std::string hlslName() const;
};

}  // namespace fx
