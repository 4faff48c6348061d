// What the runtime makes at load for an effect's buffers and read-write textures, resolved by the compiler
// from their annotations and types (fx::ParameterInfo::viewOf, elementCount, imageSize, bufferTexel) and
// the units of a pass's images (fx::ImageBinding::unit, declared in the GLSL): carried by the compiled
// effect and its file, and an invalid annotation or type a located compile error, with no GL context.
#include <fx/CompiledEffectFile.h>
#include <fx/EffectFile.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace fx::test_storage_resources {
namespace {

const char* const kStorage = R"(RWStructuredBuffer<float4> Cells < int ElementCount = 8; >;
StructuredBuffer<float4> CellsView < string ViewOf = "Cells"; >;
RWBuffer<float4> Values < int ElementCount = 5; >;
Buffer<float4> ValuesView < string ViewOf = "Values"; >;
RWTexture3D<float4> Volume < int Width = 4; int Height = 2; int Depth = 3; >;
Texture3D VolumeView < string ViewOf = "Volume"; >;
RWTexture1D<float4> Ramp < int Width = 16; int Height = 9; >;
RWTexture2DArray<float4> Layers < int ArraySize = 6; >;
RWByteAddressBuffer Plain;
Buffer<uint2> Indices;
Buffer< int > Signed;
)";

std::shared_ptr<CompiledEffect> compile(const std::string& source, DiagnosticList& diagnostics) {
    std::shared_ptr<Effect> effect = parseEffectSource(source, "storage.fx", ParseOptions{}, diagnostics);
    if (!effect) return nullptr;
    return compileEffect(effect, CompileOptions{}, diagnostics);
}

size_t indexOf(const CompiledEffect& effect, const std::string& name) {
    return static_cast<size_t>(effect.findParameter(name) - effect.parameters.data());
}

void expectResolved(const CompiledEffect& effect) {
    const auto parameter = [&effect](const char* name) -> const ParameterInfo& {
        return effect.parameters.at(indexOf(effect, name));
    };
    EXPECT_EQ(parameter("Cells").elementCount, 8u);
    EXPECT_EQ(parameter("Values").elementCount, 5u);
    EXPECT_EQ(parameter("Plain").elementCount, 1u);  // no ElementCount: one element
    EXPECT_FALSE(parameter("Cells").viewOf);
    EXPECT_EQ(parameter("CellsView").viewOf, indexOf(effect, "Cells"));
    EXPECT_EQ(parameter("ValuesView").viewOf, indexOf(effect, "Values"));
    EXPECT_EQ(parameter("VolumeView").viewOf, indexOf(effect, "Volume"));
    const auto size = [&parameter](const char* name) {
        const int* s = parameter(name).imageSize;
        return std::to_string(s[0]) + "x" + std::to_string(s[1]) + "x" + std::to_string(s[2]);
    };
    EXPECT_EQ(size("Volume"), "4x2x3");
    EXPECT_EQ(size("Ramp"), "16x1x1");     // a 1D texture has no height, whatever it says
    EXPECT_EQ(size("Layers"), "64x64x6");  // 64 x 64 without Width and Height
    const auto texel = [&parameter](const char* name) {
        const BufferTexel& t = parameter(name).bufferTexel;
        return std::string(t.component == BaseType::Float  ? "float"
                           : t.component == BaseType::Int  ? "int"
                           : t.component == BaseType::UInt ? "uint"
                                                           : "?") +
               std::to_string(t.components);
    };
    EXPECT_EQ(texel("ValuesView"), "float4");
    EXPECT_EQ(texel("Indices"), "uint2");
    EXPECT_EQ(texel("Signed"), "int1");    // blanks inside the brackets ignored
    EXPECT_EQ(texel("Values"), "float0");  // an RWBuffer is an image: no buffer texels
    EXPECT_EQ(texel("Cells"), "float0");
}

