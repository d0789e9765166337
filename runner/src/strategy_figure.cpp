#include "runner/strategy_figure.h"

#include "runner/headless_render.h"

#include "pathlab/images/image_io.h"

#include <cstdio>

namespace pathlab {

namespace {

constexpr int Gap = 8;           ///< pixels between panels
constexpr float GapGrey = 0.05f; ///< their linear grey: dark, apart from black backgrounds

} // namespace

std::vector<StrategyPanel> renderStrategyPanels(const RenderOptions& options,
                                                const RenderScene& scene) {
    std::vector<StrategyPanel> panels = {{StrategyChoice::LightOnly, "light alone", {}, 0},
                                         {StrategyChoice::LobeOnly, "lobe alone", {}, 0},
                                         {StrategyChoice::Both, "both (MIS)", {}, 0}};
    for (StrategyPanel& panel : panels) {
        RenderOptions one = options;
        one.parameters.strategies = panel.strategies;
        HeadlessResult result = renderHeadless(one, scene);
        panel.rgb = result.image.meanImage();
        panel.noise = result.stats.noise;
    }
    return panels;
}

void writeStrategyFigure(const std::string& path, const std::vector<StrategyPanel>& panels,
                         int width, int height) {
    const int count = static_cast<int>(panels.size());
    const int figureWidth = count * width + (count - 1) * Gap;
    std::vector<float> rgb(3 * static_cast<size_t>(figureWidth) * height, GapGrey);
    for (int p = 0; p < count; ++p) {
        const int left = p * (width + Gap);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c)
                    rgb[3 * (static_cast<size_t>(y) * figureWidth + left + x) + c] =
                        panels[static_cast<size_t>(p)]
                            .rgb[3 * (static_cast<size_t>(y) * width + x) + c];
    }
    writeImage(path, figureWidth, height, rgb);
}

std::string describeStrategyPanels(const std::vector<StrategyPanel>& panels) {
    std::string text;
    const StrategyPanel* quietest = nullptr;
    for (const StrategyPanel& panel : panels) {
        char line[128];
        std::snprintf(line, sizeof line, "  %-12s noise %.4f\n", panel.name, panel.noise);
        text += line;
        if (!quietest || panel.noise < quietest->noise) quietest = &panel;
    }
    if (quietest) text += std::string("  the quietest: ") + quietest->name + "\n";
    return text;
}

} // namespace pathlab
