// CheckExpectations: see CheckExpectations.h.
#include "CheckExpectations.h"

#include <fx/Preshader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

namespace runtime {

namespace {

// ExpectScenes and per-scene bounds are comma-separated lists: "dual-l, teapot", "dual-l=0.25, teapot=0.12".
std::vector<std::string> commaSeparated(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

}  // namespace

std::string sceneLabel(const std::string& scene) {
    return scene.size() > 5 && scene.compare(scene.size() - 5, 5, ".json") == 0
               ? std::filesystem::path(scene).stem().string()
               : scene;
}

bool readExpectations(const fx::Technique& technique, Expectations& out, fx::DiagnosticSink& sink) {
    bool ok = true;
    // A misspelt expectation would silently check nothing.
    static const std::set<std::string> kKnown{"expectscenes",           "expectmisclassifiedbelow",
                                              "expectpenumbramaebelow", "expectarearadius",
                                              "expectmapsize",          "expectshadows"};
    for (const fx::Annotation& a : technique.annotations) {
        std::string lower = a.name;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower.rfind("expect", 0) == 0 && kKnown.count(lower) == 0) {
            sink.report(fx::DiagId::ExpectationUnknown, a.loc, {a.name});
            ok = false;
        }
    }
    auto number = [&](const char* name) -> std::optional<double> {
        const fx::Annotation* a = technique.annotation(name);
        if (!a) return std::nullopt;
        const fx::TypeDesc scalar;  // float
        std::optional<fx::Value> value =
            a->value.kind == fx::Expr::Kind::String
                ? std::nullopt
                : fx::evaluate(
                      a->value, [](std::string_view) -> const fx::Value* { return nullptr; }, &scalar,
                      nullptr);
        if (!value || !std::isfinite(value->asFloat())) {
            sink.report(fx::DiagId::ExpectationNumberExpected, a->loc, {name});
            ok = false;
            return std::nullopt;
        }
        return value->asFloat();
    };
    if (const fx::Annotation* a = technique.annotation("ExpectScenes")) {
        if (a->value.kind != fx::Expr::Kind::String || commaSeparated(a->value.text).empty()) {
            sink.report(fx::DiagId::ExpectScenesInvalid, a->loc, {});
            ok = false;
        } else {
            out.scenes = commaSeparated(a->value.text);
            for (std::string& scene : out.scenes) {
                scene.erase(0, scene.find_first_not_of(" \t"));
                scene.erase(scene.find_last_not_of(" \t") + 1);
            }
        }
    }
    // A number, or "scene=bound, ..." naming each scene of ExpectScenes once (a misspelt or forgotten scene
    // would silently check nothing).
    auto bound = [&](const char* name) {
        SceneBound result;
        const fx::Annotation* a = technique.annotation(name);
        if (!a || a->value.kind != fx::Expr::Kind::String) {
            result.everyScene = number(name);
            return result;
        }
        auto invalid = [&](fx::DiagId id, const std::string& what) {
            sink.report(id, a->loc, {name, what});
            ok = false;
            return SceneBound{};
        };
        for (std::string entry : commaSeparated(a->value.text)) {
            const size_t eq = entry.find('=');
            std::string scene = entry.substr(0, eq);
            scene.erase(0, scene.find_first_not_of(" \t"));
            scene.erase(scene.find_last_not_of(" \t") + 1);
            const std::string text = eq == std::string::npos ? "" : entry.substr(eq + 1);
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (scene.empty() || text.empty() || *end != '\0' || !std::isfinite(value))
                return invalid(fx::DiagId::ExpectationSceneBoundSyntax, entry);
            const std::string label = sceneLabel(scene);
            if (std::none_of(out.scenes.begin(), out.scenes.end(),
                             [&](const std::string& listed) { return sceneLabel(listed) == label; }))
                return invalid(fx::DiagId::ExpectationSceneNotExpected, scene);
            if (!result.perScene.emplace(label, value).second)
                return invalid(fx::DiagId::ExpectationSceneRepeated, scene);
        }
        for (const std::string& listed : out.scenes)
            if (result.perScene.count(sceneLabel(listed)) == 0)
                return invalid(fx::DiagId::ExpectationSceneMissing, listed);
        return result;
    };
    out.misclassifiedBelow = bound("ExpectMisclassifiedBelow");
    out.penumbraMaeBelow = bound("ExpectPenumbraMaeBelow");
    if (std::optional<double> radius = number("ExpectAreaRadius")) {
        if (!(*radius > 0.0 && *radius < 1e6)) {
            sink.report(fx::DiagId::ExpectAreaRadiusInvalid, technique.annotation("ExpectAreaRadius")->loc,
                        {});
            ok = false;
        } else {
            out.areaRadius = static_cast<float>(*radius);
        }
    }
    if (std::optional<double> size = number("ExpectMapSize")) {
        if (*size < 1 || *size > 16384 || *size != std::floor(*size)) {
            sink.report(fx::DiagId::ExpectMapSizeInvalid, technique.annotation("ExpectMapSize")->loc, {});
            ok = false;
        } else {
            out.mapSize = static_cast<int>(*size);
        }
    }
    if (std::optional<double> shadows = number("ExpectShadows")) out.shadows = *shadows != 0.0;
    return ok;
}

}  // namespace runtime