TEST(StorageResourceAnnotations, TheCompiledEffectAndItsFileCarryViewsCountsAndSizes) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled = compile(kStorage, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    expectResolved(*compiled);
    const std::string bytes = serializeCompiledEffect(*compiled);
    std::unique_ptr<CompiledEffect> read = deserializeCompiledEffect(bytes, "storage.sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    expectResolved(*read);
    EXPECT_EQ(serializeCompiledEffect(*read), bytes);
}

// The one error compiling `source` reports, as the CLI prints it.
std::string compileError(const std::string& source, DiagId expected) {
    DiagnosticList diagnostics;
    EXPECT_FALSE(compile(source, diagnostics));
    EXPECT_EQ(diagnostics.items().size(), 1u) << diagnostics.str();
    if (diagnostics.items().empty()) return "";
    EXPECT_EQ(diagnostics.items()[0].id, expected) << diagnostics.str();
    return renderDiagnostic(diagnostics.items()[0], false);
}

// Each at the parameter that declares it, where the runtime reported it when it read the annotations.
TEST(StorageResourceAnnotations, AnInvalidAnnotationIsALocatedCompileError) {
    EXPECT_EQ(compileError("float Scale;\nStructuredBuffer<float4> Cells < string ViewOf = \"Scale\"; >;\n",
                           DiagId::ViewOfUnknownResource),
              "storage.fx:2:26: error: 'Cells' is a view of 'Scale', which is no buffer or read-write "
              "texture parameter of the effect");
    EXPECT_EQ(
        compileError("Texture2D Lost < string ViewOf = \"Nowhere\"; >;\n", DiagId::ViewOfUnknownResource),
        "storage.fx:1:11: error: 'Lost' is a view of 'Nowhere', which is no buffer or read-write "
        "texture parameter of the effect");
    EXPECT_EQ(compileError("\nRWStructuredBuffer<uint> Counts < int ElementCount = 0; >;\n",
                           DiagId::ElementCountInvalid),
              "storage.fx:2:26: error: ElementCount of 'Counts' is 0.000000; a storage buffer holds 1 to "
              "268435456 elements");
    EXPECT_EQ(compileError("RWBuffer<float> Values < string ElementCount = \"many\"; >;\n",
                           DiagId::ElementCountInvalid),
              "storage.fx:1:17: error: ElementCount of 'Values' is not a number; a storage buffer holds 1 to "
              "268435456 elements");
    EXPECT_EQ(compileError("RWTexture3D<float4> Volume < int Width = 4; int Height = 4; int Depth = 0; >;\n",
                           DiagId::ImageSizeOutOfRange),
              "storage.fx:1:21: error: invalid render-target size: Volume is 4 x 4 x 0");
    EXPECT_EQ(compileError("RWTexture2D<float4> Wide < int Width = 20000; >;\n", DiagId::ImageSizeOutOfRange),
              "storage.fx:1:21: error: invalid render-target size: Wide is 20000 x 64");
    // Beyond any int, and not whole: refused as the annotation's number, never converted first.
    EXPECT_EQ(compileError("RWTexture2D<float4> Huge < int Width = 1e10; >;\n", DiagId::ImageSizeOutOfRange),
              "storage.fx:1:21: error: invalid render-target size: Huge is 10000000000 x 64");
    EXPECT_EQ(
        compileError("RWTexture2D<float4> Half < float Height = 2.5; >;\n", DiagId::ImageSizeOutOfRange),
        "storage.fx:1:21: error: invalid render-target size: Half is 64 x 2.5");
    // A Buffer<T> of a T that GL buffer textures cannot hold, used or not (the runtime refused it at load).
    EXPECT_EQ(compileError("\nBuffer<double2> Wide;\n", DiagId::BufferElementUnsupported),
              "storage.fx:2:17: error: Buffer<double2>: GL buffer textures hold 32-bit float, int and uint "
              "elements of 1 to 4 components");
    EXPECT_EQ(compileError("Buffer<float5> Long;\n", DiagId::BufferElementUnsupported),
              "storage.fx:1:16: error: Buffer<float5>: GL buffer textures hold 32-bit float, int and uint "
              "elements of 1 to 4 components");
}

// An image's texel format is the one its code declares (glslang's, from the element type): float and unorm
// images have one, an integer image is a compile error at the parameter, and an image no pass uses has none.
TEST(StorageResourceAnnotations, AnImageHasTheFormatItsCodeDeclares) {
    const std::string kernel = R"(
[numthreads(1, 1, 1)] void Fill(uint3 id : SV_DispatchThreadID) { Field[id.xy] = 1; }
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, Fill())); } }
)";
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled =
        compile("RWTexture2D<float2> Field;\nRWTexture2D<float4> Unused;" + kernel, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_EQ(compiled->findParameter("Field")->imageFormat, TextureFormat::RG32F);
    EXPECT_FALSE(compiled->findParameter("Unused")->imageFormat);
    const std::string error =
        compileError("RWTexture2D<uint> Field;" + kernel, DiagId::ImageFormatUnsupported);
    EXPECT_EQ(error.rfind("storage.fx:1:19: error: 'Field' (", 0), 0u) << error;
    EXPECT_NE(error.find("is an image of format 'r32ui'"), std::string::npos) << error;
}

