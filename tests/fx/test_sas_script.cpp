// SAS script parsing: commands, case-insensitivity, selectors, locations inside concatenated strings.
#include <fx/EffectParser.h>
#include <fx/SasScript.h>

#include <gtest/gtest.h>

namespace test_sas_script {

using namespace fx;

TEST(SasScript, AllCommands) {
    DiagnosticList diags;
    auto commands = parseSasScript(
        "RenderColorTarget0=RT;RenderColorTarget=;RenderColorTarget3=X;RenderDepthStencilTarget=D;"
        "ClearSetColor=ClearColor;ClearSetDepth=ClearDepth;ClearSetStencil=S;Clear=Color;Clear=depth;"
        "Clear=STENCIL;Draw=Buffer;RenderPort=light0;LoopByCount=N;LoopGetIndex=i;LoopEnd=;Pass=p0;"
        "ScriptOrder=standard;ScriptClass=object;ScriptOutput=color;ScriptSignature=x;",
        SourceLoc{"s.fx", 1, 1}, diags);
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    ASSERT_EQ(commands.size(), 20u);
    EXPECT_EQ(commands[0].kind, ScriptCommand::Kind::RenderColorTarget);
    EXPECT_EQ(commands[0].index, 0);
    EXPECT_EQ(commands[0].value, "RT");
    EXPECT_EQ(commands[1].index, 0);
    EXPECT_EQ(commands[1].value, "");
    EXPECT_EQ(commands[2].index, 3);
    EXPECT_EQ(commands[3].kind, ScriptCommand::Kind::RenderDepthStencilTarget);
    EXPECT_EQ(commands[7].clear, ScriptCommand::ClearWhat::Color);
    EXPECT_EQ(commands[8].clear, ScriptCommand::ClearWhat::Depth);
    EXPECT_EQ(commands[9].clear, ScriptCommand::ClearWhat::Stencil);
    EXPECT_EQ(commands[10].draw, ScriptCommand::DrawWhat::Buffer);
    EXPECT_EQ(commands[14].kind, ScriptCommand::Kind::LoopEnd);
    EXPECT_EQ(commands[15].kind, ScriptCommand::Kind::Pass);
    EXPECT_EQ(commands[19].kind, ScriptCommand::Kind::ScriptSignature);
    EXPECT_EQ(scriptCommandName(commands[11].kind), "RenderPort");
}

TEST(SasScript, CaseInsensitive) {
    DiagnosticList diags;
    auto commands =
        parseSasScript(" draw = geometry ; PASS=P1;renderCOLORtarget1=T;", SourceLoc{"s.fx", 3, 10}, diags);
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    ASSERT_EQ(commands.size(), 3u);
    EXPECT_EQ(commands[0].kind, ScriptCommand::Kind::Draw);
    EXPECT_EQ(commands[0].draw, ScriptCommand::DrawWhat::Geometry);
    EXPECT_EQ(commands[0].loc.column, 11);
    EXPECT_EQ(commands[1].value, "P1");
    EXPECT_EQ(commands[2].index, 1);
}

TEST(SasScript, TechniqueSelector) {
    DiagnosticList diags;
    auto commands = parseSasScript("Technique=UseFast?Fast:Slow;", SourceLoc{"s.fx", 1, 1}, diags);
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].selectorCondition, "UseFast");
    EXPECT_EQ(commands[0].selectorTrue, "Fast");
    EXPECT_EQ(commands[0].selectorFalse, "Slow");
    commands = parseSasScript("Technique=main;", SourceLoc{"s.fx", 1, 1}, diags);
    EXPECT_EQ(commands[0].value, "main");
    EXPECT_EQ(commands[0].selectorCondition, "");
    EXPECT_FALSE(diags.hasErrors());
}

TEST(SasScript, UnknownCommandLocatedInConcatenatedString) {
    const char* source = R"(technique t <
    string Script = "Pass=a;"
                    "Pass=b;  Bogus=1;";
> { pass a {} pass b {} }
)";
    DiagnosticList diags;
    ParseOptions options;
    auto effect = parseEffectSource(source, "s.fx", options, diags);
    ASSERT_TRUE(effect) << diags.str();
    DiagnosticList scriptDiags;
    auto commands = parseSasScript(effect->techniques[0].annotation("Script")->value, scriptDiags);
    EXPECT_EQ(commands.size(), 2u);
    ASSERT_EQ(scriptDiags.items().size(), 1u);
    EXPECT_EQ(scriptDiags.items()[0].id, DiagId::UnknownScriptCommand);
    EXPECT_EQ(scriptDiags.items()[0].loc.str(), "s.fx:3:31");
    EXPECT_EQ(commands[1].loc.str(), "s.fx:3:22");
}

TEST(SasScript, InvalidValues) {
    DiagnosticList diags;
    auto commands =
        parseSasScript("Clear=Everything;Draw=Scene;Pass=;Technique=a?;Pass", SourceLoc{"s.fx", 5, 1}, diags);
    EXPECT_TRUE(commands.empty());
    ASSERT_EQ(diags.errorCount(), 5u) << diags.str();
    // One id per message: an unknown buffer, an unknown draw, an empty value, a condition without its
    // techniques, a command without '='.
    const DiagId expected[] = {DiagId::ScriptClearInvalid, DiagId::ScriptDrawInvalid,
                               DiagId::ScriptValueEmpty, DiagId::ScriptTechniqueConditionInvalid,
                               DiagId::ScriptValueMissing};
    for (size_t i = 0; i < diags.items().size(); ++i) EXPECT_EQ(diags.items()[i].id, expected[i]) << i;
    EXPECT_EQ(diags.items()[1].loc.column, 18);
}

