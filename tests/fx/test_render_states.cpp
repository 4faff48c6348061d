// The D3D9 state table: lookups, aliases, prefixes, enum names.
#include <fx/RenderStates.h>

#include <gtest/gtest.h>

namespace test_render_states {

using namespace fx;

TEST(RenderStates, CaseInsensitiveNamesAndAliases) {
    ASSERT_TRUE(findRenderState("cullmode"));
    EXPECT_EQ(*findRenderState("cullmode"), RenderStateId::CullMode);
    EXPECT_EQ(*findRenderState("ZWriteEnabled"), RenderStateId::ZWriteEnable);
    EXPECT_EQ(*findRenderState("DEPTHFUNC"), RenderStateId::ZFunc);
    EXPECT_EQ(*findRenderState("ColorWriteEnable0"), RenderStateId::ColorWriteEnable);
    EXPECT_FALSE(findRenderState("CullMood"));
    EXPECT_FALSE(findRenderState("AddressU"));
    EXPECT_EQ(*findSamplerState("addresss"), SamplerStateId::AddressU);
    EXPECT_EQ(*findSamplerState("MIPFILTER"), SamplerStateId::MipFilter);
    EXPECT_FALSE(findSamplerState("CullMode"));
}

TEST(RenderStates, InfoAndDefaults) {
    const StateInfo& cull = renderStateInfo(RenderStateId::CullMode);
    EXPECT_EQ(cull.name, "CullMode");
    EXPECT_EQ(cull.domain, StateDomain::Cull);
    EXPECT_EQ(cull.defaultValue, 3);
    EXPECT_EQ(samplerStateInfo(SamplerStateId::Texture).domain, StateDomain::TextureRef);
    EXPECT_EQ(domainName(StateDomain::BlendOp), "BlendOp");
}

TEST(RenderStates, EnumValuesWithPrefixesAndUnderscores) {
    EXPECT_EQ(findEnumValue(StateDomain::Cull, "ccw"), 3);
    EXPECT_EQ(findEnumValue(StateDomain::Cull, "D3DCULL_CCW"), 3);
    EXPECT_EQ(findEnumValue(StateDomain::Cmp, "D3DCMP_LESSEQUAL"), 4);
    EXPECT_EQ(findEnumValue(StateDomain::Blend, "D3DBLEND_INVSRCALPHA"), 6);
    EXPECT_EQ(findEnumValue(StateDomain::Blend, "INV_SRC_ALPHA"), 6);
    EXPECT_EQ(findEnumValue(StateDomain::BlendOp, "D3DBLENDOP_MIN"), 4);
    EXPECT_EQ(findEnumValue(StateDomain::Fill, "D3DFILL_WIREFRAME"), 2);
    EXPECT_EQ(findEnumValue(StateDomain::StencilOp, "D3DSTENCILOP_INCRSAT"), 4);
    EXPECT_EQ(findEnumValue(StateDomain::Address, "D3DTADDRESS_CLAMP"), 3);
    EXPECT_EQ(findEnumValue(StateDomain::TexFilter, "D3DTEXF_LINEAR"), 2);
    EXPECT_EQ(findEnumValue(StateDomain::Filter10, "min_mag_linear_mip_point"), 0x14);
    EXPECT_EQ(findEnumValue(StateDomain::ColorMask, "Alpha"), 8);
    EXPECT_EQ(findEnumValue(StateDomain::Bool, "TRUE"), 1);
    EXPECT_FALSE(findEnumValue(StateDomain::Cull, "Sideways"));
    EXPECT_FALSE(findEnumValue(StateDomain::Cull, "D3DCMP_LESS"));
}

TEST(RenderStates, EnumValueNames) {
    auto names = enumValueNames(StateDomain::Cull);
    ASSERT_EQ(names.size(), 3u);
    EXPECT_EQ(names[0], "None");
    EXPECT_EQ(names[2], "CCW");
    EXPECT_TRUE(enumValueNames(StateDomain::Float).empty());
    EXPECT_TRUE(equalsIgnoreCase("LessEqual", "LESSEQUAL"));
    EXPECT_FALSE(equalsIgnoreCase("Less", "LessEqual"));
}
}  // namespace test_render_states