// A view of no buffer or read-write texture, a size the compiler would have refused, or an image format no
// image can have, in a file: corrupt, refused before the runtime makes anything of it.
TEST(StorageResourceAnnotations, AViewOrSizeOutOfRangeInAFileIsCorrupt) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled = compile(kStorage, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const auto readErrorId = [](const CompiledEffect& damaged) {
        DiagnosticList errors;
        EXPECT_FALSE(deserializeCompiledEffect(serializeCompiledEffect(damaged), "storage.sfxo", errors));
        EXPECT_EQ(errors.items().size(), 1u) << errors.str();
        return errors.items().empty() ? DiagId{} : errors.items()[0].id;
    };
    const size_t view = indexOf(*compiled, "CellsView");
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[view].viewOf = damaged.parameters.size();
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterViewOutOfRange);
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[view].viewOf = indexOf(damaged, "VolumeView");  // a texture that is no image
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterViewOutOfRange);
    }
    for (int side = 0; side < 3; ++side) {
        CompiledEffect damaged = *compiled;
        damaged.parameters[indexOf(damaged, "Volume")].imageSize[side] = 0;
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterStorageSizeOutOfRange);
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[indexOf(damaged, "Cells")].elementCount = (1u << 28) + 1;
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterStorageSizeOutOfRange);
    }
    {
        CompiledEffect damaged = *compiled;  // a volume's sides stop at 2048, a 2D image's at 16384
        damaged.parameters[indexOf(damaged, "Volume")].imageSize[0] = 2049;
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterStorageSizeOutOfRange);
    }
    {
        CompiledEffect damaged = *compiled;  // a structured buffer is no image
        damaged.parameters[indexOf(damaged, "Cells")].imageFormat = TextureFormat::RGBA32F;
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterImageFormatInvalid);
    }
    {
        CompiledEffect damaged = *compiled;  // no image holds depth
        damaged.parameters[indexOf(damaged, "Volume")].imageFormat = TextureFormat::D24S8;
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterImageFormatInvalid);
    }
    // Buffer texels the runtime could not make a buffer texture of, or texels on no Buffer<T>.
    for (const BufferTexel texel : {BufferTexel{BaseType::Float, 0}, BufferTexel{BaseType::UInt, 5},
                                    BufferTexel{BaseType::Bool, 1}, BufferTexel{BaseType::Double, 2}}) {
        CompiledEffect damaged = *compiled;
        damaged.parameters[indexOf(damaged, "Indices")].bufferTexel = texel;
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterBufferTexelInvalid);
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[indexOf(damaged, "Cells")].bufferTexel = BufferTexel{BaseType::Float, 4};
        EXPECT_EQ(readErrorId(damaged), DiagId::CompiledEffectParameterBufferTexelInvalid);
    }
}

// The line of `glsl` that declares the uniform `name`, or "" where none does.
std::string declarationOf(const std::string& glsl, const std::string& name) {
    std::istringstream lines(glsl);
    for (std::string line; std::getline(lines, line);)
        if (line.find(" uniform ") != std::string::npos && line.size() > name.size() + 1 &&
            line.compare(line.size() - name.size() - 2, name.size() + 2, " " + name + ";") == 0)
            return line;
    return "";
}

// A resource whose name GLSL reserves is declared under another name by SPIRV-Cross ('_output'): its unit
// cannot be written into the GLSL, and the unit glslang numbered would bind another resource there, so the
// compile fails at the parameter instead.
TEST(StorageResourceAnnotations, AResourceGlslRenamesIsALocatedCompileError) {
    const std::string kernel = R"(
[numthreads(1, 1, 1)] void Fill(uint3 id : SV_DispatchThreadID) { output[id.xy] = 1; }
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, Fill())); } }
)";
    const std::string error =
        compileError("\nRWTexture2D<float4> output;" + kernel, DiagId::ResourceRenamedInGlsl);
    EXPECT_EQ(error.rfind("storage.fx:2:21: error: 'output' is a name GLSL reserves", 0), 0u) << error;
    DiagnosticList diagnostics;
    EXPECT_TRUE(compile(
        "\nRWTexture2D<float4> produced;" + std::string(kernel).replace(kernel.find("output"), 6, "produced"),
        diagnostics))
        << diagnostics.str();
}