// ScriptExternal=color is where the host draws the scene (runtime/src/HostScene.h): a command like any other.
TEST(SasScript, ScriptExternalIsACommandForTheHost) {
    DiagnosticList diags;
    auto commands = parseSasScript("ScriptExternal=color;", SourceLoc{"s.fx", 1, 1}, diags);
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].kind, ScriptCommand::Kind::ScriptExternal);
    EXPECT_TRUE(diags.items().empty()) << diags.str();
}

// RenderPort=lightN.cascadeK (or lightN.faceK, a PSMCube face) names a light's sub-view
// (runtime/CascadedShadowMaps.h): the light's name and K separately; anything else after the dot is an error
// at the command.
TEST(SasScript, RenderPortCascades) {
    DiagnosticList diags;
    auto commands = parseSasScript(
        "RenderPort=light0.cascade2; RenderPort=sun.Cascade11; RenderPort=light1; RenderPort=light0.face5;",
        SourceLoc{"s.fx", 1, 1}, diags);
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    ASSERT_EQ(commands.size(), 4u);
    EXPECT_EQ(commands[3].value, "light0");
    EXPECT_EQ(commands[3].cascade, 5);
    EXPECT_EQ(commands[0].value, "light0");
    EXPECT_EQ(commands[0].cascade, 2);
    EXPECT_EQ(commands[1].value, "sun");
    EXPECT_EQ(commands[1].cascade, 11);
    EXPECT_EQ(commands[2].value, "light1");
    EXPECT_EQ(commands[2].cascade, -1);
    for (const char* bad : {"RenderPort=light0.tile1;", "RenderPort=light0.cascade;", "RenderPort=.cascade0;",
                            "RenderPort=light0.cascade-1;", "RenderPort=light0.cascade123;",
                            "RenderPort=light0.face;", "RenderPort=light0.faces1;"}) {
        DiagnosticList errors;
        EXPECT_TRUE(parseSasScript(bad, SourceLoc{"s.fx", 2, 5}, errors).empty()) << bad;
        ASSERT_TRUE(errors.hasErrors()) << bad;
        EXPECT_NE(errors.str().find("s.fx:2:5: error: invalid script command 'RenderPort': expected lightN, "
                                    "lightN.cascadeK or lightN.faceK"),
                  std::string::npos)
            << errors.str();
    }
}

// What FX Composer took and D3DX's SAS hosts documented less: `Clear=Depth0` (the one depth buffer),
// `Color0`; `Clear=` names no buffer and is left out with a warning, not an error.
TEST(SasScript, ClearFormsFxComposerTook) {
    DiagnosticList diags;
    auto commands =
        parseSasScript("Clear=Color0;Clear=Depth0;Clear=;Clear=Stencil0;", SourceLoc{"s.fx", 2, 1}, diags);
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    ASSERT_EQ(commands.size(), 3u);
    EXPECT_EQ(commands[0].clear, ScriptCommand::ClearWhat::Color);
    EXPECT_EQ(commands[1].clear, ScriptCommand::ClearWhat::Depth);
    EXPECT_EQ(commands[2].clear, ScriptCommand::ClearWhat::Stencil);
    ASSERT_EQ(diags.items().size(), 1u);
    EXPECT_EQ(diags.items()[0].id, DiagId::ScriptClearNamesNoBuffer);
    EXPECT_EQ(diags.items()[0].severity, Severity::Warning);
    EXPECT_EQ(diags.items()[0].loc.column, 27);
}

// 3ds Max's `Clear=SV_TARGETn` (case-blind): a colour clear of target n alone; beyond the four targets a
// script binds, a warning at the command and nothing cleared.
TEST(SasScript, ClearNamesATargetAs3dsMaxDoes) {
    DiagnosticList diags;
    auto commands = parseSasScript("Clear=SV_TARGET0;Clear=sv_target3|Depth;Clear=SV_Target5;Clear=Color;",
                                   SourceLoc{"s.fx", 2, 1}, diags);
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    ASSERT_EQ(commands.size(), 4u);
    EXPECT_EQ(commands[0].clear, ScriptCommand::ClearWhat::Color);
    EXPECT_EQ(commands[0].clearTarget, 0);
    EXPECT_EQ(commands[1].clear, ScriptCommand::ClearWhat::Color);
    EXPECT_EQ(commands[1].clearTarget, 3);
    EXPECT_EQ(commands[2].clear, ScriptCommand::ClearWhat::Depth);
    EXPECT_EQ(commands[3].clearTarget, -1);  // every bound target
    ASSERT_EQ(diags.items().size(), 1u);
    EXPECT_EQ(diags.items()[0].id, DiagId::ScriptClearTargetBeyond);
    EXPECT_EQ(diags.items()[0].loc.column, 41);
    EXPECT_NE(diags.str().find("'Clear=SV_Target5': colour target 5 is beyond the 4"), std::string::npos)
        << diags.str();
    for (const char* bad : {"Clear=SV_TARGET8;", "Clear=SV_TARGETS;", "Clear=SV_TARGET01;"}) {
        DiagnosticList errors;
        EXPECT_TRUE(parseSasScript(bad, SourceLoc{"s.fx", 2, 1}, errors).empty()) << bad;
        EXPECT_TRUE(errors.hasErrors()) << bad;
    }
}
}  // namespace test_sas_script
