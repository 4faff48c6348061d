// The bench's error-vs-time plot (report/ErrorTimePlot.h): read back from the SVG it writes, no
// two label boxes overlap and none covers a marker, even when the points cluster (a sweep whose settings
// barely change time or error), and every run's label is either beside its marker or in the table of
// numbered labels.
#include <report/ErrorTimePlot.h>
#include "ScratchDirectory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace shadowfx::test::test_error_time_plot {
namespace {

struct Rect {
    double x, y, width, height;
};

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The numbers an SVG element's attributes hold, in the order of `names`, for each element `tag` of class
// `cls`.
std::vector<std::vector<double>> elements(const std::string& svg, const std::string& tag,
                                          const std::string& cls, const std::vector<std::string>& names) {
    std::string pattern = "<" + tag + " class=\"" + cls + "\"";
    for (const std::string& name : names) pattern += " " + name + "=\"([-0-9.e]+)\"";
    const std::regex element(pattern);
    std::vector<std::vector<double>> found;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), element); it != std::sregex_iterator();
         ++it) {
        std::vector<double> values;
        for (size_t i = 1; i <= names.size(); ++i) values.push_back(std::stod((*it)[i]));
        found.push_back(values);
    }
    return found;
}

std::vector<Rect> labelBoxes(const std::string& svg) {
    std::vector<Rect> boxes;
    for (const std::vector<double>& v : elements(svg, "rect", "label-box", {"x", "y", "width", "height"}))
        boxes.push_back(Rect{v[0], v[1], v[2], v[3]});
    return boxes;
}

std::vector<Rect> markerBounds(const std::string& svg) {
    std::vector<Rect> markers;
    for (const std::vector<double>& v : elements(svg, "circle", "marker", {"cx", "cy", "r"}))
        markers.push_back(Rect{v[0] - v[2], v[1] - v[2], 2 * v[2], 2 * v[2]});
    return markers;
}

bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// Writes the plot of `points` and checks it: returns the SVG.
std::string plotAndCheck(const std::vector<report::PlotPoint>& points, const std::string& name) {
    const ScratchDirectory scratch("plot");
    const std::filesystem::path path = scratch / (name + ".svg");
    std::string error;
    EXPECT_TRUE(report::writeErrorTimePlot(path.string(), points, "full cost: every pass drawn", error))
        << error;
    const std::string svg = readText(path);
    const std::vector<Rect> boxes = labelBoxes(svg);
    const std::vector<Rect> markers = markerBounds(svg);
    EXPECT_EQ(markers.size(), points.size()) << svg;
    EXPECT_FALSE(boxes.empty()) << svg;
    for (size_t a = 0; a < boxes.size(); ++a) {
        for (size_t b = a + 1; b < boxes.size(); ++b)
            EXPECT_FALSE(overlap(boxes[a], boxes[b])) << "label boxes " << a << " and " << b << " overlap";
        for (size_t m = 0; m < markers.size(); ++m)
            EXPECT_FALSE(overlap(boxes[a], markers[m])) << "label box " << a << " covers marker " << m;
    }
    for (size_t i = 0; i < points.size(); ++i) {
        const bool beside = svg.find(">" + points[i].label + "</text>") != std::string::npos;
        const bool numbered =
            svg.find(">" + std::to_string(i + 1) + "  " + points[i].label + "</text>") != std::string::npos;
        EXPECT_TRUE(beside || numbered)
            << points[i].label << " is neither beside its marker nor in the table";
    }
    return svg;
}

TEST(ErrorTimePlot, ClusteredPointsGetLabelsThatOverlapNothing) {
    // 40 runs within 1 % of each other in time and a few thousandths of a percent in error: a naive label
    // at a fixed offset from each marker would pile 40 labels onto one spot.
    std::vector<report::PlotPoint> points;
    for (int i = 0; i < 40; ++i)
        points.push_back(report::PlotPoint{10.0 + 0.0025 * i, 0.5 + 0.001 * (i % 5),
                                           "esm/esm (Exponent=" + std::to_string(10 + i) + ") 1024",
                                           i % 2 ? "dual-l" : "teapot"});
    const std::string svg = plotAndCheck(points, "clustered");
    EXPECT_NE(svg.find("class=\"leader\""), std::string::npos) << "labels moved away get leader lines";
    EXPECT_NE(svg.find("numbered points:"), std::string::npos) << "a cluster this tight needs the table";
}

TEST(ErrorTimePlot, PointsApartKeepTheirLabelsBesideThem) {
    const std::vector<report::PlotPoint> points{{1.0, 0.1, "pcf/bilinear 1024", "boxes"},
                                                {10.0, 2.0, "thesis_fxcomposer/main 1024", "boxes"},
                                                {100.0, 5.0, "vsm/vsm_blur 1024", "teapot"}};
    const std::string svg = plotAndCheck(points, "apart");
    EXPECT_EQ(labelBoxes(svg).size(), 3u);
    EXPECT_EQ(svg.find("numbered points:"), std::string::npos) << svg;
    EXPECT_EQ(svg.find("class=\"leader\""), std::string::npos) << svg;
}

}  // namespace
}  // namespace shadowfx::test::test_error_time_plot
