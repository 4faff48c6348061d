// Whether a stage's generated GLSL is valid GLSL 4.50 for glslang's GLSL front end: the GL-free tests' check
// of what SPIRV-Cross wrote (a driver would refuse what glslang refuses).
#pragma once

#include <fx/CompiledEffect.h>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

namespace fx::test {

inline ::testing::AssertionResult compilesAsGlsl450(const StageProgram& p) {
    glslang::InitializeProcess();
    EShLanguage lang = p.stage == ShaderStage::Vertex ? EShLangVertex : EShLangFragment;
    glslang::TShader shader(lang);
    const char* text = p.glsl.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientOpenGL, 450);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetSpv_1_0);
    if (shader.parse(GetDefaultResources(), 450, ECoreProfile, true, false, EShMsgDefault))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << shader.getInfoLog() << "\n" << p.glsl;
}

}  // namespace fx::test