// A pass's images take units in the order of their parameters, the same in every stage that declares one,
// and the GLSL declares each at its unit: the runtime binds them there and sets no unit by name. (glslang
// numbers the texture, the images and the buffer together, 1 and 3 for the images: the units replace its.)
const char* const kTwoImages = R"(
Texture2D Before;
RWTexture2D<float4> Source;
StructuredBuffer<float4> Data;
RWTexture2D<float2> Target;
[numthreads(1, 1, 1)] void Copy(uint3 id : SV_DispatchThreadID) {
    Target[id.xy] = Source[id.xy].xy + Before.Load(int3(id.xy, 0)).xy + Data[0].xy;
}
technique11 t { pass p { SetComputeShader(CompileShader(cs_5_0, Copy())); } }
)";

TEST(StorageResourceAnnotations, APassDeclaresEachImageAtItsUnit) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled = compile(kTwoImages, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const StageProgram& stage = compiled->techniques.at(0).passes.at(0).compute;
    ASSERT_EQ(stage.images.size(), 2u) << stage.glsl;
    for (const ImageBinding& image : stage.images) {
        const int unit = image.glslName == "Source" ? 0 : 1;  // Source is declared first
        EXPECT_EQ(image.unit, unit) << image.glslName;
        const std::string line = declarationOf(stage.glsl, image.glslName);
        EXPECT_EQ(line.rfind("layout(", 0), 0u) << stage.glsl;
        const std::string binding = "binding = " + std::to_string(unit);
        EXPECT_TRUE(line.find(binding + ",") != std::string::npos ||
                    line.find(binding + ")") != std::string::npos)
            << line;
        EXPECT_NE(line.find(image.format), std::string::npos) << line;
    }
    const std::string bytes = serializeCompiledEffect(*compiled);
    std::unique_ptr<CompiledEffect> read = deserializeCompiledEffect(bytes, "images.sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    for (size_t i = 0; i < 2; ++i)
        EXPECT_EQ(read->techniques[0].passes[0].compute.images[i].unit, stage.images[i].unit);
    EXPECT_EQ(serializeCompiledEffect(*read), bytes);
}

// An image unit the runtime would bind two parameters at, or out of range, an image of no parameter, and a
// list of the parameters a pass reads that is out of order or names none: corrupt.
TEST(StorageResourceAnnotations, AnImageUnitOrAPassReadOutOfRangeInAFileIsCorrupt) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled = compile(kTwoImages, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.at(0).passes.at(0).readParameters, (std::vector<size_t>{0, 1, 2, 3}));
    const auto readErrorId = [](const CompiledEffect& damaged) {
        DiagnosticList errors;
        EXPECT_FALSE(deserializeCompiledEffect(serializeCompiledEffect(damaged), "images.sfxo", errors));
        EXPECT_EQ(errors.items().size(), 1u) << errors.str();
        return errors.items().empty() ? DiagId{} : errors.items()[0].id;
    };
    const auto damage = [&compiled](const auto& change) {
        CompiledEffect damaged = *compiled;
        change(damaged.techniques[0].passes[0]);
        return damaged;
    };
    for (const int unit : {-1, 4}) {  // 4: as many as the effect has parameters
        EXPECT_EQ(readErrorId(damage([unit](CompiledPass& pass) { pass.compute.images[0].unit = unit; })),
                  DiagId::CompiledEffectImageUnitInvalid);
    }
    EXPECT_EQ(readErrorId(damage([](CompiledPass& pass) {
                  pass.compute.images[0].unit = pass.compute.images[1].unit;  // two parameters, one unit
              })),
              DiagId::CompiledEffectImageUnitInvalid);
    EXPECT_EQ(readErrorId(damage([](CompiledPass& pass) {
                  pass.compute.images.push_back(pass.compute.images[0]);  // one parameter at another unit
                  pass.compute.images.back().unit = 1 - pass.compute.images[0].unit;
              })),
              DiagId::CompiledEffectImageUnitInvalid);
    EXPECT_EQ(readErrorId(damage([](CompiledPass& pass) { pass.compute.images[0].parameter = 4; })),
              DiagId::CompiledEffectImageWithoutParameter);
    EXPECT_EQ(readErrorId(damage([](CompiledPass& pass) {
                  pass.readParameters = {1, 0};
              })),
              DiagId::CompiledEffectPassReadsOutOfRange);
    EXPECT_EQ(readErrorId(damage([](CompiledPass& pass) {
                  pass.readParameters = {0, 0};
              })),
              DiagId::CompiledEffectPassReadsOutOfRange);
    EXPECT_EQ(readErrorId(damage([](CompiledPass& pass) { pass.readParameters.push_back(4); })),
              DiagId::CompiledEffectPassReadsOutOfRange);
}

}  // namespace
}  // namespace fx::test_storage_resources
