// ParameterSemantics: the runtime's semantics, their spellings and the compiler's classification
// (fx/ParameterSemantics.h, SemanticClassification.h).
#include "SemanticClassification.h"

#include "CaseFolding.h"

#include <fx/ParameterSemantics.h>

#include <cctype>
#include <iterator>
#include <optional>
#include <string_view>
#include <utility>

namespace fx {

namespace {

// Every semantic with its spellings, as the docs write them (matched case-blind).
constexpr std::pair<const char*, SemanticKind> kMatrixSemantics[] = {
    {"World", SemanticKind::World},
    {"View", SemanticKind::View},
    {"Projection", SemanticKind::Projection},
    {"WorldView", SemanticKind::WorldView},
    {"ViewProjection", SemanticKind::ViewProjection},
    {"WorldViewProjection", SemanticKind::WorldViewProjection},
};
constexpr const char* kMatrixSuffixes[] = {"Inverse", "Transpose", "InverseTranspose"};
constexpr std::pair<const char*, SemanticKind> kOtherSemantics[] = {
    {"ViewportPixelSize", SemanticKind::ViewportPixelSize},
    {"Time", SemanticKind::Time},
    {"CameraPosition", SemanticKind::CameraPosition},
    {"EyePosition", SemanticKind::CameraPosition},
    {"ObjectId", SemanticKind::ObjectId},
    {"Position", SemanticKind::LightPosition},
    {"LightPosition", SemanticKind::LightPosition},
    {"Direction", SemanticKind::LightDirection},
    {"LightDirection", SemanticKind::LightDirection},
    {"LightColor", SemanticKind::LightColor},
    {"LightAreaRadius", SemanticKind::LightAreaRadius},
    {"LightSize", SemanticKind::LightAreaRadius},
    {"LightRange", SemanticKind::LightRange},
    {"Diffuse", SemanticKind::ObjectColor},
    {"MaterialDiffuse", SemanticKind::ObjectColor},
    {"DiffuseColor", SemanticKind::ObjectColor},
    {"Ambient", SemanticKind::Ambient},
    {"LightCount", SemanticKind::LightCount},
    {"SceneHasClosedObjects", SemanticKind::SceneHasClosedObjects},
    {"CascadeViewProjection", SemanticKind::CascadeViewProjection},
    {"CascadeAtlasRects", SemanticKind::CascadeAtlasRects},
    {"CascadeSplitDepths", SemanticKind::CascadeSplitDepths},
    {"CubeFaceSelect", SemanticKind::CubeFaceSelect},
    {"WorldMatrixArray", SemanticKind::WorldMatrixArray},
    {"BonePalette", SemanticKind::BonePalette},
    {"FXCOMPOSER_RESETPULSE", SemanticKind::ResetPulse},
};
// Read by the light fits, whatever the parameter's type (LiSPSMNOpt is a string).
constexpr std::pair<const char*, SemanticKind> kTunableSemantics[] = {
    {"LiSPSMNScale", SemanticKind::LispsmNScale},
    {"LiSPSMNOpt", SemanticKind::LispsmNOpt},
    {"LiSPSMDepthExtent", SemanticKind::LispsmDepthExtent},
    {"LiSPSMMiddleVector", SemanticKind::LispsmMiddleVector},
    {"LightPancaking", SemanticKind::LightPancaking},
    {"TSMFocus", SemanticKind::TsmFocus},
    {"PSMSlideBack", SemanticKind::PsmSlideBack},
    {"PSMMaxWarpRatio", SemanticKind::PsmMaxWarpRatio},
    {"CascadeCount", SemanticKind::CascadeCount},
    {"CascadeSplitLambda", SemanticKind::CascadeSplitLambda},
    {"CascadeBlend", SemanticKind::CascadeBlend},
    {"LightFitVisibleSamples", SemanticKind::LightFitVisibleSamples},
    // The parameter whose Script the compiler reads (ScriptValidation.cpp).
    {"STANDARDSGLOBAL", SemanticKind::StandardsGlobal},
};

// Each kind's name, in SemanticKind's order.
constexpr const char* kKindNames[] = {
    "",
    "World",
    "View",
    "Projection",
    "WorldView",
    "ViewProjection",
    "WorldViewProjection",
    "ViewportPixelSize",
    "Time",
    "CameraPosition",
    "ObjectId",
    "LightPosition",
    "LightDirection",
    "LightColor",
    "LightAreaRadius",
    "LightRange",
    "Diffuse",
    "Ambient",
    "LightCount",
    "SceneHasClosedObjects",
    "CascadeViewProjection",
    "CascadeAtlasRects",
    "CascadeSplitDepths",
    "CubeFaceSelect",
    "WorldMatrixArray",
    "BonePalette",
    "FXCOMPOSER_RESETPULSE",
    "LiSPSMNScale",
    "LiSPSMNOpt",
    "LiSPSMDepthExtent",
    "LiSPSMMiddleVector",
    "LightPancaking",
    "TSMFocus",
    "PSMSlideBack",
    "PSMMaxWarpRatio",
    "CascadeCount",
    "CascadeSplitLambda",
    "CascadeBlend",
    "LightFitVisibleSamples",
    "STANDARDSGLOBAL",
};
static_assert(std::size(kKindNames) == static_cast<size_t>(SemanticKind::StandardsGlobal) + 1);

bool consumeSuffix(std::string& text, std::string_view suffix) {
    if (text.size() < suffix.size() || text.compare(text.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
    text.resize(text.size() - suffix.size());
    return true;
}

bool consumePrefix(std::string& text, std::string_view prefix) {
    if (text.size() <= prefix.size() || text.compare(0, prefix.size(), prefix) != 0) return false;
    text.erase(0, prefix.size());
    return true;
}

// A bound semantic's kind and matrix suffix; false for one the runtime does not bind.
bool classifyBound(std::string_view semantic, SemanticBinding& binding) {
    std::string name = upperCase(semantic);
    if (consumeSuffix(name, "INVERSETRANSPOSE")) {
        binding.inverse = binding.transpose = true;
    } else if (consumeSuffix(name, "TRANSPOSE")) {
        binding.transpose = true;
    } else if (consumeSuffix(name, "INVERSE")) {
        binding.inverse = true;
    }
    for (const auto& [text, kind] : kMatrixSemantics) {
        if (name == upperCase(text)) {
            binding.kind = kind;
            return true;
        }
    }
    if (binding.inverse || binding.transpose) return false;
    for (const auto& [text, kind] : kOtherSemantics) {
        if (name == upperCase(text)) {
            binding.kind = kind;
            return true;
        }
    }
    return false;
}

// `name` without its scope prefix (g_, m_, g before a capital) and Hungarian type prefix (m, mat, mtx,
// v, vec, f, n, i before a capital), underscores removed, in capitals.
std::string conventionalStem(std::string_view name) {
    std::string text(name);
    const auto capitalAt = [&text](size_t i) {
        return i < text.size() && (std::isupper(static_cast<unsigned char>(text[i])) || text[i] == '_');
    };
    if (text.rfind("g_", 0) == 0 || text.rfind("m_", 0) == 0) {
        text.erase(0, 2);
    } else if (text.size() > 1 && text[0] == 'g' && capitalAt(1)) {
        text.erase(0, 1);
    }
    for (std::string_view hungarian : {"mtx", "mat", "vec", "m", "v", "f", "n", "i"}) {
        if (text.rfind(hungarian, 0) == 0 && capitalAt(hungarian.size())) {
            text.erase(0, hungarian.size());
            break;
        }
    }
    std::string stem;
    for (char c : text)
        if (c != '_') stem += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return stem;
}

// The number of a numbered light's property, taken out of its stem: XNA's `DIRLIGHT1DIRECTION`, `LIGHT2POS`,
// `LIGHTDIR0`; -1 where the stem names no numbered light. A `DIR`, `DIRECTIONAL`, `POINT` or `SPOT` before
// `LIGHT` goes too (`DIRLIGHT1DIRECTION` becomes `LIGHTDIRECTION`).
int takeLightNumber(std::string& stem) {
    const size_t light = stem.find("LIGHT");
    if (light == std::string::npos) return -1;
    const auto isDigit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    size_t first = light + 5, last = first;
    while (last < stem.size() && isDigit(stem[last])) ++last;
    if (last == first) {
        last = stem.size();
        first = last;
        while (first > light + 5 && isDigit(stem[first - 1])) --first;
    }
    // One or two digits: a longer number is not a light's.
    if (last == first || last - first > 2) return -1;
    const int number = std::stoi(stem.substr(first, last - first));
    stem.erase(first, last - first);
    for (std::string_view kind : {"DIRECTIONAL", "DIR", "POINT", "SPOT"})
        if (stem.compare(0, kind.size(), kind) == 0 && stem.compare(kind.size(), 5, "LIGHT") == 0) {
            stem.erase(0, kind.size());
            break;
        }
    return number;
}

}  // namespace

bool isBoundSemantic(SemanticKind kind) {
    return kind != SemanticKind::None && kind < SemanticKind::LispsmNScale;
}

std::string semanticBindingName(const SemanticBinding& binding, std::string_view lightName) {
    std::string name = kKindNames[static_cast<size_t>(binding.kind)];
    if (binding.inverse && binding.transpose) {
        name += "InverseTranspose";
    } else if (binding.transpose) {
        name += "Transpose";
    } else if (binding.inverse) {
        name += "Inverse";
    }
    if (binding.eachLight) name += " of each light";
    if (!lightName.empty()) name += " of " + std::string(lightName);
    if (binding.viewSpace) name += " in view space";
    if (binding.towardsLight) name += ", towards the light";
    return name;
}

std::vector<std::string> standardSemanticNames() {
    std::vector<std::string> names;
    for (const auto& [text, kind] : kMatrixSemantics) {
        names.push_back(text);
        for (const char* suffix : kMatrixSuffixes) names.push_back(std::string(text) + suffix);
    }
    for (const auto& [text, kind] : kOtherSemantics) names.push_back(text);
    for (const auto& [text, kind] : kTunableSemantics) names.push_back(text);
    return names;
}

ConventionalSemantic conventionalSemantic(const ParameterInfo& parameter, bool hasInitializer) {
    if (!parameter.semantic.empty() || parameter.isStatic || !parameter.type.isNumeric()) return {};
    std::string stem = conventionalStem(parameter.name);
    const TypeDesc& type = parameter.type;
    if (type.shape == Shape::Matrix) {
        if (type.rows < 3 || type.cols < 3 || type.arrayDims.size() > 1) return {};
        // A skinning palette only its application fills (`Bones`, `g_mConstBoneWorld`, `amPalette`,
        // `g_mWorldMatrixArray`): the mesh drawn as modelled, where the object stands when the name says
        // its bones are placed in the world.
        if (!type.arrayDims.empty()) {
            const auto has = [&stem](const char* word) { return stem.find(word) != std::string::npos; };
            const bool palette = has("BONE") || has("PALETTE") || has("SKIN") || stem == "WORLDMATRIXARRAY" ||
                                 stem == "WORLDMATRICES";
            if (!palette || hasInitializer) return {};
            return {has("WORLD") ? "WorldMatrixArray" : "BonePalette"};
        }
        // `WorldMatrix`, `WorldMtx`, `WorldMat`, `WorldM`, and an engine's `MATRIX_WVP` semantic.
        if (!consumeSuffix(stem, "MATRIX") && !consumeSuffix(stem, "MTX") && !consumeSuffix(stem, "MAT"))
            consumeSuffix(stem, "M");
        consumePrefix(stem, "MATRIX");
        // A light's matrices by name (XNA's shadow-mapping sample's `LightViewProj`): the light's own.
        int lightNumber = -1;
        bool light = false;
        if (stem.rfind("LIGHT", 0) == 0) {
            lightNumber = takeLightNumber(stem);
            light = true;
            stem.erase(0, 5);
            if (stem != "VIEW" && stem != "PROJ" && stem != "PROJECTION" && stem != "VIEWPROJ" &&
                stem != "VIEWPROJECTION" && stem != "VP")
                return {};
        }
        std::string modifier;
        if (consumeSuffix(stem, "INVERSETRANSPOSE") || consumeSuffix(stem, "INVTRANSPOSE") ||
            consumeSuffix(stem, "INVTRANS") || consumeSuffix(stem, "IT")) {
            modifier = "InverseTranspose";
        } else if (consumeSuffix(stem, "INVERSE") || consumeSuffix(stem, "INV") ||
                   consumePrefix(stem, "INVERSE") || consumePrefix(stem, "INV")) {
            modifier = "Inverse";
        }
        static const std::pair<const char*, const char*> kMatrixNames[] = {
            {"WORLD", "World"},
            {"MODEL", "World"},
            {"VIEW", "View"},
            {"PROJ", "Projection"},
            {"PROJECTION", "Projection"},
            {"WORLDVIEW", "WorldView"},
            {"MODELVIEW", "WorldView"},
            {"WV", "WorldView"},
            {"VIEWPROJ", "ViewProjection"},
            {"VIEWPROJECTION", "ViewProjection"},
            {"VP", "ViewProjection"},
            {"WORLDVIEWPROJ", "WorldViewProjection"},
            {"WORLDVIEWPROJECTION", "WorldViewProjection"},
            {"MODELVIEWPROJ", "WorldViewProjection"},
            {"MODELVIEWPROJECTION", "WorldViewProjection"},
            {"WVP", "WorldViewProjection"},
            {"MVP", "WorldViewProjection"},
        };
        for (const auto& [text, semantic] : kMatrixNames)
            if (stem == text) return {semantic + modifier, false, lightNumber, light && lightNumber < 0};
        return {};
    }
    // The render target's size in pixels, which the application sets (`DestinationDimensions`,
    // `ScreenSize`), where the effect gives no value of its own (a `Resolution` with one may be a map's).
    if (type.shape == Shape::Vector && type.cols == 2 && type.arrayDims.empty()) {
        if (hasInitializer) return {};
        static const char* kViewportSizeNames[] = {
            "VIEWPORTSIZE",          "VIEWPORTPIXELSIZE", "VIEWPORTDIMENSIONS", "SCREENSIZE",
            "SCREENRESOLUTION",      "SCREENDIMENSIONS",  "RESOLUTION",         "RENDERTARGETSIZE",
            "DESTINATIONDIMENSIONS", "DESTINATIONSIZE"};
        for (const char* text : kViewportSizeNames)
            if (stem == text) return {"ViewportPixelSize"};
        return {};
    }
    // One level of array: a light property per light (SemanticBinding::eachLight).
    const bool isArray = !type.arrayDims.empty();
    if (type.shape == Shape::Vector && type.cols >= 3 && type.arrayDims.size() <= 1) {
        // A numbered light's property is one light's, never an array's.
        const int lightNumber = isArray ? -1 : takeLightNumber(stem);
        struct VectorName {
            const char* stem;
            const char* semantic;
            bool viewSpace;
            bool lightProperty;  // may be an array, one element per light
        };
        static const VectorName kVectorNames[] = {
            {"EYEPOS", "CameraPosition", false, false},
            {"EYEPOSW", "CameraPosition", false, false},
            {"EYEPOSITION", "CameraPosition", false, false},
            {"EYEPOSITIONW", "CameraPosition", false, false},
            {"EYEPT", "CameraPosition", false, false},
            {"EYE", "CameraPosition", false, false},
            {"CAMERAPOS", "CameraPosition", false, false},
            {"CAMERAPOSW", "CameraPosition", false, false},
            {"CAMERAPOSITION", "CameraPosition", false, false},
            {"CAMPOS", "CameraPosition", false, false},
            {"VIEWPOS", "CameraPosition", false, false},
            {"VIEWPOSITION", "CameraPosition", false, false},
            {"VIEWERPOS", "CameraPosition", false, false},
            {"LIGHTDIR", "LightDirection", false, true},
            {"LIGHTDIRW", "LightDirection", false, true},
            {"LIGHTDIRECTION", "LightDirection", false, true},
            {"WORLDLIGHTDIR", "LightDirection", false, true},
            {"WORLDSPACELIGHTDIR", "LightDirection", false, true},
            {"VIEWSPACELIGHTDIR", "LightDirection", true, true},
            {"VIEWLIGHTDIR", "LightDirection", true, true},
            {"LIGHTDIRVIEW", "LightDirection", true, true},
            {"LIGHTDIRV", "LightDirection", true, true},
            {"LIGHTPOS", "LightPosition", false, true},
            {"LIGHTPOSW", "LightPosition", false, true},
            {"LIGHTPOSITION", "LightPosition", false, true},
            {"WORLDLIGHTPOS", "LightPosition", false, true},
            {"VIEWSPACELIGHTPOS", "LightPosition", true, true},
            {"VIEWLIGHTPOS", "LightPosition", true, true},
            {"LIGHTPOSVIEW", "LightPosition", true, true},
            {"LIGHTPOSV", "LightPosition", true, true},
        };
        // A light's properties and the colours only where the effect gives no value of its own: an
        // application set them, and D3D leaves them zero (no light, a black object) until it does. A
        // camera's position is the camera's whatever the effect's placeholder.
        for (const VectorName& name : kVectorNames)
            if (stem == name.stem && (!isArray || name.lightProperty) &&
                (lightNumber < 0 || name.lightProperty) && !(name.lightProperty && hasInitializer))
                return {name.semantic, name.viewSpace, name.lightProperty ? lightNumber : -1};
        if (hasInitializer) return {};
        static const std::pair<const char*, const char*> kColorNames[] = {
            {"LIGHTCOLOR", "LightColor"},
            {"LIGHTCOLOUR", "LightColor"},
            {"LIGHTCOL", "LightColor"},
            {"LIGHTDIFFUSE", "LightColor"},
            {"LIGHTDIFFUSECOLOR", "LightColor"},
            {"LIGHTSPECULAR", "LightColor"},
            {"LIGHTSPECULARCOLOR", "LightColor"},
            {"AMBIENT", "Ambient"},
            {"AMBIENTCOLOR", "Ambient"},
            {"AMBIENTCOLOUR", "Ambient"},
            {"AMBIENTLIGHT", "Ambient"},
            {"AMBIENTLIGHTCOLOR", "Ambient"},
            {"LIGHTAMBIENT", "Ambient"},
            {"LIGHTAMBIENTCOLOR", "Ambient"},
            {"MATERIALDIFFUSE", "Diffuse"},
            {"MATERIALDIFFUSECOLOR", "Diffuse"},
            {"MATERIALCOLOR", "Diffuse"},
            {"MATERIALCOLOUR", "Diffuse"},
            {"MATDIFFUSE", "Diffuse"},
            {"DIFFUSECOLOR", "Diffuse"},
            {"DIFFUSECOLOUR", "Diffuse"},
            {"MATERIALAMBIENT", "Diffuse"},
            {"MATERIALAMBIENTCOLOR", "Diffuse"},
            {"MATAMBIENT", "Diffuse"},
            {"DIFFUSE", "Diffuse"},
            {"MATCOLOR", "Diffuse"},
        };
        for (const auto& [text, semantic] : kColorNames) {
            const bool isLightColor = std::string_view(semantic) == "LightColor";
            if (stem == text && (!isArray || isLightColor) && (lightNumber < 0 || isLightColor))
                return {semantic, false, lightNumber};
        }
        return {};
    }
    if (type.shape != Shape::Scalar || isArray) return {};
    if (stem == "TIME" || stem == "TOTALTIME" || stem == "APPTIME") return {"Time"};
    if (!hasInitializer && (stem == "NUMLIGHTS" || stem == "LIGHTCOUNT" || stem == "NUMACTIVELIGHTS"))
        return {"LightCount"};
    return {};
}

LightNumbering lightNumbering(const std::vector<ParameterInfo>& parameters,
                              const std::vector<bool>& hasInitializer) {
    LightNumbering numbering;
    int lowest = -1;
    for (size_t i = 0; i < parameters.size(); ++i) {
        const ParameterInfo& parameter = parameters[i];
        if (!parameter.light.empty() || !parameter.type.arrayDims.empty()) continue;  // not numbered by name
        const ConventionalSemantic conventional = conventionalSemantic(parameter, hasInitializer[i]);
        if (conventional.lightNumber >= 0) {
            if (lowest < 0 || conventional.lightNumber < lowest) lowest = conventional.lightNumber;
        } else if (conventional.semantic.rfind("Light", 0) == 0 && conventional.semantic != "LightCount") {
            numbering.afterUnnumbered = true;
        }
    }
    numbering.first = std::max(lowest, 0);
    return numbering;
}

SemanticBinding classifySemantic(const ParameterInfo& parameter, bool hasInitializer,
                                 const LightNumbering& numbering, std::string& lightName) {
    SemanticBinding binding;
    lightName.clear();
    const std::string upperSemantic = upperCase(parameter.semantic);
    for (const auto& [text, kind] : kTunableSemantics) {
        if (upperSemantic == upperCase(text)) {
            binding.kind = kind;
            return binding;
        }
    }
    // The runtime writes numbers into parameters it may change.
    if (parameter.isStatic || !parameter.type.isNumeric()) return binding;
    binding.byName = parameter.semantic.empty();
    std::string semantic = parameter.semantic;
    int lightNumber = -1;
    bool firstLight = false;
    std::optional<ConventionalSemantic> read;
    SemanticBinding standard;
    if (binding.byName) {
        read = conventionalSemantic(parameter, hasInitializer);
    } else if (!classifyBound(semantic, standard)) {
        // A semantic no table spells (an engine's `MATRIX_WVP`, `WorldMatrix`, MTA's `LIGHTDIFFUSE`): read
        // as a name would be.
        ParameterInfo spelled = parameter;
        spelled.name = parameter.semantic;
        spelled.semantic.clear();
        read = conventionalSemantic(spelled, hasInitializer);
        binding.byName = !read->semantic.empty();
    }
    if (binding.byName) {
        const ConventionalSemantic& conventional = *read;
        semantic = conventional.semantic;
        binding.viewSpace = conventional.viewSpace;
        lightNumber = conventional.lightNumber;
        firstLight = conventional.firstLight;
    }
    if (semantic.empty() || !classifyBound(semantic, binding)) return SemanticBinding{};
    // The D3D samples' light direction points towards the light; a numbered light's, as XNA's
    // DirectionalLight::Direction and D3D9's D3DLIGHT9::Direction, the way the light travels, unless the
    // effect numbers its lights after an unnumbered one (LightNumbering).
    binding.towardsLight = binding.byName && parameter.semantic.empty() &&
                           binding.kind == SemanticKind::LightDirection &&
                           (lightNumber < 0 || numbering.afterUnnumbered);

    const SemanticKind kind = binding.kind;
    const bool isCascadeProperty =
        kind == SemanticKind::CascadeViewProjection || kind == SemanticKind::CascadeAtlasRects ||
        kind == SemanticKind::CascadeSplitDepths || kind == SemanticKind::CubeFaceSelect;
    const bool isLightProperty = kind == SemanticKind::LightPosition ||
                                 kind == SemanticKind::LightDirection || kind == SemanticKind::LightColor ||
                                 kind == SemanticKind::LightAreaRadius || kind == SemanticKind::LightRange ||
                                 isCascadeProperty;
    // Position/Direction/Diffuse without a light annotation are the object's, not a light's; only
    // LightPosition/LightDirection/LightColor and the cascades default to light0.
    const bool spellsLight = upperCase(semantic).rfind("LIGHT", 0) == 0;
    // An array of a light's property without a light named: one element per light of the scene.
    if (parameter.light.empty() && isLightProperty && !isCascadeProperty && spellsLight &&
        parameter.type.arrayDims.size() == 1) {
        binding.eachLight = true;
        return binding;
    }
    if (lightNumber >= 0 && parameter.light.empty()) {
        lightName = "light" + std::to_string(numbering.sceneLight(lightNumber));
    } else if (!parameter.light.empty() || firstLight ||
               (isLightProperty && (spellsLight || isCascadeProperty))) {
        lightName = parameter.light.empty() ? "light0" : parameter.light;
        if (binding.kind == SemanticKind::ObjectColor) binding.kind = SemanticKind::LightColor;
    }
    return binding;
}

}  // namespace fx
