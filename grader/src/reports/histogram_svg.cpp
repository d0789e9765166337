#include "reports/histogram_svg.h"

#include "reports/reports.h"

#include <algorithm>
#include <sstream>

namespace pathlab::grader {

namespace {

// The layout, in SVG units (CSS pixels), for 11-pixel text: a line of text above the tallest
// bar for its count, two below the bars for the ranges and the axis title.
constexpr int Width = 520, Height = 216;
constexpr int TallestBar = 150;
constexpr int BarsBottom = 22 + TallestBar;    // room for the tallest bar's count above it
constexpr int CountGap = 5;                    // between a count's baseline and its bar
constexpr int RangeBaseline = BarsBottom + 17; // one line below the bars
constexpr int TitleBaseline = RangeBaseline + 18;
constexpr int BarPitch = 50, BarWidth = 44, LeftMargin = 10;

} // namespace

std::string histogramSvg(const std::array<int, 10>& bins, const std::string& axisTitle) {
    const int tallest = std::max(1, *std::max_element(bins.begin(), bins.end()));
    std::ostringstream svg;
    svg << "<svg width=\"" << Width << "\" height=\"" << Height << "\" viewBox=\"0 0 " << Width
        << " " << Height << "\" xmlns=\"http://www.w3.org/2000/svg\" "
        << "font-family=\"sans-serif\" font-size=\"11\">\n";
    for (int i = 0; i < 10; ++i) {
        const int h = TallestBar * bins[i] / tallest, x = LeftMargin + BarPitch * i;
        const int middle = x + BarWidth / 2;
        svg << "<rect x=\"" << x << "\" y=\"" << BarsBottom - h << "\" width=\"" << BarWidth
            << "\" height=\"" << h << "\" fill=\"#4a7ab5\"/>\n<text x=\"" << middle << "\" y=\""
            << BarsBottom - h - CountGap << "\" text-anchor=\"middle\">" << bins[i]
            << "</text>\n<text x=\"" << middle << "\" y=\"" << RangeBaseline
            << "\" text-anchor=\"middle\">" << 10 * i << "-" << (i == 9 ? 100 : 10 * i + 9)
            << "%</text>\n";
    }
    svg << "<text x=\"" << Width / 2 << "\" y=\"" << TitleBaseline << "\" text-anchor=\"middle\">"
        << escapeXml(axisTitle) << "</text></svg>\n";
    return svg.str();
}

} // namespace pathlab::grader
