// HostFile: see fx/HostFile.h. The file's reader is runtime/HostFileReader.h (JSON); this is the data's
// own logic and its check against a compiled effect.
#include <fx/HostFile.h>

namespace fx {

bool HostValue::perObject() const {
    if (kind == Kind::ObjectColor) return true;
    if (kind != Kind::Matrix) return false;
    for (const HostMatrix& factor : factors)
        if (factor.kind == HostMatrix::Kind::World || factor.kind == HostMatrix::Kind::WorldView ||
            factor.kind == HostMatrix::Kind::WorldViewProjection)
            return true;
    return false;
}

const HostTarget* HostFile::findTarget(const std::string& name) const {
    for (const HostTarget& target : targets)
        if (target.name == name) return &target;
    return nullptr;
}

std::string_view hostTargetKindName(HostTarget::Kind kind) {
    switch (kind) {
        case HostTarget::Kind::Plane:
            return "2d";
        case HostTarget::Kind::Cube:
            return "cube";
        case HostTarget::Kind::Array:
            return "array";
        case HostTarget::Kind::Volume:
            return "volume";
    }
    return "2d";
}

namespace {

// The texture types a target of this kind can be given to, as D3D10 binds a view of it.
bool targetFits(HostTarget::Kind kind, fx::BaseType type) {
    switch (kind) {
        case HostTarget::Kind::Plane:
            return type == fx::BaseType::Texture || type == fx::BaseType::Texture2D;
        case HostTarget::Kind::Cube:
            return type == fx::BaseType::TextureCube;
        case HostTarget::Kind::Array:
            return type == fx::BaseType::Texture2DArray;
        case HostTarget::Kind::Volume:
            return type == fx::BaseType::Texture3D;
    }
    return false;
}

size_t valueComponents(const HostValue& value) {
    switch (value.kind) {
        case HostValue::Kind::Constant:
            return value.numbers.size();
        case HostValue::Kind::Matrix:
            return 16;
        case HostValue::Kind::LightPosition:
        case HostValue::Kind::LightDirection:
        case HostValue::Kind::LightColor:
            return 3;
        case HostValue::Kind::LightCosHalfAngle:
            return 1;
        case HostValue::Kind::ObjectColor:
            return 4;
        case HostValue::Kind::ViewportSize:
            return 2;
    }
    return 0;
}

}  // namespace

bool checkHostFile(const HostFile& host, const fx::CompiledEffect& effect, fx::DiagnosticSink& diagnostics) {
    bool ok = true;
    const auto fail = [&](const fx::SourceLoc& loc, fx::DiagId id, const std::vector<std::string>& args) {
        diagnostics.report(id, loc, args);
        ok = false;
    };
    const auto findParameter = [&](const std::string& name) -> const fx::ParameterInfo* {
        for (const fx::ParameterInfo& parameter : effect.parameters)
            if (parameter.name == name) return &parameter;
        return nullptr;
    };
    const auto checkValue = [&](const HostParameter& parameter, const std::string& section) {
        const fx::ParameterInfo* info = findParameter(parameter.name);
        const std::string key = section + "/" + parameter.name;
        if (!info) {
            fail(parameter.loc, fx::DiagId::HostParameterUnknown, {key, parameter.name});
            return;
        }
        if (!info->type.isNumeric()) {
            fail(parameter.loc, fx::DiagId::HostParameterNotNumeric,
                 {key, parameter.name, info->type.hlslName()});
            return;
        }
        const size_t expected = static_cast<size_t>(info->type.componentCount());
        const size_t given = valueComponents(parameter.value);
        const bool matrix = parameter.value.kind == HostValue::Kind::Matrix;
        // A matrix fits a float4x4 (or its float3x3 part, as D3DX's SetMatrix fills a smaller one); light
        // vectors and colours fill float3 or float4; constants broadcast from one number, as HLSL does.
        const bool fits = matrix ? info->type.rows >= 3 && info->type.cols >= 3
                          : parameter.value.kind == HostValue::Kind::Constant
                              ? given == expected || given == 1
                              : given == expected || (given >= 3 && expected >= 3 && expected <= 4);
        if (!fits)
            fail(parameter.loc, fx::DiagId::HostValueSizeMismatch,
                 {key, parameter.name, info->type.hlslName(), std::to_string(expected),
                  std::to_string(given)});
    };
    for (const HostTarget& target : host.targets) {
        if (target.texture.empty()) continue;
        const fx::ParameterInfo* info = findParameter(target.texture);
        if (!info || info->type.isNumeric())
            fail(target.loc, fx::DiagId::HostTargetTextureUnknown,
                 {"targets/" + target.name, target.texture});
        else if (info->type.isTexture() && !targetFits(target.kind, info->type.base))
            fail(target.loc, fx::DiagId::HostTargetTextureKindMismatch,
                 {"targets/" + target.name, std::string(hostTargetKindName(target.kind)), target.texture,
                  info->type.hlslName()});
    }
    for (const HostParameter& parameter : host.parameters) checkValue(parameter, "parameters");
    if (host.visibility)
        for (const HostParameter& parameter : host.visibility->set) checkValue(parameter, "visibility/set");
    for (size_t i = 0; i < host.frame.size(); ++i) {
        const HostStep& step = host.frame[i];
        const std::string key = "frame/" + std::to_string(i);
        const fx::CompiledTechnique* technique = effect.findTechnique(step.technique);
        if (!technique) {
            fail(step.loc, fx::DiagId::HostStepTechniqueUnknown, {key, step.technique});
            continue;
        }
        if (!step.pass.empty()) {
            bool found = false;
            for (const fx::CompiledPass& pass : technique->passes) found = found || pass.name == step.pass;
            if (!found) fail(step.loc, fx::DiagId::HostStepPassUnknown, {key, step.technique, step.pass});
        }
        for (const HostStep::DispatchTerm& term : step.dispatch) {
            if (term.parameter.empty()) continue;
            const fx::ParameterInfo* info = findParameter(term.parameter);
            if (!info)
                fail(step.loc, fx::DiagId::HostParameterUnknown, {key + "/dispatch", term.parameter});
            else if (!info->type.isNumeric())
                fail(step.loc, fx::DiagId::HostParameterNotNumeric,
                     {key + "/dispatch", term.parameter, info->type.hlslName()});
        }
    }
    return ok;
}

}  // namespace fx
