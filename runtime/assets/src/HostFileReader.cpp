// HostFileReader: JSON → fx::HostFile (runtime/HostFileReader.h). Feature list:
//   [SECTION] Values     — what a parameter is: "WorldView", "light0.ViewPosition", a product, numbers
//   [SECTION] Reader     — typed reads that report at the value's line and column
//   [SECTION] Entry points
#include <runtime/HostFileReader.h>

#include "JsonLocations.h"

#include <fx/LiteralNumbers.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <limits>
#include <initializer_list>
#include <sstream>
#include <string_view>

namespace runtime {

using fx::HostFile;
using fx::HostLightProjection;
using fx::HostMatrix;
using fx::HostParameter;
using fx::HostStep;
using fx::HostTarget;
using fx::HostValue;
using fx::HostVisibility;

namespace {

using nlohmann::json;

// A JSON number as a float: clamped to float's range (a double beyond it converts to nothing defined).
float toFloat(const json& value) {
    const double d = value.get<double>();
    return static_cast<float>(
        std::clamp(d, -double(std::numeric_limits<float>::max()), double(std::numeric_limits<float>::max())));
}

// [SECTION] Values

bool endsWith(std::string_view text, std::string_view suffix) {
    return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

// "WorldViewProjectionInverseTranspose" and its shorter forms.
std::optional<HostMatrix> matrixNamed(std::string_view name) {
    HostMatrix matrix;
    if (endsWith(name, "Transpose")) {
        matrix.transpose = true;
        name.remove_suffix(9);
    }
    if (endsWith(name, "Inverse")) {
        matrix.inverse = true;
        name.remove_suffix(7);
    }
    static const std::pair<std::string_view, HostMatrix::Kind> kinds[] = {
        {"World", HostMatrix::Kind::World},
        {"View", HostMatrix::Kind::View},
        {"Projection", HostMatrix::Kind::Projection},
        {"WorldView", HostMatrix::Kind::WorldView},
        {"ViewProjection", HostMatrix::Kind::ViewProjection},
        {"WorldViewProjection", HostMatrix::Kind::WorldViewProjection},
    };
    for (const auto& [spelling, kind] : kinds)
        if (name == spelling) {
            matrix.kind = kind;
            return matrix;
        }
    return std::nullopt;
}

// One string of the value grammar (docs/host-files.md, "Parameters"): a matrix, optionally "camera." or
// "LIGHT." before it; a light's quantity after "LIGHT."; ObjectColor; ViewportSize.
std::optional<HostValue> valueNamed(const std::string& text) {
    HostValue value;
    if (text == "ObjectColor") {
        value.kind = HostValue::Kind::ObjectColor;
        return value;
    }
    if (text == "ViewportSize") {
        value.kind = HostValue::Kind::ViewportSize;
        return value;
    }
    const size_t dot = text.find('.');
    const std::string owner = dot == std::string::npos ? "" : text.substr(0, dot);
    const std::string name = dot == std::string::npos ? text : text.substr(dot + 1);
    if (std::optional<HostMatrix> matrix = matrixNamed(name)) {
        matrix->space = owner.empty()       ? HostMatrix::Space::Port
                        : owner == "camera" ? HostMatrix::Space::Camera
                                            : HostMatrix::Space::Light;
        if (matrix->space == HostMatrix::Space::Light) matrix->light = owner;
        value.kind = HostValue::Kind::Matrix;
        value.factors.push_back(*matrix);
        return value;
    }
    if (!owner.empty() && owner != "camera") {
        static const std::pair<std::string_view, std::pair<HostValue::Kind, bool>> quantities[] = {
            {"Position", {HostValue::Kind::LightPosition, false}},
            {"ViewPosition", {HostValue::Kind::LightPosition, true}},
            {"Direction", {HostValue::Kind::LightDirection, false}},
            {"ViewDirection", {HostValue::Kind::LightDirection, true}},
            {"Color", {HostValue::Kind::LightColor, false}},
            {"CosHalfAngle", {HostValue::Kind::LightCosHalfAngle, false}},
        };
        for (const auto& [spelling, kind] : quantities)
            if (name == spelling) {
                value.kind = kind.first;
                value.cameraViewSpace = kind.second;
                value.light = owner;
                return value;
            }
    }
    return std::nullopt;
}

// [SECTION] Reader

class HostFileReader {
public:
    HostFileReader(std::string path, const std::string& text, fx::DiagnosticSink& diagnostics)
        : mLocations(path, text), mDiagnostics(diagnostics) {
        mHost = std::make_shared<HostFile>();
        mHost->path = std::move(path);
    }

    std::shared_ptr<const HostFile> read(const json& root) {
        const json::json_pointer top;
        if (!isObject(root, top)) return nullptr;
        checkKeys(root, top, {"targets", "lights", "parameters", "frame", "visibility"});
        if (auto it = root.find("targets"); it != root.end() && isObject(*it, top / "targets"))
            for (const auto& [name, target] : it->items()) readTarget(name, target, top / "targets" / name);
        if (auto it = root.find("lights"); it != root.end() && isObject(*it, top / "lights"))
            for (const auto& [name, light] : it->items()) readLight(name, light, top / "lights" / name);
        if (auto it = root.find("parameters"); it != root.end() && isObject(*it, top / "parameters"))
            for (const auto& [name, value] : it->items())
                if (auto parameter = readParameter(name, value, top / "parameters" / name))
                    mHost->parameters.push_back(std::move(*parameter));
        const auto frame = root.find("frame");
        if (frame == root.end()) {
            error(top, fx::DiagId::HostFrameMissing);
        } else if (!frame->is_array() || frame->empty()) {
            error(top / "frame", fx::DiagId::HostFrameNotSteps);
        } else {
            for (size_t i = 0; i < frame->size(); ++i) readStep((*frame)[i], top / "frame" / i);
        }
        if (auto it = root.find("visibility"); it != root.end()) readVisibility(*it, top / "visibility");
        return mFailed ? nullptr : mHost;
    }

private:
    fx::SourceLoc loc(const json::json_pointer& where) const { return mLocations.at(where.to_string()); }
    static std::string key(const json::json_pointer& where) {
        std::string text = where.to_string();
        return text.empty() ? "(top)" : text.substr(1);
    }
    void error(const json::json_pointer& where, fx::DiagId id, std::vector<std::string> args = {}) {
        args.insert(args.begin(), key(where));
        mDiagnostics.report(id, loc(where), args);
        mFailed = true;
    }

    // Warns about keys outside `known`: a typo ("claer") would otherwise silently do nothing.
    void checkKeys(const json& object, const json::json_pointer& where,
                   std::initializer_list<std::string_view> known) {
        for (const auto& [name, value] : object.items()) {
            bool found = false;
            for (std::string_view k : known) found = found || name == k;
            if (!found)
                mDiagnostics.report(fx::DiagId::SceneUnknownKey, loc(where / name), {key(where), name});
        }
    }

    bool isObject(const json& value, const json::json_pointer& where) {
        if (value.is_object()) return true;
        error(where, fx::DiagId::HostObjectExpected, {value.type_name()});
        return false;
    }

    std::optional<std::string> string(const json& value, const json::json_pointer& where) {
        if (value.is_string()) return value.get<std::string>();
        error(where, fx::DiagId::HostStringExpected, {value.type_name()});
        return std::nullopt;
    }

    // A number, a bool or an array of them: the components of a constant.
    static std::optional<std::vector<float>> numbers(const json& value) {
        if (value.is_number()) return std::vector<float>{toFloat(value)};
        if (value.is_boolean()) return std::vector<float>{value.get<bool>() ? 1.0f : 0.0f};
        if (!value.is_array() || value.empty()) return std::nullopt;
        std::vector<float> out;
        for (const json& element : value) {
            if (!element.is_number()) return std::nullopt;
            out.push_back(toFloat(element));
        }
        return out;
    }

    void readTarget(const std::string& name, const json& value, const json::json_pointer& where) {
        if (!isObject(value, where)) return;
        checkKeys(value, where, {"format", "size", "texture", "kind", "layers"});
        HostTarget target;
        target.name = name;
        target.loc = loc(where);
        if (name == "frame") error(where, fx::DiagId::HostTargetNamedFrame);
        if (auto it = value.find("format"); it != value.end()) {
            if (std::optional<std::string> format = string(*it, where / "format")) {
                const std::optional<fx::TextureFormat> parsed = fx::parseTextureFormat(*format);
                if (!parsed || fx::isDepthFormat(*parsed))
                    error(where / "format", fx::DiagId::HostTargetFormatInvalid, {*format});
                else
                    target.format = *parsed;
            }
        }
        if (auto it = value.find("size"); it != value.end()) {
            const json& size = *it;
            if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() ||
                !size[1].is_number_integer() || size[0].get<long long>() < 1 ||
                size[1].get<long long>() < 1 || size[0].get<long long>() > 16384 ||
                size[1].get<long long>() > 16384)
                error(where / "size", fx::DiagId::HostTargetSizeInvalid);
            else {
                target.width = size[0].get<int>();
                target.height = size[1].get<int>();
            }
        }
        if (auto it = value.find("texture"); it != value.end())
            if (std::optional<std::string> texture = string(*it, where / "texture"))
                target.texture = *texture;
        if (auto it = value.find("kind"); it != value.end())
            if (std::optional<std::string> kind = string(*it, where / "kind")) {
                using Kind = fx::HostTarget::Kind;
                bool known = false;
                for (Kind k : {Kind::Plane, Kind::Cube, Kind::Array, Kind::Volume})
                    if (*kind == fx::hostTargetKindName(k)) {
                        target.kind = k;
                        known = true;
                    }
                if (!known) error(where / "kind", fx::DiagId::HostTargetKindInvalid, {*kind});
            }
        if (auto it = value.find("layers"); it != value.end()) {
            const json& layers = *it;
            if (target.kind != fx::HostTarget::Kind::Array && target.kind != fx::HostTarget::Kind::Volume)
                error(where / "layers", fx::DiagId::HostTargetLayersWithoutLayers,
                      {std::string(fx::hostTargetKindName(target.kind))});
            else if (!layers.is_number_integer() || layers.get<long long>() < 1 ||
                     layers.get<long long>() > 2048)
                error(where / "layers", fx::DiagId::HostTargetLayersInvalid);
            else
                target.layers = layers.get<int>();
        }
        mHost->targets.push_back(std::move(target));
    }

    void readLight(const std::string& name, const json& value, const json::json_pointer& where) {
        if (!isObject(value, where)) return;
        checkKeys(value, where, {"fovY", "near", "far"});
        HostLightProjection light;
        light.light = name;
        light.loc = loc(where);
        const auto positive = [&](const char* key, float& out) {
            const auto it = value.find(key);
            if (it == value.end() || !it->is_number() || !(it->get<double>() > 0.0)) {
                error(it == value.end() ? where : where / key, fx::DiagId::HostLightValueNotPositive, {key});
                return false;
            }
            out = toFloat(*it);
            return true;
        };
        if (positive("fovY", light.fovY) && light.fovY >= 180.0f)
            error(where / "fovY", fx::DiagId::HostLightFovTooWide);
        if (positive("near", light.nearPlane) && positive("far", light.farPlane) &&
            light.farPlane <= light.nearPlane)
            error(where / "far", fx::DiagId::HostLightFarNotBeyondNear);
        mHost->lights.push_back(std::move(light));
    }

    std::optional<HostParameter> readParameter(const std::string& name, const json& value,
                                               const json::json_pointer& where) {
        HostParameter parameter;
        parameter.name = name;
        parameter.loc = loc(where);
        if (value.is_string()) {
            std::optional<HostValue> named = valueNamed(value.get<std::string>());
            if (!named) {
                error(where, fx::DiagId::HostValueUnknown, {value.get<std::string>()});
                return std::nullopt;
            }
            parameter.value = std::move(*named);
            return parameter;
        }
        if (std::optional<std::vector<float>> constant = numbers(value)) {
            parameter.value.kind = HostValue::Kind::Constant;
            parameter.value.numbers = std::move(*constant);
            return parameter;
        }
        if (value.is_array() && !value.empty()) {
            // A product of matrices, in D3D's order: ["camera.ViewInverse", "light0.ViewProjection"].
            parameter.value.kind = HostValue::Kind::Matrix;
            for (size_t i = 0; i < value.size(); ++i) {
                std::optional<HostValue> factor =
                    value[i].is_string() ? valueNamed(value[i].get<std::string>()) : std::nullopt;
                if (value[i].is_string() && !factor) {
                    error(where / i, fx::DiagId::HostValueUnknown, {value[i].get<std::string>()});
                    return std::nullopt;
                }
                if (!factor || factor->kind != HostValue::Kind::Matrix) {
                    error(where / i, fx::DiagId::HostProductNotMatrix);
                    return std::nullopt;
                }
                parameter.value.factors.push_back(factor->factors.front());
            }
            return parameter;
        }
        error(where, fx::DiagId::HostParameterValueExpected, {value.type_name()});
        return std::nullopt;
    }

    void readStep(const json& value, const json::json_pointer& where) {
        if (!isObject(value, where)) return;
        checkKeys(value, where,
                  {"technique", "pass", "target", "port", "clear", "draw", "viewports", "dispatch"});
        HostStep step;
        step.loc = loc(where);
        if (auto it = value.find("technique"); it == value.end()) {
            error(where, fx::DiagId::HostStepWithoutTechnique);
        } else if (std::optional<std::string> technique = string(*it, where / "technique")) {
            step.technique = *technique;
        }
        if (auto it = value.find("pass"); it != value.end())
            if (std::optional<std::string> pass = string(*it, where / "pass")) step.pass = *pass;
        step.target = "frame";
        if (auto it = value.find("target"); it != value.end())
            if (std::optional<std::string> target = string(*it, where / "target")) {
                step.target = *target;
                if (*target != "frame" && !mHost->findTarget(*target))
                    error(where / "target", fx::DiagId::HostStepUnknownTarget, {*target});
            }
        step.port = "camera";
        if (auto it = value.find("port"); it != value.end())
            if (std::optional<std::string> port = string(*it, where / "port")) step.port = *port;
        if (auto it = value.find("clear"); it != value.end() && isObject(*it, where / "clear")) {
            checkKeys(*it, where / "clear", {"color", "depth"});
            if (auto color = it->find("color"); color != it->end()) {
                const std::optional<std::vector<float>> c = numbers(*color);
                if (!c || c->size() != 4)
                    error(where / "clear" / "color", fx::DiagId::HostClearColorInvalid);
                else
                    step.clearColor = std::array<float, 4>{(*c)[0], (*c)[1], (*c)[2], (*c)[3]};
            }
            if (auto depth = it->find("depth"); depth != it->end()) {
                if (!depth->is_number() || toFloat(*depth) < 0.0f || toFloat(*depth) > 1.0f)
                    error(where / "clear" / "depth", fx::DiagId::HostClearDepthInvalid);
                else
                    step.clearDepth = toFloat(*depth);
            }
        }
        if (auto it = value.find("draw"); it != value.end())
            if (std::optional<std::string> draw = string(*it, where / "draw")) {
                if (*draw == "geometry")
                    step.draw = HostStep::Draw::Geometry;
                else if (*draw == "quad")
                    step.draw = HostStep::Draw::Quad;
                else if (*draw == "nothing")
                    step.draw = HostStep::Draw::Nothing;
                else
                    error(where / "draw", fx::DiagId::HostStepDrawInvalid, {*draw});
            }
        if (auto it = value.find("viewports"); it != value.end()) {
            if (std::optional<std::vector<fx::Viewport>> viewports = readViewports(*it))
                step.viewports = *viewports;
            else
                error(where / "viewports", fx::DiagId::HostStepViewportsInvalid);
        }
        if (auto it = value.find("dispatch"); it != value.end()) {
            if (std::optional<std::vector<HostStep::DispatchTerm>> dispatch = readDispatch(*it))
                step.dispatch = *dispatch;
            else
                error(where / "dispatch", fx::DiagId::HostStepDispatchInvalid);
        }
        mHost->frame.push_back(std::move(step));
    }

    // [x, y, z], each a whole number or a parameter's name: a script's Dispatch=x,y,z.
    static std::optional<std::vector<HostStep::DispatchTerm>> readDispatch(const json& value) {
        if (!value.is_array() || value.empty() || value.size() > 3) return std::nullopt;
        std::vector<HostStep::DispatchTerm> terms;
        for (const json& term : value) {
            if (term.is_string() && !term.get<std::string>().empty())
                terms.push_back({term.get<std::string>(), 1});
            else if (term.is_number_integer() && term.get<long long>() >= 0 &&
                     term.get<long long>() <= 0xffffffffLL)
                terms.push_back({"", static_cast<uint32_t>(term.get<long long>())});
            else
                return std::nullopt;
        }
        return terms;
    }

    // [[x, y, width, height], ...]: D3D10's RSSetViewports, at most its 16 (GL's guaranteed GL_MAX_VIEWPORTS
    // too).
    static std::optional<std::vector<fx::Viewport>> readViewports(const json& value) {
        if (!value.is_array() || value.empty() || value.size() > 16) return std::nullopt;
        std::vector<fx::Viewport> viewports;
        for (const json& element : value) {
            const std::optional<std::vector<float>> n = numbers(element);
            if (!n || n->size() != 4 || !((*n)[2] > 0.0f && (*n)[3] > 0.0f)) return std::nullopt;
            viewports.push_back(fx::Viewport{(*n)[0], (*n)[1], (*n)[2], (*n)[3]});
        }
        return viewports;
    }

    void readVisibility(const json& value, const json::json_pointer& where) {
        if (!isObject(value, where)) return;
        checkKeys(value, where, {"set", "unshadowed"});
        HostVisibility visibility;
        visibility.loc = loc(where);
        if (auto it = value.find("set"); it != value.end() && isObject(*it, where / "set"))
            for (const auto& [name, constant] : it->items()) {
                std::optional<std::vector<float>> parsed = numbers(constant);
                if (!parsed) {
                    error(where / "set" / name, fx::DiagId::HostVisibilityValueInvalid);
                    continue;
                }
                HostParameter parameter;
                parameter.name = name;
                parameter.loc = loc(where / "set" / name);
                parameter.value.numbers = std::move(*parsed);
                visibility.set.push_back(std::move(parameter));
            }
        const auto unshadowed = value.find("unshadowed");
        if (unshadowed == value.end() || !unshadowed->is_array() || unshadowed->empty()) {
            error(unshadowed == value.end() ? where : where / "unshadowed",
                  fx::DiagId::HostUnshadowedMissing);
        } else {
            for (size_t i = 0; i < unshadowed->size(); ++i)
                if (std::optional<std::string> name = string((*unshadowed)[i], where / "unshadowed" / i)) {
                    if (!mHost->findTarget(*name))
                        error(where / "unshadowed" / i, fx::DiagId::HostUnshadowedUnknownTarget, {*name});
                    visibility.unshadowed.push_back(*name);
                }
        }
        mHost->visibility = std::move(visibility);
    }

    JsonLocations mLocations;
    fx::DiagnosticSink& mDiagnostics;
    std::shared_ptr<HostFile> mHost;
    bool mFailed = false;
};

}  // namespace

// [SECTION] Entry points

std::shared_ptr<const HostFile> parseHostJson(const std::string& text, const std::string& path,
                                              fx::DiagnosticSink& diagnostics) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        JsonLocations::reportSyntaxError(path, text, e.byte, e.what(), diagnostics);
        return nullptr;
    } catch (const std::exception& e) {
        diagnostics.report(fx::DiagId::SceneSyntaxError, fx::SourceLoc{path, 0, 0}, {e.what()});
        return nullptr;
    }
    try {
        return HostFileReader(path, text, diagnostics).read(root);
    } catch (const std::exception& e) {
        // The reader checks every type before reading it; this is the net under anything it missed: an
        // error, never a crash.
        diagnostics.report(fx::DiagId::HostValueUnreadable, fx::SourceLoc{path, 0, 0}, {e.what()});
        return nullptr;
    }
}

std::shared_ptr<const HostFile> loadHostFile(const std::string& path, fx::DiagnosticSink& diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diagnostics.report(fx::DiagId::FileNotFound, fx::SourceLoc{path, 0, 0}, {path});
        return nullptr;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parseHostJson(text.str(), path, diagnostics);
}

}  // namespace runtime
