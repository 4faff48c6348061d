// `shadowfx tune`'s error_surface.svg (report/TuneSurfacePlot.h): one panel per parameter, one marker per
// setting measured in each, the best marked once per panel, settings over the budget hollow; a file that
// cannot be written is said, not ignored.
#include "ScratchDirectory.h"

#include <report/TuneSurfacePlot.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace shadowfx::test::test_tune_surface_plot {
namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(TuneSurfacePlot, OnePanelPerParameterAndOneMarkerPerSettingInEach) {
    using report::TuneParameter;
    const std::vector<TuneParameter> parameters{
        {"Exponent", TuneParameter::Kind::Float, 1.0, 1000.0, 0.0, true, 10.0},
        {"Samples", TuneParameter::Kind::Int, 1.0, 32.0, 0.0, false, 16.0}};
    report::TuneResult result;
    result.evaluations = {{{10.0, 16.0}, {0.5, 12.0}, true, 0},
                          {{100.0, 16.0}, {0.05, 30.0}, false, 1},
                          {{100.0, 4.0}, {0.08, 9.0}, true, 2}};
    result.best = 2;
    const ScratchDirectory scratch("tune_surface");
    const std::string path = (scratch / "error_surface.svg").string();
    std::string error;
    ASSERT_TRUE(report::writeTuneSurfacePlot(path, parameters, result, error)) << error;
    std::ifstream in(path);
    const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(count(svg, "class=\"panel\""), 2u);
    EXPECT_EQ(count(svg, "class=\"setting\""), 4u);
    EXPECT_EQ(count(svg, "class=\"best\""), 2u);
    EXPECT_EQ(count(svg, "fill=\"none\"><title>"), 2u) << "the setting over budget, hollow in both panels";
    EXPECT_NE(svg.find("Exponent (log)"), std::string::npos);
    EXPECT_NE(svg.find("--set Exponent=100 --set Samples=4: 0.08%, 9 ms"), std::string::npos);

    EXPECT_FALSE(report::writeTuneSurfacePlot((scratch / "no" / "such" / "plot.svg").string(), parameters,
                                              result, error));
    EXPECT_NE(error.find("plot.svg"), std::string::npos);
}

}  // namespace
}  // namespace shadowfx::test::test_tune_surface_plot
